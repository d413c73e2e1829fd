//! Plain two-column records (`time, acceleration`, commas or white space)
//! with a units suffix, against the same motion as PEER `.AT2`, and their
//! malformed forms: one line on stderr naming the file and line, exit 2.

use std::fs;
use std::process::Command;

use pounding::model::record::{self, Units};

const AT2: &str = "PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic\n\
ACCELERATION TIME SERIES IN UNITS OF G\n\
NPTS=   5, DT=   .0200 SEC\n\
 0.0 0.1 -0.2\n 0.05 0.0\n";

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_pounding"))
}

#[test]
fn a_csv_in_g_and_a_text_file_in_m_s2_read_as_the_at2() {
    let dir = tempfile::tempdir().unwrap();
    let at2 = record::parse_at2("x.at2", AT2).unwrap();
    let csv = dir.path().join("quake.csv");
    fs::write(
        &csv,
        "time_s,acc_g\n1.00,0.0\n1.02,0.1\n1.04,-0.2\n1.06,0.05\n1.08,0.0\n",
    )
    .unwrap();
    let from_csv = record::read(csv.to_str().unwrap()).unwrap();
    assert_eq!(from_csv.acceleration.len(), 5);
    assert!((from_csv.dt - 0.02).abs() < 1e-15);
    for (a, b) in from_csv.acceleration.iter().zip(&at2.acceleration) {
        assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    }
    let txt = dir.path().join("quake.txt");
    let si: String = at2
        .acceleration
        .iter()
        .enumerate()
        .map(|(k, a)| format!("{}   {a}\n", k as f64 * 0.02))
        .collect();
    fs::write(&txt, format!("# accelerations in m/s2\n{si}")).unwrap();
    let spec = format!("{}@m/s2", txt.display());
    let from_txt = record::read(&spec).unwrap();
    assert_eq!(from_txt.acceleration, at2.acceleration);
    assert_eq!(from_txt.spec, format!("record:{spec}"));
    assert_eq!(Units::parse("cm/s2").unwrap().in_si(), 0.01);
}

#[test]
fn a_csv_record_runs_through_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("quake.csv");
    let rows: String = (0..200)
        .map(|k| format!("{},{}\n", k as f64 * 0.01, (k as f64 * 0.3).sin() * 2.0))
        .collect();
    fs::write(&csv, rows).unwrap();
    let out = bin()
        .args([
            "run",
            "--method",
            "exact",
            "--format",
            "json",
            "--excitation",
        ])
        .arg(format!("record:{}@m/s2", csv.display()))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(
        v["excitation"]
            .as_str()
            .unwrap()
            .ends_with("quake.csv@m/s2"),
        "{}",
        v["excitation"]
    );
}

#[test]
fn malformed_plain_records_name_the_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("uneven.csv", "0,0\n0.01,1\n0.03,2\n", "", "line 3"),
        ("word.csv", "t,a\n0,0\n0.01,oops\n", "", "line 3"),
        ("one.csv", "0,0\n", "", "line 1"),
        ("units.csv", "0,0\n0.01,1\n", "@furlongs", "unknown unit"),
    ];
    for (name, text, suffix, expected) in cases {
        let path = dir.path().join(name);
        fs::write(&path, text).unwrap();
        let out = bin()
            .args(["run", "--method", "exact", "--excitation"])
            .arg(format!("record:{}{suffix}", path.display()))
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{name}: {err}");
        assert!(
            err.contains(name) && err.contains(expected),
            "{name}: {err}"
        );
    }
}
