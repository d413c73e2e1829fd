//! A gap sweep (`gap --x`) as shards: its units are the axis's points, one
//! free run each.

use super::fingerprint::Fingerprint;
use crate::analysis::gap::{MinimumGap, minimum_gaps};
use crate::analysis::work;
use crate::model::Params;

/// Each point's estimated work.
pub fn unit_work(points: &[(f64, Params)]) -> Vec<f64> {
    points.iter().map(|(_, p)| work::free_run(p)).collect()
}

/// The request's fingerprint: the preset and every point's parameters.
pub fn fingerprint(preset: &str, points: &[(f64, Params)]) -> Fingerprint {
    let mut f = Fingerprint::new("gap");
    f.add_str(preset);
    f.add_debug(&points);
    f
}

/// The minimum gaps at the points `mine` (indices), in that order.
pub fn compute(points: &[(f64, Params)], mine: &[usize]) -> Vec<MinimumGap> {
    minimum_gaps(
        &mine
            .iter()
            .map(|&i| points[i].1.clone())
            .collect::<Vec<_>>(),
    )
}
