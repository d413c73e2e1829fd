//! The spectrum engine: every curve of a family over one Π_ω1 grid
//! (SPEC §7), peaks only, points in parallel (rayon).
//!
//! The runs are one [`super::batch`]: every pounding run (`gap` finite) of
//! every curve, and the baselines the [`BaselineCache`] does not hold yet,
//! one per [`BaselineKey`] (shared by all curves that differ only in gap,
//! restitution, contact frequency, contact model or grazing floor), none
//! where a pounding run had no impact (it is its own baseline). Then each
//! point is [`combine`]d from its pounding run and its baseline.
//!
//! [`BaselineKey`]: super::baseline::BaselineKey

use super::baseline::{BaselineCache, FreePeaks};
use super::batch::run_points;
use super::family::{Family, FamilyError, Member};
use super::spectrum::{SpectrumPoint, at_omega, combine};
use crate::model::Params;
use crate::solver::exact::ContactExtremes;

/// One curve to compute: the family member it stands for (none without a
/// family), its parameters and its frequency ratio μ.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveSpec {
    pub member: Option<Member>,
    pub params: Params,
    pub mu: f64,
}

/// A computed curve: its spec and one point per grid value.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    pub spec: CurveSpec,
    pub points: Vec<SpectrumPoint>,
}

/// The curves of `family` on `base` with frequency ratio `mu` (one curve,
/// `member: None`, without a family).
pub fn curve_specs(
    base: &Params,
    mu: f64,
    family: Option<&Family>,
) -> Result<Vec<CurveSpec>, FamilyError> {
    let Some(family) = family else {
        return Ok(vec![CurveSpec {
            member: None,
            params: base.clone(),
            mu,
        }]);
    };
    family
        .members
        .iter()
        .map(|m| {
            let (params, mu) = m.apply(base, mu)?;
            Ok(CurveSpec {
                member: Some(m.clone()),
                params,
                mu,
            })
        })
        .collect()
}

/// Computes every curve on the grid `omega1`, reusing and filling `cache`.
pub fn sweep(specs: &[CurveSpec], omega1: &[f64], cache: &mut BaselineCache) -> Vec<Curve> {
    let points: Vec<Params> = specs
        .iter()
        .flat_map(|s| omega1.iter().map(|&w| at_omega(&s.params, w, s.mu)))
        .collect();

    let batch = run_points(&points, ContactExtremes::None, |q| cache.contains(q));
    for b in &batch.baselines {
        cache.record(&points[b.point], b);
    }
    let pounding = batch.pounding;

    // Combine.
    let mut results = points.iter().zip(pounding).map(|(q, with)| {
        // A pounding run with no impact is its own baseline, bit for bit.
        let free = match &with {
            Some(r) if r.impacts.is_empty() => Some(FreePeaks::of(r)),
            _ => cache.get(q),
        };
        let without = free.unwrap_or_default().as_run();
        combine(q, with.as_ref().unwrap_or(&without), &without)
    });
    specs
        .iter()
        .map(|s| Curve {
            spec: s.clone(),
            points: results.by_ref().take(omega1.len()).collect(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::spectrum::point;
    use crate::model::SET1;

    #[test]
    fn sweep_matches_point_by_point() {
        let grid = [0.3, 1.05, 1.5, 2.5];
        let specs = curve_specs(&SET1, 2.25, None).unwrap();
        let mut cache = BaselineCache::new();
        let curves = sweep(&specs, &grid, &mut cache);
        for (w, got) in grid.iter().zip(&curves[0].points) {
            assert_eq!(*got, point(&SET1, *w, 2.25));
        }
        // A second sweep needs no new baseline.
        let runs = cache.runs;
        sweep(&specs, &grid, &mut cache);
        assert_eq!(cache.runs, runs);
    }
}
