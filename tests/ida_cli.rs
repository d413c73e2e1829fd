//! `pounding ida` end to end (SPEC §12): a level's rows are bit for bit
//! those of `pounding suite --level`; scaled to Sa(T1), the elastic left
//! building without contact has the peak drift Sa/ω1² that the independent
//! intensity computation implies; the fragility of a deterministic limit
//! state is a separation at the level the closed form predicts.

mod common;

use common::{fails, json, stdout, succeeds};

const G: f64 = 9.80665;
/// two-buildings: T1 = 0.95 s, u_y1 = 0.11 m.
const T1: f64 = 0.95;
const YIELD1: f64 = 0.11;

fn ida(levels: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec![
        "ida",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:8@4",
        "--im",
        "sa:0.95",
        "--levels",
        levels,
        "--format",
        "json",
    ];
    args.extend(extra);
    json(&args)
}

#[test]
fn a_level_is_the_suite_at_that_level_bit_for_bit() {
    let v = ida("0.1:0.3:0.1", &[]);
    let levels = v["levels"].as_array().unwrap();
    assert_eq!(levels.len(), 3);
    assert_eq!(levels[2]["level_g"], 0.3);
    let suite = json(&[
        "suite",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:8@4",
        "--im",
        "sa:0.95",
        "--level",
        "0.3",
        "--format",
        "json",
    ]);
    assert_eq!(levels[2]["records"], suite["records"]);
    assert_eq!(levels[2]["statistics"], suite["statistics"]);
}

#[test]
fn an_elastic_building_scaled_to_its_sa_has_the_drift_sa_over_omega_squared() {
    // Sa(T1) = ω1² max|u| of a 5 %-damped oscillator of period T1 over the
    // record (model::intensity); the left building is that oscillator when
    // it neither yields nor pounds, so its peak drift is level·g/ω1²,
    // unless the free vibration after the record exceeds the record's peak.
    let omega1 = 2.0 * std::f64::consts::PI / T1;
    let v = ida("0.1,0.2,0.3", &[]);
    let mut equal = 0;
    let mut total = 0;
    for level in v["levels"].as_array().unwrap() {
        let x = level["level_g"].as_f64().unwrap();
        let expected = x * G / (omega1 * omega1);
        for row in level["records"].as_array().unwrap() {
            let u = row["no_pounding"][0]["peak_displacement_m"]
                .as_f64()
                .unwrap();
            assert!(u >= expected * (1.0 - 1e-12), "{u} < {expected}");
            total += 1;
            if (u / expected - 1.0).abs() < 1e-12 {
                equal += 1;
            }
        }
    }
    // Every record of this suite peaks within the record itself.
    assert_eq!(equal, total);
}

#[test]
fn the_free_left_building_yields_exactly_above_its_yield_intensity() {
    // Elastic until Sa(T1) = u_y ω1² = 0.4904 g: every record's free left
    // building exceeds μ = 1 at 0.5 g and none does at 0.45 g, so the counts
    // separate there and no lognormal is fitted.
    let omega1 = 2.0 * std::f64::consts::PI / T1;
    let threshold = YIELD1 * omega1 * omega1 / G;
    assert!(threshold > 0.45 && threshold < 0.5, "{threshold}");
    let v = ida("0.3,0.45,0.5,0.6", &["--ductility", "left:1"]);
    let f = v["fragility"]
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["limit_state"] == "ductility>1 (left)")
        .expect("the limit state is reported");
    let free = &f["no_pounding_fragility"];
    assert_eq!(free["outcome"], "separated", "{free}");
    assert_eq!(free["below"], 0.45);
    assert_eq!(free["above"], 0.5);
    let counts: Vec<u64> = f["no_pounding_counts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["exceeded"].as_u64().unwrap())
        .collect();
    assert_eq!(counts, [0, 0, 8, 8]);
    // Pounding is always the first limit state.
    assert_eq!(v["fragility"][0]["limit_state"], "pounding");
}

#[test]
fn the_table_gives_medians_per_level_and_each_fragility() {
    let o = succeeds(&[
        "ida",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:6",
        "--im",
        "sa:0.95",
        "--levels",
        "0.2:1.0:0.2",
        "--ductility",
        "2",
    ]);
    let text = stdout(&o);
    for fragment in [
        "IDA of suite synthetic:6 (6 records) at 5 levels of sa:0.95",
        "level g",
        "pounding",
        "ductility>2 (either)",
        "without pounding",
        "records exceeding each limit state",
    ] {
        assert!(text.contains(fragment), "{fragment} missing:\n{text}");
    }
}

#[test]
fn bad_levels_and_limit_states_are_refused() {
    let base = ["ida", "--preset", "two-buildings", "--suite", "synthetic:2"];
    for levels in ["0.3,0.2", "0:1:0.1", "-1,1", "0.1:1", "x"] {
        let mut a = base.to_vec();
        a.extend(["--levels", levels]);
        fails(&a, 2, &["--levels"]);
    }
    let mut a = base.to_vec();
    a.extend(["--levels", "0.1,0.2", "--ductility", "two"]);
    fails(&a, 2, &["--ductility"]);
    let mut a = base.to_vec();
    a.extend(["--levels", "0.1,0.2", "--level", "0.3"]);
    fails(&a, 2, &["--level"]);
    let mut a = base.to_vec();
    a.extend(["--levels", "0.1,0.2", "--im", "sa:0"]);
    fails(&a, 2, &["sa:0"]);
}

#[test]
fn pounding_counts_follow_the_separation_of_the_elastic_pair() {
    // Below yielding the pair without contact is linear, so each record's
    // Π_d,min in m grows in proportion to its scale: d(x) = d(0.3 g)·x/0.3.
    // A record pounds at the 25 mm joint exactly when d(x) > 25 mm, so the
    // IDA's pounding counts follow from one `gap --suite` at 0.3 g.
    let gap = json(&[
        "gap",
        "--preset",
        "two-buildings",
        "--suite",
        "synthetic:8@4",
        "--im",
        "sa:0.95",
        "--level",
        "0.3",
        "--format",
        "json",
    ]);
    let d: Vec<f64> = gap["records"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["min_gap_m"].as_f64().unwrap())
        .collect();
    let v = ida("0.06:0.16:0.02", &[]);
    let counts = v["fragility"][0]["counts"].as_array().unwrap();
    let mut mixed = 0;
    for c in counts {
        let x = c["level"].as_f64().unwrap();
        let scaled: Vec<f64> = d.iter().map(|d| d * x / 0.3).collect();
        assert!(
            scaled.iter().all(|s| (s - 0.025).abs() > 1e-9),
            "a grazing record"
        );
        let expected = scaled.iter().filter(|s| **s > 0.025).count() as u64;
        assert_eq!(c["exceeded"].as_u64().unwrap(), expected, "at {x} g");
        mixed += usize::from(expected > 0 && expected < d.len() as u64);
    }
    assert!(mixed >= 2, "the levels straddle the joint");
}
