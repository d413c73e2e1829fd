//! Quiet samples of a recorded accelerogram by a linear map (SPEC §9).
//!
//! Between two samples a record's g is linear, g(τ_k + t) = g_k + s t. Out of
//! contact, on a fixed branch, each structure obeys
//! ẍ = Q/m − (c/m) ẋ − (K/m) x − g (SPEC §2–3), so its state y = (x, ẋ) one
//! sample interval h later is linear in its inputs (the Nigam–Jennings
//! recurrence):
//!
//! ```text
//! y(τ_k + h) = (x*, 0) + Σ_j input_j · e_j,
//! inputs = (x − x*, ẋ, g_k, s, Q/m),   x* = Q/K the branch's equilibrium,
//! ```
//!
//! where e_j is unit response j at h (the load input is used only where
//! K = 0 and there is no equilibrium). The five unit responses are computed
//! once per structure and branch kind as series summed to round-off, which
//! asks Ω h ≤ 1 (Ω the structure's fastest rate); a record sampled more
//! coarsely than that is left to the segments' series.
//!
//! The same superposition bounds how far x and ẋ move inside the interval,
//! |x(τ_k + t) − x(τ_k)| ≤ Σ_j |input_j| swing_j with swing_j = Σ_{n≥1}
//! |u_{j,n}| h^n, and, where that swing alone cannot clear a band, the cubic
//! majorants of [`SampleMajorants`] (Taylor's theorem with a bound of the
//! third derivative) clear it near an extremum. A sample whose bounds keep
//! every event function negative and every peak below its running value is
//! quiet, and is advanced by the map alone.

use super::acceleration;
use super::dynamics::{Branch, Structure, oscillator};
use super::quiet::Bands;
use super::sample_peaks::IntervalSeries;
use super::sample_run::{Lane, inside};
use super::series::{MAX_DEGREE, Series};

use super::linear_map;
/// The inputs x − x*, ẋ, g_k, s, Q/m ([`linear_map`]).
pub use super::linear_map::INPUTS;

/// The unit responses of one structure on one branch kind over one sample interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampleMap {
    /// The interval h = DT·ω_p.
    pub length: f64,
    /// (x, ẋ) at h for each unit input.
    end: [[f64; 2]; INPUTS],
    /// (swing of x, swing of ẋ) over [0, h] for each unit input.
    swing: [[f64; 2]; INPUTS],
    /// ∫₀ʰ t ẋ dt of each unit response, and the Gram matrix
    /// ∫₀ʰ ẋ_j ẋ_l dt of their rates: the work integrals of [`work`].
    moment: [f64; INPUTS],
    gram: [[f64; INPUTS]; INPUTS],
    /// Degree of the interval's series where a peak inside it is located
    /// ([`super::sample_peaks`]): that of a free segment of length h, set
    /// by the run (the unit responses' own degree until then).
    pub series_degree: usize,
    /// K/m and c/m of the branch, and 1/(K/m) (0 where K = 0).
    pub stiffness: f64,
    pub damping: f64,
    inverse_stiffness: f64,
}

