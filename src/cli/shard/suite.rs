//! `suite`, `ida` and `map --suite` with `--shard`, on the pair or a row:
//! their sweeps through [`super::ShardArgs::try_sweep`].

use super::{Results, ShardArgs, Sweep};
use crate::analysis::shard::Fingerprint;
use crate::analysis::shard::suite::{Unit, add_records, compute, fingerprint, rebuild, unit_work};
use crate::analysis::subject::Subject;
use crate::analysis::suite_map::{MapSubject, compute_listed};
use crate::cli::CliError;
use crate::model::suite::SuiteMember;

/// Every unit's record, with the merged parts' time in ms when they come
/// from parts; `None` when a shard's part was written. `name` names the
/// subject (the preset or the row), `extra` is what else the command
/// reports from its request (levels, limit states); `failed` turns a run's
/// failure into the command's error.
#[allow(clippy::too_many_arguments)]
pub fn runs<S: Subject>(
    shard: &ShardArgs,
    command: &str,
    name: &str,
    subject: &S,
    members: &[SuiteMember],
    units: &[Unit<S::Plan>],
    extra: &impl std::fmt::Debug,
    failed: impl Fn(S::Error) -> CliError,
    whole: impl FnOnce() -> Result<Vec<S::Run>, CliError>,
) -> Results<Vec<S::Run>> {
    shard.check()?;
    if !shard.active() {
        return Ok(Some((whole()?, None)));
    }
    let fp = fingerprint(command, name, subject, members, units, extra);
    let work = unit_work(subject, members, units);
    Ok(
        match shard.try_sweep(command, fp, &work, |mine| {
            compute(subject, members, units, mine).map_err(&failed)
        })? {
            Sweep::Whole => Some((whole()?, None)),
            Sweep::Done => None,
            Sweep::Merged(runs, ms) => Some((rebuild(subject, members, units, runs), Some(ms))),
        },
    )
}

/// A suite map's cells from a shard or from parts: [`Sweep::Whole`] when
/// neither is asked for (the caller computes row by row as it prints). A
/// unit is one cell: its records' runs, reduced to the cell. `failed`
/// turns a run's failure into the command's error.
pub fn map_cells<S: MapSubject>(
    shard: &ShardArgs,
    name: &str,
    cells: &[(f64, f64, S)],
    plans: &[Vec<S::Plan>],
    members: &[SuiteMember],
    extra: &impl std::fmt::Debug,
    failed: impl Fn(S::Error) -> CliError,
) -> Result<Sweep<S::Cell>, CliError> {
    shard.check()?;
    if !shard.active() {
        return Ok(Sweep::Whole);
    }
    let Some((_, _, first)) = cells.first() else {
        return Ok(Sweep::Whole);
    };
    let all: Vec<&S::Plan> = plans.iter().flatten().collect();
    let mut fp = Fingerprint::new("map-suite");
    first.describe(&mut fp, name);
    add_records(&mut fp, members);
    fp.add_debug(&all);
    fp.add_debug(&(extra, cells));
    let work: Vec<f64> = cells
        .iter()
        .zip(plans)
        .map(|((_, _, s), cell)| members.iter().zip(cell).map(|(m, p)| s.work(m, p)).sum())
        .collect();
    shard.try_sweep("map-suite", fp, &work, |mine| {
        compute_listed(cells, plans, members, mine, &|| {}).map_err(failed)
    })
}
