//! The quintic Hermite interpolant through a quantity's value, rate and
//! second rate at both ends of a sub-step, and whether its rigorous range
//! stays within limits (SPEC §13).
//!
//! The interpolant H matches q, q̇ and q̈ at 0 and h, so q − H vanishes to
//! third order at both ends, and the remainder of Hermite interpolation
//! gives, for some ξ in the sub-step,
//!
//! ```text
//! q(t) − H(t) = q⁽⁶⁾(ξ)/6! · t³(t − h)³,   so   |q − H| ≤ h⁶/46080 · max|q⁽⁶⁾|,
//! ```
//!
//! since |t³(t − h)³| peaks at h⁶/64 at the midpoint. Against the cubic of
//! [`super::hermite`] (h⁴/384 · max|q⁗|) the allowance is smaller by about
//! (ωh)²/120 on a mode of rate ω, some 170 times at the sub-step's one
//! radian of the fastest mode, and the interpolant is closer to q by as
//! much: a quantity whose cubic range passes its running peak while q
//! itself stays below it is often held below it by the quintic.
//!
//! On θ = t/h ∈ [0, 1] H is a quintic in Bernstein form with the control
//! points
//!
//! ```text
//! b₀ = q₀,  b₁ = q₀ + hq̇₀/5,  b₂ = q₀ + 2hq̇₀/5 + h²q̈₀/20,
//! b₅ = q₁,  b₄ = q₁ − hq̇₁/5,  b₃ = q₁ − 2hq̇₁/5 + h²q̈₁/20
//! ```
//!
//! (from H′(0) = 5(b₁ − b₀), H″(0) = 20(b₂ − 2b₁ + b₀) and their mirror
//! at θ = 1), and lies in their hull; halving the interval by de
//! Casteljau's construction gives each half's control points, whose hulls
//! close in on H's range. [`within`] asks the hull of the whole, then of
//! halves, down to sixteenths, and fails where a piece's end (a value of H
//! itself) is outside, or at that depth: a yes is rigorous, a no only says
//! the test could not tell.

/// 6! · 2⁶: the remainder's h⁶/46080.
pub const REMAINDER: f64 = 46080.0;

/// Halvings [`within`] makes at most (pieces of 1/16 of the sub-step).
const DEPTH: usize = 4;

/// Relative allowance for the rounding of the control points and of de
/// Casteljau's averages (a few ulps of the data's size per level).
const ROUNDING: f64 = 1e-13;

/// Whether the quintic through (q, q̇, q̈) = `start` at 0 and `end` at `h`,
/// widened by `e` (its remainder's bound) and by the rounding of its
/// control points, lies strictly inside (lower, upper) over the whole
/// sub-step (strictly, so that an event's limit is not reached; a peak's
/// is then asked a hair more than it needs). A NaN anywhere gives false.
pub fn within(start: [f64; 3], end: [f64; 3], h: f64, e: f64, (lower, upper): (f64, f64)) -> bool {
    let [q0, d0, a0] = start;
    let [q1, d1, a1] = end;
    let (d0, d1) = (h * d0 / 5.0, h * d1 / 5.0);
    let (a0, a1) = (h * h * a0 / 20.0, h * h * a1 / 20.0);
    let points = [
        q0,
        q0 + d0,
        q0 + 2.0 * d0 + a0,
        q1 - 2.0 * d1 + a1,
        q1 - d1,
        q1,
    ];
    let size = q0.abs() + q1.abs() + 2.0 * (d0.abs() + d1.abs()) + a0.abs() + a1.abs();
    let slack = e + ROUNDING * size;
    fits(points, DEPTH, slack, (lower, upper))
}

/// Whether the quintic with Bernstein control points `b` on its piece,
/// widened by `slack`, lies inside (lower, upper): by its hull, else by its two
/// halves', `depth` more times.
fn fits(b: [f64; 6], depth: usize, slack: f64, (lower, upper): (f64, f64)) -> bool {
    let inside = |x: f64| x - slack > lower && x + slack < upper;
    if b.iter().all(|&x| inside(x)) {
        return true;
    }
    // A piece's ends are values of H: outside, no halving can clear it.
    if depth == 0 || !inside(b[0]) || !inside(b[5]) {
        return false;
    }
    let (left, right) = halves(b);
    fits(left, depth - 1, slack, (lower, upper)) && fits(right, depth - 1, slack, (lower, upper))
}

/// The control points of the two halves of the quintic with control points
/// `b`, by de Casteljau's construction at θ = 1/2.
fn halves(b: [f64; 6]) -> ([f64; 6], [f64; 6]) {
    let mut row = b;
    let (mut left, mut right) = ([0.0; 6], [0.0; 6]);
    for level in 0..6 {
        left[level] = row[0];
        right[5 - level] = row[5 - level];
        for j in 0..5 - level {
            row[j] = 0.5 * (row[j] + row[j + 1]);
        }
    }
    (left, right)
}