impl SampleMap {
    /// For stiffness `k` (k or Π_α k) on structure `s` over the interval `h`,
    /// with series of degree `n`; `None` where Ω h > 1, where the series
    /// would not sum to round-off.
    /// The work integrals' moments and Gram matrix are made only `with_work`
    /// (a run that integrates the energy); else they are zero.
    pub fn new(s: &Structure, k: f64, h: f64, n: usize, with_work: bool) -> Option<Self> {
        if !(h > 0.0 && h * s.rate <= 1.0) {
            return None;
        }
        let inv_m = 1.0 / s.mass;
        let (c, k) = (s.damping * inv_m, k * inv_m);
        let zero = Series {
            degree: n,
            ..Series::default()
        };
        let (mut constant, mut ramp) = (zero, zero);
        constant.c[0] = 1.0;
        ramp.c[1] = 1.0;
        let units = [
            oscillator(c, k, 0.0, 1.0, 0.0, &zero, n),
            oscillator(c, k, 0.0, 0.0, 1.0, &zero, n),
            oscillator(c, k, 0.0, 0.0, 0.0, &constant, n),
            oscillator(c, k, 0.0, 0.0, 0.0, &ramp, n),
            oscillator(c, k, 1.0, 0.0, 0.0, &zero, n),
        ];
        let mut rates = [Series::default(); INPUTS];
        let (end, swing) = linear_map::ends_and_swings(&units, h, &mut rates);
        let mut moment = [0.0; INPUTS];
        let mut gram = [[0.0; INPUTS]; INPUTS];
        if with_work {
            // h^e/e for e = 1 … 2n + 2.
            let mut power = [0.0; 2 * MAX_DEGREE + 3];
            let mut p = 1.0;
            for (e, w) in power.iter_mut().enumerate().skip(1) {
                p *= h;
                *w = p / e as f64;
            }
            // Each rate's terms d_a t^a past the last one above 1e-4 ε of its
            // largest on [0, h] are left out of the Gram matrix: each product
            // they would add is below 1e-4 ε of the largest, far below the
            // round-off of the sum itself (made once per run: a run's setup
            // under a short record, four maps to degree 20, was a sixth of it).
            let kept = rates.map(|du| {
                let mut p = 1.0;
                let sizes: [f64; MAX_DEGREE + 1] = std::array::from_fn(|a| {
                    let size = if a <= du.degree {
                        du.c[a].abs() * p
                    } else {
                        0.0
                    };
                    p *= h;
                    size
                });
                let largest = sizes.iter().fold(0.0f64, |m, s| m.max(*s));
                (0..=du.degree)
                    .rev()
                    .find(|&a| sizes[a] > 1e-4 * f64::EPSILON * largest)
                    .unwrap_or(0)
            });
            for j in 0..INPUTS {
                let du = &rates[j];
                // ∫₀ʰ t Σ d_a t^a dt = Σ d_a h^{a+2}/(a+2), smallest terms first.
                moment[j] = (0..=du.degree).rev().map(|a| du.c[a] * power[a + 2]).sum();
                for l in 0..=j {
                    let (p, q) = (&rates[j], &rates[l]);
                    // ∫₀ʰ Σ p_a t^a Σ q_b t^b dt = Σ p_a q_b h^{a+b+1}/(a+b+1).
                    let mut sum = 0.0;
                    for a in (0..=kept[j]).rev() {
                        for b in (0..=kept[l]).rev() {
                            sum += p.c[a] * q.c[b] * power[a + b + 1];
                        }
                    }
                    gram[j][l] = sum;
                    gram[l][j] = sum;
                }
            }
        }
        Some(SampleMap {
            length: h,
            end,
            swing,
            moment,
            gram,
            series_degree: n,
            stiffness: k,
            damping: c,
            inverse_stiffness: if k > 0.0 { 1.0 / k } else { 0.0 },
        })
    }

    /// The inputs of an interval for a structure at (x, ẋ) with load Q/m on
    /// this branch under g = g_k + s t, and the equilibrium x* they were
    /// taken from (0 where K = 0, the load then an input of its own).
    #[inline(always)]
    pub fn inputs(&self, x: f64, v: f64, ground: [f64; 2], load: f64) -> ([f64; INPUTS], f64) {
        linear_map::inputs(self.stiffness, self.inverse_stiffness, x, v, ground, load)
    }

    /// (x, ẋ) at the interval's end.
    #[inline(always)]
    pub fn advance(&self, inputs: &[f64; INPUTS], equilibrium: f64) -> [f64; 2] {
        linear_map::advance(&self.end, inputs, equilibrium)
    }

    /// The moments ∫₀ʰ t u_j' dt and the Gram matrix ∫₀ʰ u_j' u_l' dt of the
    /// unit responses (zero unless made with the work integrals).
    pub fn work_integrals(&self) -> ([f64; INPUTS], [[f64; INPUTS]; INPUTS]) {
        (self.moment, self.gram)
    }

