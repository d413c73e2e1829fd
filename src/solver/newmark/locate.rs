//! Event location: the instant inside a step where contact starts or ends
//! (δ crosses 0, SPEC §5).
//!
//! The penetration after a Newmark step of size s from the step's start,
//! δ(s), is a smooth function of s. Its root in (0, h] is bracketed by the
//! step's two ends and found by the Illinois variant of regula falsi. The
//! state returned is the one on the far side of the crossing (δ > 0 for an
//! onset, δ ≤ 0 for a separation), so the phase switch that follows is
//! consistent with the sign of δ.

use super::step::{Phase, State, System};

/// Relative width of the final bracket, as a fraction of the step.
const TIME_TOLERANCE: f64 = 1e-12;
/// Absolute |δ| at which the crossing is accepted as found.
const PENETRATION_TOLERANCE: f64 = 1e-15;
const MAX_ITERATIONS: usize = 100;

/// What a located crossing returns.
pub struct Located {
    pub state: State,
    /// Newton converged at every trial step.
    pub converged: bool,
    /// Trial steps taken.
    pub evaluations: usize,
}

/// Locates where δ changes side inside a step of size `h` from `start`.
///
/// `crossed(δ)` says whether δ is past the event (onset: δ > 0; end: δ ≤ 0);
/// it must be false at `start` and true at `end` (the full step's result).
pub fn locate(
    system: &System,
    start: &State,
    end: State,
    h: f64,
    phase: &Phase,
    crossed: impl Fn(f64) -> bool,
) -> Located {
    // f_lo, f_hi: the values regula falsi interpolates (Illinois may halve them);
    // pen_hi: the true penetration of the best state.
    let (mut lo, mut f_lo) = (0.0, system.penetration(start.x));
    let (mut hi, mut f_hi, mut best) = (h, system.penetration(end.x), end);
    let mut pen_hi = f_hi;
    let mut converged = true;
    let mut evaluations = 0;
    // Illinois: halve the weight of an end point that stays put twice running.
    let mut side = 0i8;
    while evaluations < MAX_ITERATIONS
        && hi - lo > TIME_TOLERANCE * h
        && pen_hi.abs() > PENETRATION_TOLERANCE
    {
        let mut s = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if !(s > lo && s < hi) {
            s = 0.5 * (lo + hi);
        }
        let (trial, ok) = system.step(start, s, phase);
        evaluations += 1;
        converged &= ok;
        let f = system.penetration(trial.x);
        if crossed(f) {
            (hi, f_hi, pen_hi, best) = (s, f, f, trial);
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        } else {
            (lo, f_lo) = (s, f);
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        }
    }
    Located {
        state: best,
        converged,
        evaluations,
    }
}
