//! `pounding map --buildings ROW --suite …`: what a retrofit buys, over
//! any two keys `--set` takes ([`crate::analysis::suite_map::row`]). Each
//! cell is `pounding suite --buildings ROW --set X=x --set Y=y`; the table
//! shows one grid per quantity: P(pounding) per joint, the median peak
//! drift ratio (%) and floor acceleration (g) per building, and the median
//! peak force (kN) per link.

use serde::Serialize;

use super::{CsvOf, MapReport, grid, prefixed, run_cells};
use crate::analysis::subject::row::{RowSuiteCase, row_intensity};
use crate::analysis::suite_map::row::set_text;
use crate::analysis::suite_map::{MapAxis, RowMapCell, cells_of, row_axis};
use crate::cli::CliError;
use crate::cli::buildings::BuildingsArgs;
use crate::cli::description::Provenance;
use crate::cli::output::{Emit, Format, num};
use crate::cli::suite::SuiteArgs;
use crate::model::buildings::Row;
use crate::model::params::echo::{self, g4};

const UNITS: &str = "SI (the axes' keys' units as in the row preset); accelerations in g, \
     link forces in kN";

/// The CSV columns: one line per cell and quantity.
const COLUMNS: [&str; 9] = [
    "version", "units", "x", "y", "quantity", "of", "value", "records", "measure",
];

/// A row's map as run: what its report and its figure show.
pub struct RowMap {
    pub names: Names,
    pub measure: String,
    pub level_g: Option<f64>,
    pub records: usize,
    pub x: MapAxis,
    pub y: MapAxis,
    pub cells: Vec<RowMapCell>,
    pub elapsed_ms: f64,
}

/// Runs the row's suite map of `suite_args` (with `--buildings`) over
/// `x` × `y` (texts of `--x`, `--y`), its typed report handed to `emit`
/// (as CSV, streamed instead).
pub fn report_with(
    suite_args: &SuiteArgs,
    x_text: &str,
    y_text: &str,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let Some(map) = run(suite_args, x_text, y_text)? else {
        return Ok(());
    };
    let buildings = suite_args.buildings.as_deref().unwrap_or_default();
    let report = MapReport {
        provenance: Provenance::new(buildings, UNITS),
        suite: &suite_args.suite,
        measure: map.measure.clone(),
        level_g: map.level_g,
        records: map.records,
        names: map.names,
        x: &map.x,
        y: &map.y,
        cells: map.cells,
        elapsed_ms: map.elapsed_ms,
        subject: "row",
        grids,
    };
    match suite_args.output.format {
        Format::Csv => Ok(()),
        Format::Json | Format::Table => emit(&report),
    }
}

/// Plans, bounds and runs the row's map of `suite_args` over `x` × `y`
/// (CSV streamed as it goes when that is the format); `None` when a
/// shard's part was written.
pub fn run(suite_args: &SuiteArgs, x_text: &str, y_text: &str) -> Result<Option<RowMap>, CliError> {
    let x = row_axis("--x", x_text).map_err(CliError::Usage)?;
    let y = row_axis("--y", y_text).map_err(CliError::Usage)?;
    if x.key == y.key {
        return Err(CliError::Usage(format!(
            "--x, --y: both set `{}`; give two different keys",
            x.key
        )));
    }
    let Some(study) = suite_args.row_study()? else {
        return Err(CliError::Usage("--buildings: no row given".into()));
    };
    let (base, members) = crate::cli::subject::row::case_of(&study)?;
    let buildings = BuildingsArgs {
        buildings: Some(study.buildings.to_string()),
        ..BuildingsArgs::default()
    };
    let params = &suite_args.params;
    let row_with = |sets: &[String]| {
        buildings.row(
            &[&params.overrides[..], sets].concat(),
            params.model.as_deref(),
        )
    };
    // Each axis alone first, so that a value out of its key's range is
    // reported against its flag.
    for (flag, text, axis) in [("--x", x_text, &x), ("--y", y_text, &y)] {
        for &v in &axis.values {
            row_with(&[set_text(&axis.key, v)])
                .map_err(|e| prefixed(&format!("{flag} {}: ", echo::text(text)), e))?;
        }
    }
    // `--im sa` is Sa at the leftmost building's T₁, which a cell may change.
    let sa_alone = suite_args
        .im
        .as_deref()
        .is_some_and(|t| t.trim().eq_ignore_ascii_case("sa"));
    let cells = cells_of(&x, &y, |xv, yv| {
        let row = row_with(&[set_text(&x.key, xv), set_text(&y.key, yv)]).map_err(|e| {
            let at = format!("cell {}={}, {}={}: ", x.key, num(xv), y.key, num(yv));
            prefixed(&at, e)
        })?;
        let mut scaling = base.scaling;
        if sa_alone {
            scaling.measure = row_intensity(&row);
        }
        Ok::<_, CliError>(RowSuiteCase { row, scaling })
    })?;
    let names = Names::of(&base.row);
    let measure = base.scaling.measure.to_string();
    let lines = |c: &RowMapCell| -> Vec<Vec<String>> {
        names
            .quantities(c)
            .into_iter()
            .map(|(quantity, of, value)| {
                vec![
                    env!("CARGO_PKG_VERSION").to_string(),
                    UNITS.to_string(),
                    num(c.x),
                    num(c.y),
                    quantity.to_string(),
                    of.to_string(),
                    num(value),
                    c.records.to_string(),
                    measure.clone(),
                ]
            })
            .collect()
    };
    let csv_of = CsvOf {
        columns: &COLUMNS,
        lines: &lines,
    };
    let Some((cells, elapsed_ms)) = run_cells(
        suite_args,
        study.buildings,
        &cells,
        &members,
        (&x, &y),
        csv_of,
    )?
    else {
        return Ok(None);
    };
    Ok(Some(RowMap {
        names,
        measure,
        level_g: base.scaling.level,
        records: members.len(),
        x,
        y,
        cells,
        elapsed_ms,
    }))
}

