//! `pounding suite`: the physical pair (`--preset`) or a row of buildings
//! (`--buildings`, SPEC §13) under every record of a suite, each scaled to
//! an intensity, with each record's demands and their statistics over the
//! suite (SPEC §12). The study itself is [`crate::analysis::suite`] over a
//! [`crate::analysis::subject::Subject`]; this module parses and runs it,
//! and [`report`] writes it, one handler and one writer for both subjects.

use clap::Args;

mod compare;
pub mod report;

use super::budget::{LongArg, Work, run_steps};
use super::output::{Emit, FormatArg, printer};
use super::params::ParamArgs;
use super::records::members;
use super::spelling::Spelling;
use super::subject::row::RowStudyArgs;
use super::subject::{CliSubject, Study};
use super::{CliError, usage};
use crate::analysis::subject::row::RowSuiteCase;
use crate::analysis::suite::{MemberPlan, Scaling, SuiteCase, SuiteRun};
use crate::model::Params;
use crate::model::intensity::IntensityMeasure;

#[derive(Debug, Clone, Default, Args)]
pub struct SuiteArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// The records: a directory (every record file in it, in name order), a
    /// text file with one `PATH [SCALE]` a line (`#` comments), or
    /// `synthetic:N[@SEED]` (N simulated records, made in memory).
    #[arg(long, value_name = "SUITE")]
    pub suite: String,
    /// Intensity measure: `pga`, or `sa:T`, the 5 %-damped pseudo-spectral
    /// acceleration at period T seconds, 0 < T ≤ 10 (SPEC §12) [default: pga];
    /// with --buildings, `sa` alone is Sa at the leftmost building's T₁.
    #[arg(long, value_name = "pga|sa:T")]
    pub im: Option<String>,
    /// Scale each record so that its intensity measure equals X, in g
    /// (`0.3` or `0.3g`); without it each record runs at its list's scale.
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub level: Option<String>,
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub long: LongArg,
    /// Exit 0 even when a record's result is unreliable (it is still flagged).
    #[arg(long)]
    pub allow_unreliable: bool,
    #[command(flatten)]
    pub shard: super::shard::ShardArgs,
    /// A row of shear buildings (SPEC §13) instead of the preset's pair: a
    /// built-in row (two-buildings, block-and-frame, three-in-series, block-and-frame-pdelta,
    /// block-and-frame-retrofit) or a
    /// path to a row preset; `--im sa` is then Sa at the leftmost building's
    /// T₁ (to four significant digits).
    #[arg(long, value_name = "NAME|PATH")]
    pub buildings: Option<String>,
    /// An IDA of a suite scaled to a target: its levels scale the suite as a
    /// whole (set by `ida --target`, not a flag of its own).
    #[arg(skip)]
    pub collective: bool,
    /// Scale the records to a target spectrum by the code's rule (see
    /// `records scale`) instead of --level; the suite's name then says so.
    #[command(flatten)]
    pub design: super::design::TargetArgs,
    /// With --buildings: run the same study on each of these rows too (a
    /// retrofit, say: built-in names or paths), each with the first row's
    /// buildings by name, and report them side by side.
    #[arg(long, value_name = "NAME|PATH", num_args = 1.., value_delimiter = ',')]
    pub compare: Vec<String>,
    /// With --target: T1 (s) [default: the pair's left T1, or the row's longest T1].
    #[arg(long, value_name = "T1")]
    pub period: Option<String>,
}

/// `--suite`, `--im` and `--level` for a command that runs one set or,
/// given `--suite`, a suite of records (`gap`, `map`).
#[derive(Debug, Clone, Default, Args)]
pub struct SuiteOptions {
    /// Over a suite of records, as `pounding suite --suite` takes it.
    #[arg(long, value_name = "SUITE")]
    pub suite: Option<String>,
    /// With --suite: the intensity measure, pga or sa:T [default: pga].
    #[arg(long, value_name = "pga|sa:T")]
    pub im: Option<String>,
    /// With --suite: scale each record so that its intensity measure equals X (g).
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub level: Option<String>,
    /// With --suite: scale the records to a target spectrum by the code's
    /// rule (T1: `--period`, else the buildings').
    #[command(flatten)]
    pub design: super::design::TargetArgs,
}

