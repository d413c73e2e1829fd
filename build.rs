//! Compiles every `presets/*.toml` into the binary, so the built-in presets
//! work from any directory. Adding a preset needs no code change.

use std::{env, fs, path::Path};

fn main() {
    println!("cargo:rerun-if-changed=presets");
    let dir = Path::new(&env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"))
        .join("presets");
    let mut entries: Vec<_> = fs::read_dir(&dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect()
        })
        .unwrap_or_default();
    // The paper's parameter sets first (keys 1 and 2 in the explorer), then the rest by name.
    entries.sort_by_key(|p| {
        let stem = p
            .file_stem()
            .unwrap_or_default()
            .to_string_lossy()
            .into_owned();
        (!stem.starts_with("set"), stem)
    });
    let mut out = String::from(
        "/// (name, file name, contents) of every built-in preset: set1, set2, then the rest by name.\npub static BUILTIN: &[(&str, &str, &str)] = &[\n",
    );
    for p in &entries {
        println!("cargo:rerun-if-changed={}", p.display());
        let stem = p.file_stem().unwrap().to_string_lossy();
        let file = p.file_name().unwrap().to_string_lossy();
        out += &format!(
            "    ({stem:?}, {file:?}, include_str!({:?})),\n",
            p.display().to_string()
        );
    }
    out += "];\n";
    fs::write(
        Path::new(&env::var("OUT_DIR").unwrap()).join("builtin_presets.rs"),
        out,
    )
    .unwrap();
}
