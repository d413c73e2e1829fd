//! Many points at once: each point's pounding run and, where the cache does
//! not hold it yet, its no-pounding baseline (SPEC §7), in one parallel pass.
//!
//! Points that share a [`BaselineKey`] (curves or map cells that differ only
//! in gap, restitution, contact frequency, contact model or grazing floor)
//! make one task: their pounding runs, then at most one baseline run, and
//! none where one of them had no impact (it never touched contact, so it is
//! the baseline, bit for bit). With no barrier between the pounding runs and
//! the baselines, both cores stay busy to the end of the batch.

use std::collections::HashMap;

use rayon::prelude::*;

use super::baseline::{BaselineKey, FreePeaks, NewBaseline};
use super::spectrum::baseline_params;
use crate::model::Params;
use crate::solver::exact::ContactExtremes;
use crate::solver::{RunResult, run_for_sweep};

/// What a batch computed.
#[derive(Debug, Clone, Default)]
pub struct Batch {
    /// Each point's pounding run; none where its gap is infinite.
    pub pounding: Vec<Option<RunResult>>,
    /// The baselines of the keys that `cached` did not hold, one per key.
    pub baselines: Vec<NewBaseline>,
}

/// Runs `points` in parallel, one task per baseline key, locating the
/// contact `extremes` the caller reports; `cached` says which baselines need no run.
pub fn run_points(
    points: &[Params],
    extremes: ContactExtremes,
    cached: impl Fn(&Params) -> bool + Sync,
) -> Batch {
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut by_key: HashMap<BaselineKey, usize> = HashMap::new();
    for (i, p) in points.iter().enumerate() {
        let g = *by_key.entry(BaselineKey::of(p)).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(i);
    }
    let done: Vec<(Vec<Option<RunResult>>, Option<NewBaseline>)> = groups
        .par_iter()
        .map(|group| {
            let runs: Vec<Option<RunResult>> = group
                .iter()
                .map(|&i| {
                    let p = &points[i];
                    p.pounding().then(|| run_for_sweep(p, extremes))
                })
                .collect();
            let first = group[0];
            let baseline = (!cached(&points[first])).then(|| {
                let untouched = runs.iter().flatten().find(|r| r.impacts.is_empty());
                let own;
                let (r, from_pounding) = match untouched {
                    Some(r) => (r, true),
                    None => {
                        own =
                            run_for_sweep(&baseline_params(&points[first]), ContactExtremes::None);
                        (&own, false)
                    }
                };
                NewBaseline {
                    point: first,
                    peaks: FreePeaks::of(r),
                    completed: r.completed,
                    from_pounding,
                }
            });
            (runs, baseline)
        })
        .collect();
    let mut pounding: Vec<Option<RunResult>> = (0..points.len()).map(|_| None).collect();
    let mut baselines = Vec::new();
    for (group, (runs, baseline)) in groups.iter().zip(done) {
        for (&i, r) in group.iter().zip(runs) {
            pounding[i] = r;
        }
        baselines.extend(baseline);
    }
    baselines.sort_by_key(|b| b.point);
    Batch {
        pounding,
        baselines,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn one_baseline_per_key_and_none_where_a_pounding_run_is_untouched() {
        // Two gaps at each of three frequencies: the wide gap never pounds at
        // Π_ω1 = 2.5 (its run is the baseline); set 1's gap pounds at 1.05.
        let points: Vec<Params> = [0.6, 1.05, 2.5]
            .iter()
            .flat_map(|&w| {
                [0.2, 50.0].map(|gap| Params {
                    omega1: w,
                    omega2: 2.25 * w,
                    gap,
                    ..SET1
                })
            })
            .collect();
        let batch = run_points(&points, ContactExtremes::None, |_| false);
        assert_eq!(batch.pounding.len(), 6);
        assert!(batch.pounding.iter().all(Option::is_some));
        assert_eq!(
            batch.baselines.iter().map(|b| b.point).collect::<Vec<_>>(),
            [0, 2, 4]
        );
        for b in &batch.baselines {
            let wide = batch.pounding[b.point + 1].as_ref().unwrap();
            assert!(wide.impacts.is_empty(), "Π_d = 50 pounds at {}", b.point);
            assert!(b.from_pounding && b.completed);
            assert_eq!(b.peaks, FreePeaks::of(wide));
            // The same as a run of its own without contact.
            let own = run_for_sweep(&baseline_params(&points[b.point]), ContactExtremes::None);
            let err = (own.left.peak_displacement - b.peaks.left.peak_displacement).abs();
            assert!(err < 1e-12 * own.left.peak_displacement, "{err:e}");
        }
        // Keys the cache holds get no baseline; a lone pounding point gets its own run.
        assert!(
            run_points(&points, ContactExtremes::None, |_| true)
                .baselines
                .is_empty()
        );
        let lone = run_points(&points[2..3], ContactExtremes::None, |_| false);
        assert_eq!(lone.baselines.len(), 1);
        assert!(!lone.baselines[0].from_pounding);
    }
}
