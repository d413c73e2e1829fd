//! `suite`, `ida` and `map --suite` with `--shard`: their sweeps through
//! [`super::ShardArgs::sweep`].

use super::{Results, ShardArgs, Sweep};
use crate::analysis::shard::suite::{Pair, compute, fingerprint, member_work, rebuild};
use crate::analysis::suite::{MemberPlan, SuiteCase, SuiteRun};
use crate::analysis::suite_map::{SuiteMapCell, compute_listed};
use crate::cli::CliError;
use crate::model::suite::SuiteMember;

/// Every pair's row, with the merged parts' time in ms when they come from
/// parts; `None` when a shard's part was written. `extra` is what else the
/// command reports from its request (levels, limit states).
pub fn runs(
    shard: &ShardArgs,
    command: &str,
    preset: &str,
    pairs: &[Pair],
    members: &[SuiteMember],
    extra: &impl std::fmt::Debug,
    whole: impl FnOnce() -> Vec<SuiteRun>,
) -> Results<Vec<SuiteRun>> {
    shard.check()?;
    if !shard.active() {
        return Ok(Some((whole(), None)));
    }
    let Some(&(case, _, _)) = pairs.first() else {
        return Ok(Some((whole(), None)));
    };
    let plans: Vec<&MemberPlan> = pairs.iter().map(|p| p.2).collect();
    let fp = fingerprint(command, preset, case, members, &plans, extra);
    let work: Vec<f64> = plans.iter().map(|p| member_work(p)).collect();
    Ok(
        match shard.sweep(command, fp, &work, |mine| compute(pairs, mine))? {
            Sweep::Whole => Some((whole(), None)),
            Sweep::Done => None,
            Sweep::Merged(runs, ms) => Some((rebuild(pairs, runs), Some(ms))),
        },
    )
}

/// A suite map's cells from a shard or from parts: [`Sweep::Whole`] when
/// neither is asked for (the caller computes row by row as it prints).
pub fn map_cells(
    shard: &ShardArgs,
    preset: &str,
    case: &SuiteCase,
    cells: &[(f64, f64, SuiteCase)],
    plans: &[Vec<MemberPlan>],
    members: &[SuiteMember],
    extra: &impl std::fmt::Debug,
) -> Result<Sweep<SuiteMapCell>, CliError> {
    shard.check()?;
    if !shard.active() {
        return Ok(Sweep::Whole);
    }
    let all: Vec<&MemberPlan> = plans.iter().flatten().collect();
    let fp = fingerprint("map-suite", preset, case, members, &all, &(extra, cells));
    let work: Vec<f64> = plans
        .iter()
        .map(|cell| cell.iter().map(member_work).sum())
        .collect();
    shard.sweep("map-suite", fp, &work, |mine| {
        compute_listed(cells, plans, members, mine, &|_| {})
    })
}
