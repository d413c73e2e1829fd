//! A stack carried across a change of ground piece (SPEC §13): the end
//! stack of one quiet sub-step made the start stack of the next without
//! its three products by M⁻¹K and M⁻¹C.
//!
//! Under a record every sample is its own ground piece, so the ground
//! (a_g, ȧ_g, ä_g = σa_g) the next sub-step starts from is not the one the
//! last ended with: a_g is continuous (the record is piecewise linear) but
//! for the rounding of the old piece's line at its end, and ȧ_g jumps.
//! The state (u, u̇) is the same, and each rate of [`Stack::set`] is
//! linear in the ground, so with Δa, Δȧ, Δä the ground's changes, 1 the
//! floors' influence vector, K = M⁻¹K and C = M⁻¹C,
//!
//! ```text
//! ü  = M⁻¹q − a_g 1 − K u − C u̇        Δü = −Δa 1,
//! u⃛  = −ȧ_g 1 − K u̇ − C ü             Δu⃛ = −Δȧ 1 + Δa C1,
//! u⁗ = −ä_g 1 − K ü − C u⃛             Δu⁗ = −Δä 1 + Δa (K1 − C²1) + Δȧ C1:
//! ```
//!
//! a correction by the fixed vectors C1 and K1 − C²1 of the configuration,
//! made once with its map. It differs from the recomputed stack by the
//! rounding of the products' terms, which only the quiet test's verdicts
//! read (the recorded ü at a sub-step's end is always recomputed).

use super::super::system::Columns;
use super::Stack;

/// The responses of a configuration's stack to a unit jump of the ground:
/// C1 and K1 − C²1 (M⁻¹K, M⁻¹C).
#[derive(Debug, Clone)]
pub struct GroundJump {
    /// C1: u⃛'s response to a_g, u⁗'s to ȧ_g.
    damping: Vec<f64>,
    /// K1 − C²1: u⁗'s response to a_g.
    second: Vec<f64>,
}

impl GroundJump {
    /// Of the configuration whose M⁻¹K and M⁻¹C are `columns` (n floors).
    pub fn of(columns: &Columns, n: usize) -> GroundJump {
        let (ones, zeros) = (vec![1.0; n], vec![0.0; n]);
        // Columns::rate gives −K x − C y (no load, g = 0).
        let (mut minus_k, mut minus_c, mut c_minus_c) = (Vec::new(), Vec::new(), Vec::new());
        columns.rate((&ones, &zeros), None, 0.0, &mut minus_k);
        columns.rate((&zeros, &ones), None, 0.0, &mut minus_c);
        // −C(−C1) = C²1.
        columns.rate((&zeros, &minus_c), None, 0.0, &mut c_minus_c);
        GroundJump {
            damping: minus_c.iter().map(|x| -x).collect(),
            second: minus_k
                .iter()
                .zip(&c_minus_c)
                .map(|(k, c2)| -k - c2)
                .collect(),
        }
    }
}

