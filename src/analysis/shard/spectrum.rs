//! A spectrum as shards: its units are the grid's Π_ω1 values, each with
//! the points of every curve there (curves that differ only in a contact
//! parameter share their baselines there); a unit's work is its points'
//! runs and their baselines.

use super::fingerprint::Fingerprint;
use super::map::{baseline_counts, group};
use crate::analysis::baseline::BaselineCache;
use crate::analysis::grid::Grid;
use crate::analysis::spectrum::{SpectrumPoint, at_omega};
use crate::analysis::sweep::{Curve, CurveSpec, sweep};
use crate::model::Params;

/// Each grid value's estimated work.
pub fn unit_work(specs: &[CurveSpec], grid: &Grid) -> Vec<f64> {
    grid.values()
        .iter()
        .map(|&w| {
            let points: Vec<Params> = specs.iter().map(|s| at_omega(&s.params, w, s.mu)).collect();
            // One free run per baseline key and every run with contact.
            group(&points).work.iter().sum::<f64>()
        })
        .collect()
}

/// The request's fingerprint: the preset, the curves and the grid.
pub fn fingerprint(preset: &impl std::fmt::Debug, specs: &[CurveSpec], grid: &Grid) -> Fingerprint {
    let mut f = Fingerprint::new("spectrum");
    f.add_debug(preset);
    f.add_debug(&specs);
    f.add_debug(grid);
    f
}

/// The points of every curve at the grid values `mine` (indices), one
/// list (one point per curve) per value.
pub fn compute(specs: &[CurveSpec], grid: &Grid, mine: &[usize]) -> Vec<Vec<SpectrumPoint>> {
    let values = grid.values();
    let omega1: Vec<f64> = mine.iter().map(|&i| values[i]).collect();
    let curves = sweep(specs, &omega1, &mut BaselineCache::new());
    (0..mine.len())
        .map(|j| curves.iter().map(|c| c.points[j]).collect())
        .collect()
}

/// The curves from every grid value's points, and the counters of the
/// baselines as one sweep over the whole grid counts them.
pub fn assemble(
    specs: &[CurveSpec],
    grid: &Grid,
    results: Vec<Vec<SpectrumPoint>>,
) -> (Vec<Curve>, BaselineCache) {
    let curves: Vec<Curve> = specs
        .iter()
        .enumerate()
        .map(|(c, s)| Curve {
            spec: s.clone(),
            points: results.iter().filter_map(|at| at.get(c).copied()).collect(),
        })
        .collect();
    // The points as the sweep orders them: curve after curve.
    let values = grid.values();
    let points: Vec<Params> = specs
        .iter()
        .flat_map(|s| values.iter().map(|&w| at_omega(&s.params, w, s.mu)))
        .collect();
    let n = values.len().max(1);
    let (runs, from_pounding) = baseline_counts(&points, |i| {
        curves[i / n].points.get(i % n).map_or(0, |p| p.impacts)
    });
    let mut cache = BaselineCache::new();
    cache.runs = runs;
    cache.from_pounding = from_pounding;
    (curves, cache)
}
