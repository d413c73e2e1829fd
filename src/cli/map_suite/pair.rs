//! `pounding map --suite` on the preset's physical pair: P(pounding) and
//! the median amplification of the left building's drift over two
//! quantities of its `[physical]` table
//! ([`crate::analysis::suite_map::pair`]).

use serde::Serialize;

use super::{CsvOf, MapReport, run_cells};
use crate::analysis::suite_map::{PhysicalAxis, SuiteMapCell, cell_cases};
use crate::cli::CliError;
use crate::cli::description::Provenance;
use crate::cli::output::{Emit, Format, num};
use crate::cli::records::members;
use crate::cli::suite::{SuiteArgs, case_of};
use crate::output::report::{Column, column_cells, column_header};

const UNITS: &str = "SI (the axes' units: kg, s, m, rad/s); gaps in m";

/// The CSV columns of a cell, after `version` and `units` and before the
/// intensity measure's name.
const COLUMNS: &[Column<SuiteMapCell>] = &[
    ("x", |c| num(c.x)),
    ("y", |c| num(c.y)),
    ("pounding_probability", |c| num(c.pounding_probability)),
    ("median_amplification", |c| num(c.median_amplification)),
    ("median_min_gap_m", |c| num(c.median_min_gap_m)),
    ("records", |c| c.records.to_string()),
];

/// Runs the pair's suite map of `suite_args` over `x` × `y` (texts of
/// `--x`, `--y`), its typed report handed to `emit` (as CSV, streamed
/// instead).
pub fn report_with(
    suite_args: &SuiteArgs,
    x: &str,
    y: &str,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let x = PhysicalAxis::parse("--x", x).map_err(CliError::Usage)?;
    let y = PhysicalAxis::parse("--y", y).map_err(CliError::Usage)?;
    let (preset, case) = case_of(suite_args)?;
    let members = members(&suite_args.suite)?;
    let cells = cell_cases(&case, &x, &y);
    let measure = case.scaling.measure.to_string();
    let mut columns = column_header(&["version", "units"], COLUMNS);
    columns.push("measure");
    let head = [env!("CARGO_PKG_VERSION").to_string(), UNITS.to_string()];
    let lines = |c: &SuiteMapCell| -> Vec<Vec<String>> {
        let cells = head.iter().cloned().chain(column_cells(COLUMNS, c));
        vec![cells.chain([measure.clone()]).collect()]
    };
    let csv_of = CsvOf {
        columns: &columns,
        lines: &lines,
    };
    let Some((cells, elapsed_ms)) =
        run_cells(suite_args, &preset.name, &cells, &members, (&x, &y), csv_of)?
    else {
        return Ok(());
    };
    let report = MapReport {
        provenance: Provenance::new(&preset.name, UNITS),
        suite: &suite_args.suite,
        measure: measure.clone(),
        level_g: case.scaling.level,
        records: members.len(),
        names: NoNames {},
        x: &x,
        y: &y,
        cells,
        elapsed_ms,
        subject: "preset",
        grids,
    };
    match suite_args.output.format {
        Format::Csv => Ok(()),
        Format::Json | Format::Table => emit(&report),
    }
}

/// The pair's cells carry no per-building names.
#[derive(Debug, Serialize)]
pub struct NoNames {}

/// Two grids, P(pounding) and the median amplification, y down the rows
/// from its largest value, x across.
fn grids(report: &MapReport<NoNames, SuiteMapCell>, s: &mut String) {
    type Get = fn(&SuiteMapCell) -> f64;
    let grids: [(&str, Get); 2] = [
        ("P(pounding)", |c| c.pounding_probability),
        ("median amplification u1/u1,free", |c| {
            c.median_amplification
        }),
    ];
    for (title, get) in grids {
        let values: Vec<f64> = report.cells.iter().map(get).collect();
        super::grid(
            s,
            title,
            report.x,
            report.y,
            &values,
            &|v| format!("{v:.2}"),
            (10, 6),
        );
    }
}
