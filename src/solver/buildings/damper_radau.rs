//! The implicit step of a row whose fluid viscous damper is stiff (SPEC §14):
//! the 3-stage Radau IIA method (order 5, stiffly accurate, L-stable;
//! Hairer & Wanner, *Solving ODEs II*, §IV.5), with each damper's force
//! F an unknown beside the velocities and its law written the other way
//! round, as Newmark writes it ([`super::newmark`]):
//!
//! ```text
//! Δv = ψ(F) = sgn F (|F|/c_l)^(1/α),   ψ'(F) = (|F|/c_l)^(1/α − 1)/(α c_l),
//! ```
//!
//! smooth with a bounded slope where F = 0, where c_l|Δv|^α has none.
//! With U_i = u₀ + h Σ_j a_ij V_j, each stage i solves
//!
//! ```text
//! V_i = v₀ + h Σ_j a_ij a(t₀ + c_j h, U_j, V_j, F_j),   ψ(F_{i,d}) = Δv_d(V_i),
//! ```
//!
//! a(…) the row's acceleration with the dampers' forces F (the linear
//! system's, each closed Hertz-type pair's), by Newton's method on all
//! stages at once, the Jacobian from M⁻¹K, M⁻¹C, the dampers' G = ∂a/∂F and
//! ψ'. The end is the last stage. Where a damper is stiff (its relaxation
//! time m̄/(c_l α |Δv|^(α−1)) shorter than the step, as from rest, where
//! the force across it is small and Δv sits on its slow manifold
//! Δv ≈ ψ(m̄ f)), an explicit step is held to that time by stability; this
//! one is not. Its local error is estimated by step doubling:
//! (y_h − y_{h/2,h/2})/(2⁵ − 1).

use nalgebra::{DMatrix, DVector};

use super::damper::Damper;
use crate::model::buildings::retrofit::{dashpot_velocity, dashpot_velocity_slope};

/// Newton iterations at most on one step's stages.
const NEWTON: usize = 50;

const SQ6: f64 = 2.449_489_742_783_178;

/// The stages' nodes c_i and matrix a_ij of Radau IIA, 3 stages.
pub const C: [f64; 3] = [(4.0 - SQ6) / 10.0, (4.0 + SQ6) / 10.0, 1.0];
pub const A: [[f64; 3]; 3] = [
    [
        (88.0 - 7.0 * SQ6) / 360.0,
        (296.0 - 169.0 * SQ6) / 1800.0,
        (-2.0 + 3.0 * SQ6) / 225.0,
    ],
    [
        (296.0 + 169.0 * SQ6) / 1800.0,
        (88.0 + 7.0 * SQ6) / 360.0,
        (-2.0 - 3.0 * SQ6) / 225.0,
    ],
    [(16.0 - SQ6) / 36.0, (16.0 + SQ6) / 36.0, 1.0 / 9.0],
];

/// Δv = ψ(F), the damper's law the other way round.
fn inverse_law(d: &Damper, force: f64) -> f64 {
    dashpot_velocity(d.damping, d.exponent, force)
}

/// ψ'(F) ≥ 0.
fn inverse_slope(d: &Damper, force: f64) -> f64 {
    dashpot_velocity_slope(d.damping, d.exponent, force)
}

/// ü at offset s from (u, u̇) with the dampers' forces F given, into the
/// last argument: (s, u, u̇, F, ü).
pub type Acceleration<'a> = &'a dyn Fn(f64, &[f64], &[f64], &[f64], &mut [f64]);

/// What the step needs of the row: its acceleration with the dampers'
/// forces given, M⁻¹K and M⁻¹C, and the dampers.
pub struct Row<'a> {
    pub acceleration: Acceleration<'a>,
    pub stiffness: &'a DMatrix<f64>,
    pub damping: &'a DMatrix<f64>,
    pub dampers: &'a [Damper],
}

