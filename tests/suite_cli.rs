//! `pounding suite` end to end (SPEC §12): every row is the `pounding run`
//! of its record at its scale, bit for bit; `--level` scales each record to
//! the intensity asked; the statistics are those of the rows; bad input is
//! refused with one line and exit 2.

mod common;

use common::{fails, json, succeeds};
use std::path::Path;

/// Writes `count` simulated records with `seed` into `dir` (`records synth`).
fn synth(dir: &Path, count: usize, seed: u64) {
    succeeds(&[
        "records",
        "synth",
        "--count",
        &count.to_string(),
        "--seed",
        &seed.to_string(),
        "--out",
        dir.to_str().unwrap(),
    ]);
}

/// The accelerations (g) of an AT2 file, read here independently of the
/// library: every number after the four header lines.
fn at2_accelerations(path: &Path) -> Vec<f64> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .skip(4)
        .flat_map(|l| l.split_whitespace())
        .map(|t| t.parse::<f64>().unwrap())
        .collect()
}

fn rows(v: &serde_json::Value) -> &Vec<serde_json::Value> {
    v["records"].as_array().expect("records")
}

/// The record file a row names, in `dir`.
fn file_of(dir: &Path, row: &serde_json::Value) -> std::path::PathBuf {
    let name = row["record"].as_str().unwrap();
    let path = dir.join(name);
    if path.exists() {
        path
    } else {
        dir.join(format!("{name}.at2"))
    }
}

#[test]
fn every_row_is_the_run_of_its_record_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    synth(dir.path(), 3, 5);
    let v = json(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        dir.path().to_str().unwrap(),
        "--im",
        "sa:0.95",
        "--level",
        "0.3",
        "--format",
        "json",
    ]);
    assert_eq!(rows(&v).len(), 3);
    let mut pounded = 0;
    for row in rows(&v) {
        let path = file_of(dir.path(), row);
        let ap = row["ap"].as_f64().unwrap();
        let scale = row["scale"].as_f64().unwrap();
        let run = json(&[
            "run",
            "--preset",
            "two-buildings",
            "--method",
            "exact",
            "--excitation",
            &format!("record:{}", path.display()),
            "--set",
            &format!("record_scale={scale}"),
            "--format",
            "json",
        ]);
        assert_eq!(row["params"], run["params"], "{}", row["record"]);
        assert_eq!(row["left"]["pi"], run["left"], "{}", row["record"]);
        assert_eq!(row["right"]["pi"], run["right"], "{}", row["record"]);
        assert_eq!(row["impacts"], run["impacts"]);
        assert_eq!(row["min_gap"], run["min_gap_no_pounding"]);
        // The run names its record's numbers.
        assert_eq!(run["a_p"].as_f64().unwrap(), ap);
        assert_eq!(run["omega_p"], row["omega_p"]);
        assert_eq!(run["samples"], row["samples"]);
        pounded += usize::from(row["impacts"].as_u64().unwrap() > 0);
    }
    assert_eq!(
        v["statistics"]["pounded"].as_u64().unwrap() as usize,
        pounded
    );
}

#[test]
fn a_level_scales_each_record_to_its_pga() {
    let dir = tempfile::tempdir().unwrap();
    synth(dir.path(), 4, 11);
    let v = json(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        dir.path().to_str().unwrap(),
        "--im",
        "pga",
        "--level",
        "0.4g",
        "--format",
        "json",
    ]);
    for row in rows(&v) {
        // The PGA of the file, read here, times the scale is the level.
        let pga = at2_accelerations(&file_of(dir.path(), row))
            .iter()
            .fold(0.0f64, |m, a| m.max(a.abs()));
        let scale = row["scale"].as_f64().unwrap();
        assert!(
            (scale * pga - 0.4).abs() < 1e-12,
            "{} {}",
            scale * pga,
            row["record"]
        );
        assert!((row["intensity_g"].as_f64().unwrap() - 0.4).abs() < 1e-12);
        // a_p is the scaled peak, in m/s².
        let ap = row["ap"].as_f64().unwrap();
        assert!((ap - 0.4 * 9.80665).abs() < 1e-10, "{ap}");
    }
}

