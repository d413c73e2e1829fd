//! The energy balance of a row (SPEC §6 summed over buildings, §13), in J:
//!
//! ```text
//! E_in = −∫ Σ m_i u̇_i ü_g dt,   E_kin = ½ Σ m_i u̇_i²,
//! E_damp = ∫ u̇ᵀC u̇ dt,   E_spring = ∫ Σ V_j Δ̇_j dt,   E_contact = ∫ Σ f_p δ̇ dt,
//! E_bumper = ∫ Σ f_b ċ dt,   E_link = ∫ Σ F_l Δv dt   (SPEC §14),
//! residual = |E_kin + E_damp + E_spring + E_contact + E_bumper + E_link − E_in − E_kin(0)|
//!            / max(max |E_in|, E_kin(0)),
//! ```
//!
//! with E_kin(0) the kinetic energy the floors start with (a type B pulse's
//! ground moving under them, SPEC §9; 0 from rest).
//!
//! The integrals are taken on each Taylor or Runge–Kutta step of the exact
//! method by Gauss–Legendre quadrature: inside a step the motion is one
//! analytic function (fixed configuration), so the rule converges
//! geometrically, to rounding with [`NODES`] points on the steps the series
//! allows. On a map step they are closed forms of the state at its ends
//! ([`super::propagator::WorkForms`]), so that a run with its balance takes
//! the steps of one without it.

use serde::{Deserialize, Serialize};

/// Points of the Gauss–Legendre rule.
pub const NODES: usize = 12;

/// (nodes, weights) of the n-point Gauss–Legendre rule on [−1, 1], by
/// Newton's method on P_n from the Chebyshev guesses.
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            // P_n(z) and P_n'(z) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// The terms of the balance, J.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct RowEnergy {
    pub input: f64,
    pub kinetic: f64,
    pub damping: f64,
    pub spring: f64,
    pub contact: f64,
    /// max over the run of |E_in|.
    pub max_input: f64,
    /// E_kin at t = 0.
    pub initial_kinetic: f64,
    /// Work of the bumpers' contact forces and of the links' forces
    /// (SPEC §14; 0 without them).
    #[serde(default)]
    pub bumper: f64,
    #[serde(default)]
    pub link: f64,
}

impl RowEnergy {
    /// The residual of the balance above.
    pub fn residual(&self) -> f64 {
        (self.kinetic + self.damping + self.spring + self.contact + self.bumper + self.link
            - self.input
            - self.initial_kinetic)
            .abs()
            / self
                .max_input
                .max(self.initial_kinetic)
                .max(f64::MIN_POSITIVE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_of_degree_2n_minus_1_exactly() {
        let (x, w) = gauss_legendre(NODES);
        // ∫₋₁¹ s^22 ds = 2/23.
        let got: f64 = x.iter().zip(&w).map(|(s, w)| w * s.powi(22)).sum();
        assert!((got - 2.0 / 23.0).abs() < 1e-15, "{got}");
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
    }
}
