//! The earliest instant at which an event function turns positive on a
//! segment, found on its Taylor series to round-off.
//!
//! Sign tests at the ends of a segment are not enough: an event function can
//! rise above zero and fall back inside a segment whose two ends are both
//! negative (a grazing contact, a yield that is undone at once). So a
//! sub-interval [t, t + w] is cleared only when the cubic majorant of
//! [`Series::cubic_majorant`],
//!
//! ```text
//! e(t + s) ≤ e(t) + e'(t) s + ½e''(t) s² + M s³,   s ∈ [0, w],
//! ```
//!
//! is negative on (0, w]. Otherwise the interval is halved, left half first,
//! until it is cleared or holds a sign change, which is then solved by
//! Newton's method kept inside the bracket.
//!
//! An event function that starts a segment at or just past zero (a root just
//! located, left with a round-off residue such as δ = +1e-17) counts as an
//! event only if it is still moving further past zero: a contact that has
//! just ended must not restart with a negative approach velocity.

// Comparisons are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::series::Series;

/// Halvings after which an interval that is neither cleared nor bracketed is
/// taken as a tangency at round-off level (no crossing).
const MAX_DEPTH: u32 = 52;

/// Whether e, at or just past zero at t = 0, is moving further past zero:
/// its first nonzero derivative there is positive. Then the event fires at once.
#[inline]
pub fn fires_at_start(e: &Series) -> bool {
    e.c[0] >= 0.0 && first_nonzero_positive(&e.c[1..=e.degree.max(1)])
}

#[inline]
fn first_nonzero_positive(derivatives: &[f64]) -> bool {
    derivatives
        .iter()
        .find(|d| **d != 0.0)
        .is_some_and(|d| *d > 0.0)
}

/// Evaluations of the majorant allowed per search: a guard against
/// pathological series (a tangency of high order); a search that exhausts it
/// reports no crossing.
const BUDGET: u32 = 4_000;

/// The earliest t ∈ [a, b] where e turns positive. At t = a a value ≥ 0
/// counts only if e is moving further past zero ([`fires_at_start`]); a
/// residue left by a located root that is moving back is taken as zero.
pub fn first_crossing(e: &Series, a: f64, b: f64) -> Option<f64> {
    if !(b > a) {
        return None;
    }
    let [d0, d1, d2] = if a == 0.0 {
        [e.c[0], e.c[1], e.c[2]]
    } else {
        e.derivatives(a)
    };
    if d0 >= 0.0 {
        let moving_on = if a == 0.0 {
            fires_at_start(e)
        } else {
            first_nonzero_positive(&[d1, d2])
        };
        if moving_on {
            return Some(a);
        }
    }
    let mut budget = BUDGET;
    search(e, a, b, 0, &mut budget)
}

fn search(e: &Series, lo: f64, hi: f64, depth: u32, budget: &mut u32) -> Option<f64> {
    if *budget == 0 {
        return None;
    }
    *budget -= 1;
    let w = hi - lo;
    let [d0, d1, d2, m] = e.cubic_majorant(lo, w);
    if cleared(d0.min(0.0), d1, d2, m, w) {
        return None;
    }
    if lo == 0.0 && d0 == 0.0 && d1 == 0.0 && d2 == 0.0 && leading_term_clears(e, w) {
        return None;
    }
    // Falling from at or below zero: no crossing, and no need of e(hi).
    let falling = decreasing(d1, d2, m, w);
    if falling && d0 <= 0.0 {
        return None;
    }
    let e_hi = e.value(hi);
    let rising = increasing(d1, d2, m, w);
    if e_hi > 0.0 {
        // A sign change inside: solve it. Where e is increasing it is the only
        // one; otherwise make sure no earlier crossing hides before the root.
        let root = solve(e, lo, hi, d0, e_hi);
        if rising || depth >= MAX_DEPTH || root <= lo {
            return Some(root);
        }
        let [d0, d1, d2, m] = e.cubic_majorant(lo, root - lo);
        if !cleared(d0.min(0.0), d1, d2, m, root - lo)
            && let Some(earlier) = search_strict(e, lo, root, depth + 1, budget)
        {
            return Some(earlier);
        }
        return Some(root);
    }
    // e(hi) ≤ 0: a monotone e has no crossing in between.
    if rising || falling {
        return None;
    }
    if depth >= MAX_DEPTH || w <= f64::EPSILON * hi.abs().max(lo.abs()).max(f64::MIN_POSITIVE) {
        return None;
    }
    let mid = lo + 0.5 * w;
    search(e, lo, mid, depth + 1, budget).or_else(|| search(e, mid, hi, depth + 1, budget))
}