    /// This map with load Q/m, laid out for the tight loop of quiet samples.
    pub fn lane(&self, load: f64) -> Lane {
        Lane::new(
            &self.end,
            [self.stiffness, self.inverse_stiffness, self.damping],
            load,
        )
    }

    /// Bounds of |x − x₀| and |ẋ − ẋ₀| over the interval: Σ_j |input_j| swing_j.
    #[inline(always)]
    pub fn swing(&self, inputs: &[f64; INPUTS]) -> [f64; 2] {
        linear_map::swing(&self.swing, inputs)
    }
}

/// Cubic majorants of x and ẋ of one structure over a sample interval:
/// q(t) ≤ q₀ + q₁ t + q₂ t² + M t³ on [0, h], and −q likewise with q₀, q₁,
/// q₂ negated (Taylor's theorem, M bounding |q'''|/6). With
/// ẍ = Q/m − (c/m) ẋ − (K/m) x − g and g = g_k + s t (g'' = 0 inside):
///
/// ```text
/// ẍ₀ = Q/m − (c/m) ẋ₀ − (K/m) x₀ − g_k,     x⁽³⁾₀ = −(c/m) ẍ₀ − (K/m) ẋ₀ − s,
/// |ẍ| ≤ A = (c/m) V + (K/m) X + G,   X ≥ |x − x*|, V ≥ |ẋ|, G = max(|g_k|, |g_k + s h|)
/// |x⁽³⁾| ≤ J = (c/m) A + (K/m) V + |s|,   |x⁽⁴⁾| ≤ (c/m) J + (K/m) A
/// ```
///
/// (where K = 0, |Q/m| joins A): [`linear_map::derivative_bounds`] with the
/// record's ground bounds (G, |s|, 0).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SampleMajorants {
    pub x: [f64; 4],
    pub v: [f64; 4],
}

impl SampleMajorants {
    /// From the map (its K/m and c/m), the state (x, ẋ), (g_k, s), the
    /// branch's Q/m and the swings of [`SampleMap::swing`].
    #[inline]
    pub fn new(
        map: &SampleMap,
        x: f64,
        v: f64,
        [g, slope]: [f64; 2],
        load: f64,
        swing: [f64; 2],
    ) -> Self {
        let h = map.length;
        // On the interval g = g_k + s t: |g| is largest at an end, g' = s, g'' = 0.
        let ground = [g.abs().max((g + slope * h).abs()), slope.abs(), 0.0];
        let [a0, j0, jerk, snap] = linear_map::derivative_bounds(
            map.stiffness,
            map.inverse_stiffness,
            map.damping,
            x,
            v,
            [g, slope],
            load,
            swing,
            ground,
        );
        let [x, v] = linear_map::cubic_majorants(x, v, a0, j0, jerk, snap);
        SampleMajorants { x, v }
    }
}

/// The work of one structure over a quiet interval (SPEC §6), per m2 a_p²/ω_p²:
/// (input −m ∫ g ẋ, damping c ∫ ẋ², spring ∫ f_s ẋ), in closed form from
/// the interval's inputs (x − x*, ẋ, g_k, s, Q/m) and its end displacement:
///
/// ```text
/// ∫ f_s ẋ = ∫ m((K/m) x − Q/m) ẋ = m (x₁ − x₀) ((K/m)(x₀ + x₁)/2 − Q/m)   (f_s affine on the branch)
/// ∫ g ẋ   = g_k (x₁ − x₀) + s ∫ t ẋ,    ∫ t ẋ = Σ_j input_j ∫ t u_j',
/// ∫ ẋ²    = Σ_{j,l} input_j input_l ∫ u_j' u_l'.
/// ```
///
/// Where K > 0 the load input is 0 and its terms, each exactly 0, are left
/// out (the same sums to the bit, in fewer products).
#[inline(always)]
pub fn work(
    map: &SampleMap,
    mass: f64,
    inputs: &[f64; INPUTS],
    load: f64,
    ends: [f64; 2],
) -> [f64; 3] {
    if inputs[INPUTS - 1] == 0.0 {
        work_of::<{ INPUTS - 1 }>(map, mass, inputs, load, ends)
    } else {
        work_of::<INPUTS>(map, mass, inputs, load, ends)
    }
}

