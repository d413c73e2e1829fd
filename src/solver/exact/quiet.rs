//! Quiet free segments by transition matrix, with no series at all.
//!
//! Out of contact, on a fixed branch, each structure's state y = (x, ẋ)
//! after a segment of the fixed length h is linear in its inputs: the
//! initial state, the ground phasor (sin τ₀, cos τ₀) of g = sin τ, and the
//! branch's constant load Q/m (SPEC §2–3):
//!
//! ```text
//! y(τ₀ + t) = Φ(t) y(τ₀) + sin τ₀ · γ_s(t) + cos τ₀ · γ_c(t) + (Q/m) · γ_1(t),
//! ```
//!
//! where Φ columns and the γ are the responses to one unit input each
//! (g(τ₀ + t) = sin τ₀ cos t + cos τ₀ sin t). These five unit responses are
//! computed once per structure and branch kind, as series summed to
//! round-off. The same superposition bounds how far x and ẋ can move inside
//! the segment: |x(τ₀ + t) − x(τ₀)| ≤ Σ_j |input_j| · swing_j, with swing_j
//! = Σ_{k≥1} |u_{j,k}| h^k of unit response j. When those bounds keep every
//! event function negative and every peak below its running value, the
//! segment is quiet: the state is advanced by the matrix alone.

use super::dynamics::{Structure, oscillator};
use super::roots::cleared;
use super::series::Series;

/// Number of inputs: x₀, ẋ₀, sin τ₀, cos τ₀, Q/m.
const INPUTS: usize = 5;

/// The unit responses of one structure on one branch kind over length h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transition {
    /// (x, ẋ) at h for each unit input.
    pub end: [[f64; 2]; INPUTS],
    /// (swing of x, swing of ẋ) over [0, h] for each unit input.
    pub swing: [[f64; 2]; INPUTS],
    /// K/m and c/m of the branch, and 1/(K/m) (0 where K = 0).
    pub stiffness: f64,
    pub damping: f64,
    inverse_stiffness: f64,
}

impl Transition {
    /// For stiffness `k` (k or Π_α k) on structure `s`, over length `h`,
    /// with series of degree `n` (summed to round-off when Ω h ≤ 1).
    pub fn new(s: &Structure, k: f64, h: f64, n: usize) -> Self {
        let inv_m = 1.0 / s.mass;
        let (c, k) = (s.damping * inv_m, k * inv_m);
        let mut ground_sin = Series {
            degree: n,
            ..Series::default()
        };
        let mut ground_cos = ground_sin;
        let zero = ground_sin;
        // g(τ₀ + t) = sin τ₀ · cos t + cos τ₀ · sin t.
        crate::model::Excitation::Sine.taylor(std::f64::consts::FRAC_PI_2, &mut ground_sin.c[..=n]);
        crate::model::Excitation::Sine.taylor(0.0, &mut ground_cos.c[..=n]);
        let units = [
            oscillator(c, k, 0.0, 1.0, 0.0, &zero, n),
            oscillator(c, k, 0.0, 0.0, 1.0, &zero, n),
            oscillator(c, k, 0.0, 0.0, 0.0, &ground_sin, n),
            oscillator(c, k, 0.0, 0.0, 0.0, &ground_cos, n),
            oscillator(c, k, 1.0, 0.0, 0.0, &zero, n),
        ];
        let mut end = [[0.0; 2]; INPUTS];
        let mut swing = [[0.0; 2]; INPUTS];
        for (j, u) in units.iter().enumerate() {
            let (du, sx, sv) = u.derivative_and_swings(h);
            end[j] = [u.value(h), du.value(h)];
            swing[j] = [sx, sv];
        }
        Transition {
            end,
            swing,
            stiffness: k,
            damping: c,
            inverse_stiffness: if k > 0.0 { 1.0 / k } else { 0.0 },
        }
    }

