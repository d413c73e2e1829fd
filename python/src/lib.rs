//! The Python module `pounding._native`: one function per command of the
//! command line, each a thin layer over the command's own code.
//!
//! A function turns its keyword arguments into the command's argument
//! struct through the command line's own parser ([`args`]), runs the
//! command's report builder without the GIL, and serializes the command's
//! typed report (the one the command line prints as JSON) straight into
//! Python objects: the values are the JSON's by construction. Lists of
//! points, cells and records then become numpy arrays ([`convert`]).
//! Errors become Python exceptions in one place ([`error`]).

mod args;
mod convert;
mod error;

use std::cell::RefCell;

use numpy::PyArray1;
use pounding::cli::output::Emit;
use pounding::cli::{self as commands, CliError};
use pounding::model::params::{FIELDS, Group, Kind};
use pounding::model::preset;
use pounding::model::target_spectrum::TargetSpectrum;
use pounding::solver::{FullHistory, solve};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use args::parse;
use convert::{columns_at, each, tuples_to_lists};
use error::{Failure, guarded};

thread_local! {
    static RUN: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
    static SPECTRUM: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
    static MAP: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
    static GAP: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
    static SUITE: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
    static IDA: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
    static SCALE: RefCell<Option<clap::Command>> = const { RefCell::new(None) };
}

/// The report of `command` as Python objects. The command runs without the
/// GIL (other Python threads go on; its batches use rayon's threads) and
/// takes it back only to hand its report over. A report handed over before
/// the command failed (an unreliable run) still fails the call.
fn emitted<F>(py: Python<'_>, command: F) -> Result<Py<PyAny>, Failure>
where
    F: FnOnce(&mut dyn FnMut(&dyn Emit) -> Result<(), CliError>) -> Result<(), CliError> + Send,
{
    let mut report: Option<Result<Py<PyAny>, Failure>> = None;
    py.detach(|| {
        guarded(|| {
            let mut emit = |r: &dyn Emit| {
                pounding::cli::output::finite(r)?;
                report = Some(Python::attach(|py| {
                    let value = pythonize::pythonize(py, r)
                        .map_err(|e| Failure::Failed(format!("to Python: {e}")))?;
                    tuples_to_lists(&value)?;
                    Ok(value.unbind())
                }));
                Ok(())
            };
            Ok(command(&mut emit)?)
        })
    })?;
    report.unwrap_or_else(|| Err(Failure::Failed("the command reported nothing".into())))
}

/// `pounding run`: one simulation's summary, as `run --format json` gives
/// it; with `history`, every accepted state as numpy arrays under `history`.
#[pyfunction]
#[pyo3(signature = (*, history = false, **kwargs))]
fn run(py: Python<'_>, history: bool, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let mut args: commands::run::RunArgs = parse(&RUN, "run", kwargs)?;
    args.history = None;
    let report = emitted(py, |emit| commands::run::report_with(&args, |r| emit(r)))?;
    if history {
        let samples = py.detach(|| {
            guarded(|| {
                let (_, p) = args.params.resolve()?;
                let mut full = FullHistory::with_capacity((p.tau_end() / p.dt) as usize + 16);
                solve(&p, &mut full);
                Ok((full.samples, p.ground()))
            })
        })?;
        let (samples, ground) = samples;
        let h = PyDict::new(py);
        let channel = |f: &dyn Fn(&pounding::solver::Sample) -> f64| -> Vec<f64> {
            samples.iter().map(f).collect()
        };
        h.set_item("tau", PyArray1::from_vec(py, channel(&|s| s.tau)))?;
        for (i, name) in pounding::solver::observer::CHANNEL_NAMES.iter().enumerate() {
            h.set_item(*name, PyArray1::from_vec(py, channel(&|s| s.channels()[i])))?;
        }
        let contact: Vec<bool> = samples.iter().map(|s| s.in_contact).collect();
        h.set_item("in_contact", PyArray1::from_vec(py, contact))?;
        for (i, name) in pounding::solver::observer::GROUND_NAMES.iter().enumerate() {
            h.set_item(
                *name,
                PyArray1::from_vec(py, channel(&|s| ground.ground(s.tau)[i])),
            )?;
        }
        report.bind(py).set_item("history", h)?;
    }
    Ok(report)
}

/// `pounding spectrum`: each curve's points as columns of numpy arrays over
/// Π_ω1; with one curve (no family), its columns also at the top.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn spectrum(py: Python<'_>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let args: commands::spectrum::SpectrumArgs = parse(&SPECTRUM, "spectrum", kwargs)?;
    let report = emitted(py, |emit| {
        commands::spectrum::report_with(&args, |r| emit(r))
    })?;
    let dict = report.bind(py).cast::<PyDict>()?;
    let curves = each(dict, "curves")?;
    for curve in &curves {
        columns_at(curve, "points", None)?;
    }
    if let [curve] = curves.as_slice()
        && let Some(points) = curve.get_item("points")?
    {
        for (k, v) in points.cast::<PyDict>()?.iter() {
            dict.set_item(k, v)?;
        }
    }
    Ok(report)
}

