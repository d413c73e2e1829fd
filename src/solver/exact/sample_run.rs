//! One structure's sample map laid out for the tight loop of quiet samples
//! (SPEC §2–3, §9): the same superposition as [`super::sample::SampleMap`],
//! its terms regrouped so that the state's chain from one sample to the
//! next is two multiply-adds.
//!
//! With x* = Q/K the branch's equilibrium (0 where K = 0, the load Q/m then
//! an input of its own) and e_j the unit responses' ends,
//!
//! ```text
//! y(h) = (x*, 0) + (x − x*) e₀ + ẋ e₁ + g_k e₂ + s e₃ [+ (Q/m) e₄]
//!      = x e₀ + ẋ e₁ + [ (x*, 0) − x* e₀ (+ (Q/m) e₄) + g_k e₂ + s e₃ ],
//! ```
//!
//! where the bracket waits on the record alone. The swing bounds stay those
//! of [`super::linear_map::swing`], |x − x₀| ≤ Σ_j |input_j| swing_j (and
//! likewise for ẋ), with the round-off allowance (1 + 1e-12) folded into
//! each swing: a bound of a sum of non-negative products, each rounded up
//! by far less than that factor, stays a bound. Regrouping moves the end
//! state by a few units in the last place of x* (of |x| on a yielded
//! branch), as the grouping about x* did.

use super::linear_map::INPUTS;
use super::quiet::Bands;
use crate::numerics::madd;

/// The round-off allowance of the swing bounds, folded into each swing.
const SWING_MARGIN: f64 = 1.0 + 1e-12;

/// One structure's map on one branch with one load, for the tight loop.
#[derive(Debug, Clone, Copy)]
pub struct Lane {
    /// (x, ẋ) at h per unit x, per unit ẋ, per unit g_k, per unit s.
    per_x: [f64; 2],
    per_v: [f64; 2],
    per_g: [f64; 2],
    per_s: [f64; 2],
    /// (x*, 0) − x* e₀ (+ (Q/m) e₄): the part of the end state fixed by the branch.
    offset: [f64; 2],
    /// The swings per unit |x − x*|, |ẋ|, |g_k|, |s| (with the margin), and
    /// the constant swing of the load input where K = 0.
    swing_x: [f64; 2],
    swing_v: [f64; 2],
    swing_g: [f64; 2],
    swing_s: [f64; 2],
    swing_load: [f64; 2],
    /// x*, and Q/m, c/m, K/m for |ẍ + g| = |Q/m − (c/m) ẋ − (K/m) x|.
    equilibrium: f64,
    load: f64,
    damping: f64,
    stiffness: f64,
}

/// What one quiet sample of one structure gave: whether the swing bounds
/// kept it in its bands, its end state, its inputs (for the work integrals)
/// and the swing of x.
#[derive(Debug, Clone, Copy)]
pub struct Step {
    pub clear: bool,
    pub end: [f64; 2],
    pub inputs: [f64; INPUTS],
    pub swing_x: f64,
}

impl Lane {
    /// From the unit responses' ends and swings ([`super::linear_map`]), the
    /// branch's K/m, 1/(K/m) (0 where K = 0), c/m, and the load Q/m.
    pub fn new(
        end: &[[f64; 2]; INPUTS],
        swing: &[[f64; 2]; INPUTS],
        [stiffness, inverse_stiffness, damping]: [f64; 3],
        load: f64,
    ) -> Self {
        let (equilibrium, free_load) = if stiffness > 0.0 {
            (load * inverse_stiffness, 0.0)
        } else {
            (0.0, load)
        };
        let scaled = |w: [f64; 2]| w.map(|w| w * SWING_MARGIN);
        Lane {
            per_x: end[0],
            per_v: end[1],
            per_g: end[2],
            per_s: end[3],
            offset: [
                equilibrium - equilibrium * end[0][0] + free_load * end[4][0],
                -equilibrium * end[0][1] + free_load * end[4][1],
            ],
            swing_x: scaled(swing[0]),
            swing_v: scaled(swing[1]),
            swing_g: scaled(swing[2]),
            swing_s: scaled(swing[3]),
            swing_load: scaled(swing[4]).map(|w| w * free_load.abs()),
            equilibrium,
            load,
            damping,
            stiffness,
        }
    }

    /// One interval from (x, ẋ) under g = g_k + s t, held to `bands` (and
    /// |ẍ + g| to its running peak where `ACCEL`) by the swing bounds alone.
    /// Computed whole, without branches.
    #[inline(always)]
    pub fn step<const ACCEL: bool>(&self, x: f64, v: f64, [g, s]: [f64; 2], bands: &Bands) -> Step {
        let d = x - self.equilibrium;
        let (ad, av, ag, as_) = (d.abs(), v.abs(), g.abs(), s.abs());
        let swing = [0, 1].map(|j| {
            self.swing_load[j]
                + ag * self.swing_g[j]
                + as_ * self.swing_s[j]
                + av * self.swing_v[j]
                + ad * self.swing_x[j]
        });
        let end = [0, 1].map(|j| {
            let record = self.offset[j] + g * self.per_g[j] + s * self.per_s[j];
            madd(x, self.per_x[j], madd(v, self.per_v[j], record))
        });
        let [sx, sv] = swing;
        let mut clear = bands.hold_by_swings(x, v, swing);
        if ACCEL {
            let accel = self.load - self.damping * v - self.stiffness * x;
            clear &=
                accel.abs() + self.damping * sv + self.stiffness * sx < bands.absolute_acceleration;
        }
        let inputs = if self.stiffness > 0.0 {
            [d, v, g, s, 0.0]
        } else {
            [x, v, g, s, self.load]
        };
        Step {
            clear,
            end,
            inputs,
            swing_x: sx,
        }
    }
}
