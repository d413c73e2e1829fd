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

use super::report::{SuiteReport, report};
use super::{Chosen, SuiteArgs};
use crate::analysis::separation::median;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteRun};
use crate::cli::CliError;
use crate::cli::compare::{Compared, Ran, Request, SideBySide, compare};
use crate::cli::output::Emit;
use crate::cli::subject::Study;
use crate::model::buildings::Row;
use crate::model::params::echo::g4;

/// Runs the suite of `args` on its row and on every `--compare` row, and
/// hands the side-by-side report to `emit`.
pub fn suite(
    args: &SuiteArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    compare(args, &args.compare_request(), emit)
}

impl SuiteArgs {
    /// What `--compare` is given with: `--buildings`, the variants and
    /// the sharding asked for.
    pub fn compare_request(&self) -> Request<'_> {
        Request {
            buildings: self.buildings.as_deref(),
            compare: &self.compare,
            shard: &self.shard,
        }
    }

    /// These arguments on the row `name` instead (a `--compare` variant,
    /// as given), with no variants of their own.
    pub fn on_variant(&self, name: &str) -> SuiteArgs {
        SuiteArgs {
            buildings: Some(name.to_string()),
            compare: Vec::new(),
            ..self.clone()
        }
    }

    /// The study of these arguments on the row `name` instead (a
    /// `--compare` variant, as given), with its records, checked.
    pub fn variant(&self, name: &str) -> Result<Study<RowSuiteCase>, CliError> {
        let Chosen::Row(study) = Chosen::of(&self.on_variant(name))? else {
            unreachable!("--buildings chooses a row");
        };
        Ok(study)
    }
}

impl Compared for SuiteArgs {
    type Variant = Study<RowSuiteCase>;
    type Summary = Summary;
    type Report<'a> = SuiteReport<'a, RowSuiteCase>;
    const STUDY: &'static str = "suite";

    fn load(&self, name: &str) -> Result<Study<RowSuiteCase>, CliError> {
        self.variant(name)
    }

    fn row(study: &Study<RowSuiteCase>) -> &Row {
        &study.subject.row
    }

    fn run<'a>(&'a self, study: &'a Study<RowSuiteCase>) -> Ran<Summary, Self::Report<'a>> {
        let Some((runs, elapsed_ms)) = study.run("suite", &self.shard, self.long.allow_long)?
        else {
            return Ok(None);
        };
        let summary = Summary::of(&study.subject.row, &runs);
        let report = report(&study.subject, &study.name, &self.suite, &runs, elapsed_ms);
        Ok(Some((summary, report)))
    }
}

/// One joint of a variant over the suite.
#[derive(Debug, Serialize)]
pub struct JointSummary {
    joint: String,
    /// The fraction of records with an impact at it.
    pounding_probability: f64,
    /// The median of its gap that prevents pounding (m).
    median_min_gap_m: f64,
}

/// One building of a variant over the suite.
#[derive(Debug, Serialize)]
pub struct BuildingSummary {
    name: String,
    /// Medians of max_i |Δ_i|/h_i, with pounding and with every joint open.
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    median_max_drift_ratio: f64,
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    no_pounding_median_max_drift_ratio: f64,
}

/// What the side-by-side summary gives of one variant.
#[derive(Debug, Serialize)]
pub struct Summary {
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

impl SideBySide for Summary {
    const HEADING: &'static str = "side by side: per joint P(pounding) and the median gap that prevents it, \
         per building the median peak storey drift ratio";

    fn table(variants: &[(&str, &Summary)], width: usize, s: &mut String) {
        let Some((_, first)) = variants.first() else {
            return;
        };
        let _ = write!(s, "{:<width$}", "variant");
        for j in &first.joints {
            let label = j.joint.split(' ').next().unwrap_or("");
            let _ = write!(
                s,
                " {:>14} {:>14}",
                format!("{label} P(pound)"),
                "d_min med mm"
            );
        }
        for b in &first.buildings {
            let _ = write!(s, " {:>16}", format!("{} drift %", b.name));
        }
        let _ = writeln!(s);
        for (name, summary) in variants {
            let _ = write!(s, "{:<width$}", name);
            for j in &summary.joints {
                let _ = write!(
                    s,
                    " {:>14} {:>14}",
                    g4(j.pounding_probability),
                    g4(j.median_min_gap_m * 1e3)
                );
            }
            for b in &summary.buildings {
                let _ = write!(s, " {:>16}", g4(b.median_max_drift_ratio * 100.0));
            }
            let _ = writeln!(s);
        }
    }
}
