//! `ida --buildings ROW --compare ROW2` and `gap --suite --buildings ROW
//! --compare ROW2` (SPEC §11, §12, §14): each variant's report is, bit for
//! bit, the study of that row alone (JSON and CSV, but its wall time); the
//! side-by-side summary is recomputed from those single runs (each limit
//! state's fragility refitted from the single run's counts, each joint's
//! gap at a probability from the single run's records); and the refusals
//! (a variant with other buildings, on the pair, with --shard, without a
//! suite) are one line each, exit 2.

mod common;

use common::{fails, json, stdout, succeeds};
use pounding::analysis::fragility::{LevelCount, fit};
use serde_json::Value;

const ROWS: [&str; 2] = ["block-and-frame", "block-and-frame-retrofit"];

/// The IDA: five records at five levels, where the drift limit state is
/// crossed (one of its fits has a median, the others say why not).
const IDA: [&str; 6] = [
    "--suite",
    "synthetic:5",
    "--levels",
    "0.1,0.15,0.2,0.25,0.3",
    "--drift",
    "0.004",
];

/// The separation study: five records at 0.3 g, two probabilities.
const GAP: [&str; 6] = [
    "--suite",
    "synthetic:5",
    "--level",
    "0.3",
    "--probability",
    "0.5,0.9",
];

/// `command --buildings first --compare second` with `tail` and `format`.
fn compared<'a>(command: &'a str, tail: &[&'a str], format: &'a str) -> Vec<&'a str> {
    let mut args = vec![command, "--buildings", ROWS[0], "--compare", ROWS[1]];
    args.extend(tail);
    args.extend(["--format", format]);
    args
}

/// `command --buildings name` with `tail` and `format`.
fn alone<'a>(command: &'a str, name: &'a str, tail: &[&'a str], format: &'a str) -> Vec<&'a str> {
    let mut args = vec![command, "--buildings", name];
    args.extend(tail);
    args.extend(["--format", format]);
    args
}

/// `v` without the keys `keys`.
fn without(v: &Value, keys: &[&str]) -> Value {
    let mut v = v.clone();
    let o = v.as_object_mut().unwrap();
    for key in keys {
        o.remove(*key);
    }
    v
}

/// Each variant of the compare's JSON against the single run of its row:
/// equal bit for bit but for the variant's name, summary and wall time.
/// Returns the pairs (the variant's summary, the single run).
fn each_variant_is_its_own_run(command: &str, tail: &[&str]) -> Vec<(Value, Value)> {
    let v = json(&compared(command, tail, "json"));
    let variants = v["variants"].as_array().unwrap();
    assert_eq!(variants.len(), 2);
    variants
        .iter()
        .zip(ROWS)
        .map(|(variant, name)| {
            assert_eq!(variant["variant"], name);
            let single = without(&json(&alone(command, name, tail, "json")), &["elapsed_ms"]);
            let own = without(variant, &["variant", "summary", "elapsed_ms"]);
            assert_eq!(own, single, "{command} {name}");
            (variant["summary"].clone(), single)
        })
        .collect()
}

/// The compare's CSV: the first single run's header behind `variant`, then
/// each variant's own lines, those of its single run bit for bit.
fn the_csv_is_each_variant_s_own(command: &str, tail: &[&str]) {
    let both = stdout(&succeeds(&compared(command, tail, "csv")));
    let mut lines = both.lines();
    let header = lines.next().unwrap();
    let rows: Vec<&str> = lines.collect();
    for (k, name) in ROWS.into_iter().enumerate() {
        let single = stdout(&succeeds(&alone(command, name, tail, "csv")));
        if k == 0 {
            assert_eq!(
                header,
                format!("variant,{}", single.lines().next().unwrap())
            );
        }
        // "block-and-frame," is no prefix of "block-and-frame-retrofit,".
        let own: Vec<&str> = rows
            .iter()
            .filter_map(|l| l.strip_prefix(&format!("{name},")))
            .collect();
        let want: Vec<&str> = single.lines().skip(1).collect();
        assert!(!want.is_empty(), "{command} {name}");
        assert_eq!(own, want, "{command} {name}");
    }
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn ida_compare_is_each_row_s_ida_and_its_summary_refits_their_counts() {
    let mut fitted = 0;
    for (summary, single) in each_variant_is_its_own_run("ida", &IDA) {
        let states = summary["limit_states"].as_array().unwrap();
        let fragility = single["fragility"].as_array().unwrap();
        assert_eq!(states.len(), 2, "pounding and drift>0.004");
        assert_eq!(states.len(), fragility.len());
        for (state, own) in states.iter().zip(fragility) {
            assert_eq!(state["limit_state"], own["limit_state"]);
            // Refit each fragility from the single run's counts (SPEC §12).
            for (fit_key, counts_key) in [
                ("fragility", "counts"),
                ("no_pounding_fragility", "no_pounding_counts"),
            ] {
                let Some(counts) = own.get(counts_key) else {
                    assert!(state.get(fit_key).is_none(), "{state}");
                    continue;
                };
                let counts: Vec<LevelCount> = counts
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|c| LevelCount {
                        level: f(&c["level"]),
                        runs: c["runs"].as_u64().unwrap() as usize,
                        exceeded: c["exceeded"].as_u64().unwrap() as usize,
                    })
                    .collect();
                assert_eq!(counts.len(), 5);
                let refit = serde_json::to_value(fit(&counts)).unwrap();
                assert_eq!(state[fit_key], refit, "{} {fit_key}", own["limit_state"]);
                fitted += usize::from(refit["outcome"] == "fitted");
            }
        }
    }
    // At least one median θ is compared, not only reasons for none.
    assert!(fitted >= 1);
    the_csv_is_each_variant_s_own("ida", &IDA);
}

