//! The two phases of a run (SPEC §4–5). Out of contact the two structures
//! are uncoupled and each step is an exact branch solve, so the free phase
//! runs whole steps of Δτ in a tight loop; the step that crosses into
//! contact and the run's last, shorter step go through [`Driver::step`].
//! In contact every step is a Newton solve at Δτ/n, which may fail and be
//! retried, so the contact phase is [`Driver::step`] alone.

use super::driver::{Driver, POLL_EVERY};
use super::policy::{Event, Policy};
use super::step::Phase;
use crate::solver::observer::Observer;
use crate::solver::result::StopReason;

impl Driver<'_> {
    /// Out of contact, until contact begins, the run ends or it stops.
    pub fn free_phase<P: Policy, O: Observer>(&mut self, policy: &P, observer: &mut O) {
        let dt = self.clock.dt;
        let last = self.clock.tau_end - self.clock.end_slack;
        while matches!(self.phase, Phase::Free) && self.running() {
            // The hot path: whole steps of Δτ while they stay out of contact
            // and the run's last step is not yet due. The state is carried in
            // `current` (registers) rather than read back from the driver.
            let mut current = self.state;
            // A step reaching the next break of g goes through `step`, which ends it there.
            let brk = self.next_break;
            while current.tau + dt <= last && current.tau + dt < brk {
                let next = self.system.free_step(&current, dt);
                if self.system.penetration(next.x) > 0.0 {
                    break;
                }
                if !self.accept(observer, &current, &next, Event::None) {
                    return;
                }
                current = next;
                if self.result.steps.is_multiple_of(POLL_EVERY) {
                    // The checkpoint re-evaluated the phasor.
                    current = self.state;
                }
            }
            if self.running() {
                // Takes the crossing step again, or the last one.
                self.step(policy, observer, dt);
            }
        }
    }

    /// In contact, until it ends, the run ends or it stops.
    pub fn contact_phase<P: Policy, O: Observer>(&mut self, policy: &P, observer: &mut O) {
        let contact_dt = self.clock.contact_dt;
        while matches!(self.phase, Phase::Contact(_)) && self.running() {
            self.step(policy, observer, contact_dt);
        }
    }

    /// One accepted step of the current phase from the current state, of size
    /// `base` (or what is left of the run, see [`Clock::step_from`]):
    /// - a step whose Newton iteration fails is retried at half the size, up
    ///   to [`max_step_halvings`] times, then accepted unconverged;
    /// - a step that crosses δ = 0 (δ > 0 after a free step, δ ≤ 0 after a
    ///   contact step) is handed to the policy, which returns the state to
    ///   accept and the phase switch there;
    /// - a NaN δ is no crossing: the state is accepted and stops the run.
    ///
    /// [`Clock::step_from`]: super::driver::Clock::step_from
    /// [`max_step_halvings`]: super::SolverOptions::max_step_halvings
    #[allow(clippy::neg_cmp_op_on_partial_ord, reason = "a NaN must compare false")]
    pub fn step<P: Policy, O: Observer>(&mut self, policy: &P, observer: &mut O, base: f64) {
        self.step_once(policy, observer, base);
        self.pass_break();
    }

    /// [`Driver::step`] before its break handling.
    #[allow(clippy::neg_cmp_op_on_partial_ord, reason = "a NaN must compare false")]
    fn step_once<P: Policy, O: Observer>(&mut self, policy: &P, observer: &mut O, base: f64) {
        let max_halvings = self.options.max_step_halvings;
        let mut halvings = 0;
        loop {
            let start = self.state;
            let h = self.to_break(start.tau, self.clock.step_from(start.tau, base, halvings));
            if !(start.tau + h > start.tau) {
                // The step no longer advances τ: it would run for ever.
                self.halt(StopReason::StepCap);
                return;
            }
            let (next, converged) = self.system.step(&start, h, &self.phase);
            if !converged && halvings < max_halvings {
                if !self.retry() {
                    return;
                }
                halvings += 1;
                continue;
            }
            let pen = self.system.penetration(next.x);
            let crossing = match self.phase {
                Phase::Free if pen > 0.0 => policy.onset(&self.system, self.p, &start, next, h),
                Phase::Contact(_) if pen <= 0.0 => {
                    policy.separation(&self.system, &start, next, h, &self.phase)
                }
                _ => {
                    if !converged {
                        self.result.unconverged_steps += 1;
                    }
                    self.accept(observer, &start, &next, Event::None);
                    return;
                }
            };
            // A contact step inside the crossing failed: retry the whole step smaller.
            if !crossing.converged && halvings < max_halvings {
                if !self.retry() {
                    return;
                }
                halvings += 1;
                continue;
            }
            if !(converged && crossing.converged) {
                self.result.unconverged_steps += 1;
            }
            self.accept(observer, &start, &crossing.state, crossing.event);
            return;
        }
    }
}
