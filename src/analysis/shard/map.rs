//! A map as shards: its units are the cells that share a baseline (one
//! [`BaselineKey`]), so that a shard never runs a baseline another shard
//! runs too; a unit's work is its cells' runs and one baseline.

use std::collections::HashMap;

use super::fingerprint::Fingerprint;
use crate::analysis::baseline::BaselineKey;
use crate::analysis::map::{MapCache, MapCell, MapPlan, compute_cells};
use crate::analysis::work;
use crate::model::Params;

/// A map's units: the row-major indices of each unit's cells, and each unit's work.
#[derive(Debug, Clone, PartialEq)]
pub struct Units {
    pub cells: Vec<Vec<usize>>,
    pub work: Vec<f64>,
}

/// The cells of `plan` grouped by baseline key, in order of first cell.
pub fn units(plan: &MapPlan) -> Units {
    group(&points(plan))
}

/// The parameters of every cell, row-major.
fn points(plan: &MapPlan) -> Vec<Params> {
    let xs = plan.x.values();
    plan.y
        .values()
        .iter()
        .flat_map(|&y| xs.iter().map(move |&x| plan.at(x, y)))
        .collect()
}

/// `points` grouped by baseline key, with each group's estimated work.
pub fn group(points: &[Params]) -> Units {
    let mut by_key: HashMap<BaselineKey, usize> = HashMap::new();
    let mut units = Units {
        cells: Vec::new(),
        work: Vec::new(),
    };
    for (i, p) in points.iter().enumerate() {
        let u = *by_key.entry(BaselineKey::of(p)).or_insert_with(|| {
            units.cells.push(Vec::new());
            units.work.push(work::free_run(p));
            units.cells.len() - 1
        });
        units.cells[u].push(i);
        units.work[u] += work::pounding_run(p);
    }
    units
}

/// The request's fingerprint: the preset's name and the whole plan.
pub fn fingerprint(preset: &str, plan: &MapPlan) -> Fingerprint {
    let mut f = Fingerprint::new("map");
    f.add_str(preset);
    f.add_debug(plan);
    f
}

/// The cells of the units `mine`, one list per unit, in one batch.
pub fn compute(plan: &MapPlan, units: &Units, mine: &[usize]) -> Vec<Vec<MapCell>> {
    let (xs, ys) = (plan.x.values(), plan.y.values());
    let nx = xs.len();
    let at: Vec<(f64, f64)> = mine
        .iter()
        .flat_map(|&u| units.cells[u].iter())
        .map(|&c| (xs[c % nx], ys[c / nx]))
        .collect();
    let mut cells = compute_cells(plan, &at, &mut MapCache::default()).into_iter();
    mine.iter()
        .map(|&u| cells.by_ref().take(units.cells[u].len()).collect())
        .collect()
}

/// Every unit's cells put back row-major, and the counters of the
/// baselines as one pass over the whole map counts them.
pub fn assemble(
    plan: &MapPlan,
    units: &Units,
    results: Vec<Vec<MapCell>>,
) -> (Vec<MapCell>, MapCache) {
    let mut cells: Vec<Option<MapCell>> = vec![None; plan.cells()];
    for (unit, got) in units.cells.iter().zip(results) {
        for (&i, c) in unit.iter().zip(got) {
            cells[i] = Some(c);
        }
    }
    // The units hold every cell once (see [`group`]).
    let cells: Vec<MapCell> = cells.into_iter().flatten().collect();
    let (runs, from_pounding) = baseline_counts(&points(plan), |i| cells[i].impacts);
    let mut cache = MapCache::default();
    cache.baselines.runs = runs;
    cache.baselines.from_pounding = from_pounding;
    (cells, cache)
}

/// The baselines one batch over `points` makes with an empty cache (see
/// [`crate::analysis::batch`]): per key, none when a point of it ran with
/// contact and had no impact (that run is the baseline), else one run.
/// Returns (runs, taken from pounding runs).
pub fn baseline_counts(points: &[Params], impacts: impl Fn(usize) -> usize) -> (usize, usize) {
    let mut untouched: HashMap<BaselineKey, bool> = HashMap::new();
    for (i, p) in points.iter().enumerate() {
        let free = p.pounding() && impacts(i) == 0;
        *untouched.entry(BaselineKey::of(p)).or_insert(false) |= free;
    }
    let from_pounding = untouched.values().filter(|&&u| u).count();
    (untouched.len() - from_pounding, from_pounding)
}
