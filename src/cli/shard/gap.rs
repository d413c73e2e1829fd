//! `gap --x --shard`: a gap sweep through [`super::ShardArgs::sweep`].

use super::{Results, ShardArgs, Sweep};
use crate::analysis::gap::MinimumGap;
use crate::analysis::shard::gap::{compute, fingerprint, unit_work};
use crate::cli::CliError;
use crate::model::Params;

/// The minimum gaps, with the merged parts' time in ms when they come from
/// parts; `None` when a shard's part was written. Only a sweep (`--x`) shards.
pub fn run(
    shard: &ShardArgs,
    preset: &str,
    points: &[(f64, Params)],
    sweep: bool,
    whole: impl FnOnce() -> Vec<MinimumGap>,
) -> Results<Vec<MinimumGap>> {
    shard.check()?;
    if !shard.active() {
        return Ok(Some((whole(), None)));
    }
    if !sweep {
        return Err(CliError::Usage(
            "--shard: gap shards a sweep or a suite; give --x KEY=START:STOP:STEP or --suite SUITE"
                .into(),
        ));
    }
    let fp = fingerprint(preset, points);
    Ok(
        match shard.sweep("gap", fp, &unit_work(points), |mine| compute(points, mine))? {
            Sweep::Whole => Some((whole(), None)),
            Sweep::Done => None,
            Sweep::Merged(gaps, ms) => Some((gaps, Some(ms))),
        },
    )
}