/// [`work`] over the first `N` inputs.
#[inline(always)]
fn work_of<const N: usize>(
    map: &SampleMap,
    mass: f64,
    inputs: &[f64; INPUTS],
    load: f64,
    [x0, x1]: [f64; 2],
) -> [f64; 3] {
    let (g, slope) = (inputs[2], inputs[3]);
    let dx = x1 - x0;
    let mut moment = 0.0;
    let mut square = 0.0;
    // The Gram matrix is symmetric: Σ_j u_j (G_jj u_j + 2 Σ_{l<j} G_jl u_l).
    for j in 0..N {
        moment += inputs[j] * map.moment[j];
        let row = &map.gram[j];
        let mut r = 0.0;
        for l in 0..j {
            r += row[l] * inputs[l];
        }
        square += inputs[j] * (row[j] * inputs[j] + 2.0 * r);
    }
    [
        -mass * (g * dx + slope * moment),
        mass * map.damping * square,
        mass * dx * (map.stiffness * 0.5 * (x0 + x1) - load),
    ]
}

/// One structure's sample cleared by [`clear`]: its state at the interval's
/// end, the inputs and swings of the interval, the cubic majorant of x where
/// it was made, and the running peaks (Π_u, Π_v, A) raised to the interval's
/// where they rose at one of its ends.
#[derive(Debug, Clone, Copy)]
pub struct Cleared {
    pub end: [f64; 2],
    /// The interval's inputs, for [`work`].
    pub inputs: [f64; INPUTS],
    pub swing: [f64; 2],
    pub majorant_x: Option<[f64; 4]>,
    pub peaks: [f64; 3],
}

/// What one structure must not reach inside a quiet sample: its running
/// peaks Π_u, Π_v and A (∞ where A is not located), and its branch with
/// its yield displacement Π_uy.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    pub displacement: f64,
    pub velocity: f64,
    pub absolute_acceleration: f64,
    pub branch: Branch,
    pub yield_displacement: f64,
}

/// Whether q stays strictly below `hi` with room for the round-off of q.
#[inline]
pub fn below(q: f64, hi: f64) -> bool {
    hi - q > 4.0 * f64::EPSILON * q.abs()
}

