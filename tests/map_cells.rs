//! `pounding map`: each cell is the pounding run and the no-pounding run of
//! its own parameter set; a row at fixed μ is the spectrum at that μ; the
//! baselines are shared along axes the free motion ignores; and the CLI's
//! output and bad input.

mod common;

use pounding::analysis::baseline::BaselineCache;
use pounding::analysis::gap::minimum_gap;
use pounding::analysis::map::{Axis, MapPlan, compute};
use pounding::analysis::spectrum::{Region, baseline_params};
use pounding::analysis::sweep::{curve_specs, sweep};
use pounding::model::{Method, Params, SET1};
use pounding::solver::exact::ContactExtremes;
use pounding::solver::run_for_sweep;

use common::{fails, json, stdout, succeeds};

const EXACT_SET1: Params = Params {
    method: Method::Exact,
    ..SET1
};

fn plan(x: &str, y: &str) -> MapPlan {
    MapPlan::new(
        EXACT_SET1,
        EXACT_SET1.mu(),
        Axis::parse("--x", x).unwrap(),
        Axis::parse("--y", y).unwrap(),
    )
    .unwrap()
}

#[test]
fn cells_are_their_own_runs() {
    let plan = plan("omega1=0.6:2.4:0.9", "mu=1.5:4:2.5");
    let (cells, _) = compute(&plan);
    assert_eq!(cells.len(), 6);
    for c in &cells {
        let p = plan.at(c.x, c.y);
        assert_eq!((p.omega1, p.omega2), (c.x, c.y * c.x));
        let with = run_for_sweep(&p, ContactExtremes::Forces);
        let without = run_for_sweep(&baseline_params(&p), ContactExtremes::None);
        assert_eq!(c.left, with.left);
        assert_eq!(c.right, with.right);
        assert_eq!(c.impacts, with.impacts.len());
        assert_eq!((c.max_force, c.min_force), (with.max_force, with.min_force));
        // A run without impact is its own baseline; its peaks equal the free run's
        // to round-off (the two runs cut their segments at different instants).
        for (got, free) in [
            (
                c.free_left.peak_displacement,
                without.left.peak_displacement,
            ),
            (
                c.free_right.peak_displacement,
                without.right.peak_displacement,
            ),
        ] {
            assert!((got - free).abs() <= 1e-12 * free, "{got} vs {free}");
        }
        assert_eq!(
            c.left_amplification,
            with.left.peak_displacement / c.free_left.peak_displacement
        );
        assert_eq!(
            c.region,
            Region::classify(with.left.peak_displacement, c.free_left.peak_displacement)
        );
        let gap = minimum_gap(&p).exact;
        assert!((c.min_gap.unwrap() - gap).abs() <= 1e-12 * gap);
        assert!(c.completed);
    }
}

#[test]
fn a_mu_row_is_the_spectrum() {
    let plan = plan("omega1=0.1:3.0:0.1", "mu=2:2.5:0.25");
    let (cells, _) = compute(&plan);
    let xs = plan.x.values();
    let row = &cells[xs.len()..2 * xs.len()];
    assert!(row.iter().all(|c| c.y == 2.25));
    let specs = curve_specs(&EXACT_SET1, 2.25, None).unwrap();
    let curve = &sweep(&specs, &xs, &mut BaselineCache::new())[0];
    for (c, pt) in row.iter().zip(&curve.points) {
        assert_eq!((c.omega1, c.omega2), (pt.omega1, pt.omega2));
        assert_eq!((c.left, c.right), (pt.left, pt.right));
        assert_eq!((c.free_left, c.free_right), (pt.free_left, pt.free_right));
        assert_eq!((c.impacts, c.region), (pt.impacts, pt.region));
    }
    // All three regions occur along this row (SPEC §7's picture).
    for r in [Region::Amplification, Region::Suppression, Region::None] {
        assert!(row.iter().any(|c| c.region == r), "{r:?} missing");
    }
}

#[test]
fn gap_axis_shares_baselines() {
    // The free motion ignores Π_d: five Π_ω1 values need at most five baselines.
    let plan = plan("omega1=0.5:2.5:0.5", "gap=0.2:3.2:0.5");
    let (cells, cache) = compute(&plan);
    assert_eq!(cells.len(), 35);
    assert!(cache.baselines.runs + cache.baselines.from_pounding <= 5);
    // The baseline, and so Π_d,min, is the same down every column; a gap
    // above Π_d,min never pounds.
    for c in &cells {
        let top = &cells[(cells.len() - 5) + (cells.iter().position(|d| d.x == c.x).unwrap())];
        assert_eq!(c.free_left, top.free_left);
        if c.y > c.min_gap.unwrap() {
            assert_eq!(c.impacts, 0, "gap {} above Π_d,min {:?}", c.y, c.min_gap);
        }
    }
}

