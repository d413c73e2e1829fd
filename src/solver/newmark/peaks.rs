//! Peaks between two accepted states (SPEC §6): Π_u and Π_v are the extrema
//! of the trajectory, not of its samples.

/// Largest Π_ω h at which a step's Hermite interpolant is used for peaks:
/// its error is about (Π_ω h)⁴/384 of the amplitude, 1.6e-4 here.
pub const RESOLVED_PHASE: f64 = 0.5;

/// Per structure, the largest step whose interpolant is trusted for peaks:
/// [`RESOLVED_PHASE`] / Π_ωi (any step when Π_ωi is 0).
pub fn resolved_steps(omega: [f64; 2]) -> [f64; 2] {
    omega.map(|w| {
        if w > 0.0 {
            RESOLVED_PHASE / w
        } else {
            f64::INFINITY
        }
    })
}

/// The value at the interior extremum of the cubic Hermite interpolant with
/// end values p0, p1 and end slopes m0, m1 (m0·m1 < 0) over a step of size h.
/// dp/ds = a s² + b s + c on s ∈ [0, 1], with a = 6(p0 − p1) + 3h(m0 + m1),
/// b = −6(p0 − p1) − h(4m0 + 2m1), c = h m0; its root in (0, 1) is unique
/// when the end slopes differ in sign.
pub fn hermite_extremum(p0: f64, p1: f64, m0: f64, m1: f64, h: f64) -> f64 {
    let (hm0, hm1) = (h * m0, h * m1);
    let a = 6.0 * (p0 - p1) + 3.0 * (hm0 + hm1);
    let b = -6.0 * (p0 - p1) - 4.0 * hm0 - 2.0 * hm1;
    let c = hm0;
    // Bisection-free root: the quadratic changes sign on [0, 1] (c and a + b + c = h m1 differ in sign).
    let s = if a.abs() < 1e-300 {
        -c / b
    } else {
        let disc = (b * b - 4.0 * a * c).max(0.0).sqrt();
        // Numerically stable pair of roots; take the one inside [0, 1].
        let q = -0.5 * (b + b.signum() * disc);
        let (r1, r2) = (q / a, if q != 0.0 { c / q } else { f64::NAN });
        if (0.0..=1.0).contains(&r1) { r1 } else { r2 }
    };
    let s = if s.is_finite() {
        s.clamp(0.0, 1.0)
    } else {
        0.5
    };
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * p0
        + (s3 - 2.0 * s2 + s) * hm0
        + (-2.0 * s3 + 3.0 * s2) * p1
        + (s3 - s2) * hm1
}

#[cfg(test)]
mod tests {
    use super::hermite_extremum;

    #[test]
    fn hermite_finds_the_peak_of_a_sine() {
        // sin on [1.5, 1.7]: peak 1 at π/2, cubic interpolation error O(h⁴).
        let (t0, t1) = (1.5f64, 1.7f64);
        let p = hermite_extremum(t0.sin(), t1.sin(), t0.cos(), t1.cos(), t1 - t0);
        assert!((p - 1.0).abs() < 1e-5, "{p}");
        // A parabola is reproduced exactly: p = 1 − (t − 0.3)², t ∈ [0, 1].
        let p = hermite_extremum(1.0 - 0.09, 1.0 - 0.49, 0.6, -1.4, 1.0);
        assert!((p - 1.0).abs() < 1e-14, "{p}");
    }
}
