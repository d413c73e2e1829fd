//! The collocation's polynomials in s over a step of length h (SPEC §14):
//! the Lagrange basis on the Radau IIA nodes, the node polynomial π, and
//! the forces' collocated polynomials and defect models written in powers
//! of s.

use nalgebra::DVector;

use super::{MODEL, NODES, POWERS, STAGES};

/// ℓ_j(θ), the Lagrange basis on the nodes: Π_{k≠j} (θ − c_k)/(c_j − c_k),
/// the factors taken in order of k. A constant function, so that its
/// values at the fixed points of a step (its start, the defect model's
/// θ, the halves' nodes) are tables made once, to the bit the values it
/// gives at run time.
pub(super) const fn lagrange(j: usize, theta: f64) -> f64 {
    let mut product = 1.0;
    let mut k = 0;
    while k < STAGES {
        if k != j {
            product *= (theta - NODES[k]) / (NODES[j] - NODES[k]);
        }
        k += 1;
    }
    product
}

/// ℓ_j(θ_p) of every j at each point θ_p of `points` (row p).
pub(super) const fn lagrange_at<const P: usize>(points: [f64; P]) -> [[f64; STAGES]; P] {
    let mut table = [[0.0; STAGES]; P];
    let mut p = 0;
    while p < P {
        let mut j = 0;
        while j < STAGES {
            table[p][j] = lagrange(j, points[p]);
            j += 1;
        }
        p += 1;
    }
    table
}

/// Π (θ − c_k) over the nodes k other than `skip` (none where it is
/// [`STAGES`]), in order of k, in powers of θ.
const fn expanded<const N: usize>(skip: usize) -> [f64; N] {
    let mut p = [0.0; N];
    p[0] = 1.0;
    let mut degree = 0;
    let mut root = 0;
    while root < STAGES {
        if root != skip {
            // p ← (θ − c) p, p of degree `degree` so far.
            let r = NODES[root];
            let mut k = degree + 1;
            loop {
                let below = if k > 0 { p[k - 1] } else { 0.0 };
                p[k] = below - r * p[k];
                if k == 0 {
                    break;
                }
                k -= 1;
            }
            degree += 1;
        }
        root += 1;
    }
    p
}

/// The Lagrange basis ℓ_j(θ) in powers of θ (row j): Π_{k≠j} (θ − c_k)
/// expanded, times Π_{k≠j} 1/(c_j − c_k).
const THETA_BASIS: [[f64; STAGES]; STAGES] = {
    let mut table = [[0.0; STAGES]; STAGES];
    let mut j = 0;
    while j < STAGES {
        let mut w = 1.0;
        let mut k = 0;
        while k < STAGES {
            if k != j {
                w *= 1.0 / (NODES[j] - NODES[k]);
            }
            k += 1;
        }
        let p: [f64; STAGES] = expanded(j);
        let mut q = 0;
        while q < STAGES {
            table[j][q] = p[q] * w;
            q += 1;
        }
        j += 1;
    }
    table
};

/// π(θ) in powers of θ.
const THETA_NODE_POLYNOMIAL: [f64; STAGES + 1] = expanded(STAGES);

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
    in_powers_of_s(THETA_BASIS[j], h)
}

/// The node polynomial π(θ) = Π_i (θ − c_i), θ = s/h, in powers of s:
/// zero at every node.
pub(super) fn node_polynomial(h: f64) -> [f64; STAGES + 1] {
    in_powers_of_s(THETA_NODE_POLYNOMIAL, h)
}

/// π(θ) at θ, the factors in order of the nodes (constant, as [`lagrange`]).
pub(super) const fn node_value(theta: f64) -> f64 {
    let mut product = 1.0;
    let mut k = 0;
    while k < STAGES {
        product *= theta - NODES[k];
        k += 1;
    }
    product
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

/// Element e's force over the step: its collocated polynomial
/// ([`collocated`]) plus `model` (its defect model, or the forces' answer
/// to it), in powers of s.
pub(super) fn corrected(
    x: &DVector<f64>,
    ne: usize,
    e: usize,
    h: f64,
    model: &[f64; POWERS],
) -> [f64; POWERS] {
    let mut p = collocated(x, ne, e, h);
    for (p, q) in p.iter_mut().zip(model) {
        *p += q;
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
