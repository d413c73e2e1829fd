//! `pounding records scale` and `records select` at the command line: the
//! list `scale` writes, run through `suite`, equals `suite` run with those
//! scales bit for bit; JSON and CSV carry the grid, the target, each
//! record's spectrum, the mean and the verdict; `select` keeps K per event
//! as the AT2 headers name them; bad input is one line and exit 2, a rule
//! that does not hold exit 1.

mod common;

use std::fs;
use std::path::Path;

use common::{fails, json, pounding, stderr, stdout, succeeds};

const EC8: &str = "ec8:ag=0.3,ground=B,type=1";

fn synth(dir: &Path, count: &str) {
    succeeds(&[
        "records",
        "synth",
        "--count",
        count,
        "--seed",
        "3",
        "--out",
        dir.to_str().unwrap(),
    ]);
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The records of a suite's JSON report (its timing left out).
fn records(v: &serde_json::Value) -> serde_json::Value {
    v["records"].clone()
}

#[test]
fn a_written_list_runs_through_suite_as_the_same_scales_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    let recs = dir.path().join("records");
    fs::create_dir(&recs).unwrap();
    synth(&recs, "4");
    let out = dir.path().join("scaled.txt");
    let report = json(&[
        "records",
        "scale",
        "--suite",
        s(&recs),
        "--target",
        EC8,
        "--period",
        "0.5",
        "--out",
        s(&out),
        "--format",
        "json",
    ]);
    assert_eq!(report["check"]["holds"], true);
    let list = fs::read_to_string(&out).unwrap();
    assert!(
        list.starts_with("# pounding records scale --suite"),
        "{list}"
    );
    assert!(list.contains("# target: ec8:ag=0.3,ground=B,type=1,importance=1"));
    assert!(list.contains("EN 1998-1 §3.2.3.1.2(4)"));
    // The same scales by hand, each as the report's number prints.
    let mut hand = String::new();
    for (j, r) in report["records"].as_array().unwrap().iter().enumerate() {
        let f = r["factor"].as_f64().unwrap();
        let line = format!("records/synthetic-{:03}.at2 {f}", j + 1);
        assert!(
            list.contains(&format!("{line}\n")),
            "{line} missing from {list}"
        );
        hand.push_str(&line);
        hand.push('\n');
    }
    let hand_path = dir.path().join("hand.txt");
    fs::write(&hand_path, hand).unwrap();
    let run = |list: &Path| {
        json(&[
            "suite",
            "--preset",
            "two-buildings",
            "--suite",
            s(list),
            "--format",
            "json",
        ])
    };
    let (a, b) = (run(&out), run(&hand_path));
    assert_eq!(records(&a), records(&b));
    assert_eq!(a["statistics"], b["statistics"]);
    // `--check` on the written list: the rule holds at its scales.
    let checked = json(&[
        "records",
        "scale",
        "--suite",
        s(&out),
        "--target",
        EC8,
        "--period",
        "0.5",
        "--check",
        "--format",
        "json",
    ]);
    assert_eq!(checked["check"]["holds"], true);
    assert_eq!(checked["common_factor"], 1.0);
}

