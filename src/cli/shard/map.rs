//! `map --shard`: a map's sweep through [`super::ShardArgs::sweep`].

use super::{ShardArgs, Sweep};
use crate::analysis::map::{MapCache, MapCell, MapPlan};
use crate::analysis::shard::map::{assemble, compute, fingerprint, units};
use crate::cli::CliError;

/// The map's cells and baselines, with the merged parts' time in ms when
/// they come from parts; `None` when a shard's part was written.
pub fn run(
    shard: &ShardArgs,
    preset: &str,
    plan: &MapPlan,
    whole: impl FnOnce() -> (Vec<MapCell>, MapCache),
) -> Result<Option<(Vec<MapCell>, MapCache, Option<f64>)>, CliError> {
    shard.check()?;
    if !shard.active() {
        let (cells, cache) = whole();
        return Ok(Some((cells, cache, None)));
    }
    let units = units(plan);
    let fp = fingerprint(preset, plan);
    Ok(
        match shard.sweep("map", fp, &units.work, |mine| compute(plan, &units, mine))? {
            Sweep::Whole => {
                let (cells, cache) = whole();
                Some((cells, cache, None))
            }
            Sweep::Done => None,
            Sweep::Merged(results, ms) => {
                let (cells, cache) = assemble(plan, &units, results);
                Some((cells, cache, Some(ms)))
            }
        },
    )
}
