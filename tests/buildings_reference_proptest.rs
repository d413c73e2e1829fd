//! The exact method against the independent reference (SPEC §13) over
//! random rows (stiffness, yield drift, gap, contact law), simulated records
//! and scales: the same impacts at every floor pair, and every floor's
//! peaks (|u|, |u̇|, |Δ|, |ü + ü_g|) within 1e-8 of the building's largest.
//!
//! The reference (Dormand–Prince 5(4) held to 1e-13, events found by
//! bisection on retaken steps) shares nothing with the exact method's
//! series, bounds or event search, so an event the exact method's search
//! misses shows here as an impact count or a peak that differs, where the
//! quiet path against the series path shows it only when the two paths'
//! steps happen to differ around it. (Such misses are rare: the touch again
//! right after a slow separation that the search once missed came in none
//! of 800 random cases run with that fix undone; the quiet-path proptest's
//! kept case and `poly`'s unit test hold that one.)
//!
//! Over 1,600 random cases every impact count was equal and the largest
//! difference was 1.1e-10 (a peak floor acceleration), so 1e-8 is the
//! reference's own accuracy with a margin; a missed event moves the motion
//! by a part of itself.

mod common;

use proptest::prelude::*;

use pounding::reference::row::reference_row;
use pounding::solver::buildings::{RowOptions, run_row};

const TOLERANCE: f64 = 1e-8;

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]

    #[test]
    fn the_exact_method_and_the_reference_agree(case in common::random_row()) {
        let (row, ground) = case.make();
        let duration = ground.end() + 0.5;
        let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).expect("runs");
        let reference = reference_row(&row, &ground, duration, 1e-13);
        let counts: Vec<usize> = exact.pairs.iter().map(|p| p.impacts.len()).collect();
        prop_assert_eq!(&counts, &reference.impacts, "impacts per floor pair");
        for (b, floors) in exact.floors.iter().enumerate() {
            let largest = |v: &Vec<f64>| v.iter().fold(f64::MIN_POSITIVE, |m, x| m.max(*x));
            let quantities = [
                ("displacement", &reference.displacement[b]),
                ("velocity", &reference.velocity[b]),
                ("drift", &reference.drift[b]),
                ("acceleration", &reference.absolute_acceleration[b]),
            ];
            for (q, (what, expected)) in quantities.into_iter().enumerate() {
                let scale = largest(expected);
                for (i, f) in floors.iter().enumerate() {
                    let got = [f.displacement, f.velocity, f.drift, f.absolute_acceleration][q];
                    let e = (got - expected[i]).abs() / scale;
                    prop_assert!(e < TOLERANCE, "building {} floor {} {}: {:e}", b, i, what, e);
                }
            }
        }
    }
}
