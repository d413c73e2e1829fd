//! The estimated work of a run, for dealing a sweep's units to shards.
//!
//! Only the ratios between the units of one sweep matter. A Newmark run
//! takes τ_end/Δτ steps whatever the frequencies; an exact run takes a few
//! closed-form segments per half-period of the stiffer structure, so its
//! work grows with τ_end · max(1, Π_ω1, Π_ω2). A run with contact (finite
//! gap) counts [`POUNDING`] times a free run: its impacts add contact
//! phases, located roots and, with Newmark, sub-steps.

use crate::model::{Method, Params};

/// Work of a run with contact relative to the same run without.
pub const POUNDING: f64 = 2.0;

/// Estimated work of one free run of `p` (no contact).
pub fn free_run(p: &Params) -> f64 {
    match p.method {
        Method::Newmark => p.tau_end() / p.dt,
        Method::Exact => p.tau_end() * p.omega1.max(p.omega2).max(1.0),
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
