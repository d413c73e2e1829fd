//! The estimated work of a run, before it starts: for dealing a sweep's
//! units to shards (where only the ratios between the units of one sweep
//! matter), and, in seconds ([`seconds`]), for the commands' bound on long
//! requests and their progress bars.
//!
//! A Newmark run
//! takes τ_end/Δτ steps whatever the frequencies; an exact run takes a few
//! closed-form segments per excitation cycle and per half-period of the
//! stiffer structure, so its work grows as τ_end · (1 + max(Π_ω1, Π_ω2)).
//! Measured on set 1 (exact, 8 cycles, no contact, `run --repeat`): 78,
//! 130, 357 and 1189 segments at Π_ω2 = 0.68, 2.25, 6.75 and 22.5, against
//! 84, 162, 387 and 1175 by this rule; the time follows the segments. A run
//! with contact (finite gap) counts [`POUNDING`] times a free run: set 1's
//! nine impacts at Π_ω1 = 1 double its time (0.10 against 0.05 ms).

use crate::model::buildings::Row;
use crate::model::{Method, Params};

/// Cost of one nominal Newmark step, measured on set 1 in a release build:
/// 29 ns (`pounding run --repeat 50`: 1.64 ms for 55 840 accepted steps,
/// 50 266 nominal; contact sub-steps add about 10 %).
pub const SECONDS_PER_NEWMARK_STEP: f64 = 3e-8;

/// Cost of one unit of the exact method's work, τ_end·(1 + max(Π_ω1,
/// Π_ω2)) of a free run, measured in a release build
/// (`pounding run --method exact --repeat 400`, set 1 without contact):
/// 0.043 ms for 169 units at Π_ω1 = 0.3, 0.137 ms for 553 at Π_ω1 = 10,
/// both 0.25 µs a unit; under a 1000-sample record (preset
/// `record-synthetic`) 0.18 µs a unit. About eight Newmark steps.
pub const SECONDS_PER_EXACT_UNIT: f64 = 2.5e-7;

/// Estimated seconds of one free run of `p` on this class of machine (two
/// cores of a few GHz): the order of magnitude a request's time is judged
/// by, not a measurement.
pub fn seconds(p: &Params) -> f64 {
    free_run(p)
        * match p.method {
            Method::Newmark => SECONDS_PER_NEWMARK_STEP,
            Method::Exact => SECONDS_PER_EXACT_UNIT,
        }
}

/// Work of a run with contact relative to the same run without.
pub const POUNDING: f64 = 2.0;

/// Estimated work of one free run of `p` (no contact).
pub fn free_run(p: &Params) -> f64 {
    match p.method {
        Method::Newmark => p.tau_end() / p.dt,
        Method::Exact => p.tau_end() * (1.0 + p.omega1.max(p.omega2)),
    }
}

/// Estimated work of `p`'s own run in a sweep: a run with contact where
/// the gap is finite, nothing else (its baseline is counted per key).
pub fn pounding_run(p: &Params) -> f64 {
    if p.pounding() {
        POUNDING * free_run(p)
    } else {
        0.0
    }
}

/// Estimated seconds of one run of a row of buildings (SPEC §13) with
/// `floors` floors in all (n), over `duration` seconds of ground motion and
/// tail: an order of magnitude, as [`seconds`] is.
/// - The exact method takes sub-steps of one radian of the fastest mode,
///   each a dense map of the 2n-state: about 6.4 µs × n² per second
///   (block-and-frame, n = 11: 11.4 ms for 14.6 s; three-in-series, n = 17,
///   0.9 ms a second, half that), and a matrix exponential of the 2n-state
///   per configuration, (2n)³ operations at about a nanosecond, two at least.
/// - Newmark at step Δt (`newmark_step`) takes duration/Δt steps, each a
///   Newton solve of the dense n-system: about 12 ns × n² on small rows
///   (block-and-frame: 430 ms for 292 000 steps; three-in-series: 3.4 s for
///   900 000), and its LU's n³/3 operations on tall ones.
/// - A fluid viscous damper (a link with α < 1, SPEC §14) makes the exact
///   method take series steps with its force in them and collocated steps
///   (the force at the Radau IIA nodes) for the whole run, never a map:
///   [`FLUID_DAMPER_EXACT`] times the linear row's map.
///   Newmark's mixed step costs about the same with or without one.
pub fn row_seconds(row: &Row, duration: f64, newmark_step: Option<f64>) -> f64 {
    let n = row.dofs() as f64;
    match newmark_step {
        None => {
            let factor = if row.has_fluid_damper() {
                FLUID_DAMPER_EXACT
            } else {
                1.0
            };
            factor * (6.4e-6 * n * n * duration + 2.0 * 1e-9 * (2.0 * n).powi(3))
        }
        Some(dt) => duration / dt * (1.24e-8 * n * n + 3.3e-10 * n.powi(3)),
    }
}

