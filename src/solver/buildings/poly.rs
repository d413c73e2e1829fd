//! Polynomials on [0, s]: values, bounds, the first instant one turns
//! positive (an event) and the largest magnitude (a peak). A polynomial is
//! its coefficients, lowest order first: p(s) = Σ c_k s^k.

/// Sample points per interval when scanning for sign changes: the Taylor
/// steps hold less than one radian of the fastest mode, so a polynomial
/// on one has at most a few turning points.
const SCAN: usize = 16;

#[inline]
pub fn eval(c: &[f64], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * s + x)
}

/// The coefficient of s^k in the product of two series from their first
/// k + 1 coefficients each (`a`, `b`, of one length): Σ_j a_j b_{k−j},
/// j rising, on slices (no index checks in the chain of adds).
#[inline]
pub fn product_coefficient(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b.iter().rev()).map(|(x, y)| x * y).sum()
}

/// p(0) = c₀, which [`eval`] at 0 also gives (every higher term times 0
/// adds a zero), without its chain of multiply-adds.
#[inline]
fn at_zero(c: &[f64]) -> f64 {
    c.first().map_or(0.0, |&c0| c0 + 0.0)
}

/// s⁰, s¹, … into `powers`, for many polynomials at one s by [`dot`].
pub fn powers(s: f64, powers: &mut [f64]) {
    let mut x = 1.0;
    for p in powers {
        *p = x;
        x *= s;
    }
}

/// p(s) = Σ c_k s^k from the powers of s ([`powers`], at least as many as
/// c): four partial sums side by side, where Horner's rule is one chain
/// of multiply-adds, each waiting on the last.
#[inline]
pub fn dot(c: &[f64], powers: &[f64]) -> f64 {
    let mut sum = [0.0; 4];
    let (chunks, rest) = (c.chunks_exact(4), c.len() % 4);
    let tail = &c[c.len() - rest..];
    for (block, p) in chunks.zip(powers.chunks_exact(4)) {
        for k in 0..4 {
            sum[k] += block[k] * p[k];
        }
    }
    let base = c.len() - rest;
    let tail: f64 = tail.iter().zip(&powers[base..]).map(|(c, p)| c * p).sum();
    (sum[0] + sum[1]) + (sum[2] + sum[3]) + tail
}

/// p'(s).
#[inline]
pub fn eval_derivative(c: &[f64], s: f64) -> f64 {
    let mut acc = 0.0;
    for k in (1..c.len()).rev() {
        acc = acc * s + k as f64 * c[k];
    }
    acc
}

/// Σ |c_k| s^k ≥ max over [0, s] of |p|: four Horner chains in s⁴, one per
/// k mod 4, run side by side (a single chain waits on each multiply-add in
/// turn; the bound is taken dozens of times a step), then joined in s.
#[inline]
pub fn bound(c: &[f64], s: f64) -> f64 {
    let s2 = s * s;
    let s4 = s2 * s2;
    let mut acc = [0.0f64; 4];
    let mut chunks = c.rchunks_exact(4);
    for chunk in &mut chunks {
        for (a, &x) in acc.iter_mut().zip(chunk) {
            *a = *a * s4 + x.abs();
        }
    }
    // The lowest len mod 4 coefficients: c_0 … c_{r−1}; the chains above
    // hold c_r, c_{r+1}, … in order, so they take r more powers of s.
    let rest = chunks.remainder();
    let head = rest.iter().rev().fold(0.0, |a, &x| a * s + x.abs());
    let chains = acc[0] + s * (acc[1] + s * (acc[2] + s * acc[3]));
    head + chains * power_below_four(s, rest.len())
}

