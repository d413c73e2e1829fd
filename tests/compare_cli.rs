//! `pounding suite --buildings ROW --compare ROW2` (SPEC §12, §14): each
//! variant's report is, bit for bit, `suite --buildings` of that row alone
//! (but its wall time); the side-by-side summary is read from those
//! records; a variant whose buildings differ from the first row's exits 2
//! with one line naming it and what differs.

mod common;

use common::{fails, json, stdout, succeeds};

const SUITE: [&str; 6] = [
    "--suite",
    "synthetic:6",
    "--level",
    "0.3",
    "--format",
    "json",
];

/// `suite --buildings NAME` of the common suite, as JSON, without its timing.
fn alone(name: &str) -> serde_json::Value {
    let mut args = vec!["suite", "--buildings", name];
    args.extend(SUITE);
    let mut v = json(&args);
    v.as_object_mut().unwrap().remove("elapsed_ms");
    v
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The median of `values` by the order statistics (numpy's default).
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

#[test]
fn each_variant_is_its_own_suite_bit_for_bit_and_the_summary_reads_its_records() {
    let mut args = vec![
        "suite",
        "--buildings",
        "block-and-frame",
        "--compare",
        "block-and-frame-retrofit",
    ];
    args.extend(SUITE);
    let v = json(&args);
    let variants = v["variants"].as_array().unwrap();
    assert_eq!(variants.len(), 2);
    for (variant, name) in variants
        .iter()
        .zip(["block-and-frame", "block-and-frame-retrofit"])
    {
        assert_eq!(variant["variant"], name);
        let mut own = variant.clone();
        let o = own.as_object_mut().unwrap();
        for key in ["variant", "summary", "elapsed_ms"] {
            o.remove(key);
        }
        let single = alone(name);
        assert_eq!(own, single, "{name}");
        // The summary, from the single run's records: P(pounding) at the
        // joint and the medians of its gap and of each drift ratio.
        let records = single["records"].as_array().unwrap();
        let summary = &variant["summary"];
        let joint = &summary["joints"][0];
        let pounded = records
            .iter()
            .filter(|r| r["joints"][0]["impacts"].as_u64().unwrap() > 0)
            .count();
        assert_eq!(f(&joint["pounding_probability"]), pounded as f64 / 6.0);
        let gaps = records
            .iter()
            .map(|r| f(&r["joints"][0]["min_gap"]))
            .collect();
        assert_eq!(f(&joint["median_min_gap_m"]), median(gaps));
        for (i, b) in summary["buildings"].as_array().unwrap().iter().enumerate() {
            let drifts = records
                .iter()
                .map(|r| f(&r["buildings"][i]["max_drift_ratio"]))
                .collect();
            assert_eq!(f(&b["median_max_drift_ratio"]), median(drifts));
        }
    }
    // The retrofit's bumper and dashpot take drift off the frame.
    let drift = |k: usize| f(&variants[k]["summary"]["buildings"][1]["median_max_drift_ratio"]);
    assert!(drift(1) < drift(0), "{} against {}", drift(1), drift(0));
}

#[test]
fn the_csv_is_each_variant_s_own_csv_behind_a_variant_column() {
    let csv = |args: &[&str]| {
        let mut a = args.to_vec();
        a.extend(&SUITE[..4]);
        a.extend(["--format", "csv"]);
        stdout(&succeeds(&a))
    };
    let both = csv(&[
        "suite",
        "--buildings",
        "block-and-frame",
        "--compare",
        "block-and-frame-retrofit",
    ]);
    let mut lines = both.lines();
    let header = lines.next().unwrap();
    let single_header = |name| csv(&["suite", "--buildings", name]);
    let first = single_header("block-and-frame");
    assert_eq!(header, format!("variant,{}", first.lines().next().unwrap()));
    let rows: Vec<&str> = lines.collect();
    for name in ["block-and-frame", "block-and-frame-retrofit"] {
        // "block-and-frame," is no prefix of "block-and-frame-retrofit,".
        let own: Vec<&str> = rows
            .iter()
            .filter_map(|l| l.strip_prefix(&format!("{name},")))
            .collect();
        let single = single_header(name);
        let want: Vec<&str> = single.lines().skip(1).collect();
        assert_eq!(own.len(), 6 * 3, "{name}: 2 buildings and 1 joint a record");
        assert_eq!(own, want, "{name}");
    }
}

#[test]
fn a_variant_with_other_buildings_is_refused_naming_it_and_what_differs() {
    fails(
        &[
            "suite",
            "--buildings",
            "block-and-frame",
            "--compare",
            "three-in-series",
            "--suite",
            "synthetic:2",
        ],
        2,
        &[
            "--compare three-in-series",
            "block, mid, tall",
            "block, frame",
        ],
    );
    fails(
        &[
            "suite",
            "--preset",
            "two-buildings",
            "--compare",
            "block-and-frame",
            "--suite",
            "synthetic:2",
        ],
        2,
        &["--compare", "--buildings"],
    );
}
