//! `pounding suite --buildings ROW --compare ROW2,…`: the same suite (the
//! same records, intensity and level) run on each variant of a row, a
//! retrofit say, and reported side by side (SPEC §12, §13, §14).
//!
//! Each variant's report is bit for bit the report `suite --buildings` makes
//! of it alone (but its wall time); the summary beside them gives, per
//! variant,
//!
//! - per joint P(pounding), the fraction of records with an impact there,
//!   and the median over the records of its gap that prevents pounding;
//! - per building the median of its peak storey drift ratio
//!   max_i |Δ_i|/h_i, with pounding and with every joint open.
//!
//! A variant must have the first row's buildings, by number and name, so
//! that its demands compare one to one.

use std::fmt::Write as _;

use serde::Serialize;

use super::row::{RowSuiteReport, report};
use super::{Chosen, SuiteArgs};
use crate::analysis::separation::median;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteRun};
use crate::cli::CliError;
use crate::cli::output::Emit;
use crate::cli::subject::Study;
use crate::model::buildings::Row;
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// Runs the suite of `args` on its row and on every `--compare` row, and
/// hands the side-by-side report to `emit`.
pub fn suite(
    args: &SuiteArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    if args.buildings.is_none() {
        return Err(CliError::Usage(
            "--compare: compares rows of buildings; give --buildings ROW".into(),
        ));
    }
    if args.shard.shard.is_some() {
        return Err(CliError::Usage(
            "--compare: not with --shard; shard each row's suite on its own".into(),
        ));
    }
    let names = args.buildings.iter().chain(&args.compare);
    let mut studies: Vec<Study<RowSuiteCase>> = Vec::new();
    for name in names {
        let variant = SuiteArgs {
            buildings: Some(name.clone()),
            compare: Vec::new(),
            ..args.clone()
        };
        let Chosen::Row(study) = Chosen::of(&variant)? else {
            unreachable!("--buildings chooses a row");
        };
        if let Some(first) = studies.first() {
            same_buildings(&first.subject.row, &study.subject.row, name)?;
        }
        studies.push(study);
    }
    let mut ran = Vec::new();
    for study in &studies {
        let Some((runs, elapsed_ms)) = study.run("suite", &args.shard, args.long.allow_long)?
        else {
            return Ok(());
        };
        ran.push((runs, elapsed_ms));
    }
    let variants = studies
        .iter()
        .zip(&ran)
        .map(|(study, (runs, elapsed_ms))| Variant {
            variant: study.name.clone(),
            summary: Summary::of(&study.subject.row, runs),
            report: report(&study.subject, &args.suite, runs, *elapsed_ms),
        })
        .collect();
    emit(&CompareReport { variants })
}

/// Refuses a variant whose buildings differ from the first row's in number
/// or names, naming it (`variant`, as given) and what differs.
fn same_buildings(first: &Row, other: &Row, variant: &str) -> Result<(), CliError> {
    let names = |r: &Row| -> Vec<String> { r.buildings.iter().map(|b| b.name.clone()).collect() };
    let (a, b) = (names(first), names(other));
    if a == b {
        return Ok(());
    }
    Err(CliError::Usage(format!(
        "--compare {}: its buildings are {} ({}), the first row's {} ({}); a variant keeps \
         the buildings and their names",
        crate::model::params::echo::text(variant),
        b.len(),
        b.join(", "),
        a.len(),
        a.join(", ")
    )))
}

/// One joint of a variant over the suite.
#[derive(Debug, Serialize)]
struct JointSummary {
    joint: String,
    /// The fraction of records with an impact at it.
    pounding_probability: f64,
    /// The median of its gap that prevents pounding (m).
    median_min_gap_m: f64,
}

/// One building of a variant over the suite.
#[derive(Debug, Serialize)]
struct BuildingSummary {
    name: String,
    /// Medians of max_i |Δ_i|/h_i, with pounding and with every joint open.
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    median_max_drift_ratio: f64,
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    no_pounding_median_max_drift_ratio: f64,
}

/// What the side-by-side summary gives of one variant.
#[derive(Debug, Serialize)]
struct Summary {
    joints: Vec<JointSummary>,
    buildings: Vec<BuildingSummary>,
}

impl Summary {
    fn of(row: &Row, runs: &[RowSuiteRun]) -> Summary {
        let n = runs.len().max(1) as f64;
        let joints = (0..row.joints.len())
            .map(|j| JointSummary {
                joint: format!(
                    "joint{} {}–{}",
                    j + 1,
                    row.buildings[j].name,
                    row.buildings[j + 1].name
                ),
                pounding_probability: runs
                    .iter()
                    .filter(|r| r.demands.joints[j].impacts > 0)
                    .count() as f64
                    / n,
                median_min_gap_m: median(runs.iter().map(|r| r.demands.joints[j].gap.min_gap)),
            })
            .collect();
        let buildings = row
            .buildings
            .iter()
            .enumerate()
            .map(|(i, b)| BuildingSummary {
                name: b.name.clone(),
                median_max_drift_ratio: median(
                    runs.iter().map(|r| r.demands.buildings[i].max_drift_ratio),
                ),
                no_pounding_median_max_drift_ratio: median(
                    runs.iter()
                        .map(|r| r.demands.no_pounding[i].max_drift_ratio),
                ),
            })
            .collect();
        Summary { joints, buildings }
    }
}

/// One variant: its name as given, its summary and its own suite report.
#[derive(Debug, Serialize)]
struct Variant<'a> {
    variant: String,
    summary: Summary,
    #[serde(flatten)]
    report: RowSuiteReport<'a>,
}

/// `pounding suite --buildings --compare` in every format.
#[derive(Debug, Serialize)]
struct CompareReport<'a> {
    variants: Vec<Variant<'a>>,
}

impl Report for CompareReport<'_> {
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
        let mut s = String::new();
        let Some(first) = self.variants.first() else {
            return s;
        };
        let width = self
            .variants
            .iter()
            .map(|v| v.variant.chars().count())
            .max()
            .unwrap_or(7)
            .max(7);
        let _ = writeln!(
            s,
            "side by side: per joint P(pounding) and the median gap that prevents it, \
             per building the median peak storey drift ratio"
        );
        let _ = write!(s, "{:<width$}", "variant");
        for j in &first.summary.joints {
            let label = j.joint.split(' ').next().unwrap_or("");
            let _ = write!(
                s,
                " {:>14} {:>14}",
                format!("{label} P(pound)"),
                "d_min med mm"
            );
        }
        for b in &first.summary.buildings {
            let _ = write!(s, " {:>16}", format!("{} drift %", b.name));
        }
        let _ = writeln!(s);
        for v in &self.variants {
            let _ = write!(s, "{:<width$}", v.variant);
            for j in &v.summary.joints {
                let _ = write!(
                    s,
                    " {:>14} {:>14}",
                    g4(j.pounding_probability),
                    g4(j.median_min_gap_m * 1e3)
                );
            }
            for b in &v.summary.buildings {
                let _ = write!(s, " {:>16}", g4(b.median_max_drift_ratio * 100.0));
            }
            let _ = writeln!(s);
        }
        for v in &self.variants {
            let _ = writeln!(s);
            let _ = writeln!(s, "── variant {} ──", v.variant);
            s.push_str(&v.report.table());
        }
        s
    }
}