/// Whether, inside the interval, structure state (x, ẋ) under g = g_k + s t
/// with load Q/m keeps clear of every event: on an elastic branch |x − p|
/// below Π_uy (no yield), yielded σ ẋ > 0 (no unloading); and whether each
/// of |x|, |ẋ| and |ẍ + g| = |Q/m − (c/m) ẋ − (K/m) x| either stays below its
/// running peak or peaks at an end of the interval. Each quantity is taken
/// by the first of three tests that clears it:
///
/// 1. its swing bound keeps it inside its band (the peak, and the yield
///    surface or the loading side);
/// 2. it is monotone on the interval, its rate keeping one sign by the
///    rate's own swing bound (ẋ for x; ẍ for ẋ, |ẍ − ẍ₀| ≤ (c/m) s_v +
///    (K/m) s_x + |s| h; (ẍ + g)' = −(c/m) ẍ − (K/m) ẋ for the acceleration):
///    its extremes are then its end values, the event bands are checked
///    there, and the peak is raised to the end value (a true maximum, not a
///    sample of one);
/// 3. its cubic majorant keeps it inside its band.
///
/// Where none clears |x| or |ẋ| but the event band alone holds (by the
/// swing, else the majorant, against the yield surface or the loading side
/// only), no event can happen and only the peak may rise inside: it is
/// located on the interval's series ([`IntervalSeries`]), as a segment
/// would locate it, and the sample stays on the map.
///
/// `None`: an event may happen (or |ẍ + g| may beat its peak), the interval
/// is left to the series, which locates it.
#[inline]
pub fn clear(
    map: &SampleMap,
    x: f64,
    v: f64,
    ground: [f64; 2],
    load: f64,
    limits: &Limits,
) -> Option<Cleared> {
    let h = map.length;
    let (inputs, equilibrium) = map.inputs(x, v, ground, load);
    let [sx, sv] = map.swing(&inputs);
    if !(sx + sv).is_finite() {
        return None;
    }
    let (px, pv, pa) = (
        limits.displacement,
        limits.velocity,
        limits.absolute_acceleration,
    );
    let (c, k) = (map.damping, map.stiffness);
    let bands = Bands::new(limits.branch, limits.yield_displacement, px, pv, pa);
    // ẍ + g = Q/m − (c/m) ẋ − (K/m) x out of contact: g does not enter.
    let accel = load - c * v - k * x;
    let within_a = accel.abs() + c * sv + k * sx < pa;
    let end = map.advance(&inputs, equilibrium);
    let mut peaks = [px, pv, pa];
    if within_a && bands.hold_by_swings(x, v, [sx, sv]) {
        return Some(Cleared {
            end,
            inputs,
            swing: [sx, sv],
            majorant_x: None,
            peaks,
        });
    }
    let uy = limits.yield_displacement;
    // The event bands alone (no peak): x inside the yield surface, ẋ on the loading side.
    let (x_lo, x_hi) = match limits.branch {
        Branch::Elastic { offset } if uy.is_finite() => (offset - uy, offset + uy),
        _ => (f64::NEG_INFINITY, f64::INFINITY),
    };
    let (v_lo, v_hi) = match limits.branch {
        Branch::Yielded { sign } if sign > 0.0 => (0.0, f64::INFINITY),
        Branch::Yielded { .. } => (f64::NEG_INFINITY, 0.0),
        Branch::Elastic { .. } => (f64::NEG_INFINITY, f64::INFINITY),
    };
    let mut majorants = None;
    let mut majorant = || {
        *majorants.get_or_insert_with(|| SampleMajorants::new(map, x, v, ground, load, [sx, sv]))
    };
    let between = |m: &[f64; 4], [lo, hi]: [f64; 2]| {
        super::quiet::stays_below(m, hi, h) && super::quiet::stays_above(m, lo, h)
    };
    let mut series: Option<IntervalSeries> = None;
    let interval_series = || IntervalSeries::new(k, c, load, [x, v], ground, map.series_degree);
    // x: monotone while ẋ keeps its sign.
    let x_clear = (x - sx > bands.x[0] && x + sx < bands.x[1])
        || (v.abs() > sv && inside(x_lo, end[0], x_hi) && {
            peaks[0] = px.max(end[0].abs());
            true
        })
        || between(&majorant().x, bands.x);
    if !x_clear {
        if !((x - sx > x_lo && x + sx < x_hi) || between(&majorant().x, [x_lo, x_hi])) {
            return None;
        }
        series
            .get_or_insert_with(interval_series)
            .raise_displacement(h, sx, &mut peaks[0]);
    }
    // ẋ: monotone while ẍ keeps its sign.
    let accel_change = c * sv + k * sx + ground[1].abs() * h;
    let a0 = accel - ground[0];
    let v_clear = (v - sv > bands.v[0] && v + sv < bands.v[1])
        || (a0.abs() > accel_change && inside(v_lo, v, v_hi) && inside(v_lo, end[1], v_hi) && {
            peaks[1] = pv.max(end[1].abs());
            true
        })
        || between(&majorant().v, bands.v);
    if !v_clear {
        if !((v - sv > v_lo && v + sv < v_hi) || between(&majorant().v, [v_lo, v_hi])) {
            return None;
        }
        series
            .get_or_insert_with(interval_series)
            .raise_velocity(h, sv, &mut peaks[1]);
    }
    // ẍ + g: monotone while −(c/m) ẍ − (K/m) ẋ keeps its sign.
    let a_clear = within_a
        || (-c * a0 - k * v).abs() > c * accel_change + k * sv && {
            peaks[2] = pa.max((load - c * end[1] - k * end[0]).abs());
            true
        }
        || {
            let m = majorant();
            between(&acceleration::majorant(&m.x, &m.v, k, c, load), [-pa, pa])
        };
    if !a_clear {
        // Located on the interval's series, as x and ẋ are.
        series
            .get_or_insert_with(interval_series)
            .raise_absolute_acceleration([k, c, load], h, c * sv + k * sx, &mut peaks[2]);
    }
    Some(Cleared {
        end,
        inputs,
        swing: [sx, sv],
        majorant_x: majorants.map(|m| m.x),
        peaks,
    })
}

