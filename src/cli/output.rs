//! Output formats shared by the commands: a table for people, JSON and CSV
//! for scripts, each written by one writer from the command's typed report
//! (see [`crate::output::report`]).

use clap::{Args, ValueEnum};

use super::CliError;
use crate::model::Params;
use crate::model::params::FIELDS;
use crate::output::Num;
use crate::output::report::{self, Report};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum Format {
    /// Aligned columns for people.
    #[default]
    Table,
    /// Exactly one JSON object on stdout.
    Json,
    /// A header row, then one row per record.
    Csv,
}

/// `--format`, as every command that writes a report takes it.
#[derive(Debug, Clone, Copy, Default, Args)]
pub struct FormatArg {
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// `report` in `format`, once [`finite`] has passed it.
pub fn render(r: &impl Report, format: Format) -> Result<String, CliError> {
    finite(r)?;
    Ok(match format {
        Format::Table => r.table(),
        Format::Json => report::json(r).map_err(|e| CliError::Failed(format!("JSON: {e}")))?,
        Format::Csv => report::csv(&r.csv_header(), &r.csv_rows()),
    })
}

/// Refuses a report holding a non-finite number where a finite one is
/// meant ([`crate::output::audit`]): a failed run (exit 1), naming the
/// quantity, rather than an absurd result printed as a success. Every
/// front end (the tables, JSON and CSV here, the Python module) passes its
/// report through this before showing it.
pub fn finite<R: serde::Serialize + ?Sized>(report: &R) -> Result<(), CliError> {
    match crate::output::audit::first_non_finite(report) {
        Some(found) => Err(CliError::Failed(found.to_string())),
        None => Ok(()),
    }
}

/// A command's typed report as its printing step receives it: rendered in
/// a format for the command line, or serialized by any serde serializer for
/// another front end (the Python module turns it into Python objects), so
/// that both show the same values by construction.
pub trait Emit: erased_serde::Serialize {
    /// The report in `format`, as the command line prints it.
    fn render(&self, format: Format) -> Result<String, CliError>;
}

impl<R: Report> Emit for R {
    fn render(&self, format: Format) -> Result<String, CliError> {
        render(self, format)
    }
}

erased_serde::serialize_trait_object!(Emit);

/// The printing step of a command: its report in `format` on stdout.
pub fn printer(format: Format) -> impl FnOnce(&dyn Emit) -> Result<(), CliError> {
    move |report| print(&report.render(format)?)
}

/// Writes `text` to stdout.
pub fn print(text: &str) -> Result<(), CliError> {
    if super::shard::held(text) {
        return Ok(());
    }
    Ok(crate::output::stdout::print(text)?)
}

/// A float for tables and CSV: `inf` for infinity, otherwise the shortest exact form.
pub fn num(v: f64) -> String {
    Num(v).to_string()
}

/// A cell that may be empty: the number, or nothing.
pub fn optional(v: Option<f64>) -> String {
    v.map(num).unwrap_or_default()
}

/// CSV columns naming a whole parameter set: μ, then every key of the table.
/// The columns of the eight peaks with and without pounding, in the order
/// of [`crate::analysis::spectrum::eight_peaks`].
pub const PEAK_COLUMNS: [&str; 8] = [
    "left_peak_displacement",
    "left_peak_velocity",
    "right_peak_displacement",
    "right_peak_velocity",
    "free_left_peak_displacement",
    "free_left_peak_velocity",
    "free_right_peak_displacement",
    "free_right_peak_velocity",
];

pub fn param_columns() -> Vec<&'static str> {
    let mut h = vec!["mu"];
    h.extend(FIELDS.iter().map(|f| f.key));
    h
}

/// The cells of [`param_columns`] for `p`.
pub fn param_cells(p: &Params) -> Vec<String> {
    let mut row = vec![num(p.mu())];
    row.extend(FIELDS.iter().map(|f| f.text(p)));
    row
}

/// An existing target that is not a regular file (after links) is refused.
pub fn refuse_non_file(path: &std::path::Path) -> Result<(), CliError> {
    match std::fs::metadata(path) {
        Ok(m) if !m.is_file() => Err(CliError::Failed(format!(
            "cannot write {}: it exists and is not a regular file",
            crate::output::shown(path)
        ))),
        _ => Ok(()),
    }
}