/// [`bound`] of many polynomials side by side, Σ_k |c_k| s^k of each lane
/// into `out`: `c` holds c_0 of every lane, then c_1, …, each as wide as
/// `out`; `chains` is a buffer. Each lane runs [`bound`]'s four chains in
/// s⁴ and its head in s, the same operations in the same order (the same
/// bound to the bit), the lanes together: four orders' coefficients lie
/// side by side as the four chains' lanes, one multiply-add across them
/// all. A step's reach asks it of every floor's u and u̇ at once.
pub fn bound_lanes(c: &[f64], s: f64, chains: &mut Vec<f64>, out: &mut [f64]) {
    let lanes = out.len();
    if lanes == 0 {
        return;
    }
    let s2 = s * s;
    let s4 = s2 * s2;
    chains.clear();
    chains.resize(4 * lanes, 0.0);
    // c_r … c_{len−1} in blocks of four from the top, as `rchunks_exact`
    // takes them: chain j holds each block's j-th, at j·lanes + lane.
    let mut blocks = c.rchunks_exact(4 * lanes);
    for block in &mut blocks {
        for (a, &x) in chains.iter_mut().zip(block) {
            *a = *a * s4 + x.abs();
        }
    }
    out.fill(0.0);
    let rest = blocks.remainder();
    for column in rest.rchunks_exact(lanes) {
        for (a, &x) in out.iter_mut().zip(column) {
            *a = *a * s + x.abs();
        }
    }
    let power = power_below_four(s, rest.len() / lanes);
    let (a0, a1, a2, a3) = (
        &chains[..lanes],
        &chains[lanes..2 * lanes],
        &chains[2 * lanes..3 * lanes],
        &chains[3 * lanes..],
    );
    for (l, head) in out.iter_mut().enumerate() {
        let chains = a0[l] + s * (a1[l] + s * (a2[l] + s * a3[l]));
        *head += chains * power;
    }
}

/// s^r for r < 4 as [`f64::powi`] forms it (by repeated squaring: 1, s,
/// s², s·s²), to the bit, without its call into the runtime's loop.
#[inline]
fn power_below_four(s: f64, r: usize) -> f64 {
    match r {
        0 => 1.0,
        1 => s,
        2 => s * s,
        _ => s * (s * s),
    }
}

/// An upper bound of p over [0, s]: the quadratic part c₀ + c₁t + c₂t²
/// exactly (its ends and its vertex, if inside), the rest by Σ_{k≥3} |c_k| s^k,
/// which no t ∈ [0, s] exceeds. On a step of a radian or less the quadratic
/// part holds most of p, so this is far tighter than [`bound`].
#[inline]
pub fn upper_bound(c: &[f64], s: f64) -> f64 {
    let (top, _) = quadratic_range(c, s);
    top + tail(c, s)
}

/// A bound on |p| over [0, s], as [`upper_bound`].
#[inline]
pub fn magnitude_bound(c: &[f64], s: f64) -> f64 {
    let (top, bottom) = quadratic_range(c, s);
    top.abs().max(bottom.abs()) + tail(c, s)
}

/// [`magnitude_bound`] of many polynomials side by side into `out` (one
/// per lane, laid as [`bound_lanes`] takes them, each at least three
/// orders long), the same to the bit: each lane's quadratic part exactly,
/// its tail by [`bound_lanes`] (`chains` its buffer). A step's search for
/// peaks asks it of every floor's acceleration at once.
pub fn magnitude_bound_lanes(c: &[f64], s: f64, chains: &mut Vec<f64>, out: &mut [f64]) {
    let lanes = out.len();
    debug_assert!(c.len() >= 3 * lanes && c.len().is_multiple_of(lanes.max(1)));
    let tail = c.len() > 3 * lanes;
    if tail {
        bound_lanes(&c[3 * lanes..], s, chains, out);
    }
    for (l, bound) in out.iter_mut().enumerate() {
        let (top, bottom) = quadratic_range(&[c[l], c[lanes + l], c[2 * lanes + l]], s);
        let tail = if tail { *bound * s * s * s } else { 0.0 };
        *bound = top.abs().max(bottom.abs()) + tail;
    }
}

/// (max, min) of c₀ + c₁t + c₂t² over t ∈ [0, s].
#[inline]
fn quadratic_range(c: &[f64], s: f64) -> (f64, f64) {
    let at = |k: usize| c.get(k).copied().unwrap_or(0.0);
    let (c0, c1, c2) = (at(0), at(1), at(2));
    let end = c0 + s * (c1 + s * c2);
    let (mut top, mut bottom) = (c0.max(end), c0.min(end));
    if c2 != 0.0 {
        let vertex = -c1 / (2.0 * c2);
        if vertex > 0.0 && vertex < s {
            let v = c0 + vertex * (c1 + vertex * c2);
            top = top.max(v);
            bottom = bottom.min(v);
        }
    }
    (top, bottom)
}