/// `pounding map`: the cells as columns, each numeric one a numpy array of
/// shape (y points, x points); with `suite`, the map of P(pounding) and the
/// median amplification over two physical quantities.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn map(py: Python<'_>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let args: commands::map::MapArgs = parse(&MAP, "map", kwargs)?;
    let report = emitted(py, |emit| commands::map::report_with(&args, |r| emit(r)))?;
    let dict = report.bind(py).cast::<PyDict>()?;
    let points = |axis: &str| -> PyResult<usize> {
        // A Π axis says how many points it has; a suite's physical axis lists its values.
        match dict.get_item(axis)? {
            Some(a) => match a.get_item("points") {
                Ok(n) => n.extract(),
                Err(_) => a.get_item("values")?.len(),
            },
            None => Ok(0),
        }
    };
    let shape = [points("y")?, points("x")?];
    columns_at(dict, "cells", Some(shape))?;
    Ok(report)
}

/// `pounding gap`: the points as columns (over the axis with `x`); with
/// `suite`, the separation of a suite's buildings, its records as columns.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn gap(py: Python<'_>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let args: commands::gap::GapArgs = parse(&GAP, "gap", kwargs)?;
    let report = emitted(py, |emit| commands::gap::report_with(&args, |r| emit(r)))?;
    let dict = report.bind(py).cast::<PyDict>()?;
    columns_at(dict, "points", None)?;
    columns_at(dict, "records", None)?;
    Ok(report)
}

/// `pounding suite`: the records as columns.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn suite(py: Python<'_>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let args: commands::suite::SuiteArgs = parse(&SUITE, "suite", kwargs)?;
    let report = emitted(py, |emit| commands::suite::report_with(&args, |r| emit(r)))?;
    columns_at(report.bind(py).cast::<PyDict>()?, "records", None)?;
    Ok(report)
}

/// `pounding ida`: each level's records as columns, then the levels as
/// columns; each limit state's counts over the levels as columns.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn ida(py: Python<'_>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let args: commands::ida::IdaArgs = parse(&IDA, "ida", kwargs)?;
    let report = emitted(py, |emit| commands::ida::report_with(&args, |r| emit(r)))?;
    let dict = report.bind(py).cast::<PyDict>()?;
    for level in each(dict, "levels")? {
        columns_at(&level, "records", None)?;
    }
    columns_at(dict, "levels", None)?;
    for state in each(dict, "fragility")? {
        columns_at(&state, "counts", None)?;
        columns_at(&state, "no_pounding_counts", None)?;
    }
    Ok(report)
}

/// `pounding records scale`: a suite's records scaled to a target spectrum
/// by the code's rule, as `records scale --format json` gives it, whether
/// or not the rule holds (`check.holds` says); the records as columns.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn records_scale(py: Python<'_>, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Py<PyAny>> {
    let args: commands::records_scale::ScaleArgs = parse(&SCALE, "records scale", kwargs)?;
    let report = emitted(py, |emit| {
        commands::records_scale::scaled(&args, |r| emit(r)).map(|_| ())
    })?;
    columns_at(report.bind(py).cast::<PyDict>()?, "records", None)?;
    Ok(report)
}

