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
//! where the bracket waits on the record alone. Regrouping moves the end
//! state by a few units in the last place of x* (of |x| on a yielded
//! branch), as the grouping about x* did.
//!
//! A sample is cleared, without branches, from its two end states (exact)
//! and bounds of the motion's higher derivatives over the interval. For
//! any q with |q''| ≤ M on [0, h], q lies within M h²/8 of the chord of its
//! end values (the interpolation error t(h − t)/2 · M), so
//!
//! ```text
//! max q ≤ max(q(0), q(h)) + M h²/8,     min q ≥ min(q(0), q(h)) − M h²/8.
//! ```
//!
//! With d = x − x*, ẍ = −(c/m) ẋ − (K/m) d − g and g = g_k + s t, the norm
//! N = √(ẋ² + (K/m) d²) grows no faster than |g| (dN/dt = −((c/m) ẋ² + g ẋ)/N
//! ≤ |g|), and where K = 0 |ẋ| grows no faster than |Q/m − g|; hence, with
//! G = max(|g_k|, |g_k + s h|), L = |Q/m| where K = 0 (else 0) and ω = √(K/m),
//!
//! ```text
//! |ẋ|    ≤ V  = |ẋ₀| + ω |d₀| + (G + L) h
//! |ẍ|    ≤ A  = ((c/m) + ω) V + G + L
//! |x⁽³⁾| ≤ J  = (c/m) A + (K/m) V + |s|
//! |x⁽⁴⁾| ≤ J₄ = (c/m) J + (K/m) A,            (g'' = 0 inside)
//! ```
//!
//! and |ẍ + g| = |Q/m − (c/m) ẋ − (K/m) x| has its second derivative within
//! J₄ and its rate's within (c/m) J₄ + (K/m) J. Each watched quantity (x,
//! ẋ, and |ẍ + g| where asked) must then either stay, with that margin, in
//! its band (the event band and its running peak), or be monotone (its
//! rate keeping one sign, by the same bound on the rate) with both ends
//! inside the event band: a monotone quantity peaks at an end, so its
//! running peak becomes max(peak, |q(h)|). Near an extremum only the
//! second-order margin is spent, so the samples left to the full tests are
//! those whose extremum comes within about (ωh)²/8 of its running peak.

use super::dynamics::Branch;
use super::linear_map::INPUTS;
use crate::numerics::madd;

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
    /// x*, Q/m, c/m, K/m, and L = |Q/m| where K = 0 (else 0).
    pub(super) equilibrium: f64,
    pub(super) load: f64,
    damping: f64,
    pub(super) stiffness: f64,
    free_load: f64,
}

impl Lane {
    /// From the unit responses' ends ([`super::linear_map`]), the branch's
    /// K/m, 1/(K/m) (0 where K = 0), c/m, and the load Q/m.
    pub fn new(
        end: &[[f64; 2]; INPUTS],
        [stiffness, inverse_stiffness, damping]: [f64; 3],
        load: f64,
    ) -> Self {
        let (equilibrium, free_load) = if stiffness > 0.0 {
            (load * inverse_stiffness, 0.0)
        } else {
            (0.0, load)
        };
        Lane {
            per_x: end[0],
            per_v: end[1],
            per_g: end[2],
            per_s: end[3],
            offset: [
                equilibrium - equilibrium * end[0][0] + free_load * end[4][0],
                -equilibrium * end[0][1] + free_load * end[4][1],
            ],
            equilibrium,
            load,
            damping,
            stiffness,
            free_load: free_load.abs(),
        }
    }

    /// The inputs of the work integrals ([`super::sample::work`]).
    #[inline(always)]
    pub fn inputs(&self, x: f64, v: f64, [g, s]: [f64; 2]) -> [f64; INPUTS] {
        if self.stiffness > 0.0 {
            [x - self.equilibrium, v, g, s, 0.0]
        } else {
            [x, v, g, s, self.load]
        }
    }
}

/// The event bands of one structure on its branch: x inside the yield
/// surface on an elastic branch, ẋ on the loading side while yielded
/// (infinite where the branch watches no such event).
#[derive(Debug, Clone, Copy)]
pub struct Watch {
    pub x: [f64; 2],
    pub v: [f64; 2],
}

