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
//!
//! The swings Σ|u_k| h^k grow like e^{Ωh}, so they serve only while Ω h ≤ 1.
//! A structure much faster than the other would then hold both to its own
//! short segments. Over longer ones its unit responses come from doubling a
//! short one, and its bounds from splitting x = x* + x_p + y into the
//! equilibrium of the branch, the steady response to g and the free
//! vibration, whose energy cannot grow ([`Majorants::new`]): once the free
//! vibration has decayed, a stiff structure moves like its small steady
//! response, whatever its own rate.

use super::dynamics::{Branch, Structure, oscillator};
use super::roots::cleared;
use super::series::Series;

/// The inputs x − x*, ẋ, sin τ₀, cos τ₀, Q/m ([`linear_map`]).
use super::linear_map::{self, INPUTS};

/// The unit responses of one structure on one branch kind over length h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transition {
    /// The segment's length h.
    pub length: f64,
    /// (x, ẋ) at h for each unit input.
    pub end: [[f64; 2]; INPUTS],
    /// (swing of x, swing of ẋ) over [0, h] for each unit input, where the
    /// series give them (Ω h ≤ 1); else `None`, and [`Transition::swing`]
    /// takes the bounds of the steady and free split instead.
    series_swing: Option<[[f64; 2]; INPUTS]>,
    /// K/m and c/m of the branch, and 1/(K/m) (0 where K = 0).
    pub stiffness: f64,
    pub damping: f64,
    inverse_stiffness: f64,
    /// √(K/m) and its inverse (0 where K = 0).
    root_stiffness: f64,
    inverse_root_stiffness: f64,
    /// (P, Q) of the steady response x_p = P sin τ + Q cos τ to g = sin τ,
    /// and its amplitude √(P² + Q²) (∞ where there is none: K/m = 1, c = 0).
    steady: [f64; 2],
    steady_amplitude: f64,
}

impl Transition {
    /// For stiffness `k` (k or Π_α k) on structure `s`, over length `h`,
    /// with series of degree `n` summed to round-off over lengths with
    /// Ω h ≤ 1 (Ω the structure's rate), and longer lengths reached by
    /// doubling such a one.
    pub fn new(s: &Structure, k: f64, h: f64, n: usize) -> Self {
        let mut doublings = 0;
        while h * s.rate > (1u64 << doublings) as f64 && doublings < 60 {
            doublings += 1;
        }
        let mut t = Transition::series(s, k, h / (1u64 << doublings) as f64, n);
        for _ in 0..doublings {
            t = t.doubled();
        }
        t
    }

