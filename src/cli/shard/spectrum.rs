//! `spectrum --shard`: a spectrum's sweep through [`super::ShardArgs::sweep`].

use super::{ShardArgs, Sweep};
use crate::analysis::baseline::BaselineCache;
use crate::analysis::grid::Grid;
use crate::analysis::shard::spectrum::{assemble, compute, fingerprint, unit_work};
use crate::analysis::sweep::{Curve, CurveSpec};
use crate::cli::CliError;

/// The curves, their baselines and the time in ms (the merged parts' sum
/// when they come from parts); `None` when a shard's part was written.
pub fn run(
    shard: &ShardArgs,
    preset: &impl std::fmt::Debug,
    specs: &[CurveSpec],
    grid: &Grid,
    whole: impl FnOnce() -> Result<(Vec<Curve>, BaselineCache, f64), CliError>,
) -> Result<Option<(Vec<Curve>, BaselineCache, f64)>, CliError> {
    shard.check()?;
    if !shard.active() {
        return whole().map(Some);
    }
    let work = unit_work(specs, grid);
    let fp = fingerprint(preset, specs, grid);
    Ok(
        match shard.sweep("spectrum", fp, &work, |mine| compute(specs, grid, mine))? {
            Sweep::Whole => Some(whole()?),
            Sweep::Done => None,
            Sweep::Merged(results, ms) => {
                let (curves, cache) = assemble(specs, grid, results);
                Some((curves, cache, ms))
            }
        },
    )
}
