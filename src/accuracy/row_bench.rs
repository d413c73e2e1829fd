//! Work-precision rows for a row of buildings (SPEC §13): each method's
//! error against the independent reference ([`crate::reference::row`]) and
//! its time per run, best of repeated runs after a warm-up.
//!
//! The error is the largest difference over every floor of the peaks |u|,
//! |u̇| and |Δ|, each relative to its building's largest peak of that kind;
//! the acceleration error is the same for the peak absolute floor
//! accelerations |ü + ü_g| (SPEC §13), kept apart because contact spikes
//! make them the hardest peaks to resolve.

use std::time::Instant;

use serde::Serialize;

use crate::model::buildings::{Ground, Row};
use crate::reference::row::{RowReference, reference_row};
use crate::solver::buildings::{RowError, RowOptions, RowRun, default_step, run_newmark, run_row};

/// Tolerance of the reference the rows are measured against.
pub const REFERENCE_TOLERANCE: f64 = 1e-13;
/// Newmark steps of the table (s).
pub const NEWMARK_STEPS: [f64; 4] = [4e-4, 2e-4, 1e-4, 5e-5];

#[derive(Debug, Clone, Serialize)]
pub struct RowBenchRow {
    pub method: String,
    /// Δt (s) for Newmark, the tolerance for the reference, 0 for exact.
    pub setting: f64,
    pub error: f64,
    /// Largest relative difference of the peak floor accelerations.
    pub acceleration_error: f64,
    pub ms: f64,
    pub impacts: usize,
    /// Impact counts equal to the reference's at every floor pair.
    pub impacts_match: bool,
}

/// A building's largest peak of one kind (never 0, so that it divides).
fn top(v: &[f64]) -> f64 {
    v.iter()
        .fold(0.0f64, |m, x| m.max(*x))
        .max(f64::MIN_POSITIVE)
}

/// Largest difference of the peak floor accelerations of `run` from
/// `reference`, relative to each building's largest.
pub fn acceleration_error(run: &RowRun, reference: &RowReference) -> f64 {
    let mut worst = 0.0f64;
    for (b, floors) in run.floors.iter().enumerate() {
        let scale = top(&reference.absolute_acceleration[b]);
        for (f, a) in floors.iter().zip(&reference.absolute_acceleration[b]) {
            worst = worst.max((f.absolute_acceleration - a).abs() / scale);
        }
    }
    worst
}

/// Largest relative peak difference of `run` from `reference`.
pub fn peak_error(run: &RowRun, reference: &RowReference) -> f64 {
    let mut worst = 0.0f64;
    for (b, floors) in run.floors.iter().enumerate() {
        let (su, sv, sd) = (
            top(&reference.displacement[b]),
            top(&reference.velocity[b]),
            top(&reference.drift[b]),
        );
        for (i, f) in floors.iter().enumerate() {
            worst = worst
                .max((f.displacement - reference.displacement[b][i]).abs() / su)
                .max((f.velocity - reference.velocity[b][i]).abs() / sv)
                .max((f.drift - reference.drift[b][i]).abs() / sd);
        }
    }
    worst
}

/// Best time (ms) of `repeat` runs after one warm-up, and the last result.
fn best<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut out = f();
    let mut best = f64::INFINITY;
    for _ in 0..repeat {
        let t = Instant::now();
        out = f();
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
    }
    (best, out)
}

/// The reference, the exact method, and Newmark at [`NEWMARK_STEPS`] and
/// at its default step ([`default_step`]).
pub fn row_bench(row: &Row, ground: &Ground, duration: f64) -> Result<Vec<RowBenchRow>, RowError> {
    let t = Instant::now();
    let reference = reference_row(row, ground, duration, REFERENCE_TOLERANCE);
    let reference_ms = t.elapsed().as_secs_f64() * 1e3;
    let counts = |r: &RowRun| r.pairs.iter().map(|p| p.impacts.len()).collect::<Vec<_>>();
    let mut rows = vec![RowBenchRow {
        method: "reference".into(),
        setting: REFERENCE_TOLERANCE,
        error: 0.0,
        acceleration_error: 0.0,
        ms: reference_ms,
        impacts: reference.impacts.iter().sum(),
        impacts_match: true,
    }];
    let options = RowOptions::lasting(duration);
    let (ms, exact) = best(10, || run_row(row, ground, &options));
    let exact = exact?;
    rows.push(RowBenchRow {
        method: "exact".into(),
        setting: 0.0,
        error: peak_error(&exact, &reference),
        acceleration_error: acceleration_error(&exact, &reference),
        ms,
        impacts: exact.impacts(),
        impacts_match: counts(&exact) == reference.impacts,
    });
    // The fixed steps, and the default step of this run's length.
    let default = default_step(row, duration, ground);
    let steps = NEWMARK_STEPS
        .into_iter()
        .chain((!NEWMARK_STEPS.contains(&default)).then_some(default));
    for dt in steps {
        let (ms, nm) = best(2, || run_newmark(row, ground, duration, dt));
        let nm = nm?;
        rows.push(RowBenchRow {
            method: "newmark".into(),
            setting: dt,
            error: peak_error(&nm, &reference),
            acceleration_error: acceleration_error(&nm, &reference),
            ms,
            impacts: nm.impacts(),
            impacts_match: counts(&nm) == reference.impacts,
        });
    }
    Ok(rows)
}
