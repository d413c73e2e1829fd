//! `pounding map --suite`: the probability of pounding and the median
//! amplification of the left building's drift over two physical quantities
//! of the buildings, under a suite of records (SPEC §12). The study is
//! [`crate::analysis::suite_map`]; this module parses, runs and prints. CSV
//! rows are written as each row of the map is done, so a long map streams.

use std::fmt::Write as _;
use std::time::Instant;

use serde::Serialize;

use super::CliError;
use super::description::Provenance;
use super::output::{Emit, Format, num, print};
use super::progress::Progress;
use super::records::members;
use super::shard::Sweep;
use super::suite::{SuiteArgs, case_of, record_steps, work_of};
use crate::analysis::suite::SuiteRun;
use crate::analysis::suite_map::{
    MAX_RUNS, PhysicalAxis, SuiteMapCell, cell_cases, compute_cells, plan_cells,
};
use crate::model::params::echo::g4;
use crate::output::report::{csv, json};

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

const UNITS: &str = "SI (the axes' units: kg, s, m, rad/s); gaps in m";

/// The CSV columns of a cell.
const COLUMNS: [&str; 9] = [
    "version",
    "units",
    "x",
    "y",
    "pounding_probability",
    "median_amplification",
    "median_min_gap_m",
    "records",
    "measure",
];

/// Runs the suite map of `suite_args` over `x` × `y` (texts of `--x`, `--y`),
/// its typed report handed to `emit` (as CSV, streamed here instead).
pub fn report_with(
    suite_args: &SuiteArgs,
    x: &str,
    y: &str,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let x = PhysicalAxis::parse("--x", x).map_err(usage)?;
    let y = PhysicalAxis::parse("--y", y).map_err(usage)?;
    let (preset, case) = case_of(suite_args)?;
    let members = members(&suite_args.suite)?;
    let cells = cell_cases(&case, &x, &y);
    if cells.len() * members.len() > MAX_RUNS {
        return Err(usage(format!(
            "--x, --y: {} cells × {} records is more than {MAX_RUNS} pairs of runs",
            cells.len(),
            members.len()
        )));
    }
    let plans = plan_cells(&cells, &members).map_err(|(cx, cy, e)| {
        usage(format!(
            "cell {}={}, {}={}: {e}",
            x.key,
            num(cx),
            y.key,
            num(cy)
        ))
    })?;
    let work = work_of(plans.iter().flatten());
    work.check("map --suite", suite_args.long.allow_long, false)?;
    let sharded = super::shard::suite::map_cells(
        &suite_args.shard,
        &preset.name,
        &case,
        &cells,
        &plans,
        &members,
        &(&x, &y),
    )?;
    if matches!(sharded, Sweep::Done) {
        return Ok(());
    }
    let format = suite_args.output.format;
    let measure = case.scaling.measure.to_string();
    let row_cells = |c: &SuiteMapCell| -> Vec<String> {
        vec![
            env!("CARGO_PKG_VERSION").to_string(),
            UNITS.to_string(),
            num(c.x),
            num(c.y),
            num(c.pounding_probability),
            num(c.median_amplification),
            num(c.median_min_gap_m),
            c.records.to_string(),
            measure.clone(),
        ]
    };
    if format == Format::Csv {
        print(&csv(&COLUMNS, &[]))?;
    }
    let progress = Progress::start(&work);
    let start = Instant::now();
    let done = |r: &SuiteRun| progress.add(record_steps(&r.params));
    let width = x.values.len();
    let mut all = Vec::with_capacity(cells.len());
    for row in 0..y.values.len() {
        let computed = match &sharded {
            Sweep::Merged(all, _) => all[row * width..(row + 1) * width].to_vec(),
            _ => compute_cells(
                &cells,
                &plans,
                &members,
                row * width..(row + 1) * width,
                &done,
            ),
        };
        if format == Format::Csv {
            let rows: Vec<Vec<String>> = computed.iter().map(row_cells).collect();
            let text = csv(&COLUMNS, &rows);
            // The header went first; each row's lines follow as it is done.
            print(text.split_once('\n').map_or("", |(_, body)| body))?;
        }
        all.extend(computed);
    }
    drop(progress);
    let report = SuiteMapReport {
        provenance: Provenance::new(&preset.name, UNITS),
        suite: &suite_args.suite,
        measure,
        level_g: case.scaling.level,
        records: members.len(),
        x: &x,
        y: &y,
        cells: all,
        elapsed_ms: match sharded {
            Sweep::Merged(_, ms) => ms,
            _ => start.elapsed().as_secs_f64() * 1e3,
        },
    };
    match format {
        Format::Csv => Ok(()),
        Format::Json | Format::Table => emit(&report),
    }
}

impl Emit for SuiteMapReport<'_> {
    /// JSON or the table; its CSV is streamed as the map is computed.
    fn render(&self, format: Format) -> Result<String, CliError> {
        match format {
            Format::Json => json(self).map_err(|e| CliError::Failed(format!("JSON: {e}"))),
            Format::Table => Ok(self.table()),
            Format::Csv => Ok(String::new()),
        }
    }
}

/// `pounding map --suite` as JSON or a table.
#[derive(Debug, Serialize)]
struct SuiteMapReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    suite: &'a str,
    measure: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    level_g: Option<f64>,
    records: usize,
    x: &'a PhysicalAxis,
    y: &'a PhysicalAxis,
    /// Row after row (y), x along each row.
    cells: Vec<SuiteMapCell>,
    elapsed_ms: f64,
}

impl SuiteMapReport<'_> {
    /// Two grids, P(pounding) and the median amplification, y down the
    /// rows from its largest value, x across.
    fn table(&self) -> String {
        let mut s = String::new();
        let level = self.level_g.map_or(String::new(), |l| {
            format!(", each record scaled to {} = {} g", self.measure, num(l))
        });
        let _ = writeln!(
            s,
            "suite map of {} ({} records{level}), preset {}: {} × {}",
            self.suite, self.records, self.provenance.preset, self.x.key, self.y.key
        );
        let width = self.x.values.len();
        for (title, get) in [
            (
                "P(pounding)",
                (|c: &SuiteMapCell| c.pounding_probability) as fn(&SuiteMapCell) -> f64,
            ),
            ("median amplification u1/u1,free", |c| {
                c.median_amplification
            }),
        ] {
            let _ = writeln!(s, "\n{title}:");
            let _ = write!(s, "{:>10}", format!("{}\\{}", self.y.key, self.x.key));
            for v in &self.x.values {
                let _ = write!(s, " {:>6}", g4(*v));
            }
            let _ = writeln!(s);
            for (row, yv) in self.y.values.iter().enumerate().rev() {
                let _ = write!(s, "{:>10}", g4(*yv));
                for c in &self.cells[row * width..(row + 1) * width] {
                    let _ = write!(s, " {:>6}", format!("{:.2}", get(c)));
                }
                let _ = writeln!(s);
            }
        }
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}