    /// The inputs of a segment, in the order of the unit responses, for a
    /// structure at (x, ẋ) with load Q/m on this branch. Where K > 0 the
    /// displacement is taken from the branch's static equilibrium x* = Q/K
    /// (with a unit displacement response, which then carries the load):
    /// the large, cancelling parts of x and Q/m of a yielded branch then do
    /// not inflate the bounds.
    /// Returns the inputs and the equilibrium they were taken from (0 without one).
    #[inline]
    pub fn inputs(&self, x: f64, v: f64, phasor: [f64; 2], load: f64) -> ([f64; INPUTS], f64) {
        if self.stiffness > 0.0 {
            let equilibrium = load * self.inverse_stiffness;
            ([x - equilibrium, v, phasor[0], phasor[1], 0.0], equilibrium)
        } else {
            ([x, v, phasor[0], phasor[1], load], 0.0)
        }
    }

    /// (x, ẋ) at the segment's end, for inputs from [`Transition::inputs`]
    /// and the equilibrium they were taken from.
    #[inline]
    pub fn advance(&self, inputs: &[f64; INPUTS], equilibrium: f64) -> [f64; 2] {
        let mut y = [equilibrium, 0.0];
        for (u, e) in inputs.iter().zip(&self.end) {
            y[0] += u * e[0];
            y[1] += u * e[1];
        }
        y
    }

    /// Bounds of |x − x₀| and |ẋ − ẋ₀| over the segment.
    #[inline]
    pub fn swing(&self, inputs: &[f64; INPUTS]) -> [f64; 2] {
        let mut s = [0.0; 2];
        for (u, w) in inputs.iter().zip(&self.swing) {
            s[0] += u.abs() * w[0];
            s[1] += u.abs() * w[1];
        }
        // The bounds are sums of products: allow for their own round-off.
        s.map(|v| v * (1.0 + 1e-12))
    }
}

/// Bounds of |g|, |g'| and |g''| of the sine excitation, g = sin τ.
const GROUND_BOUND: f64 = 1.0;

/// Cubic majorants of x and ẋ of one structure over a quiet segment:
/// q(s) ≤ q₀ + q₁ s + q₂ s² + M s³ for s ∈ [0, h], and −q likewise with
/// q₀, q₁, q₂ negated (Taylor's theorem, M bounding |q'''|/6).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Majorants {
    pub x: [f64; 4],
    pub v: [f64; 4],
}

impl Majorants {
    /// From the branch's transition (its K/m and c/m), the state (x, ẋ),
    /// the phasor (sin τ₀, cos τ₀), the branch's Q/m and the swings of [`Transition::swing`] over the
    /// segment. With ẍ = Q/m − (c/m) ẋ − (K/m) x − g (SPEC §2–3):
    ///
    /// ```text
    /// ẍ₀  = Q/m − (c/m) ẋ₀ − (K/m) x₀ − sin τ₀
    /// x⁽³⁾₀ = −(c/m) ẍ₀ − (K/m) ẋ₀ − cos τ₀
    /// |ẍ| ≤ A = (c/m) V + (K/m) X + |g|,   X ≥ |x − x*|, V ≥ |ẋ| on the segment
    /// |x⁽³⁾| ≤ J = (c/m) A + (K/m) V + |g'|,   |x⁽⁴⁾| ≤ (c/m) J + (K/m) A + |g''|
    /// ```
    ///
    /// with x* = Q/K the branch's equilibrium (where K = 0, |Q/m| joins A).
    pub fn new(
        t: &Transition,
        x: f64,
        v: f64,
        phasor: [f64; 2],
        load: f64,
        swing: [f64; 2],
    ) -> Self {
        let (stiffness, damping) = (t.stiffness, t.damping);
        let a0 = load - damping * v - stiffness * x - phasor[0];
        let j0 = -damping * a0 - stiffness * v - phasor[1];
        let (from_equilibrium, free_load) = if stiffness > 0.0 {
            ((x - load * t.inverse_stiffness).abs(), 0.0)
        } else {
            (0.0, load.abs())
        };
        let reach_x = from_equilibrium + swing[0];
        let reach_v = v.abs() + swing[1];
        let accel = damping * reach_v + stiffness * reach_x + free_load + GROUND_BOUND;
        let jerk = damping * accel + stiffness * reach_v + GROUND_BOUND;
        let snap = damping * jerk + stiffness * accel + GROUND_BOUND;
        // The bounds are sums of products: allow for their own round-off.
        let margin = 1.0 + 1e-12;
        Majorants {
            x: [x, v, 0.5 * a0, margin * jerk / 6.0],
            v: [v, a0, 0.5 * j0, margin * snap / 6.0],
        }
    }
}

