//! The matrix exponential of the maps (SPEC §13): its Taylor polynomial
//! on X/2ˢ, squared s times.
//!
//! With ‖X/2ˢ‖₁ = ν ≤ 1/2, the truncation of eˣ after the power 16 is at
//! most ν¹⁷/17! · e^ν ≤ 4e-20 of ‖e^{X/2ˢ}‖ (≥ e^{−ν}), far below the
//! round-off, and the polynomial is evaluated by Paterson and Stockmeyer's
//! scheme in X⁴: with X², X³ and X⁴ made once,
//!
//! ```text
//! T(X) = B₀ + X⁴(B₁ + X⁴(B₂ + X⁴(B₃ + X⁴B₄))),   B_j = Σ_{i<4} Xⁱ/(4j + i)!,  B₄ = I/16!,
//! ```
//!
//! seven products in all. The maps take the exponential of the scaled
//! augmented matrix over a sixteenth of a sub-step ([`super::bound`]),
//! whose norm is below one, so s is 0 or 1. Products are all it takes:
//! a Padé approximant (nalgebra's `exp`) needs fewer of them but an LU
//! solve with as many right-hand sides as rows, which at the rows' sizes
//! costs more than twenty products.

//!
//! The augmented matrices of the maps are block upper triangular,
//! [[X, Y], [0, Z]] with X the 2n × 2n block of (u, u̇) (nothing moves from
//! the motion into the ground or the load), and so is every polynomial in
//! them and their exponential:
//!
//! ```text
//! [[X₁, Y₁], [0, Z₁]] · [[X₂, Y₂], [0, Z₂]] = [[X₁X₂, X₁Y₂ + Y₁Z₂], [0, Z₁Z₂]],
//! ```
//!
//! so [`exponential_blocks`] takes the same polynomial and squarings on the
//! three blocks, about half the work of whole products at the rows' sizes.

use nalgebra::DMatrix;

/// Largest ‖X/2ˢ‖₁ the polynomial takes.
const REACH: f64 = 0.5;
/// Degree of the Taylor polynomial.
const DEGREE: usize = 16;

/// A block upper-triangular matrix [[X, Y], [0, Z]], X and Z square.
#[derive(Debug, Clone, PartialEq)]
pub struct Blocks {
    pub x: DMatrix<f64>,
    pub y: DMatrix<f64>,
    pub z: DMatrix<f64>,
}

impl Blocks {
    /// The blocks of `m` with X its leading `t` × `t` block; the block
    /// below X must be zero.
    pub fn of(m: &DMatrix<f64>, t: usize) -> Blocks {
        let b = m.nrows() - t;
        debug_assert!(m.view((t, 0), (b, t)).iter().all(|&e| e == 0.0));
        Blocks {
            x: m.view((0, 0), (t, t)).clone_owned(),
            y: m.view((0, t), (t, b)).clone_owned(),
            z: m.view((t, t), (b, b)).clone_owned(),
        }
    }

    fn identity(t: usize, b: usize) -> Blocks {
        Blocks {
            x: DMatrix::identity(t, t),
            y: DMatrix::zeros(t, b),
            z: DMatrix::identity(b, b),
        }
    }

    /// The product self · other, block by block.
    pub fn mul(&self, other: &Blocks) -> Blocks {
        Blocks {
            x: &self.x * &other.x,
            y: &self.x * &other.y + &self.y * &other.z,
            z: &self.z * &other.z,
        }
    }

    /// Σ cₖ Mₖ over the terms (cₖ, Mₖ).
    fn sum(terms: &[(f64, &Blocks)]) -> Blocks {
        let mut out = terms[0].1.scaled(terms[0].0);
        for &(c, m) in &terms[1..] {
            out.x += &m.x * c;
            out.y += &m.y * c;
            out.z += &m.z * c;
        }
        out
    }

    fn scaled(&self, c: f64) -> Blocks {
        Blocks {
            x: &self.x * c,
            y: &self.y * c,
            z: &self.z * c,
        }
    }

    /// ‖·‖₁: the largest column sum of |entries|.
    fn norm1(&self) -> f64 {
        let sums = |m: &DMatrix<f64>| m.column_iter().map(|c| c.abs().sum()).collect::<Vec<_>>();
        let left = sums(&self.x).into_iter();
        let right = sums(&self.y)
            .into_iter()
            .zip(sums(&self.z))
            .map(|(a, b)| a + b);
        left.chain(right).fold(0.0, f64::max)
    }
}

/// e^X.
pub fn exponential(x: &DMatrix<f64>) -> DMatrix<f64> {
    exponential_blocks(&Blocks::of(x, x.nrows())).x
}

