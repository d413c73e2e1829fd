//! Self-similarity (SPEC §8): the physical example at 0.2 g, 0.5 g and 0.8 g.
//! Dimensionless spectra agree to round-off; dimensional ones scale with a_p.

mod common;

use common::{fails, json, stdout, succeeds};
use pounding::analysis::similarity::{master_curve_spread, study};
use pounding::model::Preset;
use pounding::model::physical::{G, Physical};

fn example() -> (Physical, pounding::model::Params) {
    let preset = Preset::find("two-buildings", &[]).unwrap();
    (
        Physical::from_table(preset.physical.as_ref().unwrap()).unwrap(),
        preset.params,
    )
}

#[test]
fn dimensionless_spectra_collapse_and_dimensional_ones_scale_with_ap() {
    let (phys, settings) = example();
    let levels = [0.2 * G, 0.5 * G, 0.8 * G];
    let grid = [0.6, 1.0, 1.4, 2.0];
    let result = study(&phys, &settings, &levels, &grid, 2.25, true).unwrap();
    // Every level's Π-groups, computed from its own physical values, agree to round-off.
    for l in &result[1..] {
        for key in ["yield1", "yield2", "gap", "omega1", "contact_omega"] {
            let (a, b) = (
                l.params.get(key).unwrap(),
                result[0].params.get(key).unwrap(),
            );
            assert!((a - b).abs() <= 1e-14 * b, "{key}: {a} vs {b}");
        }
    }
    let spread = master_curve_spread(&result);
    assert!(spread < 1e-9, "master curve spread {spread}");
    // Dimensional peaks: X = Π_u a_p/ω_p², so 0.8 g gives four times 0.2 g.
    for (lo, hi) in result[0].curve.points.iter().zip(&result[2].curve.points) {
        let x_lo = lo.left.peak_displacement * result[0].length_scale();
        let x_hi = hi.left.peak_displacement * result[2].length_scale();
        assert!((x_hi / x_lo - 4.0).abs() < 1e-9, "{x_hi} / {x_lo}");
        let v_lo = lo.right.peak_velocity * result[0].velocity_scale();
        let v_hi = hi.right.peak_velocity * result[2].velocity_scale();
        assert!((v_hi / v_lo - 4.0).abs() < 1e-9);
    }
    // The example pounds where the paper's Figure 7 does.
    assert!(result[1].curve.points[1].impacts > 0);
}

#[test]
fn a_fixed_structure_does_not_collapse() {
    // Same metres at every level: Π_uy and Π_d fall as a_p grows, so the
    // dimensionless spectra differ (this is not a similar family).
    let (phys, settings) = example();
    let result = study(&phys, &settings, &[0.2 * G, 0.8 * G], &[1.0], 2.25, false).unwrap();
    assert!((result[1].params.gap - result[0].params.gap / 4.0).abs() < 1e-12);
    assert!(master_curve_spread(&result) > 0.01);
}

#[test]
fn cli_reports_metres_and_refuses_bad_levels() {
    let v = json(&[
        "similarity",
        "--preset",
        "two-buildings",
        "--omega1",
        "1.0:1.0:0.1",
        "--format",
        "json",
    ]);
    let levels = v["levels"].as_array().unwrap();
    assert_eq!(levels.len(), 3);
    assert!((levels[0]["ap_g"].as_f64().unwrap() - 0.2).abs() < 1e-12);
    let x = levels[1]["points"][0]["left"]["peak_displacement_m"]
        .as_f64()
        .unwrap();
    assert!(x > 0.1 && x < 1.0, "{x} m");
    assert!(v["master_curve_spread"].as_f64().unwrap() < 1e-9);
    for (args, needle) in [
        (vec!["--ap", "0.2g,-1"], "--ap `-1`"),
        (vec!["--preset", "set1"], "--omega-p"),
        (vec!["--omega-p", "0"], "--omega-p 0"),
        (vec!["--set", "gap=0.5"], "physical units"),
    ] {
        let mut all = vec!["similarity", "--omega1", "1:1:1"];
        if !args.contains(&"--preset") {
            all.extend(["--preset", "two-buildings"]);
        }
        all.extend(args);
        fails(&all, 2, &[needle]);
    }
}

/// JSON numbers are numbers (the gap of 0.2 g is 0.025 m × 0.2/0.5), the
/// units and method are named, and every CSV row carries its level and
/// parameters, with one cell per header column.
#[test]
fn json_and_csv_are_self_describing() {
    let args = |format| {
        [
            "similarity",
            "--preset",
            "two-buildings",
            "--omega1",
            "1.0:1.1:0.1",
            "--format",
            format,
        ]
    };
    let v = json(&args("json"));
    let gap = v["levels"][0]["physical"]["gap_m"].as_f64().unwrap();
    assert!((gap - 0.01).abs() < 1e-15, "{gap}");
    assert!(v["levels"][0]["physical"]["yield1_m"].is_number());
    assert_eq!(v["method"], "exact");
    assert!(v["units"].as_str().unwrap().starts_with("SI"));
    assert_eq!(v["omega1_grid"], "1:1.1:0.1");
    let csv = stdout(&succeeds(&args("csv")));
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + 3 * 2);
    let header: Vec<&str> = lines[0].split(',').collect();
    assert!(lines.iter().all(|l| l.split(',').count() == header.len()));
    let row: Vec<&str> = lines[1].split(',').collect();
    let cell = |key: &str| row[header.iter().position(|h| *h == key).unwrap()];
    assert_eq!(cell("ap_g"), "0.2");
    assert_eq!(cell("gap_m"), "0.010000000000000002");
    assert_eq!(cell("method"), "exact");
    assert_eq!(cell("omega1"), "1");
}