impl SuiteOptions {
    /// The suite request, with the command's own options, or `None`
    /// without `--suite`; `others` names the suite-only flags given (by
    /// their flags) that are refused without it.
    pub fn request(
        &self,
        params: &ParamArgs,
        output: FormatArg,
        long: LongArg,
        others: &[(&str, bool)],
    ) -> Result<Option<SuiteArgs>, CliError> {
        let Some(suite) = &self.suite else {
            let flags = [
                ("--im", self.im.is_some()),
                ("--level", self.level.is_some()),
                ("--target", self.design.target.is_some()),
            ];
            if let Some((flag, _)) = flags.iter().chain(others).find(|(_, given)| *given) {
                return Err(usage(format!(
                    "{flag}: applies to a suite of records; give --suite SUITE"
                )));
            }
            return Ok(None);
        };
        Ok(Some(SuiteArgs {
            params: params.clone(),
            suite: suite.clone(),
            im: self.im.clone(),
            level: self.level.clone(),
            output,
            long,
            allow_unreliable: true,
            design: self.design.clone(),
            ..SuiteArgs::default()
        }))
    }
}

impl SuiteArgs {
    /// These arguments with `--target` written into the suite's name
    /// ([`super::design_suite`]): the records scaled to the target by the
    /// code's rule, T1 `--period` or the buildings'.
    pub fn at_design_level(&self) -> Result<SuiteArgs, CliError> {
        let name = super::design_suite::scaled_name(
            &self.suite,
            &self.design,
            self.period.as_deref(),
            self.level.as_deref(),
            || match &self.buildings {
                Some(b) => super::design_suite::row_period(
                    &super::buildings::BuildingsArgs {
                        buildings: Some(b.clone()),
                        ..Default::default()
                    }
                    .row(&self.params.overrides, self.params.model.as_deref())?,
                ),
                None => super::design_suite::pair_period(&self.params),
            },
        )?;
        Ok(match name {
            Some(suite) => SuiteArgs {
                suite,
                design: Default::default(),
                period: None,
                ..self.clone()
            },
            None => self.clone(),
        })
    }

    /// The study on a row that `--buildings` asks for (`--level` read), or
    /// `None` without it.
    pub fn row_study(&self) -> Result<Option<RowStudyArgs<'_>>, CliError> {
        let Some(buildings) = &self.buildings else {
            return Ok(None);
        };
        Ok(Some(RowStudyArgs {
            buildings,
            params: &self.params,
            suite: &self.suite,
            im: self.im.as_deref(),
            level: self.level.as_deref().map(parse_level).transpose()?,
            allow_long: self.long.allow_long,
            shard: &self.shard,
            collective: self.collective,
        }))
    }
}

/// `--level X`: a positive, finite level in g (`0.3` or `0.3g`).
pub fn parse_level(text: &str) -> Result<f64, CliError> {
    let t = text.trim();
    let v = t.strip_suffix('g').unwrap_or(t).trim().parse::<f64>();
    match v {
        Ok(v) if v > 0.0 && v.is_finite() => Ok(v),
        _ => Err(usage(format!(
            "--level {}: must be a positive intensity in g, e.g. 0.3 or 0.3g",
            crate::model::params::echo::text(text)
        ))),
    }
}

/// The study asked for: the buildings, settings and scaling, checked.
pub fn case_of(args: &SuiteArgs) -> Result<(crate::model::Preset, SuiteCase), CliError> {
    if args.params.excitation.is_some() {
        return Err(usage(
            "--excitation: a suite runs the records of --suite; drop --excitation",
        ));
    }
    let (preset, settings) = args.params.resolve_for_many()?;
    let physical = args.params.physical(&preset)?.ok_or_else(|| {
        usage(format!(
            "preset `{}` has no [physical] table: a suite shakes the same physical buildings \
             with every record, each record's own a_p and ω_p setting the Π-groups (SPEC §12); \
             use a preset with [physical], such as two-buildings",
            preset.name
        ))
    })?;
    let measure = match &args.im {
        Some(text) => IntensityMeasure::parse(text).map_err(|e| usage(format!("--im {e}")))?,
        None => IntensityMeasure::Pga,
    };
    let level = args.level.as_deref().map(parse_level).transpose()?;
    Ok((
        preset,
        SuiteCase {
            physical,
            settings,
            scaling: Scaling {
                measure,
                level,
                collective: args.collective,
            },
        },
    ))
}

