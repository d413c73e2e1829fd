//! `pounding map --suite`: a suite study over two quantities of the
//! buildings (SPEC §12), for the physical pair ([`pair`]: P(pounding) and
//! the median amplification of the left building's drift over two keys of
//! its `[physical]` table) or, with `--buildings`, for a row ([`row`]:
//! what a retrofit buys, over any two keys `--set` takes). The study is
//! [`crate::analysis::suite_map`]; this module plans, bounds, runs (or
//! shards, or merges) the cells once for both ([`run_cells`]), and each
//! subject's file prints them. CSV rows are written as each row of the map
//! is done, so a long map streams.

pub mod pair;
pub mod row;

use std::time::Instant;

use std::fmt::Write as _;

use serde::Serialize;

use super::CliError;
use super::budget::Work;
use super::description::Provenance;
use super::output::{Emit, Format, num, print};
use super::progress::Progress;
use super::shard::Sweep;
use super::subject::CliSubject;
use super::suite::SuiteArgs;
use crate::analysis::suite_map::{MAX_RUNS, MapAxis, MapSubject, compute_cells, plan_cells};
use crate::model::params::echo::g4;
use crate::model::suite::SuiteMember;
use crate::output::report::{csv, json};

/// How a map's cells go to CSV: the columns, and each cell's lines.
pub struct CsvOf<'a, C> {
    pub columns: &'a [&'a str],
    pub lines: &'a dyn Fn(&C) -> Vec<Vec<String>>,
}

/// A map's cells and its wall time in ms; `None` when a shard's part was
/// written.
pub type MapRan<C> = Result<Option<(Vec<C>, f64)>, CliError>;

/// `e` with `prefix` before its message (same exit code).
fn prefixed(prefix: &str, e: CliError) -> CliError {
    match e {
        CliError::Usage(m) => CliError::Usage(format!("{prefix}{m}")),
        CliError::Failed(m) => CliError::Failed(format!("{prefix}{m}")),
        other => other,
    }
}

/// The cells of a map over `x` × `y` (row after row), planned before any
/// run, within the work bound, run row by row with progress and, as CSV,
/// printed as each row is done; or with `--shard` one shard of them (then
/// `None`: its part was written), or under `pounding merge` from the parts.
/// Returns the cells and the wall time in ms (the parts' when merged).
/// `name` names the subject in the parts.
pub fn run_cells<S: MapSubject + CliSubject>(
    args: &SuiteArgs,
    name: &str,
    cells: &[(f64, f64, S)],
    members: &[SuiteMember],
    (x, y): (&MapAxis, &MapAxis),
    csv_of: CsvOf<S::Cell>,
) -> MapRan<S::Cell> {
    if cells.len() * members.len() > MAX_RUNS {
        return Err(CliError::Usage(format!(
            "--x, --y: {} cells × {} records is more than {MAX_RUNS} pairs of runs",
            cells.len(),
            members.len()
        )));
    }
    let at = |cx: f64, cy: f64| format!("cell {}={}, {}={}: ", x.key, num(cx), y.key, num(cy));
    let plans =
        plan_cells(cells, members).map_err(|(cx, cy, e)| prefixed(&at(cx, cy), S::failed(e)))?;
    let Some(first) = cells.first().map(|c| &c.2) else {
        return Ok(Some((Vec::new(), 0.0)));
    };
    let work: Work = cells
        .iter()
        .zip(&plans)
        .map(|((_, _, s), p)| s.work_of(members, std::slice::from_ref(p)))
        .sum();
    first.check(&work, "map --suite", args.long.allow_long)?;
    let sharded = super::shard::suite::map_cells(
        &args.shard,
        name,
        cells,
        &plans,
        members,
        &(x, y),
        S::failed,
    )?;
    if matches!(sharded, Sweep::Done) {
        return Ok(None);
    }
    let format = args.output.format;
    if format == Format::Csv {
        print(&csv(csv_of.columns, &[]))?;
    }
    let progress = Progress::start(&work);
    let start = Instant::now();
    // Each record's share of the work, for the bar.
    let per_record = work.steps / (cells.len() * members.len()).max(1) as f64;
    let done = || progress.add(per_record);
    let width = x.values.len();
    let mut all = Vec::with_capacity(cells.len());
    for row in 0..y.values.len() {
        let range = row * width..(row + 1) * width;
        let computed = match &sharded {
            Sweep::Merged(all, _) => all[range].to_vec(),
            _ => compute_cells(cells, &plans, members, range, &done).map_err(|e| {
                let at_row = format!("{}={}: ", y.key, num(y.values[row]));
                prefixed(&at_row, S::failed(e))
            })?,
        };
        if format == Format::Csv {
            let rows: Vec<Vec<String>> = computed.iter().flat_map(csv_of.lines).collect();
            let text = csv(csv_of.columns, &rows);
            // The header went first; each row's lines follow as it is done.
            print(text.split_once('\n').map_or("", |(_, body)| body))?;
        }
        all.extend(computed);
    }
    drop(progress);
    let elapsed_ms = match sharded {
        Sweep::Merged(_, ms) => ms,
        _ => start.elapsed().as_secs_f64() * 1e3,
    };
    Ok(Some((all, elapsed_ms)))
}

