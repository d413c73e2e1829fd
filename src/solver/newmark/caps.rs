//! Limits that turn a runaway run into a reported stop instead of a hang.
//!
//! A run of Δτ steps cannot loop for ever by itself: every accepted step
//! advances τ. It can still run away in three ways, and each has a cap:
//! - steps far smaller than planned, for ever (τ + h rounding back to τ, or a
//!   step halved to nothing and accepted unconverged each time): the step cap;
//! - contact onsets in a Zeno sequence, each a sliver of a step: the impact cap;
//! - a Newton iteration that fails at every size, so every step is retried
//!   [`SolverOptions::max_step_halvings`] times: the retry cap.
//!
//! The caps are far above what any resolved run needs (see each field), so a
//! run that meets one is wrong, and says so, rather than slow.
//!
//! [`SolverOptions::max_step_halvings`]: super::SolverOptions::max_step_halvings

use crate::model::Params;

/// Contact onsets per excitation cycle allowed on top of [`IMPACT_FLOOR`].
/// The paper's cases have one or two per cycle. Over 43,200 runs of sets 1
/// and 2 (both models; Π_d from 0 to the preset's, e from 1e-3 to 1,
/// Π_ω1 from 0.1 to 3, μ from 0.5 to 2.25, Π_ωcon from 5 to 500) the most
/// was 1,647 in 8 cycles, about 200 per cycle (a near-touching, elastic,
/// soft contact); none met a cap.
pub const IMPACTS_PER_CYCLE: usize = 1_000;
/// Contact onsets allowed in any run, however short.
pub const IMPACT_FLOOR: usize = 10_000;
/// Retries allowed in any run, on top of one per [`RETRIES_PER_STEP`] whole steps.
pub const RETRY_FLOOR: usize = 10_000;
/// One retry is allowed per this many whole steps Δτ of the run.
pub const RETRIES_PER_STEP: usize = 10;

/// The most a run may do before it is stopped (and says why).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunCaps {
    /// Accepted steps, counting contact sub-steps and split steps.
    pub steps: usize,
    /// Contact onsets.
    pub impacts: usize,
    /// Steps retried at half size after Newton failed.
    pub retries: usize,
}

impl RunCaps {
    /// The caps of a run of `p` with `substeps` Newmark steps per Δτ in contact:
    ///
    /// ```text
    /// N       = ⌈τ_end / Δτ⌉                       whole steps planned,
    /// impacts = 10 000 + 1 000 · cycles,
    /// retries = 10 000 + N / 10,
    /// steps   = 2 (n N + 2 impacts + retries) + 1024.
    /// ```
    ///
    /// The step cap is twice the most a resolved run can take: every Δτ in
    /// contact at n sub-steps, two split steps per contact and one extra step
    /// per retry. Retries cost up to [`MAX_NEWTON`] iterations times the
    /// halvings each, so their cap is what bounds a run whose contact steps
    /// never converge.
    ///
    /// [`MAX_NEWTON`]: super::MAX_NEWTON
    pub fn for_run(p: &Params, substeps: u32) -> Self {
        let whole = saturating_count((p.tau_end() / p.dt).ceil());
        let impacts =
            IMPACT_FLOOR.saturating_add(IMPACTS_PER_CYCLE.saturating_mul(p.cycles as usize));
        let retries = RETRY_FLOOR.saturating_add(whole / RETRIES_PER_STEP);
        let steps = whole
            .saturating_mul(substeps.max(1) as usize)
            .saturating_add(impacts.saturating_mul(2))
            .saturating_add(retries)
            .saturating_mul(2)
            .saturating_add(1024);
        RunCaps {
            steps,
            impacts,
            retries,
        }
    }
}

/// A non-negative count from a float: saturating above, and unlimited for
/// NaN (a Δτ of 0 or NaN then stops on the first step that fails to advance τ).
fn saturating_count(x: f64) -> usize {
    if x >= 0.0 {
        // Float-to-integer casts saturate at usize::MAX.
        x as usize
    } else if x.is_nan() {
        usize::MAX
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn caps_of_the_paper_run() {
        // 8 cycles at Δτ = 0.001: N = ⌈16π / 0.001⌉ = 50 266.
        let caps = RunCaps::for_run(&SET1, 10);
        assert_eq!(caps.impacts, 10_000 + 8_000);
        assert_eq!(caps.retries, 10_000 + 5_026);
        assert_eq!(caps.steps, 2 * (502_660 + 36_000 + 15_026) + 1024);
    }

    #[test]
    fn degenerate_steps_saturate() {
        let p = Params { dt: 0.0, ..SET1 };
        let caps = RunCaps::for_run(&p, 10);
        assert_eq!(caps.steps, usize::MAX);
        let p = Params { dt: 1e300, ..SET1 };
        assert_eq!(RunCaps::for_run(&p, 1).retries, RETRY_FLOOR);
    }
}