/// Σ_{k≥3} |c_k| s^k.
#[inline]
fn tail(c: &[f64], s: f64) -> f64 {
    if c.len() <= 3 {
        return 0.0;
    }
    bound(&c[3..], s) * s * s * s
}

/// p''(s).
#[inline]
pub fn eval_second_derivative(c: &[f64], s: f64) -> f64 {
    let mut acc = 0.0;
    for k in (2..c.len()).rev() {
        acc = acc * s + (k * (k - 1)) as f64 * c[k];
    }
    acc
}

/// A root of `f` bracketed by f(lo) ≤ 0 < f(hi), by Newton's method kept
/// inside the bracket (a bisection where a Newton step would leave it);
/// returns a point where f > 0, within a few ulps of the root, so that an
/// event is applied on its far side.
fn bisect(f: impl Fn(f64) -> f64, df: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    bisect_from(f, df, (lo, hi), 0.5 * (lo + hi))
}

/// [`bisect`] from the first guess `x` inside (lo, hi).
fn bisect_from(
    f: impl Fn(f64) -> f64,
    df: impl Fn(f64) -> f64,
    (mut lo, mut hi): (f64, f64),
    mut x: f64,
) -> f64 {
    for _ in 0..200 {
        let fx = f(x);
        if fx > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        if hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(f64::MIN_POSITIVE) {
            break;
        }
        let d = df(x);
        let newton = x - fx / d;
        if d != 0.0 && (newton - x).abs() <= 4.0 * f64::EPSILON * x.abs() {
            // Converged: the first point past the root where f > 0.
            let mut y = newton.max(lo);
            for _ in 0..16 {
                if y >= hi {
                    break;
                }
                if f(y) > 0.0 {
                    return y;
                }
                y = y.next_up();
            }
        }
        x = if d != 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if x == lo || x == hi {
            x = 0.5 * (lo + hi);
            if x == lo || x == hi {
                break;
            }
        }
    }
    hi
}

/// A turning point of p between scan points lo and hi, where p' goes from
/// `d_lo` to `d_hi` through zero (falling when `falling`), by [`bisect_from`]
/// on p' started where the chord of p' crosses zero: p' is nearly linear
/// across a scan interval (a sixteenth of a step), so Newton's method
/// starts a step or two nearer the root than from the midpoint, and ends
/// on the same root to its few ulps.
fn turning_point(c: &[f64], (lo, hi): (f64, f64), (d_lo, d_hi): (f64, f64), falling: bool) -> f64 {
    let chord = lo + (hi - lo) * (d_lo / (d_lo - d_hi));
    let start = if chord > lo && chord < hi {
        chord
    } else {
        0.5 * (lo + hi)
    };
    let df = |s: f64| eval_derivative(c, s);
    let ddf = |s: f64| eval_second_derivative(c, s);
    if falling {
        bisect_from(|x| -df(x), |x| -ddf(x), (lo, hi), start)
    } else {
        bisect_from(df, ddf, (lo, hi), start)
    }
}

/// p'(s_i) at the scan points s_i = end·i/[`SCAN`], i = 0 … SCAN: Horner's
/// rule as [`eval_derivative`], the points in lockstep so that their
/// independent chains run side by side.
#[inline]
fn scan_derivative(c: &[f64], end: f64) -> [f64; SCAN + 1] {
    let points: [f64; SCAN + 1] = std::array::from_fn(|i| end * i as f64 / SCAN as f64);
    let mut acc = [0.0; SCAN + 1];
    for k in (1..c.len()).rev() {
        let ck = k as f64 * c[k];
        for (a, &s) in acc.iter_mut().zip(&points) {
            *a = *a * s + ck;
        }
    }
    acc
}

/// p(s_i) at the scan points, as [`scan_derivative`] does p'.
#[inline]
fn scan_values(c: &[f64], end: f64) -> [f64; SCAN + 1] {
    let points: [f64; SCAN + 1] = std::array::from_fn(|i| end * i as f64 / SCAN as f64);
    let mut acc = [0.0; SCAN + 1];
    for &ck in c.iter().rev() {
        for (a, &s) in acc.iter_mut().zip(&points) {
            *a = *a * s + ck;
        }
    }
    acc
}

