//! The matrix exponential of the maps (SPEC §13): its Taylor polynomial
//! on X/2ˢ by Horner's rule on the nonzeros of X, squared s times.
//!
//! With ‖X/2ˢ‖₁ = ν ≤ 1, the truncation of eˣ after the power 18 is at
//! most ν¹⁹/19! · e^ν ≤ 2.3e-17 and ‖e^{X/2ˢ}‖ ≥ e^{−ν}, so it stays below
//! 6.2e-17 of the result, under the round-off. Horner's rule,
//!
//! ```text
//! T₁₈ = I,   T_k = I + T_{k+1} X/k  (k = 17 … 1),   T(X) = I + T₁ X,
//! ```
//!
//! takes eighteen products by X itself, and X is sparse: the augmented
//! matrix of a row holds about three nonzeros per row ([`super::sparse`]),
//! so each product costs nnz(X) column updates, about a seventh of a dense
//! product at the rows' sizes, and the eighteen together less than three
//! dense ones. (Paterson and Stockmeyer's scheme needs seven products, but
//! four of them of dense matrices; a Padé approximant, nalgebra's `exp`,
//! fewer still, but an LU solve with as many right-hand sides as rows.)
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
//! so Horner's products skip the zero block, and the squarings (and the
//! powers of [`super::bound`]) are taken on the three blocks, about half
//! the work of whole products at the rows' sizes.

use nalgebra::DMatrix;

use super::sparse::Sparse;

/// Largest ‖X/2ˢ‖₁ the polynomial takes.
const REACH: f64 = 1.0;
/// Degree of the Taylor polynomial.
const DEGREE: usize = 18;

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

    /// The largest |entry| of `whole` − [[X, Y], [0, Z]].
    #[cfg(test)]
    pub fn largest_difference(&self, whole: &DMatrix<f64>) -> f64 {
        let t = self.x.nrows();
        let mine = DMatrix::from_fn(whole.nrows(), whole.ncols(), |i, j| match (i < t, j < t) {
            (true, true) => self.x[(i, j)],
            (true, false) => self.y[(i, j - t)],
            (false, true) => 0.0,
            (false, false) => self.z[(i - t, j - t)],
        });
        (whole - mine).abs().max()
    }

    /// The product self · other, block by block.
    pub fn mul(&self, other: &Blocks) -> Blocks {
        Blocks {
            x: &self.x * &other.x,
            y: &self.x * &other.y + &self.y * &other.z,
            z: &self.z * &other.z,
        }
    }
}

/// e^X.
pub fn exponential(x: &DMatrix<f64>) -> DMatrix<f64> {
    exponential_blocks(&Sparse::of(x), x.nrows()).x
}

/// e^X of a block upper-triangular X whose leading block is `t` × `t`,
/// from its nonzeros, by blocks.
pub fn exponential_blocks(x: &Sparse, t: usize) -> Blocks {
    let norm = x.norm1();
    let s = if norm > REACH {
        (norm / REACH).log2().ceil() as i32
    } else {
        0
    };
    let x = x.scaled(0.5f64.powi(s));
    let d = x.size();
    // Column k of a polynomial in X is zero below row t when k < t.
    let lead = |k: usize| if k < t { t } else { d };
    let mut r = DMatrix::identity(d, d);
    let mut next = DMatrix::zeros(d, d);
    for k in (1..=DEGREE).rev() {
        x.right_product(&r, 1.0 / k as f64, lead, &mut next);
        for i in 0..d {
            next[(i, i)] += 1.0;
        }
        std::mem::swap(&mut r, &mut next);
    }
    let mut r = Blocks::of(&r, t);
    for _ in 0..s {
        r = r.mul(&r);
    }
    r
}

#[cfg(test)]
mod tests {
    use super::{exponential, exponential_blocks};
    use crate::solver::buildings::sparse::Sparse;
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
            let blocks = exponential_blocks(&Sparse::of(&m), 2 * n);
            let size = whole.abs().max().max(1.0);
            assert!(
                blocks.largest_difference(&whole) <= 1e-14 * size,
                "scale {scale}"
            );
            let t = 2 * n;
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

    /// Random rows of shear storeys (2 to 9 floors, stiffnesses and masses
    /// spread over a decade, Rayleigh damping, a sine of the ground and a
    /// load per floor), augmented as the maps take them, at norms from 0.05
    /// to 12 (up to four squarings): the exponential by the nonzeros agrees
    /// with nalgebra's Padé approximant, which shares no code with it, to
    /// 1e-14 of the largest entry, nalgebra's lower-left block (zero in
    /// ours by its structure) included.
    #[test]
    fn agrees_with_nalgebra_on_random_rows() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut uniform = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..40 {
            let n = 2 + (uniform() * 8.0) as usize;
            let mass: Vec<f64> = (0..n).map(|_| 1.0 + 9.0 * uniform()).collect();
            let k: Vec<f64> = (0..n).map(|_| 1.0 + 9.0 * uniform()).collect();
            let mut stiffness = DMatrix::<f64>::zeros(n, n);
            for i in 0..n {
                stiffness[(i, i)] += k[i];
                if i > 0 {
                    stiffness[(i - 1, i - 1)] += k[i];
                    stiffness[(i, i - 1)] -= k[i];
                    stiffness[(i - 1, i)] -= k[i];
                }
            }
            let (a0, a1) = (0.1 * uniform(), 0.02 * uniform());
            let d = 3 * n + 2;
            let mut a = DMatrix::<f64>::zeros(d, d);
            for i in 0..n {
                a[(i, n + i)] = 1.0;
                for j in 0..n {
                    let kij = stiffness[(i, j)] / mass[i];
                    a[(n + i, j)] = -kij;
                    a[(n + i, n + j)] = -(a1 * kij + if i == j { a0 } else { 0.0 });
                }
                a[(n + i, 2 * n)] = -1.0;
                a[(n + i, 2 * n + 2 + i)] = 1.0;
            }
            a[(2 * n, 2 * n + 1)] = 1.0;
            a[(2 * n + 1, 2 * n)] = -uniform();
            let norm = a.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
            let target = 0.05 * 240f64.powf(uniform());
            let m = &a * (target / norm);
            let ours = exponential_blocks(&Sparse::of(&m), 2 * n);
            let theirs = m.exp();
            let err = ours.largest_difference(&theirs);
            let size = theirs.abs().max();
            assert!(err <= 1e-14 * size, "n = {n}, norm {target}: off by {err}");
        }
    }
}
