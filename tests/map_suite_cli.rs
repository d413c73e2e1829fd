//! `pounding map --suite` end to end (SPEC §12): a cell is the suite of the
//! buildings with the cell's quantities, as `pounding suite` runs it; CSV
//! rows stream with version and units; bad axes are refused.

mod common;

use common::{fails, json, stdout, succeeds};

const ARGS: [&str; 9] = [
    "--preset",
    "two-buildings",
    "--suite",
    "synthetic:6@3",
    "--im",
    "sa:0.95",
    "--level",
    "0.2",
    "--format",
];

#[test]
fn a_cell_is_the_suite_of_its_buildings() {
    let mut args = vec![
        "map",
        "--x",
        "period1=0.75:1.25:0.25",
        "--y",
        "gap=0.03:0.05:0.02",
    ];
    args.extend(ARGS);
    args.push("json");
    let v = json(&args);
    let cells = v["cells"].as_array().unwrap();
    assert_eq!(cells.len(), 6);
    // The cell (period1 = 1.25 s, gap = 0.05 m): row 1, column 2.
    let cell = &cells[5];
    assert_eq!(
        (cell["x"].as_f64(), cell["y"].as_f64()),
        (Some(1.25), Some(0.05))
    );
    // The same buildings as a preset of their own.
    let dir = tempfile::tempdir().unwrap();
    let preset = std::fs::read_to_string("presets/two-buildings.toml")
        .unwrap()
        .replace("name = \"two-buildings\"", "name = \"cell\"")
        .replace("period1 = 0.95", "period1 = 1.25")
        .replace("gap = 0.025", "gap = 0.05");
    let path = dir.path().join("cell.toml");
    std::fs::write(&path, preset).unwrap();
    let mut suite_args = vec!["suite", "--preset", path.to_str().unwrap()];
    suite_args.extend(&ARGS[2..]);
    suite_args.push("json");
    let s = json(&suite_args);
    let rows = s["records"].as_array().unwrap();
    let pounded = rows
        .iter()
        .filter(|r| r["impacts"].as_u64().unwrap() > 0)
        .count();
    assert_eq!(
        cell["pounding_probability"].as_f64().unwrap(),
        pounded as f64 / 6.0
    );
    let mut ratios: Vec<f64> = rows
        .iter()
        .map(|r| {
            r["left"]["peak_displacement_m"].as_f64().unwrap()
                / r["no_pounding"][0]["peak_displacement_m"].as_f64().unwrap()
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    let median = 0.5 * (ratios[2] + ratios[3]);
    let got = cell["median_amplification"].as_f64().unwrap();
    assert!((got - median).abs() <= 1e-14 * median, "{got} vs {median}");
    let gap = s["statistics"]["demands"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["demand"] == "min_gap_m")
        .unwrap()["median"]
        .as_f64()
        .unwrap();
    assert_eq!(cell["median_min_gap_m"].as_f64().unwrap(), gap);
}

#[test]
fn csv_streams_one_row_per_cell_with_version_and_units() {
    let mut args = vec![
        "map",
        "--x",
        "period1=0.75:1.25:0.25",
        "--y",
        "gap=0.03:0.05:0.02",
    ];
    args.extend(ARGS);
    args.push("csv");
    let text = stdout(&succeeds(&args));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 7, "{text}");
    assert!(lines[0].starts_with("version,units,x,y,pounding_probability"));
    assert!(lines[1].starts_with(env!("CARGO_PKG_VERSION")));
}

#[test]
fn bad_axes_are_refused() {
    for (x, fragment) in [
        ("omega1=0.5:1:0.1", "unknown key"),
        ("period1=0:1:0.1", "> 0"),
        ("period1=1:0.5:0.1", "START <= STOP"),
    ] {
        let mut args = vec!["map", "--x", x, "--y", "gap=0.01:0.02:0.01"];
        args.extend(&ARGS[..8]);
        fails(&args, 2, &["--x", fragment]);
    }
    fails(
        &[
            "map",
            "--x",
            "omega1=0.5:1:0.1",
            "--y",
            "gap=0.1:0.2:0.1",
            "--level",
            "0.3",
        ],
        2,
        &["--level", "--suite"],
    );
}
