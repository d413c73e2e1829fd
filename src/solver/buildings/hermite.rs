//! The cubic Hermite interpolant through a quantity's values and rates at
//! both ends of a sub-step, and its range over the sub-step (SPEC §13).
//!
//! The interpolant H matches q and q̇ at 0 and h, so q − H vanishes to
//! second order at both ends, and the classical remainder of Hermite
//! interpolation gives, for some ξ in the sub-step,
//!
//! ```text
//! q(t) − H(t) = q⁗(ξ)/4! · t²(t − h)²,   so   |q − H| ≤ h⁴/384 · max|q⁗|,
//! ```
//!
//! since t²(h − t)² peaks at h⁴/16 at the midpoint. The range of H widened
//! by that bound therefore holds q's range; [`super::bound`] supplies
//! max|q⁗|.

use crate::numerics::extremes::{largest, least};

/// An enclosure of [`range`] without its turning points: the cubic in
/// Bernstein form on [0, h] has the control points q0, q0 + d0h/3,
/// q1 − d1h/3, q1, and lies in their hull (a convex combination of them at
/// every θ), so (min, max) of the four holds the cubic's range. A watched
/// quantity far from its limit is cleared on it, before the exact range
/// is asked for: whatever the hull clears, the range clears.
///
/// The least and largest are taken by plain comparisons
/// ([`crate::numerics::extremes`]): the control points of a finite
/// state's cubic are finite, and on finite values both pick the same as
/// `f64::min`/`f64::max` (up to the sign of a zero, which no comparison
/// sees).
#[inline]
pub fn hull(q0: f64, d0: f64, q1: f64, d1: f64, h: f64) -> (f64, f64) {
    let (b1, b2) = (q0 + d0 * h / 3.0, q1 - d1 * h / 3.0);
    (
        least(least(q0, q1), least(b1, b2)),
        largest(largest(q0, q1), largest(b1, b2)),
    )
}

/// (min, max) of the cubic through (0, q0, d0) and (h, q1, d1) over the
/// whole sub-step: its ends and every interior turning point.
pub fn range(q0: f64, d0: f64, q1: f64, d1: f64, h: f64) -> (f64, f64) {
    // H(θ) on θ ∈ [0, 1]: q0 + d0hθ + (3Δ − (2d0 + d1)h)θ² + ((d0 + d1)h − 2Δ)θ³.
    let dq = q1 - q0;
    let c1 = d0 * h;
    let c2 = 3.0 * dq - (2.0 * d0 + d1) * h;
    let c3 = (d0 + d1) * h - 2.0 * dq;
    let value = |t: f64| q0 + t * (c1 + t * (c2 + t * c3));
    let mut lo = q0.min(q1);
    let mut hi = q0.max(q1);
    // The Bernstein control points q0 + d0h/3 and q1 − d1h/3 hold the cubic
    // in their hull with the ends: inside the ends' range, so is the cubic.
    let (b1, b2) = (q0 + c1 / 3.0, q1 - d1 * h / 3.0);
    if b1 >= lo && b1 <= hi && b2 >= lo && b2 <= hi {
        return (lo, hi);
    }
    let mut take = |t: f64| {
        if t > 0.0 && t < 1.0 {
            let v = value(t);
            lo = lo.min(v);
            hi = hi.max(v);
        }
    };
    // H' = c1 + 2c2θ + 3c3θ².
    let (a, b, c) = (3.0 * c3, 2.0 * c2, c1);
    if a == 0.0 {
        if b != 0.0 {
            take(-c / b);
        }
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            // The stable pair of roots: q = −(b + sign(b)√disc)/2, θ = q/a, c/q.
            let r = disc.sqrt();
            let q = -0.5 * (b + r.copysign(b));
            take(q / a);
            if q != 0.0 {
                take(c / q);
            }
        }
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::{hull, range};
    use proptest::prelude::*;

    proptest! {
        /// The hull of the control points holds the cubic's exact range,
        /// and the cubic itself at 64 points: what the hull clears, the
        /// range clears. Within a relative 1e-15 for the rounding of the
        /// turning points' values.
        #[test]
        fn the_hull_holds_the_range(
            q0 in -1.0f64..1.0,
            d0 in -10.0f64..10.0,
            q1 in -1.0f64..1.0,
            d1 in -10.0f64..10.0,
            h in 0.01f64..1.0,
        ) {
            let (lo, hi) = hull(q0, d0, q1, d1, h);
            let (rlo, rhi) = range(q0, d0, q1, d1, h);
            let slack = 1e-15 * (q0.abs() + q1.abs() + (d0.abs() + d1.abs()) * h);
            prop_assert!(lo <= rlo + slack && rhi <= hi + slack);
            for i in 0..=64 {
                let t = i as f64 / 64.0;
                // The cubic in its Hermite basis at θ = t.
                let (t2, t3) = (t * t, t * t * t);
                let q = (2.0 * t3 - 3.0 * t2 + 1.0) * q0
                    + (t3 - 2.0 * t2 + t) * h * d0
                    + (-2.0 * t3 + 3.0 * t2) * q1
                    + (t3 - t2) * h * d1;
                prop_assert!(lo <= q + slack && q <= hi + slack);
                prop_assert!(rlo <= q + slack && q <= rhi + slack);
            }
        }
    }

    #[test]
    fn holds_the_turning_points_and_the_ends() {
        // sin on [0, π]: H has its peak near 1 at the middle.
        let h = std::f64::consts::PI;
        let (lo, hi) = range(0.0, 1.0, 0.0, -1.0, h);
        assert_eq!(lo, 0.0);
        assert!((hi - h / 4.0).abs() < 1e-12);
        // Same-sign rates at both ends, two turning points inside.
        let (lo, hi) = range(0.0, 1.0, 0.0, 1.0, 1.0);
        assert!(lo < 0.0 && hi > 0.0);
        // Monotone: the ends.
        assert_eq!(range(1.0, 2.0, 3.0, 2.0, 1.0), (1.0, 3.0));
        // A turning point just past an end, by the exact roots.
        let (lo, hi) = range(0.0, 1.0, 0.0, -0.1, 1.0);
        assert_eq!(lo, 0.0);
        assert!(hi > 0.0);
    }
}
