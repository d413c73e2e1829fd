//! The check of the events the driver applies (SPEC §13), in tests only:
//! each is applied at a state where its function has reached zero, to
//! within 1e-9 of the motion's scales, so that no storey is put on a
//! branch, and no pair in or out of contact, that the motion has not
//! reached.

use std::cell::Cell;

use super::super::event_function::EventFunction;
use super::Run;

thread_local! {
    /// Events checked on this thread.
    pub(super) static CHECKED: Cell<usize> = const { Cell::new(0) };
}

impl Run<'_> {
    /// Panics where g at the current state lies below zero by more than
    /// 1e-9 of the motion's scales `scale` (displacement, velocity).
    pub(super) fn check_event(&self, g: &EventFunction, scale: (f64, f64)) {
        let value = g.value(&self.u, &self.v);
        let size = if g.reads_velocities() {
            scale.1
        } else {
            scale.0
        };
        assert!(
            value >= -1e-9 * size,
            "an event applied at g = {value:e} (scale {size:e}), t = {}",
            self.t
        );
        CHECKED.set(CHECKED.get() + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::CHECKED;
    use crate::model::ContactModel;
    use crate::model::buildings::{self, Ground, Row};
    use crate::model::physical::G;
    use crate::solver::buildings::{RowOptions, run_row};

    /// block-and-frame-retrofit in Hertz contact with its damper at
    /// α = 0.35 and c_l = 1e6 under ten cycles of a 0.3 g sine of period
    /// 1 s: at 9.4803 s its frame's fifth storey unloads at its yield
    /// drift, in a Hertz contact phase, and the quintic of the next
    /// Runge–Kutta step put the same storey's yield function a hair
    /// above zero at its start. That yield was applied at the step's end
    /// with g = −2.2e-7 m, the storey on a plastic branch it was
    /// leaving, and the floors' final displacements moved by 1.5e-7 m.
    /// Every event is now checked where it is applied, and the run's end
    /// is the run's at a hundredth of the tolerance to 1e-10 m.
    #[test]
    fn a_storey_that_unloads_in_contact_does_not_yield_again_at_once() {
        let before = CHECKED.get();
        let row = buildings::load_with(
            "block-and-frame-retrofit",
            &["link1.exponent=0.35".into(), "link1.damping=1e6".into()],
        )
        .expect("a shipped row");
        let row = Row {
            model: ContactModel::Hertz,
            ..row
        };
        let ground = Ground::sine(0.3 * G, 2.0 * std::f64::consts::PI, 10.0);
        let run = run_row(&row, &ground, &RowOptions::lasting(10.0)).expect("runs");
        // Every floor at 10 s, by the same row run at a hundredth
        // of the tolerance (contact_rk's TOLERANCE at 1e-14).
        let reference = [
            0.0015476607706747492,
            0.0031230360492877475,
            0.004558577364454229,
            0.03478352754575275,
            0.06977846932951558,
            0.09497168512115532,
            0.08495183752525809,
            0.08100693274295663,
            0.08573541262118996,
            0.0949373352838061,
            0.10244777413758759,
        ];
        for (u, r) in run.final_displacement.iter().zip(reference) {
            assert!((u - r).abs() <= 1e-10, "{u} against {r}");
        }
        assert!(CHECKED.get() - before > 100, "events checked");
    }
}
