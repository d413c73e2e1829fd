//! `map --shard`: a map's sweep through [`super::ShardArgs::sweep`].

use super::{Results, ShardArgs, Sweep};
use crate::analysis::map::{MapCache, MapCell, MapPlan};
use crate::analysis::shard::map::{assemble, compute, fingerprint, units};

/// The map's cells and baselines, with the merged parts' time in ms when
/// they come from parts; `None` when a shard's part was written.
pub fn run(
    shard: &ShardArgs,
    preset: &str,
    plan: &MapPlan,
    whole: impl FnOnce() -> (Vec<MapCell>, MapCache),
) -> Results<(Vec<MapCell>, MapCache)> {
    shard.check()?;
    if !shard.active() {
        return Ok(Some((whole(), None)));
    }
    let units = units(plan);
    let fp = fingerprint(preset, plan);
    Ok(
        match shard.sweep("map", fp, &units.work, |mine| compute(plan, &units, mine))? {
            Sweep::Whole => Some((whole(), None)),
            Sweep::Done => None,
            Sweep::Merged(results, ms) => Some((assemble(plan, &units, results), Some(ms))),
        },
    )
}
