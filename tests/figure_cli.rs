//! `pounding figure` end to end: PNG size and ink, atomic output, `figure all`,
//! and bad input (exit 2, one line).

mod common;

use common::{fails, succeeds};
use std::path::Path;

/// Pixels that differ from the white background.
fn ink(path: &Path) -> (u32, u32, usize) {
    let img = image::open(path).expect("PNG decodes").to_rgb8();
    let ink = img.pixels().filter(|p| p.0 != [255, 255, 255]).count();
    (img.width(), img.height(), ink)
}

#[test]
fn png_has_the_requested_size_and_ink() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("fig3.png");
    succeeds(&[
        "figure",
        "fig3",
        "--out",
        out.to_str().unwrap(),
        "--width",
        "800",
        "--height",
        "600",
    ]);
    let (w, h, ink) = ink(&out);
    assert_eq!((w, h), (800, 600));
    // Pinned once by looking at the figure (four panels of curves, grid,
    // text: 6.7 % of the canvas at 800 × 600); the font is embedded, so the
    // count is the same on every machine. A figure without its curves or
    // text falls below, a smeared one above.
    let share = ink as f64 / (w * h) as f64;
    assert!((0.055..0.085).contains(&share), "ink share {share}");
    // Only the figure is left in the directory (no temporary file).
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("fig3.png")]);
}

#[test]
fn svg_is_the_default_and_replaces_an_old_file_whole() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("loops.svg");
    std::fs::write(&out, "old contents that are longer than nothing").unwrap();
    succeeds(&[
        "figure",
        "loops",
        "--preset",
        "set2",
        "--out",
        out.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("<svg"), "{}", &text[..40]);
    assert!(text.trim_end().ends_with("</svg>"));
    assert!(text.contains("set2"), "the caption names the preset");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn all_writes_every_paper_figure_in_both_formats() {
    let dir = tempfile::tempdir().unwrap();
    succeeds(&[
        "figure",
        "all",
        "--out",
        dir.path().to_str().unwrap(),
        "--omega1",
        "0.5:2.0:0.25",
        "--width",
        "400",
        "--height",
        "300",
    ]);
    for n in 3..=10 {
        for ext in ["svg", "png"] {
            let p = dir.path().join(format!("fig{n}.{ext}"));
            assert!(p.is_file(), "{} missing", p.display());
        }
        let (w, h, ink) = ink(&dir.path().join(format!("fig{n}.png")));
        assert_eq!((w, h), (400, 300));
        assert!(ink > 5_000, "fig{n}: {ink} pixels of ink");
    }
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    let cases: [(&[&str], &str); 8] = [
        (&["figure", "fig11"], "figure `fig11`: unknown"),
        (
            &["figure", "fig3", "--format", "gif"],
            "--format gif: must be `svg` or `png`",
        ),
        (
            &["figure", "fig3", "--width", "10"],
            "--width 10: must be an integer in [200, 10000]",
        ),
        (
            &["figure", "fig3", "--height", "tall"],
            "--height tall: must be an integer",
        ),
        (
            &["figure", "fig3", "--method", "euler"],
            "invalid value 'euler' for '--method",
        ),
        (
            &["figure", "fig3", "--preset", "set2"],
            "apply to the scenes",
        ),
        (
            &["figure", "history", "--omega1", "0:1:0.1"],
            "--omega1 applies to spectrum figures",
        ),
        (
            &["figure", "spectrum", "--omega1", "1:0:0.1"],
            "`omega1` grid = 1:0:0.1",
        ),
    ];
    for (args, expected) in cases {
        fails(args, 2, &[expected]);
    }
}

#[test]
fn unwritable_output_is_exit_1() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "x").unwrap();
    let out = file.join("fig3.svg");
    fails(
        &["figure", "fig3", "--out", out.to_str().unwrap()],
        1,
        &["cannot write"],
    );
}

#[test]
fn map_with_buildings_draws_the_retrofit_map() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("retrofit.svg");
    let base = [
        "figure",
        "map",
        "--buildings",
        "block-and-frame-retrofit",
        "--suite",
        "synthetic:2",
        "--level",
        "0.3",
    ];
    let mut args = base.to_vec();
    args.extend([
        "--x",
        "link1.damping=2e6:6e6:2e6",
        "--y",
        "joint1.bumper.thickness=0.002:0.004:0.002",
        "--out",
        out.to_str().unwrap(),
    ]);
    succeeds(&args);
    let svg = std::fs::read_to_string(&out).unwrap();
    for text in [
        "P(pounding)",
        "median peak drift ratio",
        "median peak floor acceleration",
        "median peak link force",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    // The axes are the map's: without them, one line and exit 2.
    fails(&base, 2, &["--x"]);
}