/// Sa (g) of the target spectrum `target` (`asce7:…`, `asce7-mce:…`,
/// `ec8:…`, `file:PATH`) at each of `periods` (s).
#[pyfunction]
fn target_spectrum<'py>(
    py: Python<'py>,
    target: &str,
    periods: Vec<f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let spectrum =
        TargetSpectrum::parse(target).map_err(|e| Failure::Usage(format!("target {e}")))?;
    let (first, last) = spectrum.periods();
    let values = periods
        .iter()
        .map(|&t| {
            spectrum.sa(t).ok_or_else(|| {
                Failure::Usage(format!(
                    "periods: {t} s is outside the target's periods {first}–{last} s"
                ))
            })
        })
        .collect::<Result<Vec<f64>, Failure>>()?;
    Ok(PyArray1::from_vec(py, values))
}

/// The built-in presets: name and description of each.
#[pyfunction]
fn presets(py: Python<'_>) -> PyResult<Py<PyList>> {
    let list = PyList::empty(py);
    for p in preset::builtins() {
        let d = PyDict::new(py);
        d.set_item("name", &p.name)?;
        d.set_item("description", &p.description)?;
        d.set_item("physical", p.physical.is_some())?;
        list.append(d)?;
    }
    Ok(list.unbind())
}

/// The parameter table: every key with its symbol, meaning, group, range
/// and default (set 1's value, the default preset's).
#[pyfunction]
fn parameter_table(py: Python<'_>) -> PyResult<Py<PyList>> {
    let set1 = pounding::model::SET1;
    let list = PyList::empty(py);
    for f in FIELDS {
        let d = PyDict::new(py);
        d.set_item("key", f.key)?;
        d.set_item("symbol", f.symbol)?;
        d.set_item("ascii", f.ascii)?;
        d.set_item("meaning", f.meaning)?;
        d.set_item(
            "group",
            match f.group {
                Group::Pi => "pi",
                Group::Setting => "setting",
            },
        )?;
        d.set_item("range", f.range())?;
        d.set_item("allowed", f.allowed())?;
        match f.kind {
            Kind::Number {
                min, max, inf, get, ..
            } => {
                d.set_item("kind", "number")?;
                d.set_item("min", min)?;
                d.set_item("max", max)?;
                d.set_item("inf", inf)?;
                d.set_item("default", get(&set1))?;
            }
            Kind::Integer { min, max, get, .. } => {
                d.set_item("kind", "integer")?;
                d.set_item("min", min)?;
                d.set_item("max", max)?;
                d.set_item("inf", false)?;
                d.set_item("default", get(&set1))?;
            }
            Kind::Choice { names, get, .. } => {
                d.set_item("kind", "choice")?;
                d.set_item("choices", names.to_vec())?;
                d.set_item("default", get(&set1))?;
            }
        }
        list.append(d)?;
    }
    Ok(list.unbind())
}

/// `n` runs of `pounding.run(**kwargs)`'s work inside Rust (arguments
/// parsed once, each run's typed report built and dropped): the time in
/// seconds, against which the cost of calling from Python is measured.
#[pyfunction]
#[pyo3(signature = (n, **kwargs))]
fn _run_in_rust(py: Python<'_>, n: u32, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<f64> {
    let args: commands::run::RunArgs = parse(&RUN, "run", kwargs)?;
    let seconds = py.detach(|| {
        guarded(|| {
            let start = std::time::Instant::now();
            for _ in 0..n {
                commands::run::report_with(&args, |r| {
                    std::hint::black_box(r);
                    Ok(())
                })?;
            }
            Ok(start.elapsed().as_secs_f64())
        })
    })?;
    Ok(seconds)
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(map, m)?)?;
    m.add_function(wrap_pyfunction!(gap, m)?)?;
    m.add_function(wrap_pyfunction!(suite, m)?)?;
    m.add_function(wrap_pyfunction!(ida, m)?)?;
    m.add_function(wrap_pyfunction!(records_scale, m)?)?;
    m.add_function(wrap_pyfunction!(target_spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(parameter_table, m)?)?;
    m.add_function(wrap_pyfunction!(_run_in_rust, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