/// The first s in [0, end] where p turns positive, if any: scanned on
/// `SCAN` points, with a positive hump between two non-positive points
/// caught by the sign change of p' between them. A p already positive at 0
/// counts at 0 if rising there; if falling (it was just switched on, at its
/// own root, and rounding put it a hair above zero) only after it has been
/// non-positive again. That dip may lie wholly between two scan points: a
/// pair that separates with a small relative velocity can touch again a
/// fraction of a millisecond later, p ≤ 0 only on (0, s_r). So until p has
/// been seen non-positive, a minimum between two scan points (p' turning
/// from negative to positive) is located, and if p ≤ 0 there, p's rise
/// after it is the root.
pub fn first_rise(c: &[f64], end: f64) -> Option<f64> {
    // When p's upper bound on [0, end] stays ≤ 0, nothing to scan.
    if c[0] <= 0.0 && upper_bound(c, end) <= 0.0 {
        return None;
    }
    let f = |s: f64| eval(c, s);
    let df = |s: f64| eval_derivative(c, s);
    let ddf = |s: f64| eval_second_derivative(c, s);
    let mut lo = 0.0;
    let mut f_lo = f(0.0);
    let mut d_lo = df(0.0);
    if f_lo > 0.0 && d_lo > 0.0 {
        return Some(0.0);
    }
    let mut armed = f_lo <= 0.0;
    let (values, rates) = (scan_values(c, end), scan_derivative(c, end));
    for i in 1..=SCAN {
        let s = end * i as f64 / SCAN as f64;
        let (fs, ds) = (values[i], rates[i]);
        if armed {
            if fs > 0.0 {
                return Some(bisect(f, df, lo, s));
            }
            if d_lo > 0.0 && ds < 0.0 {
                // A maximum inside (lo, s): is it above zero?
                let top = bisect(|x| -df(x), |x| -ddf(x), lo, s);
                if f(top) > 0.0 {
                    return Some(bisect(f, df, lo, top));
                }
            }
        } else if fs <= 0.0 {
            armed = true;
        } else if d_lo < 0.0 && ds > 0.0 {
            // A minimum inside (lo, s): is p non-positive there?
            let bottom = bisect(df, ddf, lo, s);
            if f(bottom) <= 0.0 {
                return Some(bisect(f, df, bottom, s));
            }
        }
        lo = s;
        f_lo = fs;
        d_lo = ds;
    }
    let _ = f_lo;
    None
}

/// Relative margin by which p' must clear zero on [0, end] for
/// [`keeps_slope`]: far above the rounding of p' by Horner's rule at any
/// degree kept (γ_{2K} ≈ 9e-15 at K = 40) and of the bound's own sums.
const SLOPE_MARGIN: f64 = 1e-12;

/// Whether p' keeps one sign on [0, end] by a margin that no rounding of
/// the scan of [`scan_derivative`] can cross, so that the scan would find
/// no sign change and p's extremes on [0, end] are its ends. On [0, s],
///
/// ```text
/// p'(t) = (c₁ + 2c₂t) + Σ_{k≥3} k c_k t^{k−1},   |Σ_{k≥3} …| ≤ T = Σ_{k≥3} k|c_k| s^{k−1},
/// ```
///
/// the linear part's range exactly (its ends), so p' > 0 throughout when
/// min(c₁, c₁ + 2c₂s) − T exceeds the margin times the terms' size
/// |c₁| + 2|c₂|s + T, which bounds the rounding of every p'(s_i) computed
/// at the scan points s_i ≤ s (and p' < 0 likewise). One pass over the
/// coefficients against the scan's [`SCAN`] + 1: most steps' peaks lie at
/// an end (a step is at most a radian of the fastest mode), where this
/// answers. A NaN or an infinity fails every comparison and goes to the
/// scan.
#[inline]
fn keeps_slope(c: &[f64], end: f64) -> bool {
    let at = |k: usize| c.get(k).copied().unwrap_or(0.0);
    let (c1, c2) = (at(1), at(2));
    let far = c1 + 2.0 * c2 * end;
    let mut tail = 0.0;
    for k in (3..c.len()).rev() {
        tail = tail * end + k as f64 * c[k].abs();
    }
    let tail = tail * end * end;
    let margin = SLOPE_MARGIN * (c1.abs() + 2.0 * c2.abs() * end + tail);
    c1.min(far) - tail > margin || c1.max(far) + tail < -margin
}