    /// [`Transition::new`] over a length short enough for the series.
    fn series(s: &Structure, k: f64, h: f64, n: usize) -> Self {
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
        let (end, swing) = linear_map::ends_and_swings(&units, h, &mut [Series::default(); INPUTS]);
        // x_p'' + c x_p' + K x_p = −sin τ: (K − 1) P − c Q = −1, c P + (K − 1) Q = 0.
        let d = (k - 1.0) * (k - 1.0) + c * c;
        let (steady, steady_amplitude) = if d > 0.0 {
            ([(1.0 - k) / d, c / d], 1.0 / d.sqrt())
        } else {
            ([0.0; 2], f64::INFINITY)
        };
        Transition {
            length: h,
            end,
            series_swing: Some(swing),
            stiffness: k,
            damping: c,
            inverse_stiffness: if k > 0.0 { 1.0 / k } else { 0.0 },
            root_stiffness: k.sqrt(),
            inverse_root_stiffness: if k > 0.0 { 1.0 / k.sqrt() } else { 0.0 },
            steady,
            steady_amplitude,
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
        linear_map::inputs(self.stiffness, self.inverse_stiffness, x, v, phasor, load)
    }

    /// (x, ẋ) at the segment's end, for inputs from [`Transition::inputs`]
    /// and the equilibrium they were taken from.
    #[inline]
    pub fn advance(&self, inputs: &[f64; INPUTS], equilibrium: f64) -> [f64; 2] {
        linear_map::advance(&self.end, inputs, equilibrium)
    }

    /// The same over 2h: the segment twice, the second from the state and
    /// phasor the first reaches, (sin, cos)(τ₀ + h) = R(h) (sin τ₀, cos τ₀):
    ///
    /// ```text
    /// E₂[x₀, ẋ₀, L] = E_y E[·] (+ E[L] for the load),
    /// E₂[sin] = E_y E[sin] + cos h · E[sin] − sin h · E[cos],
    /// E₂[cos] = E_y E[cos] + sin h · E[sin] + cos h · E[cos],
    /// ```
    ///
    /// with E_y = (E[x₀] E[ẋ₀]) the 2 × 2 transition of the state.
    fn doubled(&self) -> Self {
        let e = &self.end;
        let through = |col: [f64; 2]| {
            [
                e[0][0] * col[0] + e[1][0] * col[1],
                e[0][1] * col[0] + e[1][1] * col[1],
            ]
        };
        let (sh, ch) = self.length.sin_cos();
        let [a, b] = [through(e[2]), through(e[3])];
        let [l, load] = [through(e[4]), e[4]];
        let end = [
            through(e[0]),
            through(e[1]),
            [
                a[0] + ch * e[2][0] - sh * e[3][0],
                a[1] + ch * e[2][1] - sh * e[3][1],
            ],
            [
                b[0] + sh * e[2][0] + ch * e[3][0],
                b[1] + sh * e[2][1] + ch * e[3][1],
            ],
            [l[0] + load[0], l[1] + load[1]],
        ];
        Transition {
            length: 2.0 * self.length,
            end,
            series_swing: None,
            ..*self
        }
    }

    /// Bounds of |x − x₀| and |ẋ − ẋ₀| over the segment, for a structure at
    /// (x, ẋ) with inputs from [`Transition::inputs`]: Σ_j |input_j| swing_j
    /// where the series give the swings; else, by the split of
    /// [`Majorants::new`] (x = x* + x_p + y, |x_p'| ≤ R, |x_p''| ≤ R,
    /// |y| ≤ w/ω, |y'| ≤ w),
    ///
    /// ```text
    /// |x − x₀| ≤ R min(h, 2) + |y₀| + w/ω,   |ẋ − ẋ₀| ≤ R min(h, 2) + |y₀'| + w,
    /// ```
    ///
    /// infinite where K = 0 (no split).
    #[inline]
    pub fn swing(&self, inputs: &[f64; INPUTS]) -> [f64; 2] {
        match &self.series_swing {
            Some(swing) => linear_map::swing(swing, inputs),
            None => self.split_swing(inputs),
        }
    }

    /// The jerk and snap bounds of [`Majorants::new`], each lowered to its
    /// bound by the split where that is smaller.
    #[inline(never)]
    fn split_bounds(
        &self,
        x: f64,
        v: f64,
        phasor: [f64; 2],
        load: f64,
        jerk: f64,
        snap: f64,
    ) -> (f64, f64) {
        match self.free_vibration(&self.inputs(x, v, phasor, load).0) {
            Some(FreeVibration { w, .. }) => {
                let r = self.steady_amplitude * GROUND_BOUND;
                let accel_y = (self.damping + self.root_stiffness) * w;
                let jerk_y = self.damping * accel_y + self.stiffness * w;
                let snap_y = self.damping * jerk_y + self.stiffness * accel_y;
                (jerk.min(r + jerk_y), snap.min(r + snap_y))
            }
            None => (jerk, snap),
        }
    }

    /// [`Transition::swing`] by the split.
    #[inline(never)]
    fn split_swing(&self, inputs: &[f64; INPUTS]) -> [f64; 2] {
        match self.free_vibration(inputs) {
            Some(FreeVibration { y, dy, w }) => {
                let r = self.steady_amplitude * GROUND_BOUND * self.length.min(2.0);
                let sx = r + y.abs() + w * self.inverse_root_stiffness;
                let sv = r + dy.abs() + w;
                [sx, sv].map(|v| v * (1.0 + 1e-12))
            }
            None => [f64::INFINITY; 2],
        }
    }

    /// The free vibration y = x − x* − x_p at the segment's start, for inputs
    /// from [`Transition::inputs`] (x − x*, ẋ, sin τ₀, cos τ₀, ·), and the
    /// square root w of its energy W = y'² + (K/m) y², which cannot grow
    /// (dW/dτ = −2 (c/m) y'²); `None` where K = 0 or there is no steady response.
    #[inline]
    fn free_vibration(&self, inputs: &[f64; INPUTS]) -> Option<FreeVibration> {
        if !(self.stiffness > 0.0 && self.steady_amplitude.is_finite()) {
            return None;
        }
        let [from_equilibrium, v, s, c, _] = *inputs;
        let [p, q] = self.steady;
        let y = from_equilibrium - (p * s + q * c);
        let dy = v - (p * c - q * s);
        // The energy is taken from differences of rounded values: allow for them.
        let w = (dy * dy + self.stiffness * y * y).sqrt()
            + 1e-15 * (self.root_stiffness * from_equilibrium.abs() + v.abs())
            + 1e-15 * self.steady_amplitude * (1.0 + self.root_stiffness);
        Some(FreeVibration { y, dy, w })
    }
}

/// Everything a quiet segment of one length needs: the length h, (sin h,
/// cos h) to turn the ground phasor on, and the unit responses of each
/// structure (index) on each branch kind (elastic, yielded).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuietStep {
    pub length: f64,
    pub turn: [f64; 2],
    pub transitions: [[Transition; 2]; 2],
}

