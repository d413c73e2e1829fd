//! `pounding ida`: incremental dynamic analysis of a suite (every record at
//! every intensity level), the statistics per level, and the lognormal
//! fragility of each limit state with and without pounding (SPEC §12). The
//! study is [`crate::analysis::ida`], one path for the pair (`--preset`) and
//! a row (`--buildings`, SPEC §13); this module parses and runs it, and
//! its `report` writes it, one writer for both subjects. With `--compare`, the
//! same IDA runs on each variant of a row, side by side (module `compare`).

use clap::Args;
use serde::Serialize;

mod compare;
mod report;

use super::CliError;
use super::limit_states::{LimitStateArgs, RowLimitArgs, limit_states};
use super::output::{Emit, printer};
use super::records::members;
use super::subject::row::RowStudyArgs;
use super::subject::{CliSubject, run_levels_or_shard};
use super::suite::{SuiteArgs, case_of};
use crate::analysis::ida::{LimitStateFragility, fragilities, parse_levels};
use crate::analysis::limit_state::LimitState;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteRun};
use crate::analysis::subject::runs::plan_levels;
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::model::suite::SuiteMember;

#[derive(Debug, Clone, Default, Args)]
pub struct IdaArgs {
    /// The preset, suite, intensity measure and output options of `pounding suite`.
    #[command(flatten)]
    pub suite: SuiteArgs,
    /// Intensity levels in g: START:STOP:STEP (e.g. 0.05:1.0:0.05) or a
    /// list X1,X2,…, ascending and > 0.
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub levels: String,
    #[command(flatten)]
    pub limits: LimitStateArgs,
    #[command(flatten)]
    pub row_limits: RowLimitArgs,
}

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

pub fn execute(args: &IdaArgs) -> Result<(), CliError> {
    report_with(args, printer(args.suite.output.format))
}

/// The IDA of `args` with its fragilities, its typed report handed to `emit`.
pub fn report_with(
    args: &IdaArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    if args.suite.level.is_some() {
        return Err(usage(
            "--level: an IDA runs every level of --levels; use `pounding suite` for one".into(),
        ));
    }
    // With --target, the records are first scaled to the design spectrum by
    // the code's rule, and each level then scales that suite as a whole
    // (FEMA P-695), keeping the code's proportions between records.
    let args = &IdaArgs {
        suite: SuiteArgs {
            collective: args.suite.design.target.is_some(),
            ..args.suite.at_design_level()?
        },
        ..args.clone()
    };
    let study = args.suite.row_study()?;
    if study.is_none() {
        args.row_limits.refuse_on_a_pair()?;
    }
    let levels = parse_levels(&args.levels).map_err(usage)?;
    if !args.suite.compare.is_empty() {
        return compare::ida(args, levels, emit);
    }
    if let Some(study) = study {
        let row = RowIda::load(args, &study)?;
        let ran = row.run(&levels, &args.suite)?;
        return ran.map_or(Ok(()), |ran| {
            emit(&report::report(&row.case, &row.name, study.suite, ran))
        });
    }
    let states = limit_states(&args.limits, &args.row_limits, None)?;
    let (preset, case) = case_of(&args.suite)?;
    let members = members(&args.suite.suite)?;
    let Some(ran) = ida(&case, &preset.name, &members, levels, states, &args.suite)? else {
        return Ok(());
    };
    let unreliable = ran
        .runs
        .iter()
        .flatten()
        .filter(|r| r.result.unreliable().is_some())
        .count();
    let total = ran.runs.iter().map(Vec::len).sum::<usize>();
    emit(&report::report(&case, &preset.name, &args.suite.suite, ran))?;
    if unreliable > 0 && !args.suite.allow_unreliable {
        return Err(CliError::Failed(format!(
            "unreliable result for {unreliable} of {total} runs (flagged in the output); \
             pass --allow-unreliable to accept them"
        )));
    }
    Ok(())
}

/// The IDA of a row (`--buildings`), loaded and checked before any run:
/// the row and its scaling, its records and its limit states.
struct RowIda {
    case: RowSuiteCase,
    /// `--buildings` as given, naming the row in shards' parts.
    name: String,
    members: Vec<SuiteMember>,
    states: Vec<LimitState>,
}

impl RowIda {
    /// The row `study` with the limit states `args` ask of it.
    fn load(args: &IdaArgs, study: &RowStudyArgs) -> Result<RowIda, CliError> {
        let (case, members) = super::subject::row::case_of(study)?;
        let states = limit_states(&args.limits, &args.row_limits, Some(&case.row))?;
        Ok(RowIda {
            case,
            name: study.buildings.to_string(),
            members,
            states,
        })
    }

    /// Its IDA at `levels` ([`ida`]).
    fn run(
        &self,
        levels: &[f64],
        args: &SuiteArgs,
    ) -> Result<Option<IdaRan<RowSuiteRun>>, CliError> {
        let states = self.states.clone();
        ida(
            &self.case,
            &self.name,
            &self.members,
            levels.to_vec(),
            states,
            args,
        )
    }
}

/// An IDA that ran: its levels and limit states, each level's runs, the
/// fragilities and the wall time.
struct IdaRan<R> {
    levels: Vec<f64>,
    records: usize,
    states: Vec<LimitState>,
    runs: Vec<Vec<R>>,
    fragility: Vec<LimitStateFragility>,
    elapsed_ms: f64,
}

impl<R> IdaRan<R> {
    /// Each level's statistics and rows, as a report writes them.
    fn levels<T>(
        &self,
        statistics: impl Fn(&[R]) -> SuiteStatistics,
        row: impl Fn(&R) -> T,
    ) -> Vec<LevelReport<T>> {
        self.levels
            .iter()
            .zip(&self.runs)
            .map(|(&level, at)| LevelReport {
                level_g: level,
                statistics: statistics(at),
                records: at.iter().map(&row).collect(),
            })
            .collect()
    }
}

/// The IDA of `subject` (named `name` in shards' parts) at `levels`: every
/// record planned, run within the bound (or sharded, or merged) and the
/// fragility of each limit state of `states` fitted; `None` when a shard's
/// part was written.
fn ida<S: CliSubject>(
    subject: &S,
    name: &str,
    members: &[SuiteMember],
    levels: Vec<f64>,
    states: Vec<LimitState>,
    args: &SuiteArgs,
) -> Result<Option<IdaRan<S::Run>>, CliError> {
    let plans = plan_levels(subject, members, &levels).map_err(S::failed)?;
    let extra = (&levels, &states);
    let shard = &args.shard;
    let allow_long = args.long.allow_long;
    let Some((runs, elapsed_ms)) = run_levels_or_shard(
        subject, name, members, &plans, "ida", shard, allow_long, &extra,
    )?
    else {
        return Ok(None);
    };
    let fragility = fragilities(subject, &levels, &runs, &states);
    Ok(Some(IdaRan {
        records: members.len(),
        levels,
        states,
        runs,
        fragility,
        elapsed_ms,
    }))
}

/// One intensity level: its statistics and its rows (those of `pounding
/// suite --level` at that level).
#[derive(Debug, Serialize)]
struct LevelReport<T> {
    level_g: f64,
    statistics: SuiteStatistics,
    records: Vec<T>,
}
