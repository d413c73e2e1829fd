//! The check of the damped series' steps (SPEC §14), in tests only: on
//! every step the series takes with the dampers' forces in it
//! ([`super::damped`]), each damper's Δv, sampled at 256 points of the
//! step, keeps the sign it starts with: no such step straddles a reversal,
//! where the force is not analytic and the series could not carry it.

use std::cell::Cell;

use super::super::poly;
use super::super::taylor::Series;
use super::Run;

/// Points per step.
const POINTS: usize = 256;

thread_local! {
    /// Damped series steps checked on this thread.
    pub(super) static CHECKED: Cell<usize> = const { Cell::new(0) };
}

impl Run<'_> {
    /// Panics where some damper's Δv on `series` over [0, end] is 0 or
    /// has the sign opposite to its start's.
    pub(super) fn check_damped(&self, series: &Series, end: f64) {
        let mut dv = Vec::new();
        for d in &self.layout.dampers {
            series.combine(&[], &[(d.left, 1.0), (d.right, -1.0)], &mut dv);
            let start = dv[0];
            for j in 0..=POINTS {
                let s = end * j as f64 / POINTS as f64;
                let rate = poly::eval(&dv, s);
                assert!(
                    rate * start > 0.0,
                    "Δv {rate} at {s} of a damped step of {end} from {start}, t = {}",
                    self.t
                );
            }
        }
        CHECKED.set(CHECKED.get() + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::CHECKED;
    use crate::model::buildings::{self, Ground};
    use crate::model::simulated::Simulation;
    use crate::solver::buildings::{RowOptions, run_row};

    /// block-and-frame-retrofit with its damper at α = 0.35 and at a
    /// tenth of its damping, under a simulated record of 600 samples at
    /// scales 0.5, 1 and 2 (its joints pounding at the larger): every step
    /// the damped series takes passes the check, and they are many, as
    /// are the reversals between them.
    #[test]
    fn no_damped_series_step_straddles_a_reversal() {
        let before = CHECKED.get();
        let record = Simulation::synthetic("synthetic:600", 600).expect("a record");
        let mut reversals = 0;
        for damping in ["4e6", "4e5"] {
            let row = buildings::load_with(
                "block-and-frame-retrofit",
                &[
                    "link1.exponent=0.35".into(),
                    format!("link1.damping={damping}"),
                ],
            )
            .expect("shipped");
            for scale in [0.5, 1.0, 2.0] {
                let ground = Ground::from_record(&record, scale);
                let run = run_row(&row, &ground, &RowOptions::lasting(ground.end() + 1.0));
                let profile = run.expect("runs").profile;
                reversals += profile.events.reversals;
            }
        }
        let checked = CHECKED.get() - before;
        println!("{checked} damped steps checked, {reversals} reversals");
        assert!(checked > 1000, "{checked} damped steps checked");
        assert!(reversals > 20, "{reversals} reversals");
    }
}