/// One Radau IIA step of length h from (u₀, u̇₀) = y0, the dampers'
/// forces starting at `forces`: the end y₁ = (u, u̇), or None when Newton's
/// method did not converge (to 1e-15 of `speed`, the motion's velocity
/// scale, and of each damper's force at that speed).
pub fn step(row: &Row, y0: &[f64], forces: &[f64], h: f64, speed: f64) -> Option<Vec<f64>> {
    let n = y0.len() / 2;
    let nd = row.dampers.len();
    let m = n + nd;
    let (u0, v0) = y0.split_at(n);
    // A² for U's dependence on V: ∂U_j/∂V_k = h a_jk.
    let mut a2 = [[0.0; 3]; 3];
    for i in 0..3 {
        for k in 0..3 {
            a2[i][k] = (0..3).map(|j| A[i][j] * A[j][k]).sum();
        }
    }
    // The unknowns (V_i, F_i), stage by stage; first guess: the start.
    let mut z = DVector::<f64>::zeros(3 * m);
    for i in 0..3 {
        z.rows_mut(i * m, n).copy_from_slice(v0);
        z.rows_mut(i * m + n, nd).copy_from_slice(forces);
    }
    let mut us = vec![vec![0.0; n]; 3];
    let mut acc = vec![vec![0.0; n]; 3];
    let mut residual = DVector::<f64>::zeros(3 * m);
    let mut jacobian = DMatrix::<f64>::zeros(3 * m, 3 * m);
    for _ in 0..NEWTON {
        for i in 0..3 {
            for (r, u) in us[i].iter_mut().enumerate() {
                *u = u0[r] + h * (0..3).map(|j| A[i][j] * z[j * m + r]).sum::<f64>();
            }
            let v = z.rows(i * m, n);
            let f = z.rows(i * m + n, nd);
            (row.acceleration)(C[i] * h, &us[i], v.as_slice(), f.as_slice(), &mut acc[i]);
        }
        for i in 0..3 {
            for r in 0..n {
                residual[i * m + r] =
                    z[i * m + r] - v0[r] - h * (0..3).map(|j| A[i][j] * acc[j][r]).sum::<f64>();
            }
            for (k, d) in row.dampers.iter().enumerate() {
                let rate = z[i * m + d.left] - z[i * m + d.right];
                residual[i * m + n + k] = inverse_law(d, z[i * m + n + k]) - rate;
            }
        }
        jacobian.fill(0.0);
        for i in 0..3 {
            for k in 0..3 {
                let mut block = jacobian.view_mut((i * m, k * m), (n, n));
                block -= row.damping * (-h * A[i][k]);
                block -= row.stiffness * (-h * h * a2[i][k]);
                if i == k {
                    for r in 0..n {
                        block[(r, r)] += 1.0;
                    }
                }
                // ∂a/∂F: −F/m_A at A, +F/m_B at B.
                for (q, d) in row.dampers.iter().enumerate() {
                    jacobian[(i * m + d.left, k * m + n + q)] += h * A[i][k] * d.left_rate;
                    jacobian[(i * m + d.right, k * m + n + q)] -= h * A[i][k] * d.right_rate;
                }
            }
            for (q, d) in row.dampers.iter().enumerate() {
                let r = i * m + n + q;
                jacobian[(r, i * m + d.left)] -= 1.0;
                jacobian[(r, i * m + d.right)] += 1.0;
                jacobian[(r, r)] += inverse_slope(d, z[r]);
            }
        }
        let delta = jacobian.clone().lu().solve(&residual)?;
        z -= &delta;
        let converged = (0..3).all(|i| {
            (0..n).all(|r| delta[i * m + r].abs() <= 1e-15 * speed)
                && row.dampers.iter().enumerate().all(|(q, d)| {
                    delta[i * m + n + q].abs() <= 1e-15 * d.damping * speed.powf(d.exponent)
                })
        });
        if converged {
            let mut y1 = vec![0.0; 2 * n];
            for r in 0..n {
                y1[r] = u0[r] + h * (0..3).map(|j| A[2][j] * z[j * m + r]).sum::<f64>();
                y1[n + r] = z[2 * m + r];
            }
            return Some(y1);
        }
    }
    None
}