#[test]
fn gap_compare_is_each_row_s_separation_and_its_summary_reads_their_records() {
    for (summary, single) in each_variant_is_its_own_run("gap", &GAP) {
        let joint = &summary["joints"][0];
        let study = &single["joints"][0];
        assert_eq!(joint["joint"], "joint1 block–frame");
        assert_eq!(joint["gap_m"], study["gap_m"]);
        assert_eq!(joint["rules"], study["study"]["rules"]);
        // The gap at probability p: d_(⌈pN⌉) of the records' gaps (SPEC §12),
        // and P(pounding) at the gap at rest: the share of records above it.
        let mut gaps: Vec<f64> = single["records"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| f(&r["joints"][0]["min_gap"]))
            .collect();
        gaps.sort_by(f64::total_cmp);
        assert_eq!(gaps.len(), 5);
        let at = joint["at_probability"].as_array().unwrap();
        for (a, p) in at.iter().zip([0.5, 0.9]) {
            assert_eq!(f(&a["probability"]), p);
            let k = (p * 5.0_f64).ceil() as usize;
            assert_eq!(f(&a["empirical"]), gaps[k - 1], "p = {p}");
        }
        let d = f(&joint["gap_m"]);
        let above = gaps.iter().filter(|&&g| g > d).count() as f64 / 5.0;
        assert_eq!(f(&joint["pounding_probability_at_gap"]), above);
    }
    the_csv_is_each_variant_s_own("gap", &GAP);
}

#[test]
fn the_table_puts_the_side_by_side_summary_before_each_variant_s_own_table() {
    let table = stdout(&succeeds(&compared("gap", &GAP, "table")));
    let single = stdout(&succeeds(&alone("gap", ROWS[1], &GAP, "table")));
    assert!(table.starts_with("side by side: per joint"), "{table}");
    // The retrofit's own table closes the compare's, but its wall time.
    let (_, last) = table
        .split_once(&format!("── variant {} ──\n", ROWS[1]))
        .unwrap();
    fn cut(t: &str) -> Vec<&str> {
        t.lines().filter(|l| !l.starts_with("elapsed")).collect()
    }
    assert_eq!(cut(last), cut(&single));
    let table = stdout(&succeeds(&compared("ida", &IDA, "table")));
    assert!(
        table.starts_with("side by side: per limit state"),
        "{table}"
    );
    for name in ROWS {
        assert!(
            table.contains(&format!("── variant {name} ──\n")),
            "{table}"
        );
    }
}

#[test]
fn compare_is_refused_in_one_line_where_it_cannot_compare() {
    // A variant with other buildings.
    for command in ["ida", "gap"] {
        let mut args = vec![
            command,
            "--buildings",
            ROWS[0],
            "--compare",
            "three-in-series",
        ];
        args.extend(if command == "ida" {
            &IDA[..4]
        } else {
            &GAP[..4]
        });
        fails(
            &args,
            2,
            &[
                "--compare three-in-series",
                "block, mid, tall",
                "block, frame",
            ],
        );
    }
    // On the pair.
    for (command, tail) in [("ida", &IDA[..4]), ("gap", &GAP[..4])] {
        let mut args = vec![command, "--preset", "two-buildings", "--compare", ROWS[1]];
        args.extend(tail);
        fails(&args, 2, &["--compare", "--buildings ROW"]);
    }
    // With --shard: each row's study shards on its own.
    for (command, tail, study) in [("ida", &IDA, "IDA"), ("gap", &GAP, "separation study")] {
        let mut args = compared(command, tail, "json");
        args.extend(["--shard", "1/2"]);
        fails(&args, 2, &["--compare", "--shard", study]);
    }
    // `gap --buildings` without a suite is one run, with nothing to compare.
    fails(
        &["gap", "--buildings", ROWS[0], "--compare", ROWS[1]],
        2,
        &["--compare", "--suite SUITE"],
    );
}