/// Whether q < `ceiling` on (0, h] by its cubic majorant `m`.
#[inline]
pub fn stays_below(m: &[f64; 4], ceiling: f64, h: f64) -> bool {
    let d0 = m[0] - ceiling;
    d0 <= 0.0 && cleared(d0, m[1], m[2], m[3], h)
}

/// Whether q > `floor` on (0, h] by its cubic majorant `m`.
#[inline]
pub fn stays_above(m: &[f64; 4], floor: f64, h: f64) -> bool {
    let d0 = floor - m[0];
    d0 <= 0.0 && cleared(d0, -m[1], -m[2], m[3], h)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn transition_matches_the_series_of_the_whole_state() {
        let s = Structure::pair(&SET1)[0];
        let h = 0.4;
        let (x0, v0, tau0, load) = (0.3, -1.2, 2.0, 0.05);
        let mut g = Series {
            degree: 20,
            ..Series::default()
        };
        crate::model::Excitation::Sine.taylor(tau0, &mut g.c[..=20]);
        let inv_m = 1.0 / s.mass;
        let (s0, c0) = f64::sin_cos(tau0);
        // An elastic branch (about its equilibrium) and one with K = 0 (no equilibrium).
        for k in [s.stiffness, 0.0] {
            let t = Transition::new(&s, k, h, 20);
            let whole = oscillator(s.damping * inv_m, k * inv_m, load, x0, v0, &g, 20);
            let (inputs, eq) = t.inputs(x0, v0, [s0, c0], load);
            let [x, v] = t.advance(&inputs, eq);
            let (xs, vs) = whole.value_slope(h);
            assert!(
                (x - xs).abs() < 1e-15 && (v - vs).abs() < 1e-15,
                "{x} {xs} {v} {vs}"
            );
            let [sx, sv] = t.swing(&inputs);
            let m = Majorants::new(&t, x0, v0, [s0, c0], load, [sx, sv]);
            let cubic = |c: &[f64; 4], sign: f64, u: f64| {
                sign * (c[0] + u * (c[1] + u * c[2])) + c[3] * u * u * u
            };
            for i in 0..=40 {
                let u = h * i as f64 / 40.0;
                let (xi, vi) = whole.value_slope(u);
                assert!((xi - x0).abs() <= sx && (vi - v0).abs() <= sv);
                // Both signs of x and ẋ lie under their cubic majorants.
                for sign in [1.0, -1.0] {
                    assert!(sign * xi <= cubic(&m.x, sign, u) + 1e-15, "x at {u}");
                    assert!(sign * vi <= cubic(&m.v, sign, u) + 1e-15, "v at {u}");
                }
            }
            // and they are close: the cubic term is the only slack, O(h³).
            let (xh, _) = whole.value_slope(h);
            assert!(cubic(&m.x, 1.0, h) - xh < 2.0 * m.x[3] * h.powi(3));
        }
    }

    #[test]
    fn a_peak_just_above_the_swing_is_cleared_by_the_majorant() {
        // At a maximum of x (ẋ = 0), the swing bound cannot clear a peak
        // 1e-3 above x, but the majorant can: x falls away quadratically.
        let s = Structure::pair(&SET1)[0];
        let h = 0.1;
        let t = Transition::new(&s, s.stiffness, h, 20);
        let inv_m = 1.0 / s.mass;
        let (x0, v0) = (2.0, 0.0);
        let phasor = [0.0, 1.0];
        let (inputs, _) = t.inputs(x0, v0, phasor, 0.0);
        let [sx, sv] = t.swing(&inputs);
        let peak = x0 + 1e-3;
        assert!(x0 + sx > peak, "the swing alone does not clear it");
        let m = Majorants::new(&t, x0, v0, phasor, 0.0, [sx, sv]);
        assert!(m.x[2] < 0.0 && (m.x[2] - 0.5 * (-s.stiffness * inv_m * x0)).abs() < 1e-12);
        assert!(stays_below(&m.x, peak, h));
        assert!(!stays_below(&m.x, x0 - 1e-3, h));
    }
}
