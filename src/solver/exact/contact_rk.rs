//! Contact phases under the Hertz-type laws (SPEC §10), by an embedded
//! Runge–Kutta pair.
//!
//! With f_p = K δ^{3/2}(…) and δ ≈ v₀ t just after onset, the motion holds
//! terms in t^{7/2}: it is not analytic at onset (nor at separation), so the
//! Taylor recurrence of [`super::dynamics`] cannot carry it. Instead each
//! contact segment is one step of the Dormand–Prince 5(4) pair on
//! y = (x1, ẋ1, x2, ẋ2),
//!
//! ```text
//! m_i ẍ_i = Q_i − K_i x_i − c_i ẋ_i ∓ f_p(δ, δ̇) − m_i g(τ),
//! ```
//!
//! (each spring affine on its branch, as out of contact), with its error
//! held below `tolerance` times the contact's own scales: δ ~ v₀/Π_ωcon for
//! displacements and v₀ for velocities. The accepted step becomes a segment
//! of the event-driven method like any other: x_i as the quintic Hermite
//! polynomial through (x, ẋ, ẍ) at both ends (error O(h⁶), below the step's
//! own), f_p as the quintic through six equally spaced values of the law on
//! it, so separation, yield and unloading, peaks, samples and work are found
//! on polynomials by the method's own machinery.

use crate::model::ContactLaw;
use crate::numerics::dopri5::{self, Vector};

use super::dynamics::{Branch, Structure};
use super::series::Series;

/// Smallest relative tolerance asked of the pair: below about 1e-11 of the
/// contact scale, round-off in x (of order 1) dominates the error estimate.
pub const SMALLEST_TOLERANCE: f64 = 1e-11;

/// One accepted step of the contact phase.
pub struct Piece {
    /// x1, x2 on [0, h] (degree 5).
    pub x: [Series; 2],
    /// f_p on [0, h] (degree 5).
    pub force: Series,
    /// Step length.
    pub h: f64,
    /// Suggested length of the next step.
    pub next: f64,
}

/// The coupled system in contact on fixed branches.
pub struct ContactSystem<'a> {
    pub structures: &'a [Structure; 2],
    pub branch: [Branch; 2],
    pub gap: f64,
    pub law: &'a ContactLaw,
    /// g about the segment's start (exact up to the excitation's next break).
    pub ground: &'a Series,
}

impl ContactSystem<'_> {
    fn force(&self, y: &Vector) -> f64 {
        self.law.force(y[0] - y[2] - self.gap, y[1] - y[3]).force
    }

    /// ẏ at offset t from the segment's start.
    fn rate(&self, t: f64, y: &Vector) -> Vector {
        let g = self.ground.value(t);
        let fp = self.force(y);
        let mut out = [0.0; 4];
        for i in 0..2 {
            let s = &self.structures[i];
            let (k, q) = s.affine(self.branch[i]);
            let push = if i == 0 { -fp } else { fp };
            let (x, v) = (y[2 * i], y[2 * i + 1]);
            out[2 * i] = v;
            out[2 * i + 1] = (q - k * x - s.damping * v + push) / s.mass - g;
        }
        out
    }

    /// One accepted step from (x, v), at most `h_max` long, starting from the
    /// suggestion `h_try` and shrinking it until the error is within
    /// `tolerance` of the scales (`delta_scale` for x, `velocity_scale` for ẋ).
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &self,
        x: [f64; 2],
        v: [f64; 2],
        h_try: f64,
        h_max: f64,
        tolerance: f64,
        delta_scale: f64,
        velocity_scale: f64,
    ) -> Piece {
        let y0 = [x[0], v[0], x[1], v[1]];
        let f0 = self.rate(0.0, &y0);
        let tol = tolerance.max(SMALLEST_TOLERANCE);
        let mut h = h_try.min(h_max);
        loop {
            let step = dopri5::step(&|t, y| self.rate(t, y), 0.0, &y0, &f0, h);
            let err = (0..4)
                .map(|i| {
                    let scale = if i % 2 == 0 {
                        delta_scale
                    } else {
                        velocity_scale
                    };
                    (step.error[i] / (tol * scale)).abs()
                })
                .fold(0.0, f64::max);
            let factor = if err > 0.0 {
                (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
            } else {
                5.0
            };
            // Round-off floor on h: accept rather than shrink without end.
            if err <= 1.0 || h < 1e-14 * h_max.min(1.0) {
                return self.piece(&y0, &f0, &step.y1, &step.f1, h, h * factor);
            }
            h *= factor.min(0.9);
        }
    }

    fn piece(
        &self,
        y0: &Vector,
        f0: &Vector,
        y1: &Vector,
        f1: &Vector,
        h: f64,
        next: f64,
    ) -> Piece {
        let x = [0, 1].map(|i| {
            hermite_quintic(
                [y0[2 * i], y0[2 * i + 1], f0[2 * i + 1]],
                [y1[2 * i], y1[2 * i + 1], f1[2 * i + 1]],
                h,
            )
        });
        // f_p at six equally spaced instants of the step, on the polynomials.
        let mut values = [0.0; 6];
        for (j, value) in values.iter_mut().enumerate() {
            let t = h * j as f64 / 5.0;
            let (x1, v1) = x[0].value_slope(t);
            let (x2, v2) = x[1].value_slope(t);
            *value = self.force(&[x1, v1, x2, v2]);
        }
        Piece {
            x,
            force: equispaced_quintic(&values, h),
            h,
            next,
        }
    }
}

