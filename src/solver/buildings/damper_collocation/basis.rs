//! The collocation's polynomials in s over a step of length h (SPEC §14):
//! the Lagrange basis on the Radau IIA nodes, the node polynomial π, and
//! the forces' collocated polynomials and defect models written in powers
//! of s.

use nalgebra::DVector;

use super::{MODEL, NODES, POWERS, STAGES};

/// ℓ_j(θ), the Lagrange basis on the nodes.
pub(super) fn lagrange(j: usize, theta: f64) -> f64 {
    (0..STAGES)
        .filter(|&k| k != j)
        .map(|k| (theta - NODES[k]) / (NODES[j] - NODES[k]))
        .product()
}

/// Π_k (θ − r_k) over `roots`, in powers of θ.
fn expanded<const N: usize>(roots: impl Iterator<Item = f64>) -> [f64; N] {
    let mut p = [0.0; N];
    p[0] = 1.0;
    for (degree, r) in roots.enumerate() {
        // p ← (θ − r) p, p of degree `degree` so far.
        for k in (0..=degree + 1).rev() {
            let below = if k > 0 { p[k - 1] } else { 0.0 };
            p[k] = below - r * p[k];
        }
    }
    p
}

/// θ^k = (s/h)^k: each coefficient of θ^k over h^k.
fn in_powers_of_s<const N: usize>(mut p: [f64; N], h: f64) -> [f64; N] {
    let mut scale = 1.0;
    for c in p.iter_mut() {
        *c *= scale;
        scale /= h;
    }
    p
}

/// The Lagrange polynomial ℓ_j(s/h) in powers of s, of degree
/// [`STAGES`] − 1.
pub(super) fn basis(j: usize, h: f64) -> [f64; STAGES] {
    let others = (0..STAGES).filter(|&k| k != j).map(|k| NODES[k]);
    let w: f64 = (0..STAGES)
        .filter(|&k| k != j)
        .map(|k| 1.0 / (NODES[j] - NODES[k]))
        .product();
    let mut p: [f64; STAGES] = expanded(others);
    for c in p.iter_mut() {
        *c *= w;
    }
    in_powers_of_s(p, h)
}

/// The node polynomial π(θ) = Π_i (θ − c_i), θ = s/h, in powers of s:
/// zero at every node.
pub(super) fn node_polynomial(h: f64) -> [f64; STAGES + 1] {
    in_powers_of_s(expanded(NODES.into_iter()), h)
}

/// π(θ) at θ.
pub(super) fn node_value(theta: f64) -> f64 {
    NODES.iter().map(|c| theta - c).product()
}

/// Element e's collocated polynomial Σ_j X_{e,j} ℓ_j(s/h) in powers of s.
pub(super) fn collocated(x: &DVector<f64>, ne: usize, e: usize, h: f64) -> [f64; POWERS] {
    let mut p = [0.0; POWERS];
    for j in 0..STAGES {
        for (p, b) in p.iter_mut().zip(basis(j, h)) {
            *p += x[j * ne + e] * b;
        }
    }
    p
}

/// The defect model's polynomial (κ + Σ_q a_q θ^q) π(θ), θ = s/h, with
/// `slope` = (a_1, …, a_{S−1}), in powers of s.
pub(super) fn defect_polynomial(kappa: f64, slope: [f64; MODEL], h: f64) -> [f64; POWERS] {
    let mut p = [0.0; POWERS];
    let pi = node_polynomial(h);
    let mut scale = 1.0;
    for q in 0..=MODEL {
        let a = if q == 0 { kappa } else { slope[q - 1] };
        for (k, c) in pi.iter().enumerate() {
            p[k + q] += a * scale * c;
        }
        scale /= h;
    }
    p
}
