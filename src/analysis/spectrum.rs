//! Response spectra (SPEC §7): Π_ω1 swept over a grid with Π_ω2 = μ Π_ω1,
//! every other Π fixed; at each point the peaks with pounding and without it
//! (`gap = inf`), and the left structure's spectral region.

use serde::{Deserialize, Serialize};

use super::gap::from_max_relative;
use crate::model::Params;
use crate::solver::exact::ContactExtremes;
use crate::solver::{RunResult, StructurePeaks, run_for_sweep};

/// Relative change of the left structure's Π_u beyond which pounding counts
/// as amplifying or suppressing it (SPEC §7).
pub const REGION_THRESHOLD: f64 = 0.02;

/// The left structure's spectral region at one point (SPEC §7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Region {
    /// Pounding raises Π_u by more than 2 %.
    Amplification,
    /// Pounding lowers Π_u by more than 2 %.
    Suppression,
    /// Within ±2 %.
    None,
}

impl Region {
    /// Classifies from the left structure's Π_u with and without pounding.
    pub fn classify(with_pounding: f64, without: f64) -> Region {
        if with_pounding > without * (1.0 + REGION_THRESHOLD) {
            Region::Amplification
        } else if with_pounding < without * (1.0 - REGION_THRESHOLD) {
            Region::Suppression
        } else {
            Region::None
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Region::Amplification => "amplification",
            Region::Suppression => "suppression",
            Region::None => "none",
        }
    }
}

/// One point of a spectrum.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SpectrumPoint {
    pub omega1: f64,
    pub omega2: f64,
    /// With pounding.
    pub left: StructurePeaks,
    pub right: StructurePeaks,
    /// The no-pounding baseline (`gap = inf`).
    pub free_left: StructurePeaks,
    pub free_right: StructurePeaks,
    pub impacts: usize,
    pub region: Region,
    /// Π_d,min = max(0, max over τ of x1 − x2) of the no-pounding run: the
    /// smallest gap at which this point never pounds (SPEC §11). Exact
    /// method only; `None` with Newmark, which does not track it.
    pub min_gap_no_pounding: Option<f64>,
}

impl SpectrumPoint {
    /// The eight dimensionless peaks: Π_u, Π_v of the left and right
    /// structures with pounding, then the same without it.
    pub fn peaks(&self) -> [f64; 8] {
        eight_peaks(
            [&self.left, &self.right],
            [&self.free_left, &self.free_right],
        )
    }
}

/// Π_u, Π_v of the left and right structures with pounding (`with`), then
/// the same without it (`free`): the order of every peaks-with-and-without
/// output (a spectrum point, a map cell).
pub fn eight_peaks(with: [&StructurePeaks; 2], free: [&StructurePeaks; 2]) -> [f64; 8] {
    let ([l, r], [fl, fr]) = (with, free);
    [
        l.peak_displacement,
        l.peak_velocity,
        r.peak_displacement,
        r.peak_velocity,
        fl.peak_displacement,
        fl.peak_velocity,
        fr.peak_displacement,
        fr.peak_velocity,
    ]
}

/// The parameters of the point Π_ω1 = `omega1`, Π_ω2 = μ Π_ω1.
pub fn at_omega(p: &Params, omega1: f64, mu: f64) -> Params {
    Params {
        omega1,
        omega2: mu * omega1,
        ..p.clone()
    }
}

/// The no-pounding twin of a parameter set.
pub fn baseline_params(p: &Params) -> Params {
    Params {
        gap: f64::INFINITY,
        ..p.clone()
    }
}

/// Combines a pounding run with its baseline into a spectrum point.
pub fn combine(p: &Params, with: &RunResult, without: &RunResult) -> SpectrumPoint {
    SpectrumPoint {
        omega1: p.omega1,
        omega2: p.omega2,
        left: with.left,
        right: with.right,
        free_left: without.left,
        free_right: without.right,
        impacts: with.impacts.len(),
        region: Region::classify(with.left.peak_displacement, without.left.peak_displacement),
        min_gap_no_pounding: without.max_relative_displacement.map(from_max_relative),
    }
}

/// One spectrum point, peaks only: the pounding run and its baseline. A
/// pounding run with no impact is its own baseline.
pub fn point(p: &Params, omega1: f64, mu: f64) -> SpectrumPoint {
    let q = at_omega(p, omega1, mu);
    let with = run_for_sweep(&q, ContactExtremes::None);
    if with.impacts.is_empty() {
        return combine(&q, &with, &with);
    }
    let without = run_for_sweep(&baseline_params(&q), ContactExtremes::None);
    combine(&q, &with, &without)
}

/// A run of consecutive grid points in the same region: the swept value
/// (Π_ω1 in a spectrum) from `from` to `to`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RegionRange {
    pub region: Region,
    pub from: f64,
    pub to: f64,
    /// Number of grid points in the run.
    pub points: usize,
}

/// The left structure's regions along a curve, as maximal runs of
/// consecutive points (SPEC §7).
pub fn region_ranges(points: &[SpectrumPoint]) -> Vec<RegionRange> {
    region_runs(points.iter().map(|p| (p.omega1, p.region)))
}

/// Maximal runs of consecutive equal regions along any swept value
/// (`(value, region)` in grid order): a spectrum, or one row of a map.
pub fn region_runs(points: impl IntoIterator<Item = (f64, Region)>) -> Vec<RegionRange> {
    let mut ranges: Vec<RegionRange> = Vec::new();
    for (value, region) in points {
        match ranges.last_mut() {
            Some(r) if r.region == region => {
                r.to = value;
                r.points += 1;
            }
            _ => ranges.push(RegionRange {
                region,
                from: value,
                to: value,
                points: 1,
            }),
        }
    }
    ranges
}
