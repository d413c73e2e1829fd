//! `e`: the active run's full history as CSV (the columns of
//! `pounding run --history`), written atomically.

use std::path::Path;

use crate::model::Params;
use crate::model::preset::write_atomic;
use crate::solver::{FullHistory, SolverOptions, simulate};

/// Runs `params` with a full history and writes it to `path`; the status message.
pub fn write(params: &Params, path: &Path) -> String {
    let steps = (params.tau_end() / params.dt).ceil() as usize + 1;
    let mut history = FullHistory::with_capacity(steps.min(1 << 24));
    simulate(params, &SolverOptions::default(), &mut history);
    match write_atomic(path, history.to_csv().as_bytes()) {
        Ok(()) => format!(
            "exported {} ({} rows)",
            path.display(),
            history.samples.len()
        ),
        Err(e) => format!("could not write {}: {e}", path.display()),
    }
}
