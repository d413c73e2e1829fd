//! The work integrals of both structures over the tight loop's quiet
//! samples (SPEC §6): the closed forms of [`super::sample::work`], laid out
//! structure by structure in each array as [`super::sample_run::Pair`] lays
//! out the maps, so that each line is one operation on both.
//!
//! Each structure's inputs are taken as five, u = (x − x*, ẋ, g_k, s, L)
//! with L = Q/m where K = 0 and x* = 0 there, L = 0 where K > 0: the terms
//! of an input that is exactly 0 are exactly 0, so the input and spring
//! work are those of [`super::sample::work`] over its four inputs, to the
//! bit, sample by sample (the input's running maximum is the balance's scale).
//!
//! The damping work c ∫ ẋ² = uᵀ G u of each sample is a quadratic form in
//! u, so over a run of samples on the same branches
//!
//! ```text
//! Σ_k u_kᵀ G u_k = Σ_{j,l} G_jl S_jl,    S = Σ_k u_k u_kᵀ,
//! ```
//!
//! and the loop carries the sums S instead of the form: g_k and s are the
//! same for both structures, so Σ g², Σ g s, Σ s² are shared, and L is
//! fixed, so its row is L times the sums of the inputs. The form is taken
//! once, where the run of samples ends ([`PairWork::damping`]); it differs
//! from the sum of the forms by the order of the additions alone.

use super::linear_map::INPUTS;
use super::sample::SampleMap;
use super::sample_run::{Lane, each};

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

    /// Per structure (input −m ∫ g ẋ, spring ∫ f_s ẋ) over one interval
    /// from (x, ẋ) under g = g_k + s t to the end displacement `x_end`, per
    /// m2 a_p²/ω_p² ([`super::sample::work`]); the interval's products of
    /// inputs are added to `sums` for the damping work.
    #[inline(always)]
    pub fn terms(
        &self,
        sums: &mut DampingSums,
        x: [f64; 2],
        v: [f64; 2],
        [g, s]: [f64; 2],
        x_end: [f64; 2],
    ) -> [[f64; 2]; 2] {
        let d = each(|i| x[i] - self.equilibrium[i]);
        let inputs: [[f64; 2]; INPUTS] = [d, v, [g; 2], [s; 2], self.free_load];
        let mut moment = [0.0; 2];
        for (u, m) in inputs.iter().zip(&self.moment) {
            moment = each(|i| moment[i] + u[i] * m[i]);
        }
        sums.add(d, v, g, s);
        // Written out for both: an array's map over [0, 1] is not inlined here.
        let term = |i: usize| {
            let dx = x_end[i] - x[i];
            let m = self.mass[i];
            [
                -m * (g * dx + s * moment[i]),
                m * dx * (self.stiffness[i] * 0.5 * (x[i] + x_end[i]) - self.load[i]),
            ]
        };
        [term(0), term(1)]
    }

    /// Each structure's damping work m (c/m) Σ_{j,l} G_jl S_jl over the
    /// samples summed in `sums` (the Gram matrix is symmetric: the terms
    /// off the diagonal count twice).
    #[allow(clippy::needless_range_loop)]
    pub fn damping(&self, sums: &DampingSums) -> [f64; 2] {
        let each_structure = |i: usize| {
            let products = sums.products(i, self.free_load[i]);
            let mut square = 0.0;
            for j in 0..INPUTS {
                let mut off = 0.0;
                for l in 0..j {
                    off += self.gram[j][l][i] * products[j][l];
                }
                square += self.gram[j][j][i] * products[j][j] + 2.0 * off;
            }
            self.mass[i] * self.damping[i] * square
        };
        [each_structure(0), each_structure(1)]
    }
}

/// The sums of products of the inputs over a run of quiet samples (see the
/// module's head): per structure Σ d², Σ d ẋ, Σ ẋ², Σ d g, Σ d s, Σ ẋ g,
/// Σ ẋ s, Σ d, Σ ẋ (d = x − x*), and shared Σ g², Σ g s, Σ s², Σ g, Σ s
/// and the count of samples.
#[derive(Debug, Clone, Copy, Default)]
pub struct DampingSums {
    own: [[f64; 2]; 9],
    shared: [f64; 6],
}