/// The quintic p on [0, h] with p, p', p'' given at both ends:
/// with s = t/h, p = x₀ + v₀hs + ½a₀h²s² + A s³ + B s⁴ + C s⁵, where
/// R₀ = x₁ − x₀ − v₀h − ½a₀h², R₁ = h(v₁ − v₀) − a₀h², R₂ = h²(a₁ − a₀) and
/// A = 10R₀ − 4R₁ + ½R₂, B = −15R₀ + 7R₁ − R₂, C = 6R₀ − 3R₁ + ½R₂.
pub fn hermite_quintic([x0, v0, a0]: [f64; 3], [x1, v1, a1]: [f64; 3], h: f64) -> Series {
    let r0 = x1 - x0 - v0 * h - 0.5 * a0 * h * h;
    let r1 = h * (v1 - v0) - a0 * h * h;
    let r2 = h * h * (a1 - a0);
    let a = 10.0 * r0 - 4.0 * r1 + 0.5 * r2;
    let b = -15.0 * r0 + 7.0 * r1 - r2;
    let c = 6.0 * r0 - 3.0 * r1 + 0.5 * r2;
    let mut s = Series {
        degree: 5,
        ..Series::default()
    };
    let h3 = h * h * h;
    s.c[0] = x0;
    s.c[1] = v0;
    s.c[2] = 0.5 * a0;
    s.c[3] = a / h3;
    s.c[4] = b / (h3 * h);
    s.c[5] = c / (h3 * h * h);
    s
}

/// The quintic through `values` at t = 0, h/5, …, h: Newton's forward
/// differences in s = 5t/h, expanded into powers of t.
#[allow(clippy::needless_range_loop)]
pub fn equispaced_quintic(values: &[f64; 6], h: f64) -> Series {
    // Forward differences Δᵏ y₀.
    let mut d = *values;
    let mut diff = [0.0; 6];
    for k in 0..6 {
        diff[k] = d[0];
        for j in 0..5 - k {
            d[j] = d[j + 1] - d[j];
        }
    }
    // p(s) = Σ Δᵏy₀ C(s, k); build the falling factorials s(s−1)…(s−k+1)/k! in powers of s.
    let mut poly = [0.0; 6];
    let mut basis = [0.0; 6];
    basis[0] = 1.0;
    for k in 0..6 {
        for j in 0..6 {
            poly[j] += diff[k] * basis[j];
        }
        if k < 5 {
            // basis ← basis · (s − k)/(k + 1).
            let mut next = [0.0; 6];
            for j in 0..6 {
                if j + 1 < 6 {
                    next[j + 1] += basis[j];
                }
                next[j] -= k as f64 * basis[j];
            }
            for (b, n) in basis.iter_mut().zip(next) {
                *b = n / (k + 1) as f64;
            }
        }
    }
    let mut s = Series {
        degree: 5,
        ..Series::default()
    };
    let unit = 5.0 / h;
    let mut scale = 1.0;
    for j in 0..6 {
        s.c[j] = poly[j] * scale;
        scale *= unit;
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_quintic_reproduces_a_quintic() {
        let p =
            |t: f64| 1.0 - 2.0 * t + 0.5 * t * t + 3.0 * t.powi(3) - t.powi(4) + 0.7 * t.powi(5);
        let dp = |t: f64| -2.0 + t + 9.0 * t * t - 4.0 * t.powi(3) + 3.5 * t.powi(4);
        let ddp = |t: f64| 1.0 + 18.0 * t - 12.0 * t * t + 14.0 * t.powi(3);
        let h = 0.7;
        let s = hermite_quintic([p(0.0), dp(0.0), ddp(0.0)], [p(h), dp(h), ddp(h)], h);
        for k in 0..=10 {
            let t = h * k as f64 / 10.0;
            assert!((s.value(t) - p(t)).abs() < 1e-13, "{t}");
        }
    }

    #[test]
    fn equispaced_quintic_reproduces_a_quintic() {
        let p = |t: f64| 0.3 + t - 4.0 * t.powi(2) + 2.0 * t.powi(3) + t.powi(4) - 5.0 * t.powi(5);
        let h = 0.25;
        let values = std::array::from_fn(|j| p(h * j as f64 / 5.0));
        let s = equispaced_quintic(&values, h);
        for k in 0..=10 {
            let t = h * k as f64 / 10.0;
            assert!((s.value(t) - p(t)).abs() < 1e-14, "{t}");
        }
    }
}
