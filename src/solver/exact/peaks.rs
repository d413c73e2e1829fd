//! Peaks on a segment: a running maximum of σ·q (σ = ±1) raised to the
//! true maximum over the segment, found on the series of q.
//!
//! Most segments are cleared by a bound of σq − peak, or shown monotone by
//! the cubic majorant of σq (the maximum is then at an end). Otherwise the
//! maxima of σq are at the end and at the falling zeros of σq', with a
//! rising zero (a minimum) between two of them, and the walk goes from one
//! to the next. It does not look for where σq crosses the peak: near a
//! maximum that only just fails to beat it, that crossing is a tangency,
//! costly to rule out, while the zeros of q' stay simple.
//!
//! The sign is carried, not applied: the negated series −q is never built,
//! and q' only where a walk needs it. (Negation is exact, so the maxima are
//! the same to the bit as those of a negated copy.)

use super::roots::{Reach, first_crossing, reach_from_start};
use super::series::Series;

/// Raises `peak` to the maximum of σ·q on (0, t1], given `swing` ≥
/// [`Series::swing`] of q over [0, t1] and, where it is at hand, the series
/// of q' (else it is derived if a walk needs it).
pub fn raise_max(q: &Series, dq: Option<&Series>, sign: f64, t1: f64, swing: f64, peak: &mut f64) {
    let start = sign * q.c[0];
    *peak = peak.max(start);
    if start + swing > *peak {
        walk_maxima(q, dq, sign, t1, peak);
    }
}

/// Raises `peak` to the maximum of |q| on (0, t1]: each sign is searched
/// only where it can reach the peak.
pub fn raise_abs_max(q: &Series, dq: Option<&Series>, t1: f64, swing: f64, peak: &mut f64) {
    *peak = peak.max(q.c[0].abs());
    raise_max(q, dq, 1.0, t1, swing, peak);
    raise_max(q, dq, -1.0, t1, swing, peak);
}

/// The walk of [`raise_max`], for a σq whose bound does not clear the peak.
fn walk_maxima(q: &Series, dq: Option<&Series>, sign: f64, t1: f64, peak: &mut f64) {
    match reach_from_start(q, sign, *peak, t1) {
        // σq(0) is already in the peak.
        Reach::Below | Reach::Falling => return,
        Reach::Rising => {
            *peak = peak.max(sign * q.value(t1));
            return;
        }
        Reach::Unknown => {}
    }
    let derived;
    let dq = match dq {
        Some(dq) => dq,
        None => {
            derived = q.derivative();
            &derived
        }
    };
    // Zeros of σq' at which it falls (maxima of σq) are where −σq' rises.
    let negated = dq.scaled(-1.0);
    let (falling, rising) = if sign > 0.0 {
        (&negated, dq)
    } else {
        (dq, &negated)
    };
    let mut t = 0.0;
    // A segment of at most about a radian holds one or two maxima; the cap only guards progress.
    for _ in 0..8 {
        // The next maximum: the next falling zero of σq', else the end.
        let tm = first_crossing(falling, t, t1).unwrap_or(t1);
        *peak = peak.max(sign * q.value(tm));
        if tm >= t1 {
            return;
        }
        // Past the maximum, σq falls to a minimum (a rising zero of σq') before it can rise again.
        match first_crossing(rising, tm, t1).filter(|&s| s > tm) {
            Some(tmin) => t = tmin,
            None => return,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::exact::series::MAX_DEGREE;

    /// sin(t + φ) to degree 20: on [0, 1.5] the first term left out is
    /// below 1.5²¹/21! ≈ 1e-16.
    fn sine(phase: f64) -> Series {
        let mut s = Series {
            degree: MAX_DEGREE,
            ..Series::default()
        };
        let mut factorial = 1.0;
        for k in 0..=MAX_DEGREE {
            s.c[k] = (phase + k as f64 * std::f64::consts::FRAC_PI_2).sin() / factorial;
            factorial *= (k + 1) as f64;
        }
        s
    }

    /// On [0, 1.5], sin(t + 0.3) rises from sin 0.3 to 1 at t = π/2 − 0.3
    /// and falls to sin 1.8: q's maximum is inside, −q's at the start.
    #[test]
    fn an_interior_maximum_and_a_maximum_at_the_start() {
        let q = sine(0.3);
        let swing = q.swing(1.5);
        let dq = q.derivative();
        for dq in [None, Some(&dq)] {
            let mut up = f64::NEG_INFINITY;
            raise_max(&q, dq, 1.0, 1.5, swing, &mut up);
            assert!((up - 1.0).abs() < 1e-15, "max {up}");
            let mut down = f64::NEG_INFINITY;
            raise_max(&q, dq, -1.0, 1.5, swing, &mut down);
            assert_eq!(down, -0.3f64.sin());
            let mut abs = 0.0;
            raise_abs_max(&q, dq, 1.5, swing, &mut abs);
            assert_eq!(abs, up);
        }
    }

    /// On [0, 1.5], sin(t + 3.9) falls from sin 3.9 ≈ −0.688 to −1 at
    /// t = 3π/2 − 3.9 and rises to sin 5.4 ≈ −0.773: −q's maximum is the
    /// interior minimum of q, and a peak already above every value is left alone.
    #[test]
    fn an_interior_minimum_is_the_maximum_of_the_negative() {
        let q = sine(3.9);
        let swing = q.swing(1.5);
        let mut down = 0.5;
        raise_max(&q, None, -1.0, 1.5, swing, &mut down);
        assert!((down - 1.0).abs() < 1e-15, "max of −q {down}");
        let mut up = f64::NEG_INFINITY;
        raise_max(&q, None, 1.0, 1.5, swing, &mut up);
        assert_eq!(up, 3.9f64.sin());
        let mut high = 1.5;
        raise_abs_max(&q, None, 1.5, swing, &mut high);
        assert_eq!(high, 1.5);
        // Over [0, 0.3] −q only rises: the bound shows it, and the end is the maximum.
        let mut short = 0.5;
        raise_max(&q, None, -1.0, 0.3, q.swing(0.3), &mut short);
        assert_eq!(short, -q.value(0.3));
        assert!((short + 4.2f64.sin()).abs() < 1e-15);
    }
}