impl Watch {
    /// From the branch and Π_uy.
    #[inline]
    pub fn new(branch: Branch, uy: f64) -> Self {
        let x = match branch {
            Branch::Elastic { offset } if uy.is_finite() => [offset - uy, offset + uy],
            _ => [f64::NEG_INFINITY, f64::INFINITY],
        };
        let v = match branch {
            Branch::Yielded { sign } if sign > 0.0 => [0.0, f64::INFINITY],
            Branch::Yielded { .. } => [f64::NEG_INFINITY, 0.0],
            Branch::Elastic { .. } => [f64::NEG_INFINITY, f64::INFINITY],
        };
        Watch { x, v }
    }
}

/// Whether q lies strictly inside (lo, hi) with room for its round-off
/// (either bound may be infinite).
#[inline(always)]
pub fn inside(lo: f64, q: f64, hi: f64) -> bool {
    let room = 4.0 * f64::EPSILON * q.abs();
    (hi - q > room) & (q - lo > room)
}

/// The larger of a and b as one instruction; b where either is NaN (the
/// tight loop passes its new values second, so that NaN reaches the tests,
/// which it fails).
#[inline(always)]
fn max(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// The smaller, likewise.
#[inline(always)]
fn min(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// [f(0), f(1)]: one line for both structures.
#[inline(always)]
pub(super) fn each(f: impl Fn(usize) -> f64) -> [f64; 2] {
    [f(0), f(1)]
}

/// f(0) and f(1), without a branch.
#[inline(always)]
fn all(f: impl Fn(usize) -> bool) -> bool {
    f(0) & f(1)
}

/// [f(0), f(1)] of tests.
#[inline(always)]
fn each_test(f: impl Fn(usize) -> bool) -> [bool; 2] {
    [f(0), f(1)]
}

/// Both structures' lanes, structure by structure in each array so that
/// each line of [`Pair::step`] is one operation on both, with their event
/// bands, the interval h and the ceiling of x1 − x2.
#[derive(Debug, Clone, Copy)]
pub struct Pair {
    per_x: [[f64; 2]; 2],
    per_v: [[f64; 2]; 2],
    per_g: [[f64; 2]; 2],
    per_s: [[f64; 2]; 2],
    offset: [[f64; 2]; 2],
    equilibrium: [f64; 2],
    pub(super) load: [f64; 2],
    pub(super) damping: [f64; 2],
    pub(super) stiffness: [f64; 2],
    root_stiffness: [f64; 2],
    /// c/m + ω.
    rate_sum: [f64; 2],
    free_load: [f64; 2],
    /// 8 ε |x*|: the round-off of x* cancelled in x − x*.
    equilibrium_room: [f64; 2],
    pub(super) watch_x: [[f64; 2]; 2],
    pub(super) watch_v: [[f64; 2]; 2],
    pub(super) length: f64,
    /// h²/8 with a round-off allowance.
    chord: f64,
    pub(super) gap: f64,
}

/// The running peaks the tight loop carries: per structure |x|, |ẋ| and
/// |ẍ + g| (∞ where not located), and the running maximum of x1 − x2 (∞
/// where it no longer moves).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peaks {
    pub x: [f64; 2],
    pub v: [f64; 2],
    pub a: [f64; 2],
    pub relative: f64,
}

/// The chord margins of [`Pair::margins`], per structure.
#[derive(Debug, Clone, Copy)]
pub(super) struct Margins {
    pub x: [f64; 2],
    pub v: [f64; 2],
    pub a: [f64; 2],
    pub jerk: [f64; 2],
}

/// What one quiet sample gave: whether the bounds cleared it (and which of
/// its parts: each structure, and x1 − x2), both end states, and the peaks
/// at its end (meaningful only for the parts that cleared).
#[derive(Debug, Clone, Copy)]
pub struct Step {
    pub clear: bool,
    pub cleared: [bool; 3],
    pub x: [f64; 2],
    pub v: [f64; 2],
    pub peaks: Peaks,
}

impl Pair {
    /// From both lanes and event bands, the interval h and the gap.
    pub fn new(lanes: [Lane; 2], watch: [Watch; 2], length: f64, gap: f64) -> Self {
        let both = |f: &dyn Fn(&Lane) -> f64| [f(&lanes[0]), f(&lanes[1])];
        let by_component =
            |f: &dyn Fn(&Lane) -> [f64; 2]| [0, 1].map(|j| [f(&lanes[0])[j], f(&lanes[1])[j]]);
        let root_stiffness = both(&|l| l.stiffness.sqrt());
        Pair {
            per_x: by_component(&|l| l.per_x),
            per_v: by_component(&|l| l.per_v),
            per_g: by_component(&|l| l.per_g),
            per_s: by_component(&|l| l.per_s),
            offset: by_component(&|l| l.offset),
            equilibrium: both(&|l| l.equilibrium),
            load: both(&|l| l.load),
            damping: both(&|l| l.damping),
            stiffness: both(&|l| l.stiffness),
            root_stiffness,
            rate_sum: [0, 1].map(|i| lanes[i].damping + root_stiffness[i]),
            free_load: both(&|l| l.free_load),
            equilibrium_room: both(&|l| 8.0 * f64::EPSILON * l.equilibrium.abs()),
            watch_x: [0, 1].map(|j| [watch[0].x[j], watch[1].x[j]]),
            watch_v: [0, 1].map(|j| [watch[0].v[j], watch[1].v[j]]),
            length,
            // A bound of non-negative terms, each rounded by far less than
            // this allowance, stays a bound.
            chord: length * length / 8.0 * (1.0 + 1e-12),
            gap,
        }
    }

    /// Both structures' (x, ẋ) one interval on under g = g_k + s t: the map
    /// alone, its chain from one sample to the next two multiply-adds.
    #[inline(always)]
    pub fn advance(&self, x: [f64; 2], v: [f64; 2], [g, s]: [f64; 2]) -> [[f64; 2]; 2] {
        let component = |j: usize| {
            each(|i| {
                let record = madd(
                    s,
                    self.per_s[j][i],
                    madd(g, self.per_g[j][i], self.offset[j][i]),
                );
                madd(x[i], self.per_x[j][i], madd(v[i], self.per_v[j][i], record))
            })
        };
        [component(0), component(1)]
    }

    /// The chord margins of both structures (see the module's head) over
    /// intervals whose ends span `[x_lo, x_hi, v_lo, v_hi]`, under |g| ≤ G
    /// and |s| ≤ S: A h²/8 (x), J h²/8 (ẋ), J₄ h²/8 (ẍ and ẍ + g) and
    /// ((c/m) J₄ + (K/m) J) h²/8 (the rate of ẍ + g), with room for the
    /// round-off of the end states in the first two.
    #[inline(always)]
    pub(super) fn margins(
        &self,
        [x_lo, x_hi, v_lo, v_hi]: [[f64; 2]; 4],
        big_g: f64,
        big_s: f64,
    ) -> Margins {
        let (c, k, h) = (self.damping, self.stiffness, self.length);
        let free = each(|i| big_g + self.free_load[i]);
        let big_d = each(|i| max(x_hi[i] - self.equilibrium[i], self.equilibrium[i] - x_lo[i]));
        let speed = each(|i| max(-v_lo[i], v_hi[i]));
        let big_v = each(|i| madd(free[i], h, madd(self.root_stiffness[i], big_d[i], speed[i])));
        let big_a = each(|i| madd(self.rate_sum[i], big_v[i], free[i]));
        let big_j = each(|i| madd(c[i], big_a[i], madd(k[i], big_v[i], big_s)));
        let big_j4 = each(|i| madd(c[i], big_j[i], k[i] * big_a[i]));
        let room = 8.0 * f64::EPSILON;
        Margins {
            x: each(|i| {
                let size = max(-x_lo[i], x_hi[i]);
                madd(
                    big_a[i],
                    self.chord,
                    madd(room, size, self.equilibrium_room[i]),
                )
            }),
            v: each(|i| madd(big_j[i], self.chord, room * speed[i])),
            a: each(|i| big_j4[i] * self.chord),
            jerk: each(|i| madd(c[i], big_j4[i], k[i] * big_j[i]) * self.chord),
        }
    }

    /// One interval of both structures from (x, ẋ) under g = g_k + s t,
    /// each watched quantity held to its band or found monotone (see the
    /// module's head), against the running `peaks`; |ẍ + g| is watched
    /// where `ACCEL`. Computed whole, without branches.
    #[inline(always)]
    pub fn step<const ACCEL: bool>(
        &self,
        x: [f64; 2],
        v: [f64; 2],
        [g, s]: [f64; 2],
        peaks: &Peaks,
    ) -> Step {
        let (c, k) = (self.damping, self.stiffness);
        let [xe, ve] = self.advance(x, v, [g, s]);
        let g_end = madd(s, self.length, g);
        let (x_lo, x_hi) = (each(|i| min(x[i], xe[i])), each(|i| max(x[i], xe[i])));
        let (v_lo, v_hi) = (each(|i| min(v[i], ve[i])), each(|i| max(v[i], ve[i])));
        let Margins {
            x: margin_x,
            v: margin_v,
            a: margin_a,
            jerk: margin_jerk,
        } = self.margins([x_lo, x_hi, v_lo, v_hi], max(g.abs(), g_end.abs()), s.abs());
        // ẍ + g = Q/m − (c/m) ẋ − (K/m) x at both ends, and ẍ.
        let accel = each(|i| self.load[i] - c[i] * v[i] - k[i] * x[i]);
        let accel_end = each(|i| self.load[i] - c[i] * ve[i] - k[i] * xe[i]);
        let rate = each(|i| accel[i] - g);
        let rate_end = each(|i| accel_end[i] - g_end);
        let (w_lo, w_hi) = (self.watch_x[0], self.watch_x[1]);
        // x: in its band, or monotone (ẋ keeps its sign) ending inside the event band.
        let x_clear = each_test(|i| {
            ((x_lo[i] - margin_x[i] > max(w_lo[i], -peaks.x[i]))
                & (x_hi[i] + margin_x[i] < min(w_hi[i], peaks.x[i])))
                | (((v_lo[i] > margin_v[i]) | (v_hi[i] < -margin_v[i]))
                    & inside(w_lo[i], xe[i], w_hi[i]))
        });
        let (u_lo, u_hi) = (self.watch_v[0], self.watch_v[1]);
        // ẋ: in its band, or monotone (ẍ keeps its sign) with both ends inside the event band.
        let v_clear = each_test(|i| {
            ((v_lo[i] - margin_v[i] > max(u_lo[i], -peaks.v[i]))
                & (v_hi[i] + margin_v[i] < min(u_hi[i], peaks.v[i])))
                | (((min(rate[i], rate_end[i]) > margin_a[i])
                    | (max(rate[i], rate_end[i]) < -margin_a[i]))
                    & inside(u_lo[i], v[i], u_hi[i])
                    & inside(u_lo[i], ve[i], u_hi[i]))
        });
        // x1 − x2 off its chord by the sum of the two margins: below the gap
        // and its running maximum, or monotone and below the gap.
        let (relative, relative_end) = (x[0] - x[1], xe[0] - xe[1]);
        let (rel_rate, rel_rate_end) = (v[0] - v[1], ve[0] - ve[1]);
        let margin_rate = margin_v[0] + margin_v[1];
        let relative_clear = (max(relative, relative_end) + margin_x[0] + margin_x[1]
            < min(self.gap, peaks.relative))
            | (((min(rel_rate, rel_rate_end) > margin_rate)
                | (max(rel_rate, rel_rate_end) < -margin_rate))
                & (self.gap - max(relative, relative_end)
                    > 4.0 * f64::EPSILON * max(relative.abs(), relative_end.abs())));
        let mut structure_clear = each_test(|i| x_clear[i] & v_clear[i]);
        let mut peak_a = peaks.a;
        if ACCEL {
            // ẍ + g: below its peak, or monotone (its rate −(c/m) ẍ − (K/m) ẋ keeping its sign).
            let a_clear = each_test(|i| {
                let (jerk, jerk_end) = (
                    -c[i] * rate[i] - k[i] * v[i],
                    -c[i] * rate_end[i] - k[i] * ve[i],
                );
                (max(accel[i].abs(), accel_end[i].abs()) + margin_a[i] < peaks.a[i])
                    | (min(jerk, jerk_end) > margin_jerk[i])
                    | (max(jerk, jerk_end) < -margin_jerk[i])
            });
            structure_clear = each_test(|i| structure_clear[i] & a_clear[i]);
            peak_a = each(|i| max(peaks.a[i], accel_end[i].abs()));
        }
        Step {
            clear: structure_clear[0] & structure_clear[1] & relative_clear,
            cleared: [structure_clear[0], structure_clear[1], relative_clear],
            x: xe,
            v: ve,
            peaks: Peaks {
                x: each(|i| max(peaks.x[i], xe[i].abs())),
                v: each(|i| max(peaks.v[i], ve[i].abs())),
                a: peak_a,
                relative: max(peaks.relative, relative_end),
            },
        }
    }
}

impl Pair {
    /// `B` samples of both structures from (x, ẋ) by the map alone, each
    /// sample's end state written to `ends`, and whether the whole block is
    /// quiet by one test at its end: over the block, x, ẋ, x1 − x2 (and
    /// |ẍ + g| where `ACCEL`) stay, within the chord margins of the module's
    /// head taken with the block's largest |ẋ|, |x − x*|, |g| and |s|,
    /// inside their bands and below their running peaks. Nothing rises in a
    /// quiet block, so the peaks stand. The end states are those of
    /// [`Pair::step`], bit for bit.
    #[inline(always)]
    pub fn block<const ACCEL: bool, const B: usize>(
        &self,
        mut x: [f64; 2],
        mut v: [f64; 2],
        grounds: &[[f64; 2]; B],
        peaks: &Peaks,
        ends: &mut [[[f64; 2]; 2]; B],
    ) -> bool {
        let (c, k) = (self.damping, self.stiffness);
        let h = self.length;
        let accel_of =
            |x: [f64; 2], v: [f64; 2]| each(|i| (self.load[i] - c[i] * v[i] - k[i] * x[i]).abs());
        let start = [x, v];
        let (mut big_g, mut big_s) = (0.0f64, 0.0f64);
        // The chain: the map alone, as the floor's recurrence.
        for (j, &ground) in grounds.iter().enumerate() {
            let [xe, ve] = self.advance(x, v, ground);
            ends[j] = [xe, ve];
            (x, v) = (xe, ve);
        }
        // The extremes, off the chain: the new values second, so that a NaN
        // reaches them and the tests fail.
        let (mut x_lo, mut x_hi, mut v_lo, mut v_hi) = (start[0], start[0], start[1], start[1]);
        let mut relative_hi = start[0][0] - start[0][1];
        let mut accel_hi = if ACCEL {
            accel_of(start[0], start[1])
        } else {
            [0.0; 2]
        };
        for (&[xe, ve], &[g, s]) in ends.iter().zip(grounds) {
            big_g = max(big_g, max(g.abs(), madd(s, h, g).abs()));
            big_s = max(big_s, s.abs());
            x_lo = each(|i| min(x_lo[i], xe[i]));
            x_hi = each(|i| max(x_hi[i], xe[i]));
            v_lo = each(|i| min(v_lo[i], ve[i]));
            v_hi = each(|i| max(v_hi[i], ve[i]));
            relative_hi = max(relative_hi, xe[0] - xe[1]);
            if ACCEL {
                let a = accel_of(xe, ve);
                accel_hi = each(|i| max(accel_hi[i], a[i]));
            }
        }
        let Margins {
            x: margin_x,
            v: margin_v,
            a: margin_a,
            ..
        } = self.margins([x_lo, x_hi, v_lo, v_hi], big_g, big_s);
        let (w_lo, w_hi) = (self.watch_x[0], self.watch_x[1]);
        let (u_lo, u_hi) = (self.watch_v[0], self.watch_v[1]);
        let mut clear = all(|i| {
            (x_lo[i] - margin_x[i] > max(w_lo[i], -peaks.x[i]))
                & (x_hi[i] + margin_x[i] < min(w_hi[i], peaks.x[i]))
                & (v_lo[i] - margin_v[i] > max(u_lo[i], -peaks.v[i]))
                & (v_hi[i] + margin_v[i] < min(u_hi[i], peaks.v[i]))
        }) & (relative_hi + margin_x[0] + margin_x[1]
            < min(self.gap, peaks.relative));
        if ACCEL {
            clear &= all(|i| accel_hi[i] + margin_a[i] < peaks.a[i]);
        }
        clear
    }
}

#[cfg(test)]
mod tests {
    use super::super::dynamics::{Structure, oscillator};
    use super::super::sample::SampleMap;
    use super::super::sample_peaks::{IntervalSeries, raise_relative};
    use super::super::series::Series;
    use super::*;
    use crate::model::SET1;
    use rand_chacha::ChaCha8Rng;
    use rand_chacha::rand_core::SeedableRng;
    use rand_distr::{Distribution, Uniform};

    /// A uniform draw from [lo, hi).
    fn draw(rng: &mut ChaCha8Rng, range: std::ops::Range<f64>) -> f64 {
        Uniform::new(range.start, range.end)
            .expect("a range")
            .sample(rng)
    }

    /// x, ẋ and ẍ + g of one structure over [0, h] at 2001 points, from the
    /// interval's own series (degree 24, summed to round-off at these h).
    fn dense(
        s: &Structure,
        k: f64,
        load: f64,
        [x, v]: [f64; 2],
        [g, slope]: [f64; 2],
        h: f64,
    ) -> Vec<[f64; 3]> {
        let mut ground = Series {
            degree: 1,
            ..Series::default()
        };
        (ground.c[0], ground.c[1]) = (g, slope);
        let (c, k) = (s.damping / s.mass, k / s.mass);
        let q = oscillator(c, k, load, x, v, &ground, 24);
        let dq = q.derivative();
        (0..=2000)
            .map(|n| {
                let t = h * n as f64 / 2000.0;
                let (x, v) = (q.value(t), dq.value(t));
                [x, v, load - c * v - k * x]
            })
            .collect()
    }

    /// Whatever the step and the block clear is quiet: on random states,
    /// grounds, loads and branches of set 1's structures, every point of the
    /// dense series stays inside the event bands and the running peaks of a
    /// cleared block, and below the peaks a cleared step returns (which are
    /// the true maxima to round-off where they rose). The block's ends are
    /// the steps' ends bit for bit.
    #[test]
    #[allow(clippy::needless_range_loop)]
    fn what_the_bounds_clear_is_quiet() {
        let structures = Structure::pair(&SET1);
        let h = 0.06;
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let (mut steps_cleared, mut blocks_cleared, mut raised) = (0, 0, 0);
        let (mut settled, mut located, mut located_relative) = (0, 0, 0);
        for trial in 0..400 {
            // Elastic (an offset, a yield surface) or yielded (K = α k, σ).
            let yielded = trial % 3 == 2;
            let sign = if draw(&mut rng, 0.0..1.0) < 0.5 {
                1.0
            } else {
                -1.0
            };
            let lanes_and_watch = structures.map(|s| {
                let k = if yielded {
                    s.alpha * s.stiffness
                } else {
                    s.stiffness
                };
                let load = if yielded {
                    sign * 0.3 * s.stiffness
                } else {
                    0.0
                };
                let map = SampleMap::new(&s, k, h, 20, false).expect("Ω h ≤ 1");
                let branch = if yielded {
                    Branch::Yielded { sign }
                } else {
                    Branch::Elastic {
                        offset: draw(&mut rng, -0.1..0.1),
                    }
                };
                (k, load, map.lane(load / s.mass), Watch::new(branch, 2.0))
            });
            let gap = draw(&mut rng, 0.5..3.0);
            let pair = Pair::new(
                lanes_and_watch.map(|(_, _, l, _)| l),
                lanes_and_watch.map(|(_, _, _, w)| w),
                h,
                gap,
            );
            let amplitude = draw(&mut rng, 0.05..1.0);
            let mut state = [[0.0; 2]; 2];
            for i in 0..2 {
                state[0][i] = draw(&mut rng, -amplitude..amplitude);
                state[1][i] = sign.abs() * draw(&mut rng, -amplitude..amplitude);
                if yielded {
                    state[1][i] = sign * draw(&mut rng, 0.01..amplitude);
                }
            }
            let grounds: [[f64; 2]; 8] =
                std::array::from_fn(|_| [draw(&mut rng, -1.0..1.0), draw(&mut rng, -8.0..8.0)]);
            // Running peaks hold the present state (as in a run), and lie
            // above it by a random factor.
            let [x0, v0] = state;
            let accel = [0, 1].map(|i| {
                let (k, load, _, _) = lanes_and_watch[i];
                let s = &structures[i];
                (load - s.damping * v0[i] - k * x0[i]) / s.mass
            });
            let peaks = Peaks {
                x: [0, 1].map(|i| {
                    x0[i].abs() * draw(&mut rng, 1.0..1.5) + amplitude * draw(&mut rng, 0.0..0.5)
                }),
                v: [0, 1].map(|i| {
                    v0[i].abs() * draw(&mut rng, 1.0..1.5) + amplitude * draw(&mut rng, 0.0..0.5)
                }),
                a: [0, 1].map(|i| {
                    accel[i].abs() * draw(&mut rng, 1.0..1.5) + amplitude * draw(&mut rng, 0.0..0.5)
                }),
                relative: if trial % 2 == 0 {
                    f64::INFINITY
                } else {
                    (x0[0] - x0[1]) + amplitude * draw(&mut rng, 0.0..1.0)
                },
            };
            let mut ends = [[[0.0; 2]; 2]; 8];
            let block = pair.block::<true, 8>(state[0], state[1], &grounds, &peaks, &mut ends);
            let (mut x, mut v) = (state[0], state[1]);
            let mut running = peaks;
            let mut all_steps = true;
            for (j, ground) in grounds.iter().enumerate() {
                let step = pair.step::<true>(x, v, *ground, &running);
                assert_eq!([step.x, step.v], ends[j], "block and steps apart at {j}");
                let truth: [Vec<[f64; 3]>; 2] = [0, 1].map(|i| {
                    let (k, load, _, _) = lanes_and_watch[i];
                    let s = &structures[i];
                    dense(s, k, load / s.mass, [x[i], v[i]], *ground, h)
                });
                for i in 0..2 {
                    let (lo, hi) = (pair.watch_x[0][i], pair.watch_x[1][i]);
                    let (ulo, uhi) = (pair.watch_v[0][i], pair.watch_v[1][i]);
                    for &[xt, vt, at] in &truth[i] {
                        if block {
                            assert!(xt > lo && xt < hi && xt.abs() < peaks.x[i], "block: x {xt}");
                            assert!(
                                vt > ulo && vt < uhi && vt.abs() < peaks.v[i],
                                "block: v {vt}"
                            );
                            assert!(at.abs() < peaks.a[i], "block: a {at}");
                        }
                        if step.clear {
                            let tol = 1e-12 * amplitude;
                            assert!(xt > lo && xt < hi, "step: yield at x {xt}");
                            assert!(vt > ulo && vt < uhi, "step: unloads at v {vt}");
                            assert!(
                                xt.abs() <= step.peaks.x[i] + tol,
                                "step: peak x {xt} > {}",
                                step.peaks.x[i]
                            );
                            assert!(vt.abs() <= step.peaks.v[i] + tol, "step: peak v");
                            assert!(
                                at.abs() <= step.peaks.a[i] + tol,
                                "step: peak a {at} > {:?}",
                                step.peaks.a
                            );
                        }
                    }
                    if step.clear && step.peaks.x[i] > running.x[i] {
                        raised += 1;
                        let top = truth[i].iter().fold(0.0f64, |m, q| m.max(q[0].abs()));
                        assert!(
                            (step.peaks.x[i] - top).abs() <= 1e-12 * top,
                            "raised to the end value"
                        );
                    }
                }
                if block || step.clear {
                    for n in 0..=2000 {
                        let r = truth[0][n][0] - truth[1][n][0];
                        assert!(r < gap, "contact inside a cleared interval");
                        if block {
                            assert!(r < peaks.relative, "x1 − x2 above its running maximum");
                        }
                    }
                }
                all_steps &= step.clear;
                if !step.clear {
                    // Settled with its extrema located: inside the event
                    // bands, and each peak the dense maximum where it rose.
                    if let Some(st) = pair.settle::<true>(x, v, *ground, &running, 20) {
                        settled += 1;
                        assert_eq!([st.x, st.v], ends[j], "settle and step apart");
                        for i in 0..2 {
                            let (lo, hi) = (pair.watch_x[0][i], pair.watch_x[1][i]);
                            let (ulo, uhi) = (pair.watch_v[0][i], pair.watch_v[1][i]);
                            let mut top = [0.0f64; 3];
                            for q in &truth[i] {
                                assert!(q[0] > lo && q[0] < hi, "settle: yield at x {}", q[0]);
                                assert!(q[1] > ulo && q[1] < uhi, "settle: unloads at {}", q[1]);
                                top = [0, 1, 2].map(|n| top[n].max(q[n].abs()));
                            }
                            let before = [running.x[i], running.v[i], running.a[i]];
                            let after = [st.peaks.x[i], st.peaks.v[i], st.peaks.a[i]];
                            // The segments' peak search on the interval's series.
                            let (k, load, _, _) = lanes_and_watch[i];
                            let (c, k, load) = (
                                structures[i].damping / structures[i].mass,
                                k / structures[i].mass,
                                load / structures[i].mass,
                            );
                            let series = IntervalSeries::new(k, c, load, [x[i], v[i]], *ground, 20);
                            let mut reference = before;
                            series.raise_displacement(h, series.x.swing(h), &mut reference[0]);
                            series.raise_velocity(h, series.v.swing(h), &mut reference[1]);
                            series.raise_absolute_acceleration(
                                [k, c, load],
                                h,
                                c * series.v.swing(h) + k * series.x.swing(h),
                                &mut reference[2],
                            );
                            for n in 0..3 {
                                let tol = 1e-12 * top[n].max(1e-300);
                                assert!(
                                    top[n] <= after[n] + tol,
                                    "settle: peak {n} {after:?} below {top:?}"
                                );
                                assert!(
                                    (after[n] - reference[n]).abs() <= 1e-13 * reference[n],
                                    "settle: peak {n} {} against the series' {}",
                                    after[n],
                                    reference[n]
                                );
                                located += usize::from(after[n] > before[n]);
                            }
                        }
                        let relative = (0..=2000).map(|n| truth[0][n][0] - truth[1][n][0]);
                        let top = relative.fold(f64::NEG_INFINITY, f64::max);
                        assert!(top < gap, "settle: contact inside");
                        if running.relative.is_finite() {
                            assert!(top <= st.peaks.relative + 1e-12 * top.abs());
                            let pair_series = [0, 1].map(|i| {
                                let (k, load, _, _) = lanes_and_watch[i];
                                let m = structures[i].mass;
                                let c = structures[i].damping / m;
                                IntervalSeries::new(k / m, c, load / m, [x[i], v[i]], *ground, 20)
                            });
                            let mut reference = running.relative;
                            let swing = pair_series[0].x.swing(h) + pair_series[1].x.swing(h);
                            raise_relative(
                                [&pair_series[0], &pair_series[1]],
                                h,
                                swing,
                                &mut reference,
                            );
                            assert!(
                                (st.peaks.relative - reference).abs() <= 1e-13 * reference.abs(),
                                "settle: x1 − x2 {} against the series' {reference}",
                                st.peaks.relative
                            );
                            located_relative += usize::from(st.peaks.relative > running.relative);
                        }
                    }
                    break;
                }
                steps_cleared += 1;
                (x, v, running) = (step.x, step.v, step.peaks);
            }
            blocks_cleared += usize::from(block);
            if block {
                assert!(all_steps, "a block the steps do not clear");
            }
        }
        // The test must exercise each path.
        assert!(
            blocks_cleared > 20 && steps_cleared > 300 && raised > 20,
            "{blocks_cleared} {steps_cleared} {raised}"
        );
        assert!(
            settled > 20 && located > 20 && located_relative > 5,
            "{settled} settled, {located} located, {located_relative} of x1 − x2"
        );
    }
}
