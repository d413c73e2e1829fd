//! Collapse in the commands (SPEC §15): `run --buildings` reports it and
//! exits 0; `ida --buildings --collapse` fits each P-Δ building's collapse
//! fragility on the counts it prints, and a collapsed record exceeds every
//! other limit state of its building; `--collapse` where nothing can
//! collapse is one line and exit 2.

mod common;

use common::{fails, json};
use pounding::analysis::fragility::{Fragility, LevelCount, fit};

const ROW: &str = "block-and-frame-pdelta";

#[test]
fn a_collapse_is_a_result_with_its_building_storey_and_time() {
    let r = json(&[
        "run",
        "--buildings",
        ROW,
        "--excitation",
        "synthetic:2000",
        "--scale",
        "6",
        "--format",
        "json",
    ]);
    let c = &r["collapsed"];
    assert_eq!(c["building"], "frame");
    assert_eq!(c["storey"], 4);
    let t = c["time"].as_f64().unwrap();
    assert!(t > 0.0 && t < 3.0, "{t}");
    // The storey's peak drift is the collapse drift, 0.10 · 3.2 m.
    let drift = r["buildings"][1]["floors"][3]["peak_drift"]
        .as_f64()
        .unwrap();
    assert!((drift - 0.32).abs() < 1e-12, "{drift}");
    let theta = r["buildings"][1]["stability_coefficients"]
        .as_array()
        .unwrap();
    assert_eq!(theta.len(), 8);
    // θ_1 = g · 8 · 8e5 kg / (3e8 N/m · 3.2 m).
    let t1 = 9.80665 * 6.4e6 / (3.0e8 * 3.2);
    assert!((theta[0].as_f64().unwrap() - t1).abs() < 1e-15);
    // The block has no P-Δ and no stability coefficients.
    assert!(r["buildings"][0].get("stability_coefficients").is_none());
    // A row that does not collapse says so; one that cannot says nothing.
    let calm = json(&[
        "run",
        "--buildings",
        ROW,
        "--excitation",
        "synthetic:2000",
        "--format",
        "json",
    ]);
    assert!(calm["collapsed"].is_null() && calm.get("collapsed").is_some());
    let bare = json(&[
        "run",
        "--buildings",
        "block-and-frame",
        "--excitation",
        "synthetic:2000",
        "--format",
        "json",
    ]);
    assert!(bare.get("collapsed").is_none());
}

fn counts(v: &serde_json::Value) -> Vec<LevelCount> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|c| LevelCount {
            level: c["level"].as_f64().unwrap(),
            runs: c["runs"].as_u64().unwrap() as usize,
            exceeded: c["exceeded"].as_u64().unwrap() as usize,
        })
        .collect()
}

fn same_fit(printed: &serde_json::Value, refit: Fragility) {
    match refit {
        Fragility::Fitted { theta, beta, .. } => {
            assert_eq!(printed["outcome"], "fitted", "{printed}");
            assert_eq!(printed["theta"].as_f64().unwrap(), theta);
            assert_eq!(printed["beta"].as_f64().unwrap(), beta);
        }
        other => panic!("expected a fitted collapse fragility, got {other:?} ({printed})"),
    }
}

#[test]
fn the_collapse_fragility_is_the_fit_of_its_printed_counts() {
    let r = json(&[
        "ida",
        "--buildings",
        ROW,
        "--suite",
        "synthetic:6@3",
        "--levels",
        "0.4,0.6,0.8,1.0,1.3",
        "--collapse",
        "--drift",
        "frame:0.02",
        "--format",
        "json",
    ]);
    let fragility = r["fragility"].as_array().unwrap();
    let collapse = fragility
        .iter()
        .find(|f| f["limit_state"] == "collapse (frame)")
        .expect("the frame's collapse limit state");
    let with = counts(&collapse["counts"]);
    let without = counts(&collapse["no_pounding_counts"]);
    assert!(with.iter().any(|c| c.exceeded > 0), "{with:?}");
    same_fit(&collapse["fragility"], fit(&with));
    same_fit(&collapse["no_pounding_fragility"], fit(&without));
    // The counts are the records flagged collapsed at each level.
    let levels = r["levels"].as_array().unwrap();
    for (l, c) in levels.iter().zip(&with) {
        let flagged = l["records"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|rec| rec["buildings"][1]["collapsed"] == true)
            .count();
        assert_eq!(flagged, c.exceeded);
    }
    // A collapsed record exceeds every other limit state of its building:
    // the frame's drift limit is exceeded at least as often, level by level,
    // and a collapsed building's drift is ∞.
    let drift = fragility
        .iter()
        .find(|f| f["limit_state"] == "drift>0.02 (frame)")
        .unwrap();
    for (d, c) in counts(&drift["counts"]).iter().zip(&with) {
        assert!(d.exceeded >= c.exceeded, "{d:?} against {c:?}");
    }
    let first = levels
        .iter()
        .flat_map(|l| l["records"].as_array().unwrap())
        .find(|rec| rec["buildings"][1]["collapsed"] == true)
        .unwrap();
    assert_eq!(first["buildings"][1]["max_drift_ratio"], "inf");
    assert_eq!(first["buildings"][0]["cut_short"], true);
}

#[test]
fn collapse_where_nothing_can_collapse_is_refused() {
    fails(
        &[
            "ida",
            "--buildings",
            "block-and-frame",
            "--suite",
            "synthetic:2",
            "--levels",
            "0.1,0.2",
            "--collapse",
        ],
        2,
        &[
            "--collapse: no building of `block-and-frame` has P-Δ",
            "cannot collapse",
        ],
    );
    fails(
        &[
            "ida",
            "--suite",
            "synthetic:2",
            "--levels",
            "0.1,0.2",
            "--collapse",
        ],
        2,
        &["--collapse: applies to a row of buildings"],
    );
}
