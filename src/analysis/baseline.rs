//! The no-pounding baseline of a spectrum point (`gap = inf`, SPEC §7),
//! cached by the parameters it depends on.
//!
//! Without contact the equations of motion (SPEC §2) decouple, and neither
//! Π_d, Π_e, Π_ωcon, the contact model nor the grazing floor v₀,min appears in
//! them. The baseline is therefore a function of Π_m, Π_ω1, Π_ω2, Π_uy1,
//! Π_uy2, Π_ξ, Π_α, the duration and Δτ only: [`BaselineKey`]. One cache
//! serves every curve of a family and every contact model.

use std::collections::HashMap;

use crate::model::Params;
use crate::solver::{RunResult, StructurePeaks};

/// The parameters a no-pounding run depends on, bit for bit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BaselineKey {
    bits: [u64; 8],
    cycles: u32,
}

impl BaselineKey {
    /// Π_m, Π_ω1, Π_ω2, Π_uy1, Π_uy2, Π_ξ, Π_α, Δτ and the cycle count of `p`.
    pub fn of(p: &Params) -> BaselineKey {
        BaselineKey {
            bits: [
                p.mass_ratio,
                p.omega1,
                p.omega2,
                p.yield1,
                p.yield2,
                p.damping,
                p.alpha,
                p.dt,
            ]
            .map(f64::to_bits),
            cycles: p.cycles,
        }
    }
}

/// Peaks of both structures without pounding.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FreePeaks {
    pub left: StructurePeaks,
    pub right: StructurePeaks,
    /// max over τ of x1 − x2 (exact method only; SPEC §11).
    pub max_relative_displacement: Option<f64>,
}

impl FreePeaks {
    pub fn of(r: &RunResult) -> FreePeaks {
        FreePeaks {
            left: r.left,
            right: r.right,
            max_relative_displacement: r.max_relative_displacement,
        }
    }

    /// As a run result (peaks only), for [`super::spectrum::combine`].
    pub fn as_run(&self) -> RunResult {
        RunResult {
            left: self.left,
            right: self.right,
            max_relative_displacement: self.max_relative_displacement,
            completed: true,
            ..RunResult::default()
        }
    }
}

/// Baselines already computed, and how they were obtained.
#[derive(Debug, Clone, Default)]
pub struct BaselineCache {
    map: HashMap<BaselineKey, FreePeaks>,
    /// No-pounding runs made to fill the cache.
    pub runs: usize,
    /// Baselines taken from a pounding run that had no impact (its own baseline).
    pub from_pounding: usize,
}

impl BaselineCache {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn get(&self, p: &Params) -> Option<FreePeaks> {
        self.map.get(&BaselineKey::of(p)).copied()
    }

    pub fn contains(&self, p: &Params) -> bool {
        self.map.contains_key(&BaselineKey::of(p))
    }

    pub fn len(&self) -> usize {
        self.map.len()
    }

    pub fn is_empty(&self) -> bool {
        self.map.is_empty()
    }

    /// Records the baseline of `p` from a run without any contact (a
    /// no-pounding run, or a pounding run that had no impact).
    pub fn insert(&mut self, p: &Params, free: FreePeaks) {
        self.map.entry(BaselineKey::of(p)).or_insert(free);
    }

    /// Records a baseline a [`super::batch`] obtained for `p`, and counts how.
    pub fn record(&mut self, p: &Params, b: &NewBaseline) {
        if self.contains(p) {
            return;
        }
        if b.from_pounding {
            self.from_pounding += 1;
        } else {
            self.runs += 1;
        }
        self.insert(p, b.peaks);
    }
}

/// A baseline a batch ([`super::batch`]) obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewBaseline {
    /// Index of a point (the first) with this baseline's key.
    pub point: usize,
    pub peaks: FreePeaks,
    /// Whether the run that gave it reached τ_end.
    pub completed: bool,
    /// Taken from a pounding run with no impact, not from a run of its own.
    pub from_pounding: bool,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ContactModel, SET1};

    #[test]
    fn key_ignores_only_contact_parameters() {
        let k = BaselineKey::of(&SET1);
        let contact_only = Params {
            gap: 1.5,
            restitution: 0.9,
            contact_omega: 10.0,
            model: ContactModel::Kelvin,
            min_impact_velocity: 0.1,
            contact_tolerance: 1e-14,
            ..SET1
        };
        assert_eq!(BaselineKey::of(&contact_only), k);
        for changed in [
            Params {
                mass_ratio: 0.9,
                ..SET1
            },
            Params {
                omega2: 2.0,
                ..SET1
            },
            Params {
                yield2: 0.7,
                ..SET1
            },
            Params { alpha: 0.2, ..SET1 },
            Params { cycles: 4, ..SET1 },
            Params { dt: 0.002, ..SET1 },
        ] {
            assert_ne!(BaselineKey::of(&changed), k);
        }
    }
}