/// One grid of a map's table: its title, then y down the rows from its
/// largest value and x across, each cell's value as `shown` writes it; the
/// first column `first` wide, the others `w` (wider text is not cut).
#[allow(clippy::too_many_arguments)]
pub fn grid(
    s: &mut String,
    title: &str,
    x: &MapAxis,
    y: &MapAxis,
    values: &[f64],
    shown: &dyn Fn(f64) -> String,
    (first, w): (usize, usize),
) {
    use std::fmt::Write as _;
    let _ = writeln!(s, "\n{title}:");
    let _ = write!(s, "{:>first$}", format!("{}\\{}", y.key, x.key));
    for v in &x.values {
        let _ = write!(s, " {:>w$}", g4(*v));
    }
    let _ = writeln!(s);
    let width = x.values.len();
    for (row, yv) in y.values.iter().enumerate().rev() {
        let _ = write!(s, "{:>first$}", g4(*yv));
        for v in &values[row * width..(row + 1) * width] {
            let _ = write!(s, " {:>w$}", shown(*v));
        }
        let _ = writeln!(s);
    }
}

/// A suite map as JSON or a table (its CSV is streamed as it is computed):
/// what the pair's and a row's report alike, and `names`, flattened after
/// `records`: the row's buildings, joints and links, nothing for the pair.
#[derive(Debug, Serialize)]
pub struct MapReport<'a, N, C> {
    #[serde(flatten)]
    pub provenance: Provenance<'a>,
    pub suite: &'a str,
    pub measure: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub level_g: Option<f64>,
    pub records: usize,
    #[serde(flatten)]
    pub names: N,
    pub x: &'a MapAxis,
    pub y: &'a MapAxis,
    /// Row after row (y), x along each row.
    pub cells: Vec<C>,
    pub elapsed_ms: f64,
    /// What the heading calls the subject (`preset`, `row`).
    #[serde(skip)]
    pub subject: &'static str,
    /// The table's grids, between its heading and its time.
    #[serde(skip)]
    pub grids: fn(&MapReport<'a, N, C>, &mut String),
}

impl<N: Serialize, C: Serialize> Emit for MapReport<'_, N, C> {
    /// JSON or the table; its CSV is streamed as the map is computed.
    fn render(&self, format: Format) -> Result<String, CliError> {
        match format {
            Format::Json => json(self).map_err(|e| CliError::Failed(format!("JSON: {e}"))),
            Format::Table => {
                let mut s = String::new();
                let level = self.level_g.map_or(String::new(), |l| {
                    format!(", each record scaled to {} = {} g", self.measure, num(l))
                });
                let _ = writeln!(
                    s,
                    "suite map of {} ({} records{level}), {} {}: {} × {}",
                    self.suite,
                    self.records,
                    self.subject,
                    self.provenance.preset,
                    self.x.key,
                    self.y.key
                );
                (self.grids)(self, &mut s);
                let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
                Ok(s)
            }
            Format::Csv => Ok(String::new()),
        }
    }
}
