//! The cubic Hermite interpolant through a quantity's values and rates at
//! both ends of a sub-step: a cheap estimate of its range inside, which
//! decides whether the sub-step needs the Taylor series (an event or a peak
//! may lie inside). With ωh ≤ 1 for the fastest mode the cubic is within
//! about h⁴ max|q⁗|/384 ≤ 1/384 of the quantity's amplitude; the callers
//! keep a margin of 1 % above that.

/// (min, max) over the interior turning points of the cubic through
/// (0, q0, d0) and (h, q1, d1); `None` when the rate keeps its sign.
pub fn interior_range(q0: f64, d0: f64, q1: f64, d1: f64, h: f64) -> Option<(f64, f64)> {
    if (d0 > 0.0) == (d1 > 0.0) {
        return None;
    }
    // H(θ) on θ ∈ [0, 1]: q0 + d0hθ + (3Δ − (2d0 + d1)h)θ² + ((d0 + d1)h − 2Δ)θ³.
    let dq = q1 - q0;
    let c1 = d0 * h;
    let c2 = 3.0 * dq - (2.0 * d0 + d1) * h;
    let c3 = (d0 + d1) * h - 2.0 * dq;
    let value = |t: f64| q0 + t * (c1 + t * (c2 + t * c3));
    // H' = c1 + 2c2θ + 3c3θ².
    let (a, b, c) = (3.0 * c3, 2.0 * c2, c1);
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let mut take = |t: f64| {
        if (0.0..=1.0).contains(&t) {
            let v = value(t);
            lo = lo.min(v);
            hi = hi.max(v);
        }
    };
    if a.abs() < 1e-300 {
        if b != 0.0 {
            take(-c / b);
        }
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            let r = disc.sqrt();
            take((-b + r) / (2.0 * a));
            take((-b - r) / (2.0 * a));
        }
    }
    (lo <= hi).then_some((lo, hi))
}