/// The work of one planned record: a pounding run and at most one run
/// without contact, each counted at its nominal steps.
pub fn record_steps(params: &Params) -> f64 {
    2.0 * run_steps(params)
}

/// The work of every planned record of a study.
pub fn work_of<'a>(plans: impl IntoIterator<Item = &'a MemberPlan>) -> Work {
    Work::steps(plans.into_iter().map(|m| record_steps(&m.params)).sum())
}

pub fn execute(args: &SuiteArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The suite study of `args`, on the subject `--preset` or `--buildings`
/// chooses, its typed report handed to `emit`.
pub fn report_with(
    args: &SuiteArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let args = &args.at_design_level()?;
    if !args.compare.is_empty() {
        return compare::suite(args, emit);
    }
    match Chosen::of(args)? {
        Chosen::Pair(study) => suite(&study, args, emit),
        Chosen::Row(study) => suite(&study, args, emit),
    }
}

/// The suite of `study`: its records run (or sharded, or merged), reported,
/// and refused after the report where a record's result is unreliable
/// unless `--allow-unreliable`.
fn suite<S: Spelling>(
    study: &Study<S>,
    args: &SuiteArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let Some((runs, elapsed_ms)) = study.run("suite", &args.shard, args.long.allow_long)? else {
        return Ok(());
    };
    let subject = &study.subject;
    emit(&report::report(
        subject,
        &study.name,
        &args.suite,
        &runs,
        elapsed_ms,
    ))?;
    let unreliable: Vec<String> = runs
        .iter()
        .filter_map(|r| {
            let why = study.subject.unreliable(r)?;
            Some(format!("{}: {why}", S::record_name(r)))
        })
        .collect();
    if !unreliable.is_empty() && !args.allow_unreliable {
        return Err(CliError::Failed(format!(
            "unreliable result for {} of {} records ({}); pass --allow-unreliable to accept them",
            unreliable.len(),
            runs.len(),
            unreliable.join("; ")
        )));
    }
    Ok(())
}

/// The subject `--preset` (the physical pair) or `--buildings` (a row)
/// chooses, with its records.
pub enum Chosen {
    Pair(Study<SuiteCase>),
    Row(Study<RowSuiteCase>),
}

impl Chosen {
    /// The subject and records of `args`, checked (`--level` read).
    pub fn of(args: &SuiteArgs) -> Result<Chosen, CliError> {
        if let Some(study) = args.row_study()? {
            let (subject, members) = super::subject::row::case_of(&study)?;
            return Ok(Chosen::Row(Study {
                subject,
                name: study.buildings.to_string(),
                members,
            }));
        }
        let (preset, subject) = case_of(args)?;
        Ok(Chosen::Pair(Study {
            subject,
            name: preset.name,
            members: members(&args.suite)?,
        }))
    }
}

impl CliSubject for SuiteCase {
    fn work_of(&self, _: &[crate::model::suite::SuiteMember], plans: &[Vec<MemberPlan>]) -> Work {
        work_of(plans.iter().flatten())
    }

    fn check(&self, work: &Work, command: &str, allow_long: bool) -> Result<(), CliError> {
        work.check(command, allow_long, false)
    }

    fn steps(&self, run: &SuiteRun) -> f64 {
        record_steps(&run.params)
    }

    fn failed(e: crate::analysis::suite::SuiteRunError) -> CliError {
        CliError::Usage(e.to_string())
    }

    fn record_name(run: &SuiteRun) -> &str {
        &run.name
    }

    fn unreliable(&self, run: &SuiteRun) -> Option<String> {
        run.result.unreliable()
    }

    fn free_run_stopped(&self, run: &SuiteRun) -> bool {
        !run.free.completed
    }
}
