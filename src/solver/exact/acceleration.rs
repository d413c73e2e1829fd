//! The peak absolute acceleration A_i = max |ẍ_i + g| (SPEC §6, demands)
//! on a segment's series.
//!
//! On a branch with m ẍ + c ẋ + K x = Q − m g ∓ f_p (SPEC §2–3, f_p acting
//! leftwards on structure 1 and rightwards on 2), the absolute acceleration
//! is a function of the state and the pounding force alone,
//!
//! ```text
//! ẍ + g = (Q − c ẋ − K x ∓ f_p) / m,
//! ```
//!
//! so on a segment it is a series too: the same combination of the series
//! of x, ẋ and (in contact) f_p. It does not jump where g does; it jumps
//! only with f_p (a Kelvin contact's onset and separation), and the
//! segments on either side of such an instant hold its two one-sided values
//! at their ends. Its peak is located as Π_u's and Π_v's are
//! ([`super::peaks`]), after a bound that clears most segments at the cost
//! of a few products: |ẍ + g − (ẍ + g)₀| ≤ (c S_ẋ + K S_x + S_f)/m, S the
//! swings of ẋ, x and f_p over the segment.

use super::dynamics::{Branch, Structure};
use super::peaks::raise_abs_max;
use super::series::Series;

/// The sign with which f_p enters m(ẍ_i + g): − on structure 1 (index 0),
/// + on structure 2 (SPEC §2).
#[inline(always)]
pub fn push(i: usize) -> f64 {
    if i == 0 { -1.0 } else { 1.0 }
}

/// Raises `peak` to the maximum of |ẍ_i + g| over (0, length] of a segment
/// with the series `x` and `v` of structure `i`'s x and ẋ, whose swings over
/// the segment are `swing_x` and `swing_v`, on `branch`, and in contact the
/// series of f_p with its swing.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn raise_absolute_acceleration(
    s: &Structure,
    branch: Branch,
    i: usize,
    x: &Series,
    v: &Series,
    [swing_x, swing_v]: [f64; 2],
    force: Option<(&Series, f64)>,
    length: f64,
    peak: &mut f64,
) {
    let (k, q) = s.affine(branch);
    let inv_m = 1.0 / s.mass;
    let (f0, swing_f) = force.map_or((0.0, 0.0), |(f, sf)| (f.c[0], sf));
    let sign = push(i);
    let start = (q - s.damping * v.c[0] - k * x.c[0] + sign * f0) * inv_m;
    let swing = (s.damping * swing_v + k * swing_x + swing_f) * inv_m;
    *peak = peak.max(start.abs());
    // Cleared by the bound: no value on the segment can beat the peak.
    if start.abs() + swing <= *peak {
        return;
    }
    let mut a = Series {
        degree: x.degree.max(v.degree),
        ..Series::default()
    };
    if let Some((f, _)) = force {
        a.degree = a.degree.max(f.degree);
    }
    for (j, c) in a.c[..=a.degree].iter_mut().enumerate() {
        let xj = if j <= x.degree { x.c[j] } else { 0.0 };
        let vj = if j <= v.degree { v.c[j] } else { 0.0 };
        let fj = match force {
            Some((f, _)) if j <= f.degree => f.c[j],
            _ => 0.0,
        };
        *c = (-s.damping * vj - k * xj + sign * fj) * inv_m;
    }
    a.c[0] = start;
    // The series' own swing is at most the bound (triangle inequality).
    raise_abs_max(&a, None, length, swing * (1.0 + 1e-12), peak);
}

/// Cubic majorant of ẍ + g over a quiet segment from the cubic majorants
/// `x` and `v` of x and ẋ ([`super::quiet::Majorants`]), for a branch with
/// K/m = `stiffness`, c/m = `damping` and Q/m = `load`: ẍ + g = Q/m −
/// (c/m) ẋ − (K/m) x is linear, so its Taylor part is the same combination of
/// theirs and its remainder bound the sum of theirs, weighted by |c/m| and |K/m|.
#[inline]
pub fn majorant(x: &[f64; 4], v: &[f64; 4], stiffness: f64, damping: f64, load: f64) -> [f64; 4] {
    [
        load - damping * v[0] - stiffness * x[0],
        -damping * v[1] - stiffness * x[1],
        -damping * v[2] - stiffness * x[2],
        damping * v[3] + stiffness * x[3],
    ]
}
