//! Grazes: a floor pair whose relative displacement only just passes the
//! gap, by 1e-5 of its largest value, somewhere inside a sub-step. The
//! quiet test of the exact method (SPEC §13) is a bound, not an estimate,
//! so the impact is found, as the reference finds it, at the default
//! sub-steps and at sub-steps of four radians of the fastest mode (under
//! the sine; a record's pieces are shorter), where the Hermite cubic's own
//! error allowance, (ωh)⁴/384 of the amplitude, is far above the graze.

use pounding::model::buildings::{self, Ground, Row};
use pounding::model::record::read;
use pounding::reference::row::reference_row;
use pounding::solver::buildings::layout::Layout;
use pounding::solver::buildings::{RowOptions, run_row};

/// The row `name` with its gap set just below the largest u_A − u_B its
/// facing floors reach without pounding, under `ground` for `duration`.
fn grazing(name: &str, ground: &Ground, duration: f64) -> Row {
    let mut row = buildings::load(name).unwrap();
    for j in &mut row.joints {
        j.gap = f64::INFINITY;
    }
    let free = run_row(&row, ground, &RowOptions::lasting(duration)).unwrap();
    let top = free.max_relative.iter().fold(0.0f64, |m, &x| m.max(x));
    assert!(top > 0.0);
    for j in &mut row.joints {
        j.gap = top * (1.0 - 1e-5);
    }
    row
}

fn graze_is_found(name: &str, ground: &Ground, duration: f64) {
    let row = grazing(name, ground, duration);
    let reference = reference_row(&row, ground, duration, 1e-13);
    assert!(
        reference.impacts.iter().sum::<usize>() >= 1,
        "{name}: the reference finds the graze"
    );
    let rate = Layout::of(&row).rate;
    for radians in [None, Some(4.0)] {
        let options = RowOptions {
            max_substep: radians.map(|r| r / rate),
            ..RowOptions::lasting(duration)
        };
        let exact = run_row(&row, ground, &options).unwrap();
        let counts: Vec<usize> = exact.pairs.iter().map(|p| p.impacts.len()).collect();
        assert_eq!(
            counts, reference.impacts,
            "{name}: impacts per pair, sub-steps of {radians:?} radians"
        );
    }
}

#[test]
fn a_graze_under_a_record_is_found() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    graze_is_found("block-and-frame", &ground, ground.end() + 2.0);
}

#[test]
fn a_graze_under_a_sine_is_found() {
    let ground = Ground::sine(3.0, 2.0 * std::f64::consts::PI / 0.8, 4.0);
    graze_is_found("three-in-series", &ground, 6.0);
}