#[test]
fn json_and_csv_carry_the_grid_target_spectra_mean_and_verdict() {
    let v = json(&[
        "records",
        "scale",
        "--suite",
        "synthetic:11",
        "--target",
        "asce7:SDS=1,SD1=0.6,TL=8",
        "--period",
        "0.8",
        "--range",
        "0.2:2",
        "--format",
        "json",
    ]);
    let n = v["periods"].as_array().unwrap().len();
    assert!(n >= 50);
    assert_eq!(v["target"].as_array().unwrap().len(), n);
    assert_eq!(v["mean"].as_array().unwrap().len(), n);
    let recs = v["records"].as_array().unwrap();
    assert_eq!(recs.len(), 11);
    assert_eq!(recs[0]["spectrum"].as_array().unwrap().len(), n);
    assert_eq!(v["check"]["min_records"], 11);
    assert_eq!(v["check"]["holds"], true);
    assert_eq!(v["range"]["low_s"].as_f64().unwrap(), 0.2 * 0.8);
    // The target at T = 0.8 s (between T_S = 0.6 and T_L): S_D1/T = 0.75 g.
    let periods = v["periods"].as_array().unwrap();
    let k = periods
        .iter()
        .position(|t| t.as_f64() == Some(0.8))
        .unwrap();
    assert!((v["target"][k].as_f64().unwrap() - 0.75).abs() < 1e-12);
    let o = succeeds(&[
        "records",
        "scale",
        "--suite",
        "synthetic:11",
        "--target",
        "asce7:SDS=1,SD1=0.6,TL=8",
        "--period",
        "0.8",
        "--format",
        "csv",
    ]);
    let csv = stdout(&o);
    assert_eq!(csv.lines().count(), n + 1);
    assert!(csv.starts_with("period_s,target_g,threshold_g,mean_g,p16_g,p84_g,mean_over_target\n"));
    // The table marks a factor outside [0.25, 4]: records of 0.3 g PGA
    // scaled to a 3 g plateau need more than 4.
    let o = succeeds(&[
        "records",
        "scale",
        "--suite",
        "synthetic:3",
        "--target",
        "ec8:ag=1.2,ground=D,type=1",
        "--period",
        "0.5",
    ]);
    let table = stdout(&o);
    assert!(
        table.contains(" *\n") && table.contains("* factor outside [0.25, 4]"),
        "{table}"
    );
    assert!(
        table.contains("the rule of EN 1998-1 §3.2.3.1.2(4) holds"),
        "{table}"
    );
}

#[test]
fn a_list_below_90_percent_fails_with_exit_1_naming_where() {
    let dir = tempfile::tempdir().unwrap();
    synth(dir.path(), "3");
    // The records at 0.3 g PGA, as written, against a 1 g plateau.
    let o = pounding(&[
        "records",
        "scale",
        "--suite",
        s(&dir.path().join("suite.txt")),
        "--target",
        "ec8:ag=0.4,ground=B,type=1",
        "--period",
        "0.5",
        "--check",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1);
    assert!(
        err.contains("does not meet EN 1998-1 §3.2.3.1.2(4)")
            && err.contains("of the target at T = "),
        "{err}"
    );
    assert!(stdout(&o).contains("does not hold"));
}

#[test]
fn select_keeps_k_per_event_from_the_at2_headers() {
    let dir = tempfile::tempdir().unwrap();
    synth(dir.path(), "9");
    fs::remove_file(dir.path().join("suite.txt")).unwrap();
    // Three earthquakes, three stations each.
    for j in 1..=9 {
        let p = dir.path().join(format!("synthetic-{j:03}.at2"));
        let text = fs::read_to_string(&p).unwrap();
        let mut lines: Vec<&str> = text.lines().collect();
        let event = format!("Quake {}, 01/0{}/2000, Station {j}, 90", j % 3, j % 3 + 1);
        lines[1] = &event;
        fs::write(&p, lines.join("\n") + "\n").unwrap();
    }
    let out = dir.path().join("chosen.txt");
    let v = json(&[
        "records",
        "select",
        "--from",
        s(dir.path()),
        "--target",
        EC8,
        "--period",
        "0.5",
        "--count",
        "5",
        "--per-event",
        "2",
        "--out",
        s(&out),
        "--format",
        "json",
    ]);
    let recs = v["records"].as_array().unwrap();
    assert_eq!(recs.len(), 5);
    for q in 0..3 {
        let event = format!("Quake {q}, 01/0{}/2000", q + 1);
        let n = recs.iter().filter(|r| r["event"] == event.as_str()).count();
        assert!(n <= 2, "{n} of {event}");
    }
    for r in recs {
        let f = r["factor"].as_f64().unwrap();
        assert!((0.25..=4.0).contains(&f), "{f}");
    }
    let list = fs::read_to_string(&out).unwrap();
    assert_eq!(list.lines().filter(|l| !l.starts_with('#')).count(), 5);
    // Seven of three earthquakes at two each cannot be.
    fails(
        &[
            "records",
            "select",
            "--from",
            s(dir.path()),
            "--target",
            EC8,
            "--period",
            "0.5",
            "--count",
            "7",
            "--per-event",
            "2",
        ],
        2,
        &[
            "--count 7: only 6 of the 9 records",
            "3 are beyond 2 per event",
        ],
    );
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let bad_file = dir.path().join("t.txt");
    fs::write(&bad_file, "1 0.5\n0.5 0.4\n").unwrap();
    let bad_target = format!("file:{}", s(&bad_file));
    fn scale<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let mut a = vec![
            "records",
            "scale",
            "--suite",
            "synthetic:3",
            "--period",
            "0.5",
        ];
        a.extend_from_slice(extra);
        a
    }
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (
            scale(&["--target", "nbc:x=1"]),
            vec!["--target", "unknown code `nbc`"],
        ),
        (
            scale(&["--target", "ec8:ag=0.3,ground=F,type=1"]),
            vec!["--target", "ground `F`", "A, B, C, D, E"],
        ),
        (
            scale(&["--target", "ec8:ag=-1,ground=B,type=1"]),
            vec!["a_g = `-1`", "positive"],
        ),
        (
            scale(&["--target", "asce7:SDS=0,SD1=0.6,TL=8"]),
            vec!["S_DS = `0`"],
        ),
        (
            scale(&["--target", "asce7:SDS=1,SD1=0.6,TL=0.6"]),
            vec!["T_L = 0.6 s", "T_S"],
        ),
        (
            scale(&["--target", &bad_target]),
            vec!["line 2", "must increase"],
        ),
        (
            scale(&["--target", EC8, "--code", "nbc"]),
            vec!["--code nbc", "ec8, asce7"],
        ),
        (
            scale(&["--target", EC8, "--range", "2:0.2"]),
            vec!["--range 2:0.2", "below the high end"],
        ),
        (
            scale(&["--target", EC8, "--range", "0.2:10"]),
            vec!["--range 0.2:10", "outside the target's periods"],
        ),
        (scale(&[]), vec!["--target: required"]),
        (
            scale(&["--target", EC8, "--out", "x.txt"]),
            vec!["--out x.txt", "records synth"],
        ),
        (
            vec![
                "records",
                "scale",
                "--suite",
                "synthetic:3",
                "--target",
                EC8,
                "--period",
                "0",
            ],
            vec!["--period 0", "(0, 10]"],
        ),
        (
            vec![
                "records",
                "select",
                "--from",
                s(dir.path()),
                "--target",
                EC8,
                "--period",
                "0.5",
                "--count",
                "0",
            ],
            vec!["--count 0", "≥ 1"],
        ),
        (
            vec![
                "records",
                "select",
                "--from",
                s(dir.path()),
                "--target",
                EC8,
                "--period",
                "0.5",
                "--count",
                "2",
                "--max-scale",
                "1",
            ],
            vec!["--max-scale 1", "(1, 1000]"],
        ),
    ];
    for (args, fragments) in cases {
        fails(&args, 2, &fragments);
    }
    // A list is never written over a directory.
    let recs = dir.path().join("recs");
    fs::create_dir(&recs).unwrap();
    synth(&recs, "3");
    fails(
        &[
            "records",
            "scale",
            "--suite",
            s(&recs),
            "--target",
            EC8,
            "--period",
            "0.5",
            "--out",
            s(dir.path()),
        ],
        1,
        &["not a regular file"],
    );
}

