//! Every failure of the module becomes a Python exception here, and only
//! here: bad input (the command line's exit 2) is `ValueError` with the
//! command line's one-line message, a failed run (exit 1) `RuntimeError`,
//! and a panic in the core is caught before it reaches Python.

use std::panic::{AssertUnwindSafe, catch_unwind};

use pounding::cli::CliError;
use pyo3::PyErr;
use pyo3::exceptions::{PyRuntimeError, PyValueError};

/// Why a call failed, as the command line would have exited.
#[derive(Debug)]
pub enum Failure {
    /// Bad input: the command line's message, exit code 2.
    Usage(String),
    /// A failed run or check: exit code 1.
    Failed(String),
    /// Python's own error while converting (it is raised as it is).
    Python(PyErr),
}

impl From<CliError> for Failure {
    fn from(e: CliError) -> Self {
        // One line, as the command line prints it after `error: `.
        let line = e.to_string().replace(['\n', '\r'], " ");
        match e {
            CliError::Usage(_) => Failure::Usage(line),
            CliError::Failed(_) | CliError::BrokenPipe => Failure::Failed(line),
        }
    }
}

impl From<clap::Error> for Failure {
    /// Clap's usage error: its first line, as the command line prints it,
    /// without the `error: ` that the command line puts before every message.
    fn from(e: clap::Error) -> Self {
        let text = e.render().to_string();
        let line = text.lines().next().unwrap_or("error: bad arguments");
        Failure::Usage(line.strip_prefix("error: ").unwrap_or(line).to_string())
    }
}

impl From<PyErr> for Failure {
    fn from(e: PyErr) -> Self {
        Failure::Python(e)
    }
}

impl From<Failure> for PyErr {
    fn from(f: Failure) -> PyErr {
        match f {
            Failure::Usage(m) => PyValueError::new_err(m),
            Failure::Failed(m) => PyRuntimeError::new_err(m),
            Failure::Python(e) => e,
        }
    }
}

/// Runs `work` with a panic turned into a `RuntimeError` naming it, so
/// that a bug in the core never unwinds into the interpreter.
pub fn guarded<T>(work: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    catch_unwind(AssertUnwindSafe(work)).unwrap_or_else(|panic| {
        let why = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown cause".into());
        Err(Failure::Failed(format!("internal error (a bug): {why}")))
    })
}