/// How many times the exact method's cost a row with a fluid viscous
/// damper takes: block-and-frame-retrofit with `link1.exponent = 0.35`
/// ran 202–214 ms under `synthetic:2000` against the bare row's 7.3–9.8 ms
/// side by side (21–28×), and 1.24 s under a 30 s sine (3 m/s², ω = 6)
/// against 36–43 ms (29–34×); rounded up to 35. The damper's step control
/// became honest since (its estimate bounds the local error), and the
/// same row now runs 272–310 ms against 6.6–7.2 ms (38–47×, `cargo bench
/// --bench row_speed`): still below 35 times the estimate of the bare row
/// (35 × 11.3 ms = 396 ms), whose 6.4 µs × n² per second is 1.7 times what
/// the bare row now takes. Since the damper's force rides inside the Taylor
/// series wherever it is analytic and not stiff, the same bench gives 12.9–25.0×
/// (median 17.8×, five rounds interleaved with the build before it, which
/// gave 21.6–31.7×, median 27.0×), and the 30 s sine 0.75–0.80 s against
/// 1.10–1.32 s before (a bare run 40–60 ms by the command line); with its
/// steps up to six relaxation times of the damper, 15.6–16.2× (three
/// rounds). With the series not filled where the damper's relaxation
/// time already rules it out, and the force's coefficients kept from the
/// fill, 10.7–11.0× (median 10.8×, five rounds interleaved with the build
/// before, which gave 15.5–15.8×); but under a 60 s sine (3 m/s², ω = 6,
/// 171 impacts) the run takes 1.50 s against the bare row's 70 ms (21×)
/// in improved Kelvin contact, whose closed pairs are collocated with the
/// damper, and 0.58 s against 51 ms (11×) in Kelvin contact: 25 keeps
/// the largest with room.
pub const FLUID_DAMPER_EXACT: f64 = 25.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::buildings::load_with;

    fn retrofit(exponent: &str) -> Row {
        let set = format!("link1.exponent={exponent}");
        load_with("block-and-frame-retrofit", &[set]).expect("the shipped retrofit row")
    }

    /// A fluid viscous damper multiplies the exact method's estimate by
    /// [`FLUID_DAMPER_EXACT`] and leaves Newmark's as it is, so that the
    /// `--allow-long` guard sees the Radau steps such a run takes.
    #[test]
    fn a_fluid_damper_raises_the_exact_estimate_only() {
        let (linear, fluid) = (retrofit("1.0"), retrofit("0.35"));
        let exact = |row: &Row| row_seconds(row, 30.0, None);
        let newmark = |row: &Row| row_seconds(row, 30.0, Some(1e-3));
        assert!((exact(&fluid) / exact(&linear) - FLUID_DAMPER_EXACT).abs() < 1e-12);
        assert_eq!(newmark(&fluid), newmark(&linear));
        // block-and-frame: n = 11 floors, 6.4 µs × n² a second plus two
        // exponentials of the 22-state.
        let expected = 6.4e-6 * 121.0 * 30.0 + 2.0 * 1e-9 * 22f64.powi(3);
        assert!((exact(&linear) - expected).abs() < 1e-15);
    }
}