#[test]
fn figure_match_draws_each_record_the_mean_the_target_and_the_verdict() {
    let dir = tempfile::tempdir().unwrap();
    synth(dir.path(), "3");
    let list = dir.path().join("scaled.txt");
    succeeds(&[
        "records",
        "scale",
        "--suite",
        s(dir.path()),
        "--target",
        EC8,
        "--period",
        "0.5",
        "--out",
        s(&list),
    ]);
    let svg = dir.path().join("match.svg");
    succeeds(&[
        "figure",
        "match",
        "--suite",
        s(&list),
        "--target",
        EC8,
        "--period",
        "0.5",
        "--out",
        s(&svg),
    ]);
    let text = fs::read_to_string(&svg).unwrap();
    for label in [
        "each record at its factor",
        "suite mean",
        "16–84 % of the records",
        "90 % of the target",
        "T1 = 0.5 s",
        "0.2·T1",
        "2·T1",
        "the rule of EN 1998-1 §3.2.3.1.2(4) holds",
    ] {
        assert!(text.contains(label), "`{label}` missing from the SVG");
    }
    fails(
        &["figure", "fig3", "--target", EC8],
        2,
        &["--target applies to figure match, not fig3"],
    );
    fails(
        &["figure", "match", "--suite", s(&list), "--target", EC8],
        2,
        &["give --period T1"],
    );
}
