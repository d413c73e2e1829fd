//! An impact's largest force and penetration in a row (SPEC §13, §4): a
//! run without a force history locates them on a step only where their
//! upper bounds on it (the quadratic part exactly, the rest by Σ|c_k|s^k)
//! pass the impact's peaks so far; a run with the history locates them on
//! every step. Both take the same steps, so every impact's peaks agree to
//! the bit, under both laws of the Kelvin family and where the frame yields.

use pounding::model::ContactModel;
use pounding::model::buildings::matrices::default_tail;
use pounding::model::buildings::{self, Ground};
use pounding::model::simulated::Simulation;
use pounding::solver::buildings::{RowOptions, run_row};

#[test]
fn bounded_impact_peaks_are_those_located_on_every_step() {
    let record = Simulation::synthetic("synthetic:2000", 2000).expect("a record");
    let base = buildings::load("block-and-frame").expect("a shipped row");
    let duration = Ground::from_record(&record, 1.0).end() + default_tail(&base);
    let mut compared = 0;
    for model in [ContactModel::Kelvin, ContactModel::ImprovedKelvin] {
        let row = buildings::Row {
            model,
            ..base.clone()
        };
        for scale in [1.0, 3.0] {
            let ground = Ground::from_record(&record, scale);
            let bounded = RowOptions::lasting(duration);
            let every = RowOptions {
                forces: true,
                ..bounded
            };
            let a = run_row(&row, &ground, &bounded).expect("runs");
            let b = run_row(&row, &ground, &every).expect("runs");
            assert_eq!(a.series_steps, b.series_steps, "{model:?} × {scale}");
            for (p, q) in a.pairs.iter().zip(&b.pairs) {
                assert_eq!(p.impacts.len(), q.impacts.len());
                for (x, y) in p.impacts.iter().zip(&q.impacts) {
                    assert!(x.max_force > 0.0 && x.max_penetration > 0.0, "{x:?}");
                    assert_eq!(x.max_force.to_bits(), y.max_force.to_bits(), "{x:?} {y:?}");
                    assert_eq!(x.max_penetration.to_bits(), y.max_penetration.to_bits());
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 100, "{compared} impacts compared");
}
