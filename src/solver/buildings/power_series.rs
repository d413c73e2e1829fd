//! A fluid viscous damper's force as a Taylor series in time (SPEC §14),
//! for the series of the row's motion ([`super::taylor`]).
//!
//! With Δv(s) = Σ_k Δv_k s^k and σ = sgn Δv_0 ≠ 0, the force
//! F = c_l |Δv|^α sgn Δv is c_l σ w(s) with w = x^α, x = σΔv, x_0 > 0:
//! analytic as far as the nearest (complex) zero of Δv, its branch point.
//! From w' x = α x' w, order by order,
//!
//! ```text
//! w_0 = x_0^α,
//! w_k = (1/(k x_0)) Σ_{j=1}^{k} (α j − (k − j)) x_j w_{k−j}   (k ≥ 1),
//! ```
//!
//! explicit in x_0 … x_k: the k-th coefficient of ü needs only Δv_k, which
//! the motion's recurrence has when it forms ü_k. Near the branch point at
//! distance ρ the coefficients fall like ρ^(−k), so the series' own
//! truncation test bounds its step by a fraction of ρ.

use super::damper::Damper;

/// w_k of w = x^α from x_0 … x_k (`x`, x_0 > 0) and w_0 … w_{k−1} (`w`),
/// k = `x.len()` − 1 (the recurrence in the module's doc).
pub fn power_coefficient(x: &[f64], w: &[f64], alpha: f64) -> f64 {
    let k = x.len() - 1;
    if k == 0 {
        return x[0].powf(alpha);
    }
    let kf = k as f64;
    // Σ_{j=1}^{k} (α j − (k − j)) x_j w_{k−j}, j rising.
    let sum: f64 = x[1..]
        .iter()
        .zip(w.iter().rev())
        .zip(1..)
        .map(|((&xj, &wkj), j)| {
            let j = j as f64;
            (alpha * j - (kf - j)) * xj * wkj
        })
        .sum();
    sum / (kf * x[0])
}

/// The dampers' x_k = σΔv_k and w_k, order by order, for one series:
/// each damper's coefficients in a block of `width`, its σ kept.
#[derive(Debug, Default)]
pub struct DamperPowers {
    x: Vec<f64>,
    w: Vec<f64>,
    sign: Vec<f64>,
    width: usize,
}

impl DamperPowers {
    /// Room for `dampers` dampers to order `top`. Every entry up to the
    /// order reached is written before it is read.
    pub fn size(&mut self, dampers: usize, top: usize) {
        self.width = top + 1;
        let len = dampers * self.width;
        for buffer in [&mut self.x, &mut self.w] {
            if buffer.len() < len {
                buffer.resize(len, 0.0);
            }
        }
        self.sign.resize(dampers, 0.0);
    }

    /// F_k = c_l σ w_k of damper `d` (the `index`-th) at order k, from its
    /// Δv_k = u̇_{A,k} − u̇_{B,k}; orders go 0, 1, 2, … in turn. At k = 0,
    /// σ = sgn Δv_0 (Δv_0 ≠ 0: a series is not taken from a reversal).
    #[inline]
    pub fn force(&mut self, index: usize, d: &Damper, k: usize, rate: f64) -> f64 {
        if k == 0 {
            self.sign[index] = if rate < 0.0 { -1.0 } else { 1.0 };
        }
        let sign = self.sign[index];
        let row = index * self.width;
        self.x[row + k] = sign * rate;
        let w = power_coefficient(&self.x[row..=row + k], &self.w[row..row + k], d.exponent);
        self.w[row + k] = w;
        d.damping * sign * w
    }

    /// Appends F_k = c_l σ w_k of damper `d` (the `index`-th), orders 0 to
    /// `width` − 1, all reached in turn by [`DamperPowers::force`].
    pub fn write_forces(&self, index: usize, d: &Damper, width: usize, out: &mut Vec<f64>) {
        let (row, sign) = (index * self.width, self.sign[index]);
        out.extend(
            self.w[row..row + width]
                .iter()
                .map(|w| d.damping * sign * w),
        );
    }
}

#[cfg(test)]
mod tests;