/// max |p| over [0, end]: the ends and every turning point, found where p'
/// changes sign on `SCAN` points.
pub fn max_abs(c: &[f64], end: f64) -> f64 {
    argmax_abs(c, end).1
}

/// Where on [0, end] |p| is largest, and that largest |p|, by the scan of
/// [`max_abs`] (its ends alone where a bound of p' keeps one sign).
pub fn argmax_abs(c: &[f64], end: f64) -> (f64, f64) {
    let f = |s: f64| eval(c, s);
    let (f0, f1) = (at_zero(c).abs(), f(end).abs());
    let mut best = if f1 > f0 { (end, f1) } else { (0.0, f0) };
    if keeps_slope(c, end) {
        return best;
    }
    let scan = scan_derivative(c, end);
    let mut lo = 0.0;
    let mut d_lo = scan[0];
    for (i, &ds) in scan.iter().enumerate().skip(1) {
        let s = end * i as f64 / SCAN as f64;
        if (d_lo > 0.0) != (ds > 0.0) && d_lo != 0.0 {
            let root = turning_point(c, (lo, s), (d_lo, ds), d_lo > 0.0);
            let value = f(root).abs();
            if value > best.1 {
                best = (root, value);
            }
        }
        lo = s;
        d_lo = ds;
    }
    best
}

/// max p over [0, end] (signed), by the same scan.
pub fn max(c: &[f64], end: f64) -> f64 {
    argmax(c, end).1
}