impl Stack {
    /// The same state's stack under ground (a, ȧ) on a piece with σ
    /// (ä_g = σa), from this one's by the ground's changes (module doc).
    pub fn reground(&mut self, jump: &GroundJump, (a, rate, sigma): (f64, f64, f64)) {
        let ground = [a, rate, sigma * a];
        let [da, dr, dd] = std::array::from_fn(|k| ground[k] - self.ground[k]);
        self.ground = ground;
        let [_, _, acc, jerk, snap] = &mut self.rates;
        for ((acc, jerk), &c1) in acc.iter_mut().zip(jerk.iter_mut()).zip(&jump.damping) {
            *acc -= da;
            *jerk += da * c1 - dr;
        }
        // u⁗ only where it is made ([`Stack::make_snap`]).
        if self.snap {
            for ((snap, &c1), &second) in snap.iter_mut().zip(&jump.damping).zip(&jump.second) {
                *snap += da * second + dr * c1 - dd;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::GroundJump;
    use crate::model::buildings::load;
    use crate::solver::buildings::bound::Stack;
    use crate::solver::buildings::config::{Branch, Config};
    use crate::solver::buildings::layout::Layout;
    use crate::solver::buildings::system::System;
    use proptest::prelude::*;

    /// Block-and-frame in three configurations (elastic with plastic
    /// offsets, a yielding storey in each building, the frame's first
    /// three on the lower branch): M⁻¹K, M⁻¹C and M⁻¹q of each.
    fn systems() -> Vec<System> {
        let row = load("block-and-frame").expect("a shipped row");
        let layout = Layout::of(&row);
        let storeys = layout.storeys.len();
        let branch = |f: &dyn Fn(usize) -> Branch| (0..storeys).map(f).collect::<Vec<_>>();
        [
            branch(&|_| Branch::Elastic),
            branch(&|i| {
                if i == 0 || i == 3 {
                    Branch::Plus
                } else {
                    Branch::Elastic
                }
            }),
            branch(&|i| {
                if (3..6).contains(&i) {
                    Branch::Minus
                } else {
                    Branch::Elastic
                }
            }),
        ]
        .into_iter()
        .map(|branch| {
            let mut config = Config::at_rest(storeys, layout.pairs.len());
            config.branch = branch;
            config.plastic = (0..storeys).map(|i| 1e-3 * i as f64).collect();
            System::of(&layout, &config)
        })
        .collect()
    }

    proptest! {
        /// At random states of block-and-frame's configurations (u to
        /// 0.2 m, u̇ to 2 m/s), the end stack of one piece regrounded to
        /// the next piece's ground (a_g continuous but for a rounding, or
        /// jumping too; ȧ_g and σ jumping) is the stack recomputed there, each rate
        /// within 1e-13 of the sizes of the terms it sums (Σ_j |K_ij x_j|
        /// + |C_ij y_j| and the ground's, at its largest over the floors);
        /// so is one carried without its u⁗, which is made after the jump.
        #[test]
        fn the_regrounded_stack_is_the_recomputed_one(
            which in 0usize..3,
            state in prop::collection::vec((-0.2f64..0.2, -2.0f64..2.0), 11),
            (a, old_rate, new_rate) in (-5.0f64..5.0, -500.0f64..500.0, -500.0f64..500.0),
            (rounding, jump) in (-4i32..=4, prop_oneof![Just(0.0), -5.0f64..5.0]),
            (old_sigma, new_sigma) in (prop_oneof![Just(0.0), -1e4f64..0.0], prop_oneof![Just(0.0), -1e4f64..0.0]),
        ) {
            let system = &systems()[which];
            let n = system.load.len();
            prop_assert_eq!(n, state.len());
            let u: Vec<f64> = state.iter().map(|s| s.0).collect();
            let v: Vec<f64> = state.iter().map(|s| s.1).collect();
            // The old piece's a_g at its end, off the new piece's by a few
            // ulps, or (for the correction's a_g terms) by a whole jump.
            let old_a = a + jump + rounding as f64 * f64::EPSILON * a.abs();
            let mut carried = Stack::at(system, (&u, &v), (old_a, old_rate, old_sigma));
            let jump = GroundJump::of(&system.columns, n);
            carried.reground(&jump, (a, new_rate, new_sigma));
            let fresh = Stack::at(system, (&u, &v), (a, new_rate, new_sigma));
            prop_assert_eq!(carried.ground, fresh.ground);
            // The size of each rate's terms: Σ_j |K_ij x_j| + |C_ij y_j| + |b_i|.
            let size = |x: &[f64], y: &[f64], b: f64| {
                (0..n)
                    .map(|i| {
                        (0..n)
                            .map(|j| (system.stiffness[(i, j)] * x[j]).abs() + (system.damping[(i, j)] * y[j]).abs())
                            .sum::<f64>()
                            + b.abs()
                            + system.load[i].abs()
                    })
                    .fold(0.0, f64::max)
            };
            let r = &fresh.rates;
            let sizes = [
                size(&r[0], &r[1], a),
                size(&r[1], &r[2], new_rate),
                size(&r[2], &r[3], new_sigma * a),
            ];
            for (k, size) in sizes.into_iter().enumerate() {
                for (c, f) in carried.rates[k + 2].iter().zip(&fresh.rates[k + 2]) {
                    prop_assert!(
                        (c - f).abs() <= 1e-13 * size,
                        "rate {}: {} against {} (terms of size {})", k + 2, c, f, size
                    );
                }
            }
            // (u, u̇) are the state's own.
            prop_assert_eq!(&carried.rates[..2], &fresh.rates[..2]);
            // Carried without its u⁗ (Stack::set_to_jerk), the stack's ü
            // and u⃛ are the full one's bit for bit, and the u⁗ made after
            // the jump is within the same allowance of the recomputed one.
            let mut lean = Stack::default();
            lean.set_to_jerk(system, (&u, &v), (old_a, old_rate, old_sigma));
            lean.reground(&jump, (a, new_rate, new_sigma));
            prop_assert!(!lean.snap);
            prop_assert_eq!(&lean.rates[..4], &carried.rates[..4]);
            lean.make_snap(system);
            for (c, f) in lean.rates[4].iter().zip(&fresh.rates[4]) {
                prop_assert!((c - f).abs() <= 1e-13 * sizes[2], "u⁗: {} against {}", c, f);
            }
        }
    }
}
