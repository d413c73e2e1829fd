//! The work-precision table of `pounding bench`: for one parameter
//! set, each method at several Δτ (Newmark) or tolerances (reference), with
//! its median time per run and its maximum relative peak error against the
//! reference at [`TRUTH_TOLERANCE`].
//!
//! The observed order between successive Δτ of one method is
//! log(e_coarse/e_fine) / log(Δτ_coarse/Δτ_fine) (≈ 2 for average acceleration).

use serde::Serialize;

use super::method::{Method, max_relative_error};
use super::timing::median_ms;
use crate::model::Params;
use crate::reference::{ReferenceOptions, reference};

/// Time steps of the Newmark rows, coarse to fine.
pub const STEPS: [f64; 4] = [0.004, 0.002, 0.001, 0.0005];
/// Contact tolerances of the exact rows, loose to tight.
pub const EXACT_TOLERANCES: [f64; 3] = [1e-8, 1e-11, 1e-14];
/// Tolerances of the reference rows, loose to tight.
pub const TOLERANCES: [f64; 5] = [1e-7, 1e-8, 1e-9, 1e-10, 1e-11];
/// The tolerance of the solution every error is measured against
/// (it agrees with 1e-13 to about 1e-13 on both presets).
pub const TRUTH_TOLERANCE: f64 = 1e-14;

/// The accuracy and speed Newmark's default scheme is held to at the
/// paper's Δτ = 0.001: peaks within 1e-5 of the reference, a set-1 run in 2 ms.
pub const TARGET_ERROR: f64 = 1e-5;
pub const TARGET_MS_SET1: f64 = 2.0;

/// One row of the table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    pub preset: String,
    pub model: String,
    pub method: &'static str,
    /// Δτ of a Newmark row (None for the reference).
    pub dt: Option<f64>,
    /// Tolerance of a reference row (None for Newmark).
    pub tolerance: Option<f64>,
    pub ms_per_run: f64,
    pub max_rel_error: f64,
    /// Observed order against the previous (coarser) Δτ of the same method.
    pub order: Option<f64>,
}

/// Every row for one parameter set (its `model` already chosen).
pub fn rows(preset: &str, p: &Params) -> Vec<Row> {
    let truth = reference(p, &ReferenceOptions::with_tolerance(TRUTH_TOLERANCE)).peaks;
    let mut out = Vec::new();
    let mut row = |method: Method, q: &Params, dt, tolerance, order_from: Option<(f64, f64)>| {
        let (ms, peaks) = median_ms(|| method.peaks(q));
        let error = max_relative_error(peaks, truth);
        let order = order_from.and_then(|(prev_dt, prev_err)| {
            let o = (prev_err / error).ln() / (prev_dt / q.dt).ln();
            o.is_finite().then_some(o)
        });
        out.push(Row {
            preset: preset.to_string(),
            model: p.model.name().to_string(),
            method: method.name(),
            dt,
            tolerance,
            ms_per_run: ms,
            max_rel_error: error,
            order,
        });
        error
    };
    for method in Method::NEWMARK {
        let mut previous = None;
        for dt in STEPS {
            let q = Params { dt, ..p.clone() };
            let error = row(method, &q, Some(dt), None, previous);
            previous = Some((dt, error));
        }
    }
    for tol in EXACT_TOLERANCES {
        row(Method::Exact(tol), p, None, Some(tol), None);
    }
    for tol in TOLERANCES {
        row(Method::Reference(tol), p, None, Some(tol), None);
    }
    out
}

/// Whether a row at Δτ = 0.001 meets [`TARGET_ERROR`] and [`TARGET_MS_SET1`] (the time target
/// applies to set 1 only).
pub fn meets_target(row: &Row) -> Option<bool> {
    (row.dt == Some(0.001)).then(|| {
        row.max_rel_error <= TARGET_ERROR
            && (row.preset != "set1" || row.ms_per_run <= TARGET_MS_SET1)
    })
}
