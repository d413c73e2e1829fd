//! The exact method against the independent reference (SPEC §13): peaks of
//! every floor within 1e-9 (relative to the building's largest), and equal
//! impact counts at every floor pair.

use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::reference::row::reference_row;
use pounding::solver::buildings::{RowOptions, run_row};

fn compare(name: &str, ground: &Ground, duration: f64, tolerance: f64) -> f64 {
    let row = buildings::load(name).unwrap();
    let exact = run_row(&row, ground, &RowOptions::lasting(duration)).unwrap();
    let reference = reference_row(&row, ground, duration, 1e-13);
    let counts: Vec<usize> = exact.pairs.iter().map(|p| p.impacts.len()).collect();
    assert_eq!(counts, reference.impacts, "{name}: impacts per pair");
    let mut worst = 0.0f64;
    for (b, floors) in exact.floors.iter().enumerate() {
        let scale = |v: &Vec<f64>| v.iter().fold(0.0f64, |m, x| m.max(*x));
        let (su, sv, sd) = (
            scale(&reference.displacement[b]),
            scale(&reference.velocity[b]),
            scale(&reference.drift[b]),
        );
        for (i, f) in floors.iter().enumerate() {
            worst = worst
                .max((f.displacement - reference.displacement[b][i]).abs() / su)
                .max((f.velocity - reference.velocity[b][i]).abs() / sv)
                .max((f.drift - reference.drift[b][i]).abs() / sd);
        }
    }
    assert!(
        worst < tolerance,
        "{name}: worst relative difference {worst:e}"
    );
    worst
}

#[test]
fn block_and_frame_under_a_record_matches_the_reference() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let w = compare("block-and-frame", &ground, ground.end() + 2.0, 1e-9);
    println!("block-and-frame: {w:e}");
}

#[test]
fn three_in_series_under_a_sine_matches_the_reference() {
    let ground = Ground::sine(3.0, 2.0 * std::f64::consts::PI / 0.8, 4.0);
    let w = compare("three-in-series", &ground, 6.0, 1e-9);
    println!("three-in-series: {w:e}");
}

/// Each cycloidal pulse of SPEC §9 at a_p = 0.5 g, T_p = 1 s on the block
/// and the frame (yielding, impacts at the block's roof), and 2 s of free
/// vibration; the type B pulse starts every floor at −V_p.
#[test]
fn block_and_frame_under_each_pulse_matches_the_reference() {
    use pounding::model::excitation::Pulse;
    let (ap, omega) = (0.5 * 9.80665, 2.0 * std::f64::consts::PI);
    for pulse in [Pulse::A, Pulse::B, Pulse::c(1), Pulse::c(2)] {
        let ground = Ground::from_pulse(pulse, ap, omega);
        let w = compare("block-and-frame", &ground, ground.end() + 2.0, 1e-9);
        println!("block-and-frame under {pulse:?}: {w:e}");
    }
}