#[cfg(test)]
mod tests {
    use super::super::sample_run::{Pair, Watch};
    use super::*;
    use crate::model::SET1;

    /// The map and the bounds against the series of the whole state under
    /// g = g_k + s t, on an elastic branch (about its equilibrium) and one with K = 0.
    #[test]
    fn the_map_matches_the_series_of_the_whole_state_and_the_bounds_hold() {
        let s = Structure::pair(&SET1)[1];
        let h = 0.1;
        let (x0, v0, g, slope, load) = (0.3, -1.2, 0.7, -4.0, 0.05);
        let mut ground = Series {
            degree: 20,
            ..Series::default()
        };
        ground.c[0] = g;
        ground.c[1] = slope;
        let inv_m = 1.0 / s.mass;
        for k in [s.stiffness, 0.0] {
            let map = SampleMap::new(&s, k, h, 20, true).expect("Ω h ≤ 1");
            let whole = oscillator(s.damping * inv_m, k * inv_m, load, x0, v0, &ground, 20);
            let (inputs, eq) = map.inputs(x0, v0, [g, slope], load);
            let [x, v] = map.advance(&inputs, eq);
            let (xs, vs) = whole.value_slope(h);
            assert!(
                (x - xs).abs() < 1e-15 && (v - vs).abs() < 1e-14,
                "{x} {xs} {v} {vs}"
            );
            let [sx, sv] = map.swing(&inputs);
            let m = SampleMajorants::new(&map, x0, v0, [g, slope], load, [sx, sv]);
            let cubic = |c: &[f64; 4], sign: f64, u: f64| {
                sign * (c[0] + u * (c[1] + u * c[2])) + c[3] * u * u * u
            };
            for i in 0..=40 {
                let u = h * i as f64 / 40.0;
                let (xi, vi) = whole.value_slope(u);
                assert!((xi - x0).abs() <= sx && (vi - v0).abs() <= sv);
                for sign in [1.0, -1.0] {
                    assert!(sign * xi <= cubic(&m.x, sign, u) + 1e-15, "x at {u}");
                    assert!(sign * vi <= cubic(&m.v, sign, u) + 1e-15, "v at {u}");
                }
            }
        }
    }

    /// The closed-form work against 8-point Gauss–Legendre on many pieces of the series.
    #[test]
    fn the_work_of_an_interval_matches_quadrature() {
        let s = Structure::pair(&SET1)[0];
        let h = 0.1;
        let (x0, v0, g, slope) = (0.3, -1.2, 0.7, -4.0);
        let mut ground = Series {
            degree: 20,
            ..Series::default()
        };
        ground.c[0] = g;
        ground.c[1] = slope;
        let inv_m = 1.0 / s.mass;
        for (k, load) in [(s.stiffness, 0.02), (0.0, 0.05)] {
            let map = SampleMap::new(&s, k, h, 20, true).expect("Ω h ≤ 1");
            let whole = oscillator(s.damping * inv_m, k * inv_m, load, x0, v0, &ground, 20);
            let (inputs, eq) = map.inputs(x0, v0, [g, slope], load);
            let [x1, _] = map.advance(&inputs, eq);
            let [input, damping, spring] = work(&map, s.mass, &inputs, load, [x0, x1]);
            // Simpson on 2000 pieces.
            let n = 2000;
            let (mut qi, mut qd, mut qs) = (0.0, 0.0, 0.0);
            for j in 0..=n {
                let t = h * j as f64 / n as f64;
                let w = if j == 0 || j == n {
                    1.0
                } else if j % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                let (x, v) = whole.value_slope(t);
                let gt = g + slope * t;
                qi += w * -s.mass * gt * v;
                qd += w * s.damping * v * v;
                qs += w * s.mass * (k * inv_m * x - load) * v;
            }
            let f = h / (3.0 * n as f64);
            for (a, b) in [(input, qi * f), (damping, qd * f), (spring, qs * f)] {
                assert!((a - b).abs() < 1e-13, "{a} vs {b}");
            }
        }
    }

