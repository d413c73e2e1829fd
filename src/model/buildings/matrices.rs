//! Mass, initial stiffness and Rayleigh damping of a row (SPEC §13), and the
//! modes of each building.
//!
//! Storey i joins floors i−1 and i, so the initial stiffness of one building
//! is tridiagonal: `K₀[i][i] = k_i + k_{i+1}`, `K₀[i][i−1] = −k_i` (k_{n+1} = 0).
//! With P-Δ (SPEC §15) each storey loses P_i/h_i of it, the geometric
//! stiffness K_G built as K₀ is; the stiffness below is then K₀ − K_G, the
//! elastic stiffness under gravity, and the modes, periods and Rayleigh
//! coefficients are its own (K_G = 0 without P-Δ).
//! Damping is Rayleigh on K₀ − K_G, C = a₀M + a₁(K₀ − K_G) with a₀ = 2ξω₁ω₂/(ω₁+ω₂),
//! a₁ = 2ξ/(ω₁+ω₂) at the first two modes (ω₂ = ω₁ for one storey, which
//! gives c = 2ξmω₁, SPEC §2). The row's matrices are block diagonal: the
//! buildings couple only through contact.

use nalgebra::{DMatrix, DVector};

use super::row::{Building, Row};

/// The matrices of a row, of size dofs × dofs.
#[derive(Debug, Clone)]
pub struct RowMatrices {
    pub mass: DVector<f64>,
    pub stiffness: DMatrix<f64>,
    pub damping: DMatrix<f64>,
}

/// K₀ − K_G of one building: storey i's elastic stiffness under gravity,
/// k_i − P_i/h_i (SPEC §15; k_i without P-Δ), assembled tridiagonally.
pub fn building_stiffness(b: &Building) -> DMatrix<f64> {
    let n = b.storeys();
    let mut k = DMatrix::zeros(n, n);
    for i in 0..n {
        let ki = b.stiffness[i] - b.geometric_stiffness(i);
        k[(i, i)] += ki;
        if i > 0 {
            k[(i - 1, i - 1)] += ki;
            k[(i, i - 1)] -= ki;
            k[(i - 1, i)] -= ki;
        }
    }
    k
}

/// Circular frequencies ω (rad/s) of one building, lowest first, from the
/// symmetric form M^{−½}K₀M^{−½}.
pub fn circular_frequencies(b: &Building) -> Vec<f64> {
    let mut k = building_stiffness(b);
    let n = b.storeys();
    for i in 0..n {
        for j in 0..n {
            k[(i, j)] /= (b.mass[i] * b.mass[j]).sqrt();
        }
    }
    let mut w: Vec<f64> = k
        .symmetric_eigen()
        .eigenvalues
        .iter()
        .map(|l| l.max(0.0).sqrt())
        .collect();
    w.sort_by(f64::total_cmp);
    w
}

/// Periods T = 2π/ω (s) of one building, longest first.
pub fn periods(b: &Building) -> Vec<f64> {
    circular_frequencies(b)
        .iter()
        .map(|w| 2.0 * std::f64::consts::PI / w)
        .collect()
}

/// Free vibration after a row's ground motion, unless asked otherwise:
/// four times the longest fundamental period of its buildings (s), so that
/// the slowest building's response after the motion is in the peaks.
pub fn default_tail(row: &Row) -> f64 {
    let longest = row
        .buildings
        .iter()
        .map(|b| periods(b)[0])
        .fold(0.0, f64::max);
    4.0 * longest
}

/// Rayleigh coefficients (a₀, a₁) of one building.
pub fn rayleigh(b: &Building) -> (f64, f64) {
    let w = circular_frequencies(b);
    let w1 = w[0];
    let w2 = *w.get(1).unwrap_or(&w1);
    let xi = b.damping;
    (2.0 * xi * w1 * w2 / (w1 + w2), 2.0 * xi / (w1 + w2))
}

impl RowMatrices {
    pub fn of(row: &Row) -> RowMatrices {
        let n = row.dofs();
        let mut mass = DVector::zeros(n);
        let mut stiffness = DMatrix::zeros(n, n);
        let mut damping = DMatrix::zeros(n, n);
        for (b, &o) in row.buildings.iter().zip(&row.offsets()) {
            let m = b.storeys();
            let k = building_stiffness(b);
            let (a0, a1) = rayleigh(b);
            for i in 0..m {
                mass[o + i] = b.mass[i];
                for j in 0..m {
                    stiffness[(o + i, o + j)] = k[(i, j)];
                    damping[(o + i, o + j)] = a1 * k[(i, j)];
                }
                damping[(o + i, o + i)] += a0 * b.mass[i];
            }
        }
        RowMatrices {
            mass,
            stiffness,
            damping,
        }
    }
}