/// What the row's buildings, joints and links are called in the outputs.
#[derive(Debug, Clone, Serialize)]
pub struct Names {
    pub buildings: Vec<String>,
    /// `joint1`, … (between buildings j and j + 1).
    pub joints: Vec<String>,
    /// `link1`, … in file order.
    pub links: Vec<String>,
}

impl Names {
    fn of(row: &Row) -> Names {
        Names {
            buildings: row.buildings.iter().map(|b| b.name.clone()).collect(),
            joints: (1..=row.joints.len())
                .map(|j| format!("joint{j}"))
                .collect(),
            links: (1..=row.links.len()).map(|l| format!("link{l}")).collect(),
        }
    }

    /// A cell's quantities as (quantity, of what, value), in the table's order.
    fn quantities<'a>(&'a self, c: &RowMapCell) -> Vec<(&'static str, &'a str, f64)> {
        let mut q = Vec::new();
        let mut add = |quantity, names: &'a [String], values: &[f64]| {
            for (n, v) in names.iter().zip(values) {
                q.push((quantity, n.as_str(), *v));
            }
        };
        add(
            "pounding_probability",
            &self.joints,
            &c.pounding_probability,
        );
        add("median_drift_ratio", &self.buildings, &c.median_drift_ratio);
        add(
            "median_acceleration_g",
            &self.buildings,
            &c.median_acceleration_g,
        );
        add("median_link_force_kn", &self.links, &c.median_link_force_kn);
        q
    }
}

/// One grid per quantity, y down the rows from its largest value, x
/// across.
fn grids(report: &MapReport<Names, RowMapCell>, s: &mut String) {
    let (names, x, y) = (&report.names, report.x, report.y);
    let per_cell: Vec<_> = report.cells.iter().map(|c| names.quantities(c)).collect();
    let first = format!("{}\\{}", y.key, x.key).len().max(10);
    let labels = x.values.iter().chain(&y.values).map(|v| g4(*v).len());
    let w = labels.max().unwrap_or(0).max(6);
    for (k, &(quantity, of, _)) in per_cell
        .first()
        .map_or(&[][..], |q| &q[..])
        .iter()
        .enumerate()
    {
        let (title, shown): (String, &dyn Fn(f64) -> String) = match quantity {
            "pounding_probability" => (format!("P(pounding) at {of}"), &|v| format!("{v:.2}")),
            "median_drift_ratio" => (format!("{of}: median peak drift ratio (%)"), &|v| {
                format!("{:.3}", 100.0 * v)
            }),
            "median_acceleration_g" => {
                (format!("{of}: median peak floor acceleration (g)"), &|v| {
                    format!("{v:.2}")
                })
            }
            _ => (format!("{of}: median peak force (kN)"), &|v| g4(v)),
        };
        let values: Vec<f64> = per_cell.iter().map(|q| q[k].2).collect();
        grid(s, &title, x, y, &values, shown, (first, w));
    }
}
