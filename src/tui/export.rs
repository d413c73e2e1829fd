//! `e`: a run's history as CSV, streamed to its file by the rules of
//! [`crate::output`] (atomic for a regular file, nothing kept in memory):
//! the full history (the columns of `pounding run --history`) or the
//! decimated one on screen (per bucket, the minimum and maximum of each
//! channel).

use std::io::Write;
use std::path::Path;

use super::trace::Trace;
use crate::model::Params;
use crate::output::{Num, OutputError, Target};
use crate::solver::observer::CHANNEL_NAMES;
use crate::solver::{CsvHistory, solve};

/// Which history an export writes.
#[derive(Debug, Clone, PartialEq)]
pub enum History {
    /// Every step of the run, as `pounding run --history`.
    Full,
    /// The decimated history on screen: per bucket, minimum and maximum.
    Shown(Box<Trace>),
}

/// Approximate bytes of one row of the full history CSV (ten numbers).
pub const BYTES_PER_ROW: f64 = 190.0;

/// Rows of the full history: one per output step Δτ, and τ = 0.
pub fn full_rows(p: &Params) -> u64 {
    (p.tau_end() / p.dt).floor() as u64 + 1
}

/// The full history's size in bytes, about.
pub fn full_bytes(p: &Params) -> f64 {
    full_rows(p) as f64 * BYTES_PER_ROW
}

/// A size for people: `820 KB`, `10.2 MB`.
pub fn size_text(bytes: f64) -> String {
    if bytes < 1e6 {
        format!("{:.0} KB", (bytes / 1e3).max(1.0))
    } else {
        format!("{:.1} MB", bytes / 1e6)
    }
}

/// Writes the full history of `params` to `path`; the status message.
pub fn write(params: &Params, path: &Path) -> String {
    write_history(params, path, &History::Full)
}

/// Writes the chosen history to `path`; the status message.
pub fn write_history(params: &Params, path: &Path, history: &History) -> String {
    let result = match history {
        History::Full => stream(params, path),
        History::Shown(trace) => shown(trace, path),
    };
    match result {
        Ok(rows) => format!("exported {} ({rows} rows)", crate::output::shown(path)),
        Err(e) => format!("could not export: {e}"),
    }
}

fn stream(params: &Params, path: &Path) -> Result<u64, OutputError> {
    let target = Target::open(path)?;
    let mut csv = CsvHistory::with_ground(target, params.ground());
    // The set's own method and excitation, as in the explorer's run.
    solve(params, &mut csv);
    match csv.finish() {
        Ok((target, rows)) => target.commit().map(|()| rows),
        Err((target, e)) => Err(target.error(&e)),
    }
}

fn shown(trace: &Trace, path: &Path) -> Result<u64, OutputError> {
    let mut target = Target::open(path)?;
    let mut rows = 0;
    let mut body = || -> std::io::Result<()> {
        write!(target, "tau")?;
        for name in CHANNEL_NAMES {
            write!(target, ",{name}_min,{name}_max")?;
        }
        writeln!(target)?;
        for s in trace.filled() {
            write!(target, "{}", Num(s.tau))?;
            for k in 0..CHANNEL_NAMES.len() {
                write!(target, ",{},{}", Num(s.min[k]), Num(s.max[k]))?;
            }
            writeln!(target)?;
            rows += 1;
        }
        Ok(())
    };
    match body() {
        Ok(()) => target.commit().map(|()| rows),
        Err(e) => Err(target.error(&e)),
    }
}