impl QuietStep {
    pub fn new(structures: &[Structure; 2], h: f64, n: usize) -> Self {
        let (s, c) = h.sin_cos();
        QuietStep {
            length: h,
            turn: [s, c],
            transitions: structures.map(|s| {
                [s.stiffness, s.alpha * s.stiffness].map(|k| Transition::new(&s, k, h, n))
            }),
        }
    }
}

/// A structure's free vibration at a segment's start: y, y' and √W.
struct FreeVibration {
    y: f64,
    dy: f64,
    w: f64,
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
    ///
    /// Where K > 0 a second bound holds for all later τ, and is the sharper
    /// one once the free vibration has decayed, above all for a stiff
    /// structure, whose x is then a small steady response that the terms
    /// (K/m) X and |g| above bound only by 1 each. Split x = x* + x_p + y,
    /// with x_p = P sin τ + Q cos τ the steady response to g (all of its
    /// derivatives bounded by R = √(P² + Q²)) and y the free vibration,
    /// y'' + (c/m) y' + (K/m) y = 0, whose energy W = y'² + (K/m) y² cannot
    /// grow (dW/dτ = −2 (c/m) y'²). With w = √W₀ and ω = √(K/m):
    ///
    /// ```text
    /// |y'| ≤ w,  |y''| ≤ A_y = ((c/m) + ω) w,  |y'''| ≤ J_y = (c/m) A_y + (K/m) w,
    /// |y⁽⁴⁾| ≤ (c/m) J_y + (K/m) A_y,    |x⁽ᵏ⁾| ≤ R + |y⁽ᵏ⁾|
    /// ```
    ///
    /// and each of the two jerk and snap bounds is taken at its smaller, on
    /// the segments too long for the series' swings.
    #[inline]
    pub fn new(
        t: &Transition,
        x: f64,
        v: f64,
        phasor: [f64; 2],
        load: f64,
        swing: [f64; 2],
    ) -> Self {
        let [a0, j0, jerk, snap] = linear_map::derivative_bounds(
            t.stiffness,
            t.inverse_stiffness,
            t.damping,
            x,
            v,
            phasor,
            load,
            swing,
            [GROUND_BOUND; 3],
        );
        // The split costs a square root; over the short segments whose swings
        // the series give, measured, it does not repay it.
        let (jerk, snap) = match t.series_swing {
            Some(_) => (jerk, snap),
            None => t.split_bounds(x, v, phasor, load, jerk, snap),
        };
        let [x, v] = linear_map::cubic_majorants(x, v, a0, j0, jerk, snap);
        Majorants { x, v }
    }
}

/// What x, ẋ and |ẍ + g| of one structure must stay strictly inside for a
/// stretch to be quiet: x within its running peak Π_u and, on an elastic
/// branch, within the yield surface (one band, the tighter of the two on
/// each side); ẋ within its running peak Π_v and, while yielded, on the
/// loading side σ ẋ > 0 (no unloading); |ẍ + g| below its running peak A
/// (∞ where A is not located).
#[derive(Debug, Clone, Copy)]
pub struct Bands {
    pub x: [f64; 2],
    pub v: [f64; 2],
    pub absolute_acceleration: f64,
}

impl Bands {
    /// From the branch, Π_uy, and the running peaks Π_u, Π_v and A.
    #[inline]
    pub fn new(branch: Branch, uy: f64, px: f64, pv: f64, pa: f64) -> Self {
        let x = match branch {
            Branch::Elastic { offset } if uy.is_finite() => {
                [(-px).max(offset - uy), px.min(offset + uy)]
            }
            _ => [-px, px],
        };
        let v = match branch {
            Branch::Yielded { sign } if sign > 0.0 => [0.0, pv],
            Branch::Yielded { .. } => [-pv, 0.0],
            Branch::Elastic { .. } => [-pv, pv],
        };
        Bands {
            x,
            v,
            absolute_acceleration: pa,
        }
    }

    /// By the swings: x ± s_x and ẋ ± s_v inside their bands.
    #[inline]
    pub fn hold_by_swings(&self, x: f64, v: f64, [sx, sv]: [f64; 2]) -> bool {
        // Non-short-circuit: four comparisons and no branches.
        (x - sx > self.x[0]) & (x + sx < self.x[1]) & (v - sv > self.v[0]) & (v + sv < self.v[1])
    }