/// Whether e < 0 on (0, w] for a series that starts flat at zero (e, e',
/// e'' all 0 at t = 0: from rest, x1 − x2 = −Π_ξ(Π_ω2 − Π_ω1)τ⁴/12 + …,
/// so its rate is flat at τ = 0), where the cubic majorant cannot help: with c_m the first nonzero coefficient,
/// e(s) ≤ s^m (c_m + Σ_{k>m} |c_k| s^{k−m}), negative if c_m is and the sum
/// at s = w does not outweigh it. Otherwise the search would halve towards
/// 0 to its depth limit.
fn leading_term_clears(e: &Series, w: f64) -> bool {
    let Some(m) = (3..=e.degree).find(|&k| e.c[k] != 0.0) else {
        // e ≡ 0: never positive.
        return true;
    };
    let tail = e.c[m + 1..=e.degree]
        .iter()
        .rev()
        .fold(0.0, |acc, c| acc * w + c.abs());
    e.c[m] < 0.0 && e.c[m] + w * tail < 0.0
}

/// Whether e' > 0 on [t, t + w], from e'(t + s) ≥ d1 + 2 d2 s − 3M s²
/// (concave in s, so its minimum is at an end).
#[inline]
fn increasing(d1: f64, d2: f64, m: f64, w: f64) -> bool {
    d1 > 0.0 && d1 + w * (2.0 * d2 - 3.0 * m * w) > 0.0
}

/// Whether e' < 0 on [t, t + w].
#[inline]
fn decreasing(d1: f64, d2: f64, m: f64, w: f64) -> bool {
    d1 < 0.0 && d1 + w * (2.0 * d2 + 3.0 * m * w) < 0.0
}

/// What one cubic majorant of q at 0 over [0, w] (no search) tells of the
/// largest value of q there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reach {
    /// q stays below the level on (0, w].
    Below,
    /// q' < 0 on [0, w]: the largest value is q(0).
    Falling,
    /// q' > 0 on [0, w]: the largest value is q(w).
    Rising,
    /// None of these could be shown.
    Unknown,
}

/// [`Reach`] of σ·q (σ = ±1) against `level` on [0, w]: a cheap test that
/// most segments pass. The majorant of σq is σ times q's derivatives with
/// the same bound M of the third.
pub fn reach_from_start(q: &Series, sign: f64, level: f64, w: f64) -> Reach {
    let [d0, d1, d2, m] = q.cubic_majorant(0.0, w);
    let (d0, d1, d2) = (sign * d0 - level, sign * d1, sign * d2);
    if d0 <= 0.0 && cleared(d0, d1, d2, m, w) {
        Reach::Below
    } else if decreasing(d1, d2, m, w) {
        Reach::Falling
    } else if increasing(d1, d2, m, w) {
        Reach::Rising
    } else {
        Reach::Unknown
    }
}

/// As [`search`] on [lo, root), for a root already found at `root`: only a
/// crossing strictly before it counts.
fn search_strict(e: &Series, lo: f64, root: f64, depth: u32, budget: &mut u32) -> Option<f64> {
    let mid = lo + 0.5 * (root - lo);
    if mid <= lo || mid >= root {
        return None;
    }
    search(e, lo, mid, depth, budget)
        .or_else(|| search(e, mid, root, depth, budget))
        .filter(|&t| t < root)
}

