//! `suite --buildings` and `ida --buildings` with `--shard`: their records
//! (at each level) through [`super::ShardArgs::try_sweep`].

use super::{Results, ShardArgs, Sweep};
use crate::analysis::row_suite::{RowSuiteCase, RowSuiteRun};
use crate::analysis::shard::row_suite::{RowUnit, compute, fingerprint, rebuild, unit_work};
use crate::cli::CliError;
use crate::model::suite::SuiteMember;

/// Every unit's record, with the merged parts' time in ms when they come
/// from parts; `None` when a shard's part was written. `extra` is what else
/// the command reports from its request (levels, limit states); `failed`
/// turns a run's failure into the command's error.
#[allow(clippy::too_many_arguments)]
pub fn runs(
    shard: &ShardArgs,
    command: &str,
    row_name: &str,
    case: &RowSuiteCase,
    members: &[SuiteMember],
    units: &[RowUnit],
    extra: &impl std::fmt::Debug,
    failed: impl Fn(crate::analysis::row_suite::RowSuiteError) -> CliError,
    whole: impl FnOnce() -> Result<Vec<RowSuiteRun>, CliError>,
) -> Results<Vec<RowSuiteRun>> {
    shard.check()?;
    if !shard.active() {
        return Ok(Some((whole()?, None)));
    }
    let fp = fingerprint(command, row_name, case, members, units, extra);
    let work = unit_work(&case.row, members, units);
    let row = &case.row;
    Ok(
        match shard.try_sweep(command, fp, &work, |mine| {
            compute(row, members, units, mine).map_err(&failed)
        })? {
            Sweep::Whole => Some((whole()?, None)),
            Sweep::Done => None,
            Sweep::Merged(runs, ms) => Some((rebuild(row, members, units, runs), Some(ms))),
        },
    )
}