#[test]
fn statistics_are_those_of_the_rows() {
    let v = json(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:6@3",
        "--im",
        "sa:0.95",
        "--level",
        "0.3",
        "--format",
        "json",
    ]);
    let mut u: Vec<f64> = rows(&v)
        .iter()
        .map(|r| r["left"]["peak_displacement_m"].as_f64().unwrap())
        .collect();
    u.sort_by(f64::total_cmp);
    // Six values: the median is the mean of the third and fourth (numpy),
    // the 16th percentile at rank 0.8, the 84th at rank 4.2.
    let median = 0.5 * (u[2] + u[3]);
    let p16 = u[0] + 0.8 * (u[1] - u[0]);
    let p84 = u[4] + 0.2 * (u[5] - u[4]);
    let logs: Vec<f64> = u.iter().map(|x| x.ln()).collect();
    let mean = logs.iter().sum::<f64>() / 6.0;
    let beta = (logs.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / 5.0).sqrt();
    let stat = v["statistics"]["demands"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["demand"] == "left.peak_displacement_m")
        .unwrap();
    for (key, want) in [
        ("median", median),
        ("p16", p16),
        ("p84", p84),
        ("dispersion", beta),
    ] {
        let got = stat[key].as_f64().unwrap();
        assert!(
            (got - want).abs() <= 1e-14 * want.abs(),
            "{key}: {got} vs {want}"
        );
    }
    // Every scaled record has Sa(0.95 s) = 0.3 g.
    for row in rows(&v) {
        assert!((row["intensity_g"].as_f64().unwrap() - 0.3).abs() < 1e-12);
    }
}

#[test]
fn the_table_names_records_demands_and_statistics() {
    let o = succeeds(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:3",
        "--im",
        "sa:0.95",
        "--level",
        "0.3",
    ]);
    let text = common::stdout(&o);
    for fragment in [
        "synthetic",
        "A g",
        "μ",
        "resid mm",
        "E_h kJ",
        "statistics over 3 records",
        "left.peak_absolute_acceleration_g",
        "right.ductility",
        "min_gap_m",
    ] {
        assert!(text.contains(fragment), "{fragment} missing:\n{text}");
    }
}

#[test]
fn csv_has_one_row_per_record_with_version_and_units() {
    let o = succeeds(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:2@9",
        "--format",
        "csv",
    ]);
    let text = common::stdout(&o);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3, "{text}");
    assert!(lines[0].starts_with("version,units,record,"));
    assert!(lines[0].contains("left_peak_absolute_acceleration_g"));
    assert!(lines[1].starts_with(env!("CARGO_PKG_VERSION")));
}

#[test]
fn bad_suites_and_levels_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().to_str().unwrap();
    // A preset without [physical].
    fails(
        &["suite", "--preset", "set1", "--suite", "synthetic:2"],
        2,
        &["set1", "[physical]"],
    );
    // Levels and measures out of range.
    for level in ["0", "-0.3", "inf", "abc"] {
        fails(
            &[
                "suite",
                "--preset",
                "two-buildings",
                "--suite",
                "synthetic:2",
                "--level",
                level,
            ],
            2,
            &["--level"],
        );
    }
    fails(
        &[
            "suite",
            "--preset",
            "two-buildings",
            "--suite",
            "synthetic:2",
            "--im",
            "sa:11",
        ],
        2,
        &["sa:11"],
    );
    // An empty directory has no record.
    fails(
        &["suite", "--preset", "two-buildings", "--suite", d],
        2,
        &[d],
    );
    // A record of zeros cannot be scaled: its name is given.
    let zeros = dir.path().join("quiet.csv");
    std::fs::write(&zeros, "0, 0\n0.01, 0\n0.02, 0\n").unwrap();
    fails(
        &[
            "suite",
            "--preset",
            "two-buildings",
            "--suite",
            d,
            "--level",
            "0.3",
        ],
        2,
        &["quiet"],
    );
    // `run` refuses it too, rather than inventing a_p.
    fails(
        &[
            "run",
            "--excitation",
            &format!("record:{}", zeros.display()),
        ],
        2,
        &["excitation", "zero"],
    );
    // A suite runs its own records.
    fails(
        &[
            "suite",
            "--preset",
            "two-buildings",
            "--suite",
            "synthetic:2",
            "--excitation",
            "sine",
        ],
        2,
        &["--excitation"],
    );
}
