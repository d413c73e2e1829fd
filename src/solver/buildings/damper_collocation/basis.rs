//! The collocation's polynomials in s over a step of length h (SPEC §14):
//! the Lagrange basis on the Radau IIA nodes, the node polynomial π, and
//! the forces' quadratics and defect models written in powers of s.

use nalgebra::DVector;

use super::{NODES, POWERS};

/// ℓ_j(θ), the Lagrange basis on the nodes.
pub(super) fn lagrange(j: usize, theta: f64) -> f64 {
    (0..3)
        .filter(|&k| k != j)
        .map(|k| (theta - NODES[k]) / (NODES[j] - NODES[k]))
        .product()
}

/// The quadratic ℓ_j(s/h) in powers of s.
pub(super) fn basis(j: usize, h: f64) -> [f64; 4] {
    let (a, b) = match j {
        0 => (NODES[1], NODES[2]),
        1 => (NODES[0], NODES[2]),
        _ => (NODES[0], NODES[1]),
    };
    let w = 1.0 / ((NODES[j] - a) * (NODES[j] - b));
    // (θ − a)(θ − b) w, θ = s/h.
    [a * b * w, -(a + b) * w / h, w / (h * h), 0.0]
}

/// The node polynomial π(θ) = (θ − c₁)(θ − c₂)(θ − 1), θ = s/h, in powers
/// of s: zero at every node.
pub(super) fn node_polynomial(h: f64) -> [f64; 4] {
    let [a, b, _] = NODES;
    [
        -a * b,
        (a * b + a + b) / h,
        -(a + b + 1.0) / (h * h),
        1.0 / (h * h * h),
    ]
}

/// Element e's quadratic Σ_j X_{e,j} ℓ_j(s/h) in powers of s.
pub(super) fn quadratic(x: &DVector<f64>, ne: usize, e: usize, h: f64) -> [f64; POWERS] {
    let mut p = [0.0; POWERS];
    for j in 0..3 {
        for (p, b) in p.iter_mut().zip(basis(j, h)) {
            *p += x[j * ne + e] * b;
        }
    }
    p
}

/// The defect model's polynomial (κ + λθ + μθ²)π(θ), θ = s/h, in powers
/// of s.
pub(super) fn defect_polynomial(kappa: f64, [lambda, mu]: [f64; 2], h: f64) -> [f64; POWERS] {
    let mut p = [0.0; POWERS];
    for (k, q) in node_polynomial(h).into_iter().enumerate() {
        p[k] += kappa * q;
        p[k + 1] += lambda / h * q;
        p[k + 2] += mu / (h * h) * q;
    }
    p
}