#[cfg(test)]
mod tests {
    use super::{REMAINDER, halves, within};

    /// The quintic through the ends' (q, q̇, q̈) at θ ∈ [0, 1] in its
    /// Hermite basis, for the dense checks.
    fn hermite(start: [f64; 3], end: [f64; 3], h: f64, t: f64) -> f64 {
        let (t2, t3) = (t * t, t * t * t);
        let (t4, t5) = (t3 * t, t3 * t2);
        let h00 = 1.0 - 10.0 * t3 + 15.0 * t4 - 6.0 * t5;
        let h10 = t - 6.0 * t3 + 8.0 * t4 - 3.0 * t5;
        let h20 = 0.5 * (t2 - 3.0 * t3 + 3.0 * t4 - t5);
        let h01 = 10.0 * t3 - 15.0 * t4 + 6.0 * t5;
        let h11 = -4.0 * t3 + 7.0 * t4 - 3.0 * t5;
        let h21 = 0.5 * (t3 - 2.0 * t4 + t5);
        h00 * start[0]
            + h10 * h * start[1]
            + h20 * h * h * start[2]
            + h01 * end[0]
            + h11 * h * end[1]
            + h21 * h * h * end[2]
    }

    /// cos on [0, h] from its (q, q̇, q̈) at both ends: every sampled value
    /// of cos lies within the widened quintic's limits whenever `within`
    /// says yes, the remainder's bound (max|q⁽⁶⁾| = 1) is met by the true
    /// error, and the limits it clears are near the true range (within
    /// 1e-4 at h = 1, where the bound is 2.2e-5).
    #[test]
    fn cos_is_held_within_its_bound() {
        for &(t0, h) in &[(0.3, 1.0), (2.0, 0.8), (-1.0, 0.5), (3.0, 1.0)] {
            let at = |t: f64| [t.cos(), -t.sin(), -t.cos()];
            let (start, end) = (at(t0), at(t0 + h));
            let e = h.powi(6) / REMAINDER;
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for i in 0..=2000 {
                let s = h * i as f64 / 2000.0;
                let q = (t0 + s).cos();
                let interpolated = hermite(start, end, h, s / h);
                assert!((q - interpolated).abs() <= e, "remainder at {s}");
                lo = lo.min(q);
                hi = hi.max(q);
            }
            // Just outside the true range (by the bound and a hair): cleared.
            let margin = 2.0 * e + 1e-4;
            assert!(within(start, end, h, e, (lo - margin, hi + margin)));
            // Inside it: never cleared.
            let inside = (lo + 1e-6, hi - 1e-6);
            assert!(!within(start, end, h, e, inside));
        }
    }

    /// De Casteljau's halves are the same quintic: each half's Bernstein
    /// sum at σ equals the whole's at σ/2 (left) and (1 + σ)/2 (right).
    #[test]
    fn the_halves_are_the_same_polynomial() {
        let b = [0.3, -1.2, 2.5, 0.7, -0.4, 1.1];
        let bernstein = |b: &[f64; 6], t: f64| {
            let binom = [1.0, 5.0, 10.0, 10.0, 5.0, 1.0];
            (0..6)
                .map(|i| binom[i] * t.powi(i as i32) * (1.0 - t).powi(5 - i as i32) * b[i])
                .sum::<f64>()
        };
        let (left, right) = halves(b);
        for i in 0..=20 {
            let s = i as f64 / 20.0;
            assert!((bernstein(&left, s) - bernstein(&b, 0.5 * s)).abs() < 1e-14);
            assert!((bernstein(&right, s) - bernstein(&b, 0.5 + 0.5 * s)).abs() < 1e-14);
        }
    }

    proptest::proptest! {
        /// On random ends: whenever `within` clears limits, the quintic
        /// itself, sampled at 257 points, lies inside them narrowed by the
        /// widening e; and limits a sampled value lies outside of are never
        /// cleared.
        #[test]
        fn what_is_cleared_holds_the_quintic(
            start in proptest::array::uniform3(-1.0f64..1.0),
            end in proptest::array::uniform3(-1.0f64..1.0),
            h in 0.05f64..2.0,
            e in 0.0f64..0.05,
            lower in -2.0f64..0.0,
            upper in 0.0f64..2.0,
        ) {
            let cleared = within(start, end, h, e, (lower, upper));
            for i in 0..=256 {
                let q = hermite(start, end, h, i as f64 / 256.0);
                if cleared {
                    proptest::prop_assert!(q - e >= lower - 1e-12 && q + e <= upper + 1e-12);
                }
                if q < lower || q > upper {
                    proptest::prop_assert!(!cleared);
                }
            }
        }
    }
}