/// Whether P(s) = d0 + d1 s + d2 s² + M s³ < 0 on (0, w] (d0 ≤ 0, M ≥ 0).
#[inline]
pub fn cleared(d0: f64, d1: f64, d2: f64, m: f64, w: f64) -> bool {
    // Cheap and sufficient: P(s) ≤ d0 + d1⁺ s + d2⁺ s² + M s³, which grows
    // with s, so it is enough that its value at w is negative.
    if d0 + w * (d1.max(0.0) + w * (d2.max(0.0) + w * m)) < 0.0 {
        return true;
    }
    let p = |s: f64| d0 + s * (d1 + s * (d2 + s * m));
    if !(p(w) < 0.0) {
        return false;
    }
    if d0 == 0.0 && d1 >= 0.0 && (d1 > 0.0 || d2 >= 0.0) {
        return false;
    }
    // Interior maxima: roots of P'(s) = d1 + 2 d2 s + 3M s².
    let (qa, qb, qc) = (3.0 * m, 2.0 * d2, d1);
    if qa == 0.0 {
        if qb != 0.0 {
            let s = -qc / qb;
            if s > 0.0 && s < w && !(p(s) < 0.0) {
                return false;
            }
        }
        return true;
    }
    let disc = qb * qb - 4.0 * qa * qc;
    if disc < 0.0 {
        return true;
    }
    let sq = disc.sqrt();
    let q = -0.5 * (qb + sq.copysign(qb));
    for s in [q / qa, if q != 0.0 { qc / q } else { 0.0 }] {
        if s > 0.0 && s < w && !(p(s) < 0.0) {
            return false;
        }
    }
    true
}

/// The one root of a rate known to be monotone on [0, h] and to change
/// sign there (its end values strictly of opposite signs on the series):
/// `solve` on e or on −e, whichever rises. `None` where the series' own
/// end values do not show the change (a zero at an end, to round-off).
pub fn monotone_root(e: &Series, h: f64) -> Option<f64> {
    let (e0, eh) = (e.c[0], e.value(h));
    if e0 < 0.0 && eh > 0.0 {
        Some(solve(e, 0.0, h, e0, eh))
    } else if e0 > 0.0 && eh < 0.0 {
        Some(solve(&e.scaled(-1.0), 0.0, h, -e0, -eh))
    } else {
        None
    }
}

