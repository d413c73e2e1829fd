//! Studies at the design level: `suite` and `gap --suite` with `--target
//! TARGET [--period T1]` run each record at the factor `records scale`
//! gives it, bit for bit, for the pair and for the row; the suite's name
//! in the output says the records were scaled, by which rule, at which T1
//! and where T1 came from (the pair's left T1, the row's longest); the
//! name given back as --suite runs the same study; `ida` scales that
//! suite as a whole to each level (FEMA P-695): the median IM of each
//! level's records is the level, in the proportions of the code's factors.

mod common;

use common::{fails, json};

const EC8: &str = "ec8:ag=0.3,ground=B,type=1";

/// The factors `records scale` gives `suite` at T1 = `period`.
fn factors(suite: &str, period: &str) -> Vec<f64> {
    let v = json(&[
        "records", "scale", "--suite", suite, "--target", EC8, "--period", period, "--format",
        "json",
    ]);
    v["records"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["factor"].as_f64().unwrap())
        .collect()
}

fn scales(report: &serde_json::Value) -> Vec<f64> {
    report["records"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["scale"].as_f64().unwrap())
        .collect()
}

#[test]
fn the_pair_runs_each_record_at_its_factor_at_the_left_t1() {
    let v = json(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:3",
        "--target",
        EC8,
        "--format",
        "json",
    ]);
    let name = v["suite"].as_str().unwrap();
    assert_eq!(
        name,
        "synthetic:3 scaled to ec8:ag=0.3,ground=B,type=1,importance=1 by ec8 at T1=0.95 s \
         over 0.2:2 T1 (the left building's T1)"
    );
    assert_eq!(v["period1_s"].as_f64().unwrap(), 0.95);
    assert_eq!(scales(&v), factors("synthetic:3", "0.95"));
    // The name given back as --suite is the same study.
    let again = json(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        name,
        "--format",
        "json",
    ]);
    assert_eq!(again["records"], v["records"]);
    // gap --suite with --period: the same factors at that T1.
    let g = json(&[
        "gap",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:3",
        "--target",
        EC8,
        "--period",
        "0.6",
        "--format",
        "json",
    ]);
    assert!(
        g["suite"]
            .as_str()
            .unwrap()
            .ends_with("by ec8 at T1=0.6 s over 0.2:2 T1"),
        "{}",
        g["suite"]
    );
    assert_eq!(scales(&g), factors("synthetic:3", "0.6"));
}

#[test]
fn the_row_takes_its_longest_t1() {
    let v = json(&[
        "suite",
        "--buildings",
        "block-and-frame",
        "--suite",
        "synthetic:3",
        "--target",
        EC8,
        "--format",
        "json",
    ]);
    let name = v["suite"].as_str().unwrap();
    // block-and-frame: the frame's T1 = 1.146 s is the longer.
    assert!(
        name.ends_with("at T1=1.146 s over 0.2:2 T1 (the row's longest T1, building frame)"),
        "{name}"
    );
    assert_eq!(scales(&v), factors("synthetic:3", "1.146"));
}

#[test]
fn refusals_name_the_flag() {
    fn with<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let mut a = vec![
            "suite",
            "--preset",
            "two-buildings",
            "--suite",
            "synthetic:3",
        ];
        a.extend_from_slice(extra);
        a
    }
    fails(
        &with(&["--period", "0.5"]),
        2,
        &["--period: applies with --target"],
    );
    fails(
        &with(&["--range", "0.2:2"]),
        2,
        &["--range: applies with --target"],
    );
    fails(
        &with(&["--target", EC8, "--level", "0.3"]),
        2,
        &["--level 0.3: not with --target"],
    );
    fails(
        &with(&["--target", "ec8:ag=0.3,ground=Z,type=1"]),
        2,
        &["--target", "ground `Z`"],
    );
    fails(
        &[
            "suite",
            "--preset",
            "set1",
            "--suite",
            "synthetic:3",
            "--target",
            EC8,
        ],
        2,
        &["--target: give --period T1", "set1"],
    );
    fails(
        &[
            "ida",
            "--preset",
            "two-buildings",
            "--suite",
            "synthetic:3",
            "--period",
            "0.5",
            "--levels",
            "0.1,0.2",
        ],
        2,
        &["--period: applies with --target"],
    );
    fails(
        &["gap", "--preset", "two-buildings", "--target", EC8],
        2,
        &["--target: applies to a suite of records"],
    );
}

/// The median of `values` (type 7, as the statistics take it).
fn median(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// `ida --target`, on the pair and on the row: at every level the records'
/// median IM is the level, and their scales keep the proportions of the
/// code's factors (`records scale`, the scales `suite --target` runs).
#[test]
fn an_ida_scales_the_designed_suite_as_a_whole() {
    for (study, period) in [
        (&["--preset", "two-buildings"][..], "0.95"),
        (&["--buildings", "block-and-frame"][..], "1.146"),
    ] {
        let mut args = vec!["ida"];
        args.extend_from_slice(study);
        args.extend([
            "--suite",
            "synthetic:5",
            "--target",
            EC8,
            "--levels",
            "0.2,0.5",
            "--format",
            "json",
        ]);
        let v = json(&args);
        let whole = v["scaled_as_a_whole"].as_str().unwrap();
        assert!(whole.contains("median pga is the level"), "{whole}");
        let f = factors("synthetic:5", period);
        for (level, at) in [0.2, 0.5].iter().zip(v["levels"].as_array().unwrap()) {
            assert_eq!(at["level_g"].as_f64().unwrap(), *level);
            let records = at["records"].as_array().unwrap();
            let im: Vec<f64> = records
                .iter()
                .map(|r| r["intensity_g"].as_f64().unwrap())
                .collect();
            assert!((median(&im) - level).abs() <= 1e-12 * level, "{im:?}");
            let s = scales(at);
            for (j, (sj, fj)) in s.iter().zip(&f).enumerate() {
                let ratio = (sj / s[0]) / (fj / f[0]);
                assert!(
                    (ratio - 1.0).abs() <= 1e-12,
                    "record {j}: {sj} against {fj}"
                );
            }
        }
    }
}