impl DampingSums {
    /// Adds one sample's products.
    #[inline(always)]
    fn add(&mut self, d: [f64; 2], v: [f64; 2], g: f64, s: f64) {
        let o = &mut self.own;
        o[0] = each(|i| d[i].mul_add(d[i], o[0][i]));
        o[1] = each(|i| d[i].mul_add(v[i], o[1][i]));
        o[2] = each(|i| v[i].mul_add(v[i], o[2][i]));
        o[3] = each(|i| d[i].mul_add(g, o[3][i]));
        o[4] = each(|i| d[i].mul_add(s, o[4][i]));
        o[5] = each(|i| v[i].mul_add(g, o[5][i]));
        o[6] = each(|i| v[i].mul_add(s, o[6][i]));
        o[7] = each(|i| o[7][i] + d[i]);
        o[8] = each(|i| o[8][i] + v[i]);
        let c = &mut self.shared;
        *c = [
            g.mul_add(g, c[0]),
            g.mul_add(s, c[1]),
            s.mul_add(s, c[2]),
            c[3] + g,
            c[4] + s,
            c[5] + 1.0,
        ];
    }

    /// S = Σ_k u_k u_kᵀ of structure i (lower triangle) with its fixed
    /// fifth input `load` (L).
    fn products(&self, i: usize, load: f64) -> [[f64; INPUTS]; INPUTS] {
        let o = |n: usize| self.own[n][i];
        let [gg, gs, ss, g, s, count] = self.shared;
        let mut p = [[0.0; INPUTS]; INPUTS];
        p[0][0] = o(0);
        p[1][0] = o(1);
        p[1][1] = o(2);
        p[2][0] = o(3);
        p[3][0] = o(4);
        p[2][1] = o(5);
        p[3][1] = o(6);
        p[2][2] = gg;
        p[3][2] = gs;
        p[3][3] = ss;
        p[4] = [
            load * o(7),
            load * o(8),
            load * g,
            load * s,
            load * load * count,
        ];
        p
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

    /// Over a run of samples, both structures' input and spring work equal
    /// [`work`] of each alone, to the bit, sample by sample; the damping
    /// work from the sums equals the sum of [`work`]'s to 1e-14, on
    /// branches with K > 0 and with K = 0 (its load then a fifth input).
    #[test]
    fn the_pair_s_work_is_each_structure_s() {
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
            let open = Watch::new(Branch::Elastic { offset: 0.0 }, f64::INFINITY);
            let lane_pair = Pair::new(lanes, [open; 2], h, f64::INFINITY);
            let (mut x, mut v) = ([0.31, -0.12], [-0.7, 0.45]);
            let mut sums = DampingSums::default();
            let mut alone_damping = [0.0; 2];
            for k in 0..40 {
                let t = k as f64;
                let ground = [0.6 * (0.7 * t).sin(), -2.5 * (0.3 * t).cos()];
                let [ends, v_end] = lane_pair.advance(x, v, ground);
                let terms = pair.terms(&mut sums, x, v, ground, ends);
                for i in 0..2 {
                    let inputs = lanes[i].inputs(x[i], v[i], ground);
                    let alone = work(&maps[i], mass[i], &inputs, load[i], [x[i], ends[i]]);
                    assert_eq!(
                        terms[i],
                        [alone[0], alone[2]],
                        "structure {i}, K/k = {}",
                        stiffness[i]
                    );
                    assert!(alone.iter().all(|w| w.is_finite() && *w != 0.0));
                    alone_damping[i] += alone[1];
                }
                (x, v) = (ends, v_end);
            }
            let damping = pair.damping(&sums);
            for i in 0..2 {
                let difference = (damping[i] - alone_damping[i]).abs() / alone_damping[i];
                assert!(
                    alone_damping[i] > 0.0 && difference < 1e-14,
                    "damping of {i}: {} against {} ({difference:.1e})",
                    damping[i],
                    alone_damping[i]
                );
            }
        }
    }
}
