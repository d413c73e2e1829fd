//! `pounding ida --buildings ROW --compare ROW2,…`: the same IDA (the same
//! records, intensity measure, levels and limit states) run on each variant
//! of a row, a retrofit say, and reported side by side (SPEC §12, §14;
//! [`crate::cli::compare`]).
//!
//! Each variant's report is bit for bit the report `ida --buildings` makes
//! of it alone (but its wall time); the summary beside them gives, per
//! limit state and variant, the maximum-likelihood lognormal fragility
//! P(exceed | IM = x) = Φ(ln(x/θ)/β) (SPEC §12): its median θ and
//! dispersion β, or why there is none, with pounding and with every joint
//! open. The pounding limit state has the first only.

use std::fmt::Write as _;

use serde::Serialize;

use super::report::{IdaReport, report};
use super::{Ida, IdaArgs};
use crate::analysis::fragility::{Fragility, describe};
use crate::analysis::ida::LimitStateFragility;
use crate::analysis::subject::row::RowSuiteCase;
use crate::cli::CliError;
use crate::cli::compare::{Compared, Ran, SideBySide, compare};
use crate::cli::output::Emit;
use crate::model::buildings::Row;

/// Runs the IDA of `args` at `levels` on its row and on every `--compare`
/// row, and hands the side-by-side report to `emit`.
pub(super) fn ida(
    args: &IdaArgs,
    levels: Vec<f64>,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let request = args.suite.compare_request();
    compare(&IdaCompare { args, levels }, &request, emit)
}

/// The IDA asked for, at its levels.
struct IdaCompare<'a> {
    args: &'a IdaArgs,
    levels: Vec<f64>,
}

impl Compared for IdaCompare<'_> {
    type Variant = Ida<RowSuiteCase>;
    type Summary = Summary;
    type Report<'a>
        = IdaReport<'a, RowSuiteCase>
    where
        Self: 'a;
    const STUDY: &'static str = "IDA";

    fn load(&self, name: &str) -> Result<Ida<RowSuiteCase>, CliError> {
        let suite = self.args.suite.on_variant(name);
        let Some(study) = suite.row_study()? else {
            unreachable!("--buildings chooses a row");
        };
        Ida::on_row(self.args, &study)
    }

    fn row(variant: &Ida<RowSuiteCase>) -> &Row {
        &variant.study.subject.row
    }

    fn run<'a>(&'a self, variant: &'a Ida<RowSuiteCase>) -> Ran<Summary, Self::Report<'a>> {
        let Some(ran) = variant.run(&self.levels, &self.args.suite)? else {
            return Ok(None);
        };
        let summary = Summary::of(&ran.fragility);
        let suite = &self.args.suite.suite;
        let report = report(&variant.study.subject, &variant.study.name, suite, ran);
        Ok(Some((summary, report)))
    }
}

/// One limit state of a variant: its fragility, with pounding and with
/// every joint open (none for pounding, which the open row never reaches).
#[derive(Debug, Serialize)]
pub(super) struct StateSummary {
    limit_state: String,
    fragility: Fragility,
    #[serde(skip_serializing_if = "Option::is_none")]
    no_pounding_fragility: Option<Fragility>,
}

/// What the side-by-side summary gives of one variant: each limit state's
/// fragility, in the order the IDA fits them (pounding first).
#[derive(Debug, Serialize)]
pub(super) struct Summary {
    limit_states: Vec<StateSummary>,
}

impl Summary {
    fn of(fragility: &[LimitStateFragility]) -> Summary {
        let limit_states = fragility
            .iter()
            .map(|f| StateSummary {
                limit_state: f.limit_state.clone(),
                fragility: f.fragility,
                no_pounding_fragility: f.no_pounding_fragility,
            })
            .collect();
        Summary { limit_states }
    }
}

impl SideBySide for Summary {
    const HEADING: &'static str = "side by side: per limit state the lognormal fragility Φ(ln(x/θ)/β) (SPEC §12), \
         its median θ and dispersion β or why there is none, with pounding and with \
         every joint open";

    /// One block per limit state, one line per variant in it: θ and β
    /// (or why there is no fit) with pounding, and with every joint open.
    /// The limit states are those of every variant, in order of first
    /// appearance: `--collapse` asks one of each building with P-Δ, which
    /// a variant may have and another not.
    fn table(variants: &[(&str, &Summary)], width: usize, s: &mut String) {
        let mut states: Vec<&str> = Vec::new();
        for (_, summary) in variants {
            for l in &summary.limit_states {
                if !states.contains(&l.limit_state.as_str()) {
                    states.push(&l.limit_state);
                }
            }
        }
        // Each cell: the fits with pounding and apart, or why there are none.
        let cells: Vec<Vec<(String, String)>> = states
            .iter()
            .map(|state| {
                variants
                    .iter()
                    .map(|(_, summary)| {
                        let found = summary
                            .limit_states
                            .iter()
                            .find(|l| l.limit_state == *state);
                        match found {
                            Some(l) => (
                                describe(&l.fragility),
                                l.no_pounding_fragility
                                    .as_ref()
                                    .map_or("-".to_string(), describe),
                            ),
                            None => ("not a limit state of this row".to_string(), String::new()),
                        }
                    })
                    .collect()
            })
            .collect();
        let state_width = states
            .iter()
            .map(|l| l.chars().count())
            .max()
            .unwrap_or(0)
            .max("limit state".len());
        let with_width = cells
            .iter()
            .flatten()
            .map(|(with, _)| with.chars().count())
            .max()
            .unwrap_or(0)
            .max("with pounding".len());
        let _ = writeln!(
            s,
            "{:<state_width$}  {:<width$}  {:<with_width$}  every joint open",
            "limit state", "variant", "with pounding"
        );
        for (state, row) in states.iter().zip(&cells) {
            for (v, ((name, _), (with, apart))) in variants.iter().zip(row).enumerate() {
                let label = if v == 0 { state } else { "" };
                let line =
                    format!("{label:<state_width$}  {name:<width$}  {with:<with_width$}  {apart}");
                let _ = writeln!(s, "{}", line.trim_end());
            }
        }
    }
}
