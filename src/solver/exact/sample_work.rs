//! The work integrals of both structures over the tight loop's quiet
//! samples (SPEC §6): the closed forms of [`super::sample::work`], laid out
//! structure by structure in each array as [`super::sample_run::Pair`] lays
//! out the maps, so that each line is one operation on both.
//!
//! Each structure's inputs are taken as five, (x − x*, ẋ, g_k, s, L) with
//! L = Q/m where K = 0 and x* = 0 there, L = 0 where K > 0: the terms of an
//! input that is exactly 0 are exactly 0, so the sums are those of
//! [`super::sample::work`] over its four inputs, to the bit.

use super::linear_map::INPUTS;
use super::sample::SampleMap;
use super::sample_run::Lane;

/// The moments and Gram matrices of both structures' maps, with what the
/// work needs of their branches.
#[derive(Debug, Clone, Copy)]
pub struct PairWork {
    moment: [[f64; 2]; INPUTS],
    gram: [[[f64; 2]; INPUTS]; INPUTS],
    mass: [f64; 2],
    damping: [f64; 2],
    stiffness: [f64; 2],
    load: [f64; 2],
    equilibrium: [f64; 2],
    free_load: [f64; 2],
}

/// [f(0), f(1)].
#[inline(always)]
fn each(f: impl Fn(usize) -> f64) -> [f64; 2] {
    [f(0), f(1)]
}

impl PairWork {
    /// From both structures' maps (made with their work integrals), their
    /// lanes on the same branches, and their masses.
    pub fn new(maps: [&SampleMap; 2], lanes: [&Lane; 2], mass: [f64; 2]) -> Self {
        let [(m0, g0), (m1, g1)] = maps.map(SampleMap::work_integrals);
        PairWork {
            moment: std::array::from_fn(|j| [m0[j], m1[j]]),
            gram: std::array::from_fn(|j| std::array::from_fn(|l| [g0[j][l], g1[j][l]])),
            mass,
            damping: [maps[0].damping, maps[1].damping],
            stiffness: [maps[0].stiffness, maps[1].stiffness],
            load: [lanes[0].load, lanes[1].load],
            equilibrium: [lanes[0].equilibrium, lanes[1].equilibrium],
            free_load: each(|i| {
                if lanes[i].stiffness > 0.0 {
                    0.0
                } else {
                    lanes[i].load
                }
            }),
        }
    }

    /// Per structure (input −m ∫ g ẋ, damping c ∫ ẋ², spring ∫ f_s ẋ) over
    /// one interval from (x, ẋ) under g = g_k + s t to the end
    /// displacement `x_end`, per m2 a_p²/ω_p² ([`super::sample::work`]).
    #[inline(always)]
    pub fn terms(
        &self,
        x: [f64; 2],
        v: [f64; 2],
        [g, s]: [f64; 2],
        x_end: [f64; 2],
    ) -> [[f64; 3]; 2] {
        let inputs: [[f64; 2]; INPUTS] = [
            each(|i| x[i] - self.equilibrium[i]),
            v,
            [g; 2],
            [s; 2],
            self.free_load,
        ];
        let mut moment = [0.0; 2];
        let mut square = [0.0; 2];
        // The Gram matrix is symmetric: Σ_j u_j (G_jj u_j + 2 Σ_{l<j} G_jl u_l).
        for j in 0..INPUTS {
            moment = each(|i| moment[i] + inputs[j][i] * self.moment[j][i]);
            let row = &self.gram[j];
            let mut r = [0.0; 2];
            for l in 0..j {
                r = each(|i| r[i] + row[l][i] * inputs[l][i]);
            }
            square = each(|i| square[i] + inputs[j][i] * (row[j][i] * inputs[j][i] + 2.0 * r[i]));
        }
        // Written out for both: an array's map over [0, 1] is not inlined here.
        let term = |i: usize| {
            let dx = x_end[i] - x[i];
            let m = self.mass[i];
            [
                -m * (g * dx + s * moment[i]),
                m * self.damping[i] * square[i],
                m * dx * (self.stiffness[i] * 0.5 * (x[i] + x_end[i]) - self.load[i]),
            ]
        };
        [term(0), term(1)]
    }
}

#[cfg(test)]
mod tests {
    use super::super::dynamics::Branch;
    use super::super::dynamics::Structure;
    use super::super::sample::{SampleMap, work};
    use super::super::sample_run::{Pair, Watch};
    use super::*;
    use crate::model::SET1;

    /// Both structures' terms equal [`work`] of each alone, to the bit, on
    /// branches with K > 0 and with K = 0 (its load then a fifth input).
    #[test]
    fn the_pair_s_work_is_each_structure_s_to_the_bit() {
        let structures = Structure::pair(&SET1);
        let h = 0.05;
        for (stiffness, load) in [
            ([1.0, 1.0], [0.0, 0.3]),
            ([1.0, 0.0], [0.2, -0.4]),
            ([0.0, 0.0], [0.1, 0.2]),
        ] {
            let maps = [0, 1].map(|i| {
                let s = &structures[i];
                SampleMap::new(s, stiffness[i] * s.stiffness, h, 20, true).expect("Ω h ≤ 1")
            });
            let lanes = [0, 1].map(|i| maps[i].lane(load[i]));
            let mass = structures.map(|s| s.mass);
            let pair = PairWork::new([&maps[0], &maps[1]], [&lanes[0], &lanes[1]], mass);
            let (x, v, ground) = ([0.31, -0.12], [-0.7, 0.45], [0.6, -2.5]);
            let open = Watch::new(Branch::Elastic { offset: 0.0 }, f64::INFINITY);
            let ends = Pair::new(lanes, [open; 2], h, f64::INFINITY).advance(x, v, ground)[0];
            let terms = pair.terms(x, v, ground, ends);
            for i in 0..2 {
                let inputs = lanes[i].inputs(x[i], v[i], ground);
                let alone = work(&maps[i], mass[i], &inputs, load[i], [x[i], ends[i]]);
                assert_eq!(terms[i], alone, "structure {i}, K/k = {}", stiffness[i]);
                assert!(alone.iter().all(|w| w.is_finite() && *w != 0.0));
            }
        }
    }
}
