//! `e`: the active run's full history as CSV (the columns of
//! `pounding run --history`), streamed to its file by the rules of
//! [`crate::output`] (atomic for a regular file, nothing kept in memory).

use std::path::Path;

use crate::model::Params;
use crate::output::{OutputError, Target};
use crate::solver::CsvHistory;

/// Runs `params`, streaming its history to `path`; the status message.
pub fn write(params: &Params, path: &Path) -> String {
    match stream(params, path) {
        Ok(rows) => format!("exported {} ({rows} rows)", path.display()),
        Err(e) => format!("could not export: {e}"),
    }
}

fn stream(params: &Params, path: &Path) -> Result<u64, OutputError> {
    let target = Target::open(path)?;
    let mut csv = CsvHistory::new(target);
    // The set's own method and excitation, as in the explorer's run.
    crate::solver::solve(params, &mut csv);
    match csv.finish() {
        Ok((target, rows)) => target.commit().map(|()| rows),
        Err((target, e)) => Err(target.error(&e)),
    }
}
