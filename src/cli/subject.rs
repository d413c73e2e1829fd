//! What the command line needs of a study's subject beside the study
//! itself ([`crate::analysis::subject`]): what its records cost for the work
//! bound and the progress bar, and how its failures are reported (the
//! pair's in [`super::suite`], a row's in [`row`]). One run of a suite or
//! of an IDA's levels, with `--shard` and under `merge`, is then written
//! once for the pair and a row ([`run_levels_or_shard`], [`Study::run`]).

pub mod row;

use std::time::Instant;

use super::CliError;
use super::budget::Work;
use super::progress::Progress;
use super::shard::ShardArgs;
use crate::analysis::subject::Subject;
use crate::analysis::subject::runs::{plan, run_levels};
use crate::model::suite::SuiteMember;

/// A subject as the command line runs it.
pub trait CliSubject: Subject {
    /// The work of running every planned record of `plans` (level by level).
    fn work_of(&self, members: &[SuiteMember], plans: &[Vec<Self::Plan>]) -> Work;
    /// Checks `work` against the bound, naming `command`.
    fn check(&self, work: &Work, command: &str, allow_long: bool) -> Result<(), CliError>;
    /// The steps one record's run took, for the progress bar.
    fn steps(&self, run: &Self::Run) -> f64;
    /// A failed record as the command line reports it.
    fn failed(e: Self::Error) -> CliError;
    /// The record's name in its suite.
    fn record_name(run: &Self::Run) -> &str;
    /// Why the record's result is unreliable, if it is (the pair's solver
    /// says so; a row's runs fail instead).
    fn unreliable(&self, _run: &Self::Run) -> Option<String> {
        None
    }
    /// The record's run without contact stopped before its end, so its
    /// gaps cover only the part that was run.
    fn free_run_stopped(&self, _run: &Self::Run) -> bool {
        false
    }
}

/// A suite's runs in suite order and the wall time in ms; `None` when a
/// shard's part was written.
pub type SuiteRuns<R> = Result<Option<(Vec<R>, f64)>, CliError>;

/// A suite study's subject with its records: `name` is what names it in
/// shards' parts and reports (the preset's name, or `--buildings` as given).
pub struct Study<S> {
    pub subject: S,
    pub name: String,
    pub members: Vec<SuiteMember>,
}

impl<S: CliSubject> Study<S> {
    /// Plans every record before any run (a record that cannot be scaled,
    /// or whose plan is out of range, fails at once and names it) and runs
    /// them ([`run_levels_or_shard`] at one level): the runs in suite order
    /// and the wall time in ms, or `None` when a shard's part was written.
    /// `command` names the request in the work bound's message and in parts.
    pub fn run(&self, command: &str, shard: &ShardArgs, allow_long: bool) -> SuiteRuns<S::Run> {
        let plans = [plan(&self.subject, &self.members).map_err(S::failed)?];
        let ran = run_levels_or_shard(
            &self.subject,
            &self.name,
            &self.members,
            &plans,
            command,
            shard,
            allow_long,
            &(),
        )?;
        Ok(ran.map(|(runs, elapsed_ms)| (runs.into_iter().flatten().collect(), elapsed_ms)))
    }
}

/// Each level's runs and the wall time in ms; `None` when a shard's part
/// was written.
pub type LevelRuns<R> = Result<Option<(Vec<Vec<R>>, f64)>, CliError>;

/// Runs every planned record of `plans` (level by level) within the work
/// bound, with progress, or with `--shard` one shard of them (then `None`:
/// its part was written), or under `pounding merge` their runs from the
/// parts; level by level, with the wall time in ms (the merged parts' when
/// merged). `name` names the subject in the parts, `extra` what else the
/// command reports from its request.
#[allow(clippy::too_many_arguments)]
pub fn run_levels_or_shard<S: CliSubject>(
    subject: &S,
    name: &str,
    members: &[SuiteMember],
    plans: &[Vec<S::Plan>],
    command: &str,
    shard: &ShardArgs,
    allow_long: bool,
    extra: &impl std::fmt::Debug,
) -> LevelRuns<S::Run> {
    let work = subject.work_of(members, plans);
    subject.check(&work, command, allow_long)?;
    let progress = Progress::start(&work);
    let start = Instant::now();
    // The units level by level, each in suite order.
    let units: Vec<_> = plans
        .iter()
        .flat_map(|level| level.iter().enumerate())
        .collect();
    let Some((flat, merged_ms)) = super::shard::suite::runs(
        shard,
        command,
        name,
        subject,
        members,
        &units,
        extra,
        S::failed,
        || {
            let done = |r: &S::Run| progress.add(subject.steps(r));
            let runs = run_levels(subject, members, plans, &done).map_err(S::failed)?;
            Ok(runs.into_iter().flatten().collect())
        },
    )?
    else {
        return Ok(None);
    };
    drop(progress);
    let mut flat = flat.into_iter();
    let runs = plans
        .iter()
        .map(|level| flat.by_ref().take(level.len()).collect())
        .collect();
    Ok(Some((
        runs,
        merged_ms.unwrap_or(start.elapsed().as_secs_f64() * 1e3),
    )))
}