/// Where on [0, end] p is largest, and that largest value (signed), by the
/// same scan: the ends and every maximum inside.
pub fn argmax(c: &[f64], end: f64) -> (f64, f64) {
    let f = |s: f64| eval(c, s);
    let (f0, f1) = (at_zero(c), f(end));
    let mut best = if f1 > f0 { (end, f1) } else { (0.0, f0) };
    if keeps_slope(c, end) {
        return best;
    }
    let scan = scan_derivative(c, end);
    let mut lo = 0.0;
    let mut d_lo = scan[0];
    for (i, &ds) in scan.iter().enumerate().skip(1) {
        let s = end * i as f64 / SCAN as f64;
        if d_lo > 0.0 && ds <= 0.0 {
            let root = turning_point(c, (lo, s), (d_lo, ds), true);
            let value = f(root);
            if value > best.1 {
                best = (root, value);
            }
        }
        lo = s;
        d_lo = ds;
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`dot`] on [`powers`] sums Σ s^k/k! (k ≤ 24) to e^s within 1e-15
    /// relative at s = −1, 0.5 and 1 (the truncation is below 1/25! ≈
    /// 6e-26), and agrees with Horner's [`eval`] to 1e-15.
    #[test]
    fn the_powers_sum_the_exponential_series() {
        let mut c = [0.0; 25];
        let mut factorial = 1.0;
        for (k, c) in c.iter_mut().enumerate() {
            if k > 0 {
                factorial *= k as f64;
            }
            *c = 1.0 / factorial;
        }
        let mut p = [0.0; 25];
        for s in [-1.0f64, 0.5, 1.0] {
            powers(s, &mut p);
            let sum = dot(&c, &p);
            assert!((sum - s.exp()).abs() <= 1e-15 * s.exp(), "{s}: {sum}");
            assert!((sum - eval(&c, s)).abs() <= 1e-15 * s.exp(), "{s}");
        }
    }

    #[test]
    fn finds_roots_and_extremes() {
        // p = (s − 0.3)(s − 0.7) = 0.21 − s + s²: negative on (0.3, 0.7).
        let c = [0.21, -1.0, 1.0];
        let neg = [-0.21, 1.0, -1.0];
        assert!((first_rise(&neg, 1.0).unwrap() - 0.3).abs() < 1e-15);
        assert!((max_abs(&c, 1.0) - 0.21).abs() < 1e-15);
        assert!((max(&neg, 1.0) - 0.04).abs() < 1e-15);
        let (at, top) = argmax(&neg, 1.0);
        assert!((at - 0.5).abs() < 1e-12 && top == max(&neg, 1.0));
        assert!(first_rise(&c[..1].iter().map(|x| -x).collect::<Vec<_>>(), 1.0).is_none());
    }

    /// The turning points started from the chord of p' are those started
    /// from the midpoint to a few ulps, and the closed form's: cos on
    /// [0, 4] (Taylor to 30 terms, truncation below 4³⁰/30! ≈ 4e-15)
    /// turns at π with |cos| = 1, sin on [0, 3] at π/2 with sin = 1 (to
    /// 1e-13 in s, 1e-14 in value).
    #[test]
    fn turning_points_from_the_chord_are_the_closed_forms() {
        let mut sin = [0.0; 30];
        let mut cos = [0.0; 30];
        let mut factorial = 1.0;
        for k in 0..30 {
            if k > 0 {
                factorial *= k as f64;
            }
            let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
            if k % 2 == 0 {
                cos[k] = sign / factorial;
            } else {
                sin[k] = sign / factorial;
            }
        }
        let pi = std::f64::consts::PI;
        let (at, top) = argmax_abs(&cos, 4.0);
        assert!((at - pi).abs() < 1e-13, "{at}");
        assert!((top - 1.0).abs() < 1e-14, "{top}");
        let (at, top) = argmax(&sin, 3.0);
        assert!((at - pi / 2.0).abs() < 1e-13, "{at}");
        assert!((top - 1.0).abs() < 1e-15, "{top}");
        // Against the midpoint's start, on each scan interval that holds
        // the turning point.
        for (c, end, root, falling) in [(&cos, 4.0, pi, false), (&sin, 3.0, pi / 2.0, true)] {
            let w = end / SCAN as f64;
            let lo = (root / w).floor() * w;
            let hi = lo + w;
            let (d_lo, d_hi) = (eval_derivative(c, lo), eval_derivative(c, hi));
            let chord = turning_point(c, (lo, hi), (d_lo, d_hi), falling);
            let df = |s: f64| eval_derivative(c, s);
            let ddf = |s: f64| eval_second_derivative(c, s);
            let midpoint = if falling {
                bisect(|x| -df(x), |x| -ddf(x), lo, hi)
            } else {
                bisect(df, ddf, lo, hi)
            };
            assert!(
                (chord - midpoint).abs() <= 8.0 * f64::EPSILON * root,
                "{chord} {midpoint}"
            );
        }
    }

    #[test]
    fn finds_a_touch_again_inside_the_first_scan_interval() {
        // p = s(s − r) + ε: switched on at its own root with a hair of
        // rounding above zero, falling, non-positive only on (≈0, ≈r), r far
        // inside the first of the 16 scan intervals of [0, 1]: the root
        // near r is the first rise (ε shifts it by ε/r = 1e-15).
        let r = 0.01;
        let c = [1e-19, -r, 1.0];
        let s = first_rise(&c, 1.0).expect("the touch again is found");
        assert!((s - r).abs() < 1e-14, "{s}");
        // Without the dip below zero (p's minimum −r²/4 + ε > 0) nothing rises.
        let c = [r * r / 4.0 * (1.0 + 1e-9), -r, 1.0];
        assert!(first_rise(&c, 1.0).is_none());
        // Falling from a real positive value through zero is not a rise,
        // but its return above zero is.
        let c = [0.21, -1.0, 1.0];
        assert!((first_rise(&c, 1.0).unwrap() - 0.7).abs() < 1e-15);
    }

    /// s^r for r < 4 is `powi`'s to the bit, across magnitudes from
    /// subnormal to overflowing, and at the signs and zeros.
    #[test]
    fn the_small_powers_are_powis() {
        let mut cases = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            f64::MIN_POSITIVE,
            1e-300,
            1e300,
            5e-324,
        ];
        cases.extend((1..200).map(|i| 1.37f64.powi(i - 100) * if i % 3 == 0 { -1.0 } else { 1.0 }));
        cases.extend((1..100).map(|i| 0.1 * i as f64 + 1e-3 / i as f64));
        for s in cases {
            for r in 0..4 {
                let (got, want) = (power_below_four(s, r), s.powi(r as i32));
                assert_eq!(
                    got.to_bits(),
                    want.to_bits(),
                    "{s}^{r}: {got} against {want}"
                );
            }
        }
    }

    /// Side by side, each lane's bound is [`bound`] of its own
    /// coefficients to the bit: for every length from 0 to 41 (each
    /// remainder mod 4, the series' degrees), seven lanes of mixed signs
    /// and magnitudes (a zero, a subnormal, a NaN among them), and s from
    /// 0 to past 1.
    #[test]
    fn bounds_side_by_side_are_each_lanes_bound() {
        const LANES: usize = 7;
        let coefficient = |lane: usize, k: usize| match (lane, k) {
            (5, 3) => f64::NAN,
            (6, _) => 5e-324 * k as f64,
            _ => ((lane * 7 + k * 13) as f64).sin() * 10f64.powi((k % 9) as i32 - 4),
        };
        each_lane_is_its_own(LANES, 0..=41, coefficient, bound_lanes, bound);
    }

    /// Lanes side by side ([`bound_lanes`]' layout) of `lanes`
    /// polynomials, each of every length in `lengths` (coefficient k of
    /// lane l `coefficient(l, k)`), for s from 0 to past 1: each lane's
    /// `side_by_side` result is `one` of its own coefficients to the bit.
    fn each_lane_is_its_own(
        lanes: usize,
        lengths: std::ops::RangeInclusive<usize>,
        coefficient: impl Fn(usize, usize) -> f64,
        side_by_side: Lanes,
        one: fn(&[f64], f64) -> f64,
    ) {
        let mut chains = Vec::new();
        for len in lengths {
            let columns: Vec<Vec<f64>> = (0..len)
                .map(|k| (0..lanes).map(|lane| coefficient(lane, k)).collect())
                .collect();
            for s in [0.0, 1e-3, 0.37, 1.0, 2.5] {
                let mut out = vec![7.0; lanes];
                side_by_side(&columns.concat(), s, &mut chains, &mut out);
                for (lane, got) in out.iter().enumerate() {
                    let c: Vec<f64> = (0..len).map(|k| coefficient(lane, k)).collect();
                    let want = one(&c, s);
                    assert_eq!(
                        got.to_bits(),
                        want.to_bits(),
                        "len {len}, lane {lane}, s {s}"
                    );
                }
            }
        }
    }

    /// A bound of many polynomials side by side, as [`bound_lanes`].
    type Lanes = fn(&[f64], f64, &mut Vec<f64>, &mut [f64]);

    /// Side by side, each lane's magnitude bound is [`magnitude_bound`] of
    /// its own coefficients to the bit, for every length from 3 to 41 and
    /// lanes whose quadratic parts turn inside [0, s] or not, and s from 0
    /// to past 1.
    #[test]
    fn magnitude_bounds_side_by_side_are_each_lanes_bound() {
        const LANES: usize = 6;
        let coefficient = |lane: usize, k: usize| match (lane, k) {
            // A vertex at s = 0.25 (c₁ = −0.5 c₂).
            (0, 1) => -0.5,
            (0, 2) => 1.0,
            (5, _) => 5e-324 * k as f64,
            _ => ((lane * 5 + k * 11) as f64).cos() * 10f64.powi((k % 7) as i32 - 3),
        };
        each_lane_is_its_own(
            LANES,
            3..=41,
            coefficient,
            magnitude_bound_lanes,
            magnitude_bound,
        );
    }

    #[test]
    fn bounds_hold_and_are_tight_on_a_quadratic() {
        // Exact on a quadratic: 0.21 − s + s² on [0, 1] spans [−0.04, 0.21].
        let c = [0.21, -1.0, 1.0];
        assert_eq!(upper_bound(&c, 1.0), 0.21);
        assert_eq!(magnitude_bound(&c, 1.0), 0.21);
        assert!((upper_bound(&[-0.21, 1.0, -1.0], 1.0) - 0.04).abs() < 1e-16);
        // Never below the true extremes: sin and cos to 25 terms on [0, 1.5].
        let mut sin = vec![0.0; 25];
        let mut cos = vec![0.0; 25];
        let mut f = 1.0;
        for k in 0..25 {
            if k > 0 {
                f *= k as f64;
            }
            match k % 4 {
                0 => cos[k] = 1.0 / f,
                1 => sin[k] = 1.0 / f,
                2 => cos[k] = -1.0 / f,
                _ => sin[k] = -1.0 / f,
            }
        }
        for s in [0.3, 1.0, 1.5] {
            assert!(upper_bound(&sin, s) >= max(&sin, s));
            assert!(magnitude_bound(&cos, s) >= max_abs(&cos, s));
            assert!(magnitude_bound(&cos, s) <= bound(&cos, s));
        }
        assert!((max(&sin, 1.5) - 1.5f64.sin()).abs() < 1e-15);
        // The four chains sum what one Horner chain does, for every length.
        for len in 0..25 {
            let c: Vec<f64> = (0..len).map(|k| (-1f64).powi(k) / (k + 1) as f64).collect();
            let horner = c.iter().rev().fold(0.0, |a, &x| a * 0.7 + x.abs());
            assert!(
                (bound(&c, 0.7) - horner).abs() <= 1e-15 * horner.max(1.0),
                "{len}"
            );
        }
    }

    /// The ends' shortcut where p' keeps its sign ([`keeps_slope`]) on the
    /// closed forms: sin on [0, 1] rises (p' = cos ≥ 0.54) and is taken at
    /// its ends, sin on [0, 3] turns at π/2 and is not; e^{−s} on [0, 0.5]
    /// falls throughout (on [0, 2] too, but there the slope's linear part
    /// c₁ + 2c₂s = s − 1 changes sign, and the bound leaves it to the
    /// scan). The values are the scan's, to the bit.
    #[test]
    fn a_polynomial_whose_slope_keeps_its_sign_peaks_at_an_end() {
        // Σ_k sign(k) s^k / k! to 30 terms.
        let taylor = |sign: fn(usize) -> f64| {
            let factorials = (0..30).scan(1.0, |f, k| {
                *f *= k.max(1) as f64;
                Some(*f)
            });
            factorials
                .enumerate()
                .map(|(k, f)| sign(k) / f)
                .collect::<Vec<_>>()
        };
        let sin = taylor(|k| [0.0, 1.0, 0.0, -1.0][k % 4]);
        let decay = taylor(|k| if k % 2 == 0 { 1.0 } else { -1.0 });
        assert!(keeps_slope(&sin, 1.0));
        assert_eq!(argmax_abs(&sin, 1.0), (1.0, eval(&sin, 1.0).abs()));
        assert!((max_abs(&sin, 1.0) - 1f64.sin()).abs() < 1e-15);
        assert!(!keeps_slope(&sin, 3.0));
        assert!((max_abs(&sin, 3.0) - 1.0).abs() < 1e-14);
        assert!(keeps_slope(&decay, 0.5));
        assert_eq!(argmax(&decay, 0.5), (0.0, 1.0));
        assert_eq!(argmax_abs(&decay, 0.5), (0.0, 1.0));
        assert!(!keeps_slope(&decay, 2.0));
        assert_eq!(argmax_abs(&decay, 2.0), (0.0, 1.0));
        // A NaN goes to the scan.
        assert!(!keeps_slope(&[0.0, 1.0, f64::NAN], 1.0));
    }

    proptest::proptest! {
        /// Wherever [`keeps_slope`] holds, the scan of p' finds no sign
        /// change and no zero, so the ends alone are what the scan gives:
        /// random polynomials of degree 2 to 40 whose slope at 0 is made
        /// to nearly balance the rest (the test's edge), on steps up to 2.
        #[test]
        fn where_the_slope_keeps_its_sign_the_scan_finds_no_turn(
            raw in proptest::collection::vec(-1.0f64..1.0, 3..41),
            decay in 0.05f64..1.5,
            balance in 0.9f64..1.1,
            end in 0.01f64..2.0,
        ) {
            // Coefficients falling like decay^k / k!, as a step's series do.
            let mut c: Vec<f64> = raw.clone();
            let mut scale = 1.0;
            for (k, x) in c.iter_mut().enumerate() {
                if k > 0 {
                    scale *= decay / k as f64;
                }
                *x *= scale;
            }
            let rest: f64 = (2..c.len()).map(|k| k as f64 * c[k].abs() * end.powi(k as i32 - 1)).sum();
            c[1] = c[1].signum() * balance * rest;
            if keeps_slope(&c, end) {
                let scan = scan_derivative(&c, end);
                let rising = scan[0] > 0.0;
                proptest::prop_assert!(scan.iter().all(|&d| d != 0.0 && (d > 0.0) == rising));
            }
        }
    }
}
