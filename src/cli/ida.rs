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
use super::spelling::Spelling;
use super::subject::row::RowStudyArgs;
use super::subject::{Study, run_levels_or_shard};
use super::suite::{SuiteArgs, case_of};
use crate::analysis::ida::{LimitStateFragility, fragilities, parse_levels};
use crate::analysis::limit_state::LimitState;
use crate::analysis::subject::row::RowSuiteCase;
use crate::analysis::subject::runs::plan_levels;
use crate::analysis::suite_statistics::SuiteStatistics;

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
    match study {
        Some(study) => Ida::on_row(args, &study)?.report(&levels, args, emit),
        None => {
            let states = limit_states(&args.limits, &args.row_limits, None)?;
            let (preset, subject) = case_of(&args.suite)?;
            let members = members(&args.suite.suite)?;
            let study = Study {
                subject,
                name: preset.name,
                members,
            };
            Ida { study, states }.report(&levels, args, emit)
        }
    }
}

/// An IDA, loaded and checked before any run: the subject with its
/// records, and its limit states.
struct Ida<S> {
    study: Study<S>,
    states: Vec<LimitState>,
}

impl Ida<RowSuiteCase> {
    /// The row `study` with the limit states `args` ask of it.
    fn on_row(args: &IdaArgs, study: &RowStudyArgs) -> Result<Self, CliError> {
        let (subject, members) = super::subject::row::case_of(study)?;
        let states = limit_states(&args.limits, &args.row_limits, Some(&subject.row))?;
        let name = study.buildings.to_string();
        let study = Study {
            subject,
            name,
            members,
        };
        Ok(Ida { study, states })
    }
}

impl<S: Spelling> Ida<S> {
    /// Its IDA at `levels`, reported to `emit`, and refused after the
    /// report where a run's result is unreliable unless
    /// `--allow-unreliable`.
    fn report(
        &self,
        levels: &[f64],
        args: &IdaArgs,
        emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
    ) -> Result<(), CliError> {
        let Some(ran) = self.run(levels, &args.suite)? else {
            return Ok(());
        };
        let (subject, suite) = (&self.study.subject, &args.suite.suite);
        let all = ran.runs.iter().flatten();
        let unreliable = all.filter(|r| subject.unreliable(r).is_some()).count();
        let total = ran.runs.iter().map(Vec::len).sum::<usize>();
        emit(&report::report(subject, &self.study.name, suite, ran))?;
        if unreliable > 0 && !args.suite.allow_unreliable {
            return Err(CliError::Failed(format!(
                "unreliable result for {unreliable} of {total} runs (flagged in the output); \
                 pass --allow-unreliable to accept them"
            )));
        }
        Ok(())
    }

    /// Its IDA at `levels`: every record planned, run within the bound (or
    /// sharded, or merged) and the fragility of each limit state fitted;
    /// `None` when a shard's part was written.
    fn run(&self, levels: &[f64], args: &SuiteArgs) -> Result<Option<IdaRan<S::Run>>, CliError> {
        let Study {
            subject,
            name,
            members,
        } = &self.study;
        let plans = plan_levels(subject, members, levels).map_err(S::failed)?;
        let extra = (&levels, &self.states);
        let shard = &args.shard;
        let allow_long = args.long.allow_long;
        let Some((runs, elapsed_ms)) = run_levels_or_shard(
            subject, name, members, &plans, "ida", shard, allow_long, &extra,
        )?
        else {
            return Ok(None);
        };
        let fragility = fragilities(subject, levels, &runs, &self.states);
        Ok(Some(IdaRan {
            records: members.len(),
            levels: levels.to_vec(),
            states: self.states.clone(),
            runs,
            fragility,
            elapsed_ms,
        }))
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

/// One intensity level: its statistics and its rows (those of `pounding
/// suite --level` at that level).
#[derive(Debug, Serialize)]
struct LevelReport<T> {
    level_g: f64,
    statistics: SuiteStatistics,
    records: Vec<T>,
}