    /// By the cubic majorants of x and ẋ over (0, h], and of ẍ + g where
    /// `accel` is given (its swing bound having failed).
    #[inline]
    pub fn hold_by_majorants(
        &self,
        x: &[f64; 4],
        v: &[f64; 4],
        accel: Option<[f64; 4]>,
        h: f64,
    ) -> bool {
        let between =
            |m: &[f64; 4], [lo, hi]: [f64; 2]| stays_below(m, hi, h) && stays_above(m, lo, h);
        let pa = self.absolute_acceleration;
        between(x, self.x) && between(v, self.v) && accel.is_none_or(|a| between(&a, [-pa, pa]))
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
    use crate::model::{Params, SET1};

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

    /// The motion of `s` on stiffness `k` from (x₀, ẋ₀) at τ₀ under g = sin τ
    /// with load Q/m, at `pieces` + 1 equal steps over [τ₀, τ₀ + h], each
    /// piece a series of the whole state from the last (Ω h/pieces ≪ 1).
    fn marched(
        s: &Structure,
        k: f64,
        y0: [f64; 2],
        tau0: f64,
        load: f64,
        h: f64,
        pieces: usize,
    ) -> Vec<[f64; 2]> {
        let inv_m = 1.0 / s.mass;
        let dt = h / pieces as f64;
        let mut y = y0;
        let mut out = vec![y];
        for j in 0..pieces {
            let mut g = Series {
                degree: 20,
                ..Series::default()
            };
            crate::model::Excitation::Sine.taylor(tau0 + j as f64 * dt, &mut g.c[..=20]);
            let u = oscillator(s.damping * inv_m, k * inv_m, load, y[0], y[1], &g, 20);
            let (x, v) = u.value_slope(dt);
            y = [x, v];
            out.push(y);
        }
        out
    }

    #[test]
    fn a_long_segment_of_a_stiff_structure_is_doubled_and_bounded_by_the_split() {
        // The right structure of set 1 at Π_ω2 = 20: over h = 0.5 (Ω h ≈ 10)
        // the series cannot serve; the transition is doubled from h/16.
        let s = Structure::pair(&Params {
            omega2: 20.0,
            ..SET1
        })[1];
        let h = 0.5;
        for (k, load) in [(s.stiffness, 0.0), (s.alpha * s.stiffness, 0.3)] {
            let t = Transition::new(&s, k, h, 20);
            assert!(t.series_swing.is_none());
            let inv_m = 1.0 / s.mass;
            // Near the steady response (a small free vibration) and ringing.
            let [p, q] = t.steady;
            let eq = load / (k * inv_m);
            for (tau0, ring) in [(0.7, 1e-6), (2.0, 0.01), (4.0, 0.3)] {
                let (sn, cs) = f64::sin_cos(tau0);
                let x0 = eq + p * sn + q * cs + ring;
                let v0 = p * cs - q * sn - 3.0 * ring;
                let path = marched(&s, k, [x0, v0], tau0, load, h, 400);
                let (inputs, e) = t.inputs(x0, v0, [sn, cs], load);
                let [x, v] = t.advance(&inputs, e);
                let [xe, ve] = path[400];
                assert!(
                    (x - xe).abs() < 1e-13 && (v - ve).abs() < 1e-12,
                    "end {x} {xe} {v} {ve}"
                );
                let [sx, sv] = t.swing(&inputs);
                let m = Majorants::new(&t, x0, v0, [sn, cs], load, [sx, sv]);
                let (mut seen_x, mut seen_v) = (0.0f64, 0.0f64);
                for (j, [xi, vi]) in path.iter().enumerate() {
                    let u = h * j as f64 / 400.0;
                    seen_x = seen_x.max((xi - x0).abs());
                    seen_v = seen_v.max((vi - v0).abs());
                    let cubic = |c: &[f64; 4], sign: f64| {
                        sign * (c[0] + u * (c[1] + u * c[2])) + c[3] * u * u * u
                    };
                    for sign in [1.0, -1.0] {
                        assert!(sign * xi <= cubic(&m.x, sign) + 1e-14, "x at {u}");
                        assert!(sign * vi <= cubic(&m.v, sign) + 1e-13, "v at {u}");
                    }
                }
                assert!(
                    seen_x <= sx && seen_v <= sv,
                    "{seen_x} ≤ {sx}, {seen_v} ≤ {sv}"
                );
                // Bounds, not guesses: near the steady response they are within
                // a few times the true swing.
                if ring < 1e-3 {
                    assert!(
                        sx < 4.0 * seen_x && sv < 4.0 * seen_v,
                        "{sx} {seen_x} {sv} {seen_v}"
                    );
                }
            }
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