/// The root of e in (lo, hi] with e(lo) ≤ 0 < e(hi), given those two values:
/// Halley steps, t ← t − e e' / (e'² − e e''/2), kept inside the bracket
/// (bisection when a step would leave it), to the last bit. Halley's method
/// converges cubically, so from the secant through the bracket's ends two
/// steps usually reach round-off. Each correction Δ_k then predicts the
/// next, Δ_{k+1} ≈ K Δ_k³ with K ≈ Δ_k/Δ_{k−1}³ taken from the two last; a
/// predicted correction below the last bit of t ends the iteration without
/// the evaluation that would confirm it.
fn solve(e: &Series, mut lo: f64, mut hi: f64, e_lo: f64, e_hi: f64) -> f64 {
    let secant = lo + (hi - lo) * (-e_lo / (e_hi - e_lo));
    let mut t = if secant > lo && secant < hi {
        secant
    } else {
        hi
    };
    // The last Halley correction (none yet: infinite).
    let mut last = f64::INFINITY;
    for _ in 0..100 {
        let [v, dv, half_curvature] = e.derivatives(t);
        if v == 0.0 {
            return t;
        }
        if v > 0.0 {
            hi = t;
        } else {
            lo = t;
        }
        let mid = lo + 0.5 * (hi - lo);
        if mid <= lo || mid >= hi {
            break;
        }
        let step = t - v * dv / (dv * dv - v * half_curvature);
        if step > lo && step < hi {
            let correction = (step - t).abs();
            let last_bit = 2.0 * f64::EPSILON * step.abs();
            // Converged when the correction is at the last bit of t, or
            // the next is predicted to be: K Δ³ = Δ (Δ/Δ_prev)³.
            let ratio = correction / last;
            let predicted = correction * ratio * ratio * ratio;
            if correction <= last_bit || (last.is_finite() && predicted <= 0.25 * last_bit) {
                return if e.value(step) > 0.0 {
                    step
                } else {
                    hi.min(step.next_up())
                };
            }
            last = correction;
            t = step;
        } else {
            last = f64::INFINITY;
            t = mid;
        }
    }
    hi
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(c: &[f64]) -> Series {
        let mut s = Series {
            degree: c.len() - 1,
            ..Default::default()
        };
        s.c[..c.len()].copy_from_slice(c);
        s
    }

    /// Halley's iteration, stopped on its predicted next correction, still
    /// lands on the last bits: the zero of −sin(t + φ) rising through
    /// t = π − φ (degree-20 series, exact to round-off on [0, 1.5]).
    #[test]
    fn a_root_of_a_full_series_to_the_last_bits() {
        for phase in [1.7, 2.0, 2.5, 3.0] {
            let mut e = Series {
                degree: 20,
                ..Default::default()
            };
            crate::model::Excitation::Sine.taylor(phase, &mut e.c);
            e = e.scaled(-1.0);
            let root = std::f64::consts::PI - phase;
            let t = first_crossing(&e, 0.0, 1.5).unwrap();
            assert!(
                (t - root).abs() <= 4.0 * f64::EPSILON,
                "φ = {phase}: {t} against {root}"
            );
        }
    }

    #[test]
    fn finds_a_plain_crossing() {
        // e = t − 0.3
        let t = first_crossing(&poly(&[-0.3, 1.0]), 0.0, 1.0).unwrap();
        assert!((t - 0.3).abs() < 1e-16);
    }

    #[test]
    fn finds_a_crossing_hidden_between_negative_ends() {
        // e = −(t − 0.5)² + 1e-6: positive only on 0.5 ± 1e-3, negative at both ends.
        let e = poly(&[-0.25 + 1e-6, 1.0, -1.0]);
        let t = first_crossing(&e, 0.0, 1.0).unwrap();
        assert!((t - (0.5 - 1e-3)).abs() < 1e-12, "{t}");
    }

    /// A series flat at its start (e, e', e'' = 0, as the rate of x1 − x2 is
    /// on the first segment from rest; −τ³/32 for set 2) and negative after: the cubic majorant is no
    /// help at t = 0, the leading term clears it in one evaluation, where
    /// halving alone would use up a budget of 20 (and 100 steps unbudgeted).
    #[test]
    fn a_series_flat_at_its_start_is_cleared_by_its_leading_term() {
        let e = poly(&[0.0, 0.0, 0.0, -1.0 / 32.0, 0.01]);
        let mut budget = 20;
        assert_eq!(search(&e, 0.0, 0.5, 0, &mut budget), None);
        assert_eq!(budget, 19);
        // With a term that wins at s = 1/32 there is a crossing, and it is found.
        let e = poly(&[0.0, 0.0, 0.0, -1.0 / 32.0, 1.0]);
        let t = first_crossing(&e, 0.0, 0.1).unwrap();
        assert!((t - 1.0 / 32.0).abs() < 1e-15, "{t}");
    }

    #[test]
    fn a_tangency_below_zero_is_no_crossing() {
        let e = poly(&[-0.25 - 1e-12, 1.0, -1.0]);
        assert_eq!(first_crossing(&e, 0.0, 1.0), None);
    }

    #[test]
    fn the_earliest_of_several_crossings() {
        // e = sin-like cubic with roots at 0.1, 0.4 (up, down) then 0.8 (up): (t−0.1)(t−0.4)(t−0.8)·(−1)
        let (r1, r2, r3) = (0.1, 0.4, 0.8);
        let e = poly(&[
            r1 * r2 * r3,
            -(r1 * r2 + r1 * r3 + r2 * r3),
            r1 + r2 + r3,
            -1.0,
        ])
        .scaled(-1.0);
        // e(0) = r1 r2 r3 · (−1) < 0, rises through 0.1.
        let t = first_crossing(&e, 0.0, 1.0).unwrap();
        assert!((t - 0.1).abs() < 1e-15, "{t}");
        // From 0.2, where e > 0 and rising, the event fires at once; past 0.4 the next is 0.8.
        assert_eq!(first_crossing(&e, 0.2, 1.0), Some(0.2));
        let t = first_crossing(&e, 0.45, 1.0).unwrap();
        assert!((t - 0.8).abs() < 1e-15, "{t}");
    }

    #[test]
    fn a_round_off_residue_moving_back_does_not_fire() {
        // Just after a located root: e = 1e-17 − 2t.
        let e = poly(&[1e-17, -2.0, 0.5]);
        assert!(!fires_at_start(&e));
        assert_eq!(first_crossing(&e, 0.0, 1.0), None);
        assert!(fires_at_start(&poly(&[1e-17, 2.0])));
        // ẋ = 0 exactly at an unloading point, moving back: cleared by the curvature.
        let e = poly(&[0.0, 0.0, -1.0, 0.1]);
        assert!(!fires_at_start(&e));
        assert_eq!(first_crossing(&e, 0.0, 1.0), None);
    }
}
