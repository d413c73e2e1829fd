//! The estimated work of a run, for dealing a sweep's units to shards.
//!
//! Only the ratios between the units of one sweep matter. A Newmark run
//! takes τ_end/Δτ steps whatever the frequencies; an exact run takes a few
//! closed-form segments per excitation cycle and per half-period of the
//! stiffer structure, so its work grows as τ_end · (1 + max(Π_ω1, Π_ω2)).
//! Measured on set 1 (exact, 8 cycles, no contact, `run --repeat`): 78,
//! 130, 357 and 1189 segments at Π_ω2 = 0.68, 2.25, 6.75 and 22.5, against
//! 84, 162, 387 and 1175 by this rule; the time follows the segments. A run
//! with contact (finite gap) counts [`POUNDING`] times a free run: set 1's
//! nine impacts at Π_ω1 = 1 double its time (0.10 against 0.05 ms).

use crate::model::{Method, Params};

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
