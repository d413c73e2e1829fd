//! A row of buildings (`--buildings`) as the command line builds and runs
//! it for a study (SPEC §12, §13): the flags a row refuses, its records'
//! work and how its failures are reported.

use super::CliSubject;
use crate::analysis::subject::row::record_seconds;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteError, RowSuiteRun, row_intensity};
use crate::analysis::suite::Scaling;
use crate::cli::budget::{SECONDS_PER_STEP, Work};
use crate::cli::buildings::BuildingsArgs;
use crate::cli::params::ParamArgs;
use crate::cli::records::members;
use crate::cli::shard::ShardArgs;
use crate::cli::{CliError, usage};
use crate::model::buildings::Row;
use crate::model::intensity::IntensityMeasure;
use crate::model::suite::SuiteMember;

/// A study on a row as the command line asks for it (`--buildings`):
/// what `suite`, `ida` and `gap` on a row share.
#[derive(Debug, Clone, Copy)]
pub struct RowStudyArgs<'a> {
    /// `--buildings`: a built-in row or a path.
    pub buildings: &'a str,
    /// `--set`, `--model`, and the pair's flags a row refuses.
    pub params: &'a ParamArgs,
    pub suite: &'a str,
    pub im: Option<&'a str>,
    /// `--level` (g).
    pub level: Option<f64>,
    pub allow_long: bool,
    /// `--shard`, `--part`, `--skip-done` (and a merge's parts).
    pub shard: &'a ShardArgs,
    /// An IDA's levels scale the suite as a whole ([`Scaling::collective`]).
    pub collective: bool,
}

/// The row study of `args`, checked: the row with `--set` and `--model`
/// applied, its scaling and its records.
pub fn case_of(args: &RowStudyArgs) -> Result<(RowSuiteCase, Vec<SuiteMember>), CliError> {
    let p = args.params;
    let refused = [
        ("--preset", p.preset.is_some(), "a row is its own preset"),
        (
            "--excitation",
            p.excitation.is_some(),
            "a suite runs the records of --suite",
        ),
        ("--dt", p.dt.is_some(), "a row suite runs the exact method"),
        (
            "--cycles",
            p.cycles.is_some(),
            "records have their own length",
        ),
        (
            "--no-pounding",
            p.no_pounding,
            "each record also runs without contact; both are reported",
        ),
        (
            "--presets",
            p.presets.is_some(),
            "rows are read by --buildings",
        ),
    ];
    if let Some((flag, _, why)) = refused.iter().find(|(_, given, _)| *given) {
        return Err(usage(format!(
            "{flag}: not with --buildings ({why}); drop {flag}"
        )));
    }
    if let Some(m) = p.method.as_deref().filter(|m| *m != "exact") {
        return Err(usage(format!(
            "--method {}: a row suite runs the exact method; drop --method or give exact",
            crate::model::params::echo::text(m)
        )));
    }
    let row = BuildingsArgs {
        buildings: Some(args.buildings.to_string()),
        ..BuildingsArgs::default()
    }
    .row(&p.overrides, p.model.as_deref())?;
    let measure = match args.im.map(str::trim) {
        None => IntensityMeasure::Pga,
        Some(text) if text.eq_ignore_ascii_case("sa") => row_intensity(&row),
        Some(text) => IntensityMeasure::parse(text).map_err(|e| {
            usage(format!(
                "--im {e}; or sa alone for a row: Sa(T₁) of its leftmost building"
            ))
        })?,
    };
    let level = args.level;
    let members = members(args.suite)?;
    Ok((
        RowSuiteCase {
            row,
            scaling: Scaling {
                measure,
                level,
                collective: args.collective,
            },
        },
        members,
    ))
}

/// The estimated work of one record's runs ([`record_seconds`]), in the
/// commands' steps. `samples` at interval `dt` (s).
pub fn record_steps(row: &Row, samples: usize, dt: f64) -> f64 {
    record_seconds(row, samples, dt) / SECONDS_PER_STEP
}

/// The work of running every member `times` times (levels of an IDA).
pub fn work_of(row: &Row, members: &[SuiteMember], times: usize) -> Work {
    let record = |m: &SuiteMember| record_steps(row, m.record.acceleration.len(), m.record.dt);
    Work::steps(times as f64 * members.iter().map(record).sum::<f64>())
}

/// A failed row study as the command line reports it: a record that cannot
/// be scaled is bad input, a runaway run a failure.
pub fn failed(e: RowSuiteError) -> CliError {
    match &e {
        RowSuiteError::Run {
            error:
                crate::solver::buildings::RowError::Runaway(_)
                | crate::solver::buildings::RowError::Unconverged(_),
            ..
        } => CliError::Failed(e.to_string()),
        _ => usage(e.to_string()),
    }
}

impl CliSubject for RowSuiteCase {
    fn work_of(&self, members: &[SuiteMember], plans: &[Vec<(f64, f64)>]) -> Work {
        work_of(&self.row, members, plans.len())
    }

    fn check(&self, work: &Work, command: &str, allow_long: bool) -> Result<(), CliError> {
        work.check(&format!("{command} --buildings"), allow_long, true)
    }

    fn steps(&self, run: &RowSuiteRun) -> f64 {
        record_steps(&self.row, run.samples, run.dt)
    }

    fn failed(e: RowSuiteError) -> CliError {
        failed(e)
    }

    fn record_name(run: &RowSuiteRun) -> &str {
        &run.name
    }
}
