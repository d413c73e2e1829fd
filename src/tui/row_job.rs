//! The buildings scene's computation: the row under its ground motion with
//! pounding, under each contact law shown (its own, and the other of the
//! Kelvin pair side by side), each with its trace for drawing, and once
//! with every joint open (d = ∞), peaks only, for the envelopes without
//! pounding (SPEC §13); and, only when the scene shows it, the row without
//! its retrofits (SPEC §14), with pounding under its own law, peaks only.
//! The runs are independent and go in parallel.

use std::sync::Arc;
use std::time::Instant;

use rayon::prelude::*;

use crate::analysis::work;
use crate::model::ContactModel;
use crate::model::buildings::{Ground, Row};
use crate::solver::buildings::{RowOptions, RowRun, run_row};

/// Longest estimated run the explorer starts (s): beyond it the pane refuses
/// the edit, so the screen never waits on a run it cannot cancel.
pub const MAX_SECONDS: f64 = 2.0;

/// The row to run: its buildings, ground and length, and the laws shown.
#[derive(Debug, Clone, PartialEq)]
pub struct RowSpec {
    pub row: Row,
    pub ground: Arc<Ground>,
    /// The run's length (s): the ground's and a free tail.
    pub duration: f64,
    /// The contact laws run with pounding, the row's own first.
    pub laws: Vec<ContactModel>,
    /// Also run the row without its bumpers and links ([`Row::bare`]).
    pub bare: bool,
}

impl RowSpec {
    /// Estimated wall time of the whole job (s), by [`work::row_seconds`]:
    /// each law's run and the run apart on the row, and the bare row's run
    /// without its retrofit (no fluid damper to pay for).
    pub fn seconds(&self) -> f64 {
        let bare = if self.bare {
            work::row_seconds(&self.row.bare(), self.duration, None)
        } else {
            0.0
        };
        (self.laws.len() + 1) as f64 * work::row_seconds(&self.row, self.duration, None) + bare
    }
}

/// The runs of one spec.
#[derive(Debug, Clone)]
pub struct RowOutput {
    pub spec: RowSpec,
    /// One run a law of `spec.laws`, in that order, each with its trace.
    pub runs: Vec<RowRun>,
    /// Every joint open: the response without pounding.
    pub free: RowRun,
    /// The row without its retrofits, with pounding, when asked for.
    pub bare: Option<RowRun>,
    /// Wall time of the job (ms).
    pub elapsed_ms: f64,
}

impl RowOutput {
    /// The run under `law`, when it was asked for.
    pub fn run(&self, law: ContactModel) -> Option<&RowRun> {
        let k = self.spec.laws.iter().position(|&l| l == law)?;
        self.runs.get(k)
    }
}

/// Runs a spec: the laws with their traces and the open row, in parallel.
/// An error is the solver's one line.
pub fn run(spec: &RowSpec) -> Result<RowOutput, String> {
    let start = Instant::now();
    let mut open = spec.row.clone();
    for j in &mut open.joints {
        j.gap = f64::INFINITY;
    }
    let mut cases: Vec<(Row, bool)> = spec
        .laws
        .iter()
        .map(|&law| {
            let mut row = spec.row.clone();
            row.model = law;
            (row, true)
        })
        .collect();
    cases.push((open, false));
    if spec.bare {
        cases.push((spec.row.bare(), false));
    }
    let runs: Result<Vec<RowRun>, String> = cases
        .par_iter()
        .map(|(row, trace)| {
            let options = RowOptions {
                trace: *trace,
                ..RowOptions::lasting(spec.duration)
            };
            run_row(row, &spec.ground, &options).map_err(|e| e.to_string())
        })
        .collect();
    let mut runs = runs?;
    let bare = if spec.bare { runs.pop() } else { None };
    let free = runs.pop().expect("the open row's run");
    Ok(RowOutput {
        spec: spec.clone(),
        runs,
        free,
        bare,
        elapsed_ms: start.elapsed().as_secs_f64() * 1e3,
    })
}