#[test]
fn cli_cell_matches_pounding_run() {
    let map = json(&[
        "map",
        "--x",
        "omega1=0.75:1.05:0.3",
        "--y",
        "mu=2:2.5:0.5",
        "--format",
        "json",
    ]);
    let cells = map["cells"].as_array().unwrap();
    assert_eq!(cells.len(), 4);
    // The cell (Π_ω1 = 1.05, μ = 2.5) against `pounding run` at its parameters.
    let c = &cells[3];
    assert_eq!((c["x"].as_f64(), c["y"].as_f64()), (Some(1.05), Some(2.5)));
    let omega2 = format!("omega2={}", 2.5 * 1.05);
    let run = json(&[
        "run",
        "--method",
        "exact",
        "--set",
        "omega1=1.05",
        "--set",
        &omega2,
        "--format",
        "json",
    ]);
    for side in ["left", "right"] {
        for peak in ["peak_displacement", "peak_velocity"] {
            let (a, b) = (
                c[side][peak].as_f64().unwrap(),
                run[side][peak].as_f64().unwrap(),
            );
            assert!((a - b).abs() <= 1e-10 * b, "{side}.{peak}: {a} vs {b}");
        }
    }
    assert_eq!(c["impacts"], run["impacts"]);
    // Self-describing: every parameter, both axes, the method, the threshold, the version.
    for key in pounding::model::params::keys() {
        assert!(map["params"].get(key).is_some(), "params.{key} missing");
    }
    assert_eq!(map["x"]["key"], "omega1");
    assert_eq!(map["y"]["points"], 2);
    assert_eq!(map["method"], "exact");
    assert_eq!(map["region_threshold"], 0.02);
    assert_eq!(map["version"], env!("CARGO_PKG_VERSION"));
}

#[test]
fn cli_regions_agree_with_spectrum() {
    let spectrum = json(&[
        "spectrum",
        "--omega1",
        "0.1:3:0.1",
        "--mu",
        "2.25",
        "--format",
        "json",
    ]);
    let map = json(&[
        "map",
        "--x",
        "omega1=0.1:3:0.1",
        "--y",
        "mu=2.25:2.25:1",
        "--format",
        "json",
    ]);
    let points = spectrum["curves"][0]["points"].as_array().unwrap();
    let cells = map["cells"].as_array().unwrap();
    assert_eq!(points.len(), 30);
    assert_eq!(cells.len(), 30);
    for (pt, c) in points.iter().zip(cells) {
        assert_eq!(pt["omega1"], c["x"]);
        assert_eq!(pt["region"], c["region"], "at Π_ω1 = {}", pt["omega1"]);
        assert_eq!(pt["impacts"], c["impacts"]);
    }
}

#[test]
fn cli_csv_rows_carry_every_parameter() {
    let text = stdout(&succeeds(&[
        "map",
        "--x",
        "gap=0.5:1:0.5",
        "--y",
        "restitution=0.5:0.9:0.4",
        "--format",
        "csv",
    ]));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 5);
    let header: Vec<&str> = lines[0].split(',').collect();
    let last: Vec<&str> = lines[4].split(',').collect();
    let col = |k: &str| last[header.iter().position(|h| *h == k).unwrap()];
    assert_eq!((col("gap"), col("restitution")), ("1", "0.9"));
    assert_eq!((col("omega2"), col("method")), ("2.36", "exact"));
}

#[test]
fn cli_refuses_bad_axes() {
    for (x, y, says) in [
        ("bogus=1:2:1", "mu=1:2:1", "unknown axis `bogus`"),
        ("omega1=1:2", "mu=1:2:1", "expected KEY=START:STOP:STEP"),
        ("omega1=2:1:0.5", "mu=1:2:1", "START <= STOP"),
        ("omega1=0.5:1:0", "mu=1:2:1", "STEP must be > 0"),
        ("omega1=0.5:1:0.5", "restitution=0.5:3:0.5", "[0.001, 1]"),
        ("omega1=0.5:1:0.5", "omega1=1:2:1", "different keys"),
        ("omega2=0.5:1:0.5", "mu=1:2:1", "cannot both be axes"),
        ("omega1=0.5:1:0.5", "mu=1:2000:1000", "at omega1"),
    ] {
        fails(&["map", "--x", x, "--y", y], 2, &[says]);
    }
}