    /// An interval in which x turns (ẋ changes sign) above its running peak:
    /// with the yield surface far, the sample is cleared and the peak is the
    /// interior maximum, equal to the bit to the one a free segment's series
    /// of the same degree locates; with the yield surface within reach, the
    /// sample is left to the series.
    #[test]
    fn a_peak_inside_a_sample_is_located_and_a_reachable_yield_is_not_cleared() {
        use crate::solver::exact::peaks::raise_abs_max;
        let s = Structure::pair(&SET1)[1];
        let h = 0.1;
        let mut map = SampleMap::new(&s, s.stiffness, h, 20, false).expect("Ω h ≤ 1");
        map.series_degree = 12;
        // Rising at the start, falling at the end: a maximum inside.
        let (x0, v0, ground, load) = (0.5, 0.4, [3.0, -2.0], 0.0);
        let (inputs, eq) = map.inputs(x0, v0, ground, load);
        let end = map.advance(&inputs, eq);
        assert!(end[1] < 0.0, "ẋ changes sign: {end:?}");
        let limits = |uy: f64| Limits {
            displacement: x0.max(end[0].abs()),
            velocity: 10.0,
            absolute_acceleration: f64::INFINITY,
            branch: Branch::Elastic { offset: 0.0 },
            yield_displacement: uy,
        };
        let cleared = clear(&map, x0, v0, ground, load, &limits(f64::INFINITY))
            .expect("no event can happen: the peak is located");
        let mut g = Series {
            degree: 1,
            ..Series::default()
        };
        (g.c[0], g.c[1]) = (ground[0], ground[1]);
        let inv_m = 1.0 / s.mass;
        let q = oscillator(s.damping * inv_m, s.stiffness * inv_m, load, x0, v0, &g, 12);
        let mut peak = limits(f64::INFINITY).displacement;
        raise_abs_max(&q, Some(&q.derivative()), h, q.swing(h), &mut peak);
        assert_eq!(cleared.peaks[0], peak);
        assert!(peak > x0 && peak > end[0], "{peak} inside");
        // The yield surface between the start and the maximum.
        assert!(clear(&map, x0, v0, ground, load, &limits(0.5 * (x0 + peak))).is_none());
    }

    /// The tight loop's lane against the map: the same end state to a few
    /// units in the last place, and the same inputs.
    #[test]
    fn a_lane_steps_as_the_map() {
        let s = Structure::pair(&SET1)[0];
        let h = 0.05;
        for (k, load) in [(s.stiffness, 0.3), (0.0, 0.2)] {
            let map = SampleMap::new(&s, k, h, 20, false).expect("Ω h ≤ 1");
            let lane = map.lane(load);
            let (x, v, ground) = (0.7, -0.4, [0.6, 2.5]);
            let (inputs, eq) = map.inputs(x, v, ground, load);
            let end = map.advance(&inputs, eq);
            let open = Watch::new(Branch::Elastic { offset: 0.0 }, f64::INFINITY);
            let pair = Pair::new([lane; 2], [open; 2], h, f64::INFINITY);
            let [xe, ve] = pair.advance([x; 2], [v; 2], ground);
            for (a, b) in [xe[0], ve[0]].iter().zip(end) {
                assert!((a - b).abs() <= 4.0 * f64::EPSILON * b.abs().max(1.0));
            }
            assert_eq!(lane.inputs(x, v, ground), inputs);
        }
    }

    #[test]
    fn a_coarse_interval_is_left_to_the_series() {
        let s = Structure::pair(&SET1)[1];
        assert!(SampleMap::new(&s, s.stiffness, 2.0 / s.rate, 20, false).is_none());
    }
}
