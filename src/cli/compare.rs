//! `--compare ROW2,…`: one study of a row (`suite`, `ida`, `gap --suite`,
//! SPEC §12–§14) run on each variant of the row, a retrofit say, and
//! reported side by side. What the three share is written here once:
//!
//! - the refusals: `--compare` compares rows (`--buildings`), and is not
//!   sharded (each row's study shards on its own);
//! - the variants: the first row, then each `--compare` row as given, each
//!   loaded and checked before any run, each with the first row's buildings
//!   by number and name, so that their demands compare one to one;
//! - the report: a side-by-side summary, then each variant's own report,
//!   bit for bit the study's report of that row alone (but its wall time).
//!   JSON gives `variants`, each its own report with its `variant` name and
//!   `summary`; CSV gives each variant's own lines behind a `variant`
//!   column.
//!
//! Each study says what it loads, runs and summarises ([`Compared`]).

use std::fmt::Write as _;

use serde::Serialize;

use super::CliError;
use super::output::Emit;
use super::shard::ShardArgs;
use crate::model::buildings::Row;
use crate::model::params::echo::text;
use crate::output::report::Report;

/// A study that `--compare` runs on each variant of a row.
pub trait Compared {
    /// One variant's study, loaded and checked, before any run.
    type Variant;
    /// What the side-by-side summary gives of one variant.
    type Summary: SideBySide;
    /// The study's own report of one variant, as the study writes it of
    /// that row alone.
    type Report<'a>: Report
    where
        Self: 'a;
    /// The study's name in messages: `suite`, `IDA`, …
    const STUDY: &'static str;

    /// The variant `name` (`--buildings` or a `--compare` row, as given),
    /// loaded and checked.
    fn load(&self, name: &str) -> Result<Self::Variant, CliError>;
    /// The variant's row.
    fn row(variant: &Self::Variant) -> &Row;
    /// Runs the study of `variant`.
    fn run<'a>(&'a self, variant: &'a Self::Variant) -> Ran<Self::Summary, Self::Report<'a>>;
}

/// A variant's study that ran: its summary and its own report, or `None`
/// when there is nothing to report (a shard's part was written).
pub type Ran<S, R> = Result<Option<(S, R)>, CliError>;

/// A summary that writes the variants side by side, as a table's opening.
pub trait SideBySide: Serialize {
    /// The table's first line: what it gives of each variant.
    const HEADING: &'static str;
    /// Writes the side-by-side table of every variant's summary (at least
    /// one), each with its name, in the order given, to `s` after the
    /// heading; `width` is the `variant` column's.
    fn table(variants: &[(&str, &Self)], width: usize, s: &mut String);
}

/// What `--compare` is given with: the first row, the variants and the
/// sharding asked for.
pub struct Request<'a> {
    /// `--buildings`, the first row (none on the pair).
    pub buildings: Option<&'a str>,
    /// `--compare`, the other rows as given.
    pub compare: &'a [String],
    pub shard: &'a ShardArgs,
}

/// Runs `study` on the first row of `request` and on every `--compare`
/// row, and hands the side-by-side report to `emit`. Refused in one line
/// (exit 2) on the pair, with `--shard`, and when a variant's buildings
/// differ from the first row's; every variant is loaded and checked before
/// any runs.
pub fn compare<C: Compared>(
    study: &C,
    request: &Request,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let Some(first) = request.buildings else {
        return Err(CliError::Usage(
            "--compare: compares rows of buildings; give --buildings ROW".into(),
        ));
    };
    if request.shard.shard.is_some() {
        return Err(CliError::Usage(format!(
            "--compare: not with --shard; shard each row's {} on its own",
            C::STUDY
        )));
    }
    let mut loaded: Vec<(&str, C::Variant)> = Vec::new();
    for name in std::iter::once(first).chain(request.compare.iter().map(String::as_str)) {
        let variant = study.load(name)?;
        if let Some((_, head)) = loaded.first() {
            same_buildings(C::row(head), C::row(&variant), name)?;
        }
        loaded.push((name, variant));
    }
    let mut variants = Vec::new();
    for (name, variant) in &loaded {
        let Some((summary, report)) = study.run(variant)? else {
            return Ok(());
        };
        variants.push(Variant {
            variant: name.to_string(),
            summary,
            report,
        });
    }
    emit(&CompareReport { variants })
}

/// Refuses a variant whose buildings differ from the first row's in number
/// or names, naming it (`variant`, as given) and what differs.
pub fn same_buildings(first: &Row, other: &Row, variant: &str) -> Result<(), CliError> {
    let names = |r: &Row| -> Vec<String> { r.buildings.iter().map(|b| b.name.clone()).collect() };
    let (a, b) = (names(first), names(other));
    if a == b {
        return Ok(());
    }
    Err(CliError::Usage(format!(
        "--compare {}: its buildings are {} ({}), the first row's {} ({}); a variant keeps \
         the buildings and their names",
        text(variant),
        b.len(),
        b.join(", "),
        a.len(),
        a.join(", ")
    )))
}

/// One variant: its name as given, its summary and its own report.
#[derive(Debug, Serialize)]
struct Variant<S, R> {
    variant: String,
    summary: S,
    #[serde(flatten)]
    report: R,
}

/// A study with `--compare` in every format.
#[derive(Debug, Serialize)]
struct CompareReport<S, R> {
    variants: Vec<Variant<S, R>>,
}

impl<S: SideBySide, R: Report> Report for CompareReport<S, R> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["variant"];
        if let Some(v) = self.variants.first() {
            h.extend(v.report.csv_header());
        }
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for v in &self.variants {
            for line in v.report.csv_rows() {
                let mut row = vec![v.variant.clone()];
                row.extend(line);
                rows.push(row);
            }
        }
        rows
    }

    fn table(&self) -> String {
        if self.variants.is_empty() {
            return String::new();
        }
        let summaries: Vec<(&str, &S)> = self
            .variants
            .iter()
            .map(|v| (v.variant.as_str(), &v.summary))
            .collect();
        // The `variant` column: its longest name, and at least its heading.
        let width = summaries
            .iter()
            .map(|(name, _)| name.chars().count())
            .max()
            .unwrap_or(0)
            .max("variant".len());
        let mut s = String::new();
        let _ = writeln!(s, "{}", S::HEADING);
        S::table(&summaries, width, &mut s);
        for v in &self.variants {
            let _ = writeln!(s);
            let _ = writeln!(s, "── variant {} ──", v.variant);
            s.push_str(&v.report.table());
        }
        s
    }
}