/// e^M of a block upper-triangular M, by blocks.
pub fn exponential_blocks(m: &Blocks) -> Blocks {
    let norm = m.norm1();
    let s = if norm > REACH {
        (norm / REACH).log2().ceil() as i32
    } else {
        0
    };
    let x = m.scaled(0.5f64.powi(s));
    let identity = Blocks::identity(x.x.nrows(), x.z.nrows());
    let x2 = x.mul(&x);
    let x3 = x2.mul(&x);
    let x4 = x2.mul(&x2);
    // 1/k! for k ≤ 16.
    let mut inverse = [1.0f64; DEGREE + 1];
    for k in 1..=DEGREE {
        inverse[k] = inverse[k - 1] / k as f64;
    }
    let block = |j: usize| {
        let c = &inverse[4 * j..];
        Blocks::sum(&[(c[0], &identity), (c[1], &x), (c[2], &x2), (c[3], &x3)])
    };
    let mut r = identity.scaled(inverse[DEGREE]);
    for j in (0..DEGREE / 4).rev() {
        let b = block(j);
        r = Blocks::sum(&[(1.0, &x4.mul(&r)), (1.0, &b)]);
    }
    for _ in 0..s {
        r = r.mul(&r);
    }
    r
}

#[cfg(test)]
mod tests {
    use super::{Blocks, exponential, exponential_blocks};
    use nalgebra::DMatrix;

    /// By blocks as whole: an augmented matrix of two floors (2 × 2 blocks
    /// of stiffness and damping, the ground's sine and two loads), at norms
    /// with and without squaring; the blocks agree within round-off.
    #[test]
    fn by_blocks_as_whole() {
        let (n, d) = (2, 8);
        let mut a = DMatrix::<f64>::zeros(d, d);
        let (k, c) = ([[2.0, -1.0], [-1.5, 1.5]], [[0.1, -0.02], [-0.03, 0.08]]);
        for i in 0..n {
            a[(i, n + i)] = 1.0;
            for j in 0..n {
                a[(n + i, j)] = -k[i][j];
                a[(n + i, n + j)] = -c[i][j];
            }
            a[(n + i, 2 * n)] = -1.0;
            a[(n + i, 2 * n + 2 + i)] = 1.0;
        }
        a[(2 * n, 2 * n + 1)] = 1.0;
        a[(2 * n + 1, 2 * n)] = -0.7;
        for scale in [0.05, 0.3, 2.0, 9.0] {
            let m = &a * scale;
            let whole = exponential(&m);
            let blocks = exponential_blocks(&Blocks::of(&m, 2 * n));
            let size = whole.abs().max().max(1.0);
            let t = 2 * n;
            let parts = [
                (whole.view((0, 0), (t, t)).clone_owned(), &blocks.x),
                (whole.view((0, t), (t, d - t)).clone_owned(), &blocks.y),
                (whole.view((t, t), (d - t, d - t)).clone_owned(), &blocks.z),
            ];
            for (w, b) in parts {
                assert!((w - b).abs().max() <= 1e-14 * size, "scale {scale}");
            }
            assert_eq!(whole.view((t, 0), (d - t, t)).abs().max(), 0.0);
        }
    }

    /// A rotation beside a nilpotent block: e^X in closed form, at norms
    /// below the polynomial's reach and up to 60 times it (six squarings).
    #[test]
    fn matches_closed_forms_with_and_without_squaring() {
        for w in [0.1, 0.5, 1.5, 4.0, 30.0] {
            // A rotation by w beside a 2 × 2 Jordan block of eigenvalue 0.
            let mut x = DMatrix::<f64>::zeros(4, 4);
            x[(0, 1)] = w;
            x[(1, 0)] = -w;
            x[(2, 3)] = w;
            let e = exponential(&x);
            let (s, c) = w.sin_cos();
            let expected = [
                [c, s, 0.0, 0.0],
                [-s, c, 0.0, 0.0],
                [0.0, 0.0, 1.0, w],
                [0.0, 0.0, 0.0, 1.0],
            ];
            for i in 0..4 {
                for j in 0..4 {
                    let err = (e[(i, j)] - expected[i][j]).abs();
                    assert!(
                        err <= 1e-14 * w.max(1.0),
                        "w = {w}: ({i}, {j}) off by {err}"
                    );
                }
            }
        }
    }

    /// Against nalgebra's own exponential on a damped oscillator's
    /// augmented matrix, within round-off.
    #[test]
    fn agrees_with_nalgebra() {
        let x = DMatrix::from_row_slice(
            4,
            4,
            &[
                0.0, 0.3, 0.0, 0.0, -0.3, -0.05, -0.1, 0.2, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, -0.2, 0.0,
            ],
        );
        for scale in [0.5, 2.0, 6.0, 40.0] {
            let x = &x * scale;
            let (ours, theirs) = (exponential(&x), x.exp());
            let size = theirs.abs().max();
            assert!((ours - theirs).abs().max() <= 1e-13 * size.max(1.0));
        }
    }
}
