//! `e` and `g` in the buildings scene: the row as on screen (its preset
//! with the edits made, its ground, its length) written as the CSV of
//! `pounding run --buildings --format csv` (the peaks per floor) or as the
//! SVG of `pounding figure buildings`, each through [`crate::output`]
//! (atomic: a temporary file renamed into place once complete).

use std::path::Path;
use std::sync::Arc;

use crate::analysis::buildings_report::RowReport;
use crate::figure::buildings::{ROW_FIGURE_SIZE, row_figure_of};
use crate::figure::{Format, encode};
use crate::model::buildings::{Ground, Row};
use crate::output::report::{Report, csv};
use crate::solver::buildings::{RowOptions, run_row};

/// Which file of the row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowFile {
    /// The peaks per floor, as `run --buildings --format csv`.
    Csv,
    /// The envelopes and impact forces, as `figure buildings`.
    Figure,
}

impl RowFile {
    pub fn extension(self) -> &'static str {
        match self {
            RowFile::Csv => "csv",
            RowFile::Figure => "svg",
        }
    }
}

/// The row a file is written from, as the scene holds it.
#[derive(Debug, Clone, PartialEq)]
pub struct RowSnapshot {
    pub row: Row,
    pub ground: Arc<Ground>,
    /// The ground's name (`synthetic:2000`, `record:PATH`, `sine`).
    pub ground_name: String,
    /// s.
    pub duration: f64,
}

/// Writes `file` of `snapshot` to `path`; the status message.
pub fn write(snapshot: &RowSnapshot, file: RowFile, path: &Path) -> String {
    let bytes = match file {
        RowFile::Csv => csv_text(snapshot).map(String::into_bytes),
        RowFile::Figure => figure_svg(snapshot),
    };
    match bytes {
        Ok(b) => match crate::output::write_file(path, &b) {
            Ok(()) => format!(
                "{} written to {} ({} KB)",
                match file {
                    RowFile::Csv => "the row's peaks",
                    RowFile::Figure => "figure `buildings`",
                },
                crate::output::shown(path),
                b.len().div_ceil(1024)
            ),
            Err(e) => format!("could not write {}: {e}", crate::output::shown(path)),
        },
        Err(e) => format!("could not write {}: {e}", crate::output::shown(path)),
    }
}

/// The CSV of `run --buildings --format csv` (exact method).
fn csv_text(s: &RowSnapshot) -> Result<String, String> {
    let run =
        run_row(&s.row, &s.ground, &RowOptions::lasting(s.duration)).map_err(|e| e.to_string())?;
    let report = RowReport::new(&s.row, &run, (&s.ground, &s.ground_name), "exact", 0.0);
    if let Some(found) = crate::output::audit::first_non_finite(&report) {
        return Err(found.to_string());
    }
    Ok(csv(&report.csv_header(), &report.csv_rows()))
}

/// The SVG of `figure buildings`, as the command draws it.
fn figure_svg(s: &RowSnapshot) -> Result<Vec<u8>, String> {
    let fig =
        row_figure_of(&s.row, &s.ground, &s.ground_name, s.duration).map_err(|e| e.to_string())?;
    encode(&fig, Format::Svg, ROW_FIGURE_SIZE).map_err(|e| e.to_string())
}
