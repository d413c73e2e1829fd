//! The augmented matrix 𝒜 of a configuration by its nonzeros (SPEC §13),
//! for the products that make its exponential and the quiet test's bounds.
//!
//! 𝒜 = [[0, I, 0], [−M⁻¹K, −M⁻¹C, ·], [0, 0, ·]] holds few nonzeros: a
//! row of u one, a row of u̇ its floor's neighbours in K and C (tridiagonal
//! per building under Rayleigh damping, a few more for links), the ground
//! and its own load. A product R·𝒜 by column j,
//!
//! ```text
//! (R𝒜)_{·j} = Σ_{k: 𝒜_kj ≠ 0} 𝒜_kj R_{·k},
//! ```
//!
//! costs nnz(𝒜) column updates instead of the d of a dense product: at the
//! rows' sizes (d = 35, nnz ≈ 100) about a seventh of the work.

use nalgebra::DMatrix;

/// A matrix by its nonzeros, column by column: (row, value) of column j
/// in `entries[start[j]..start[j + 1]]`, in the order of the rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Sparse {
    rows: usize,
    entries: Vec<(usize, f64)>,
    start: Vec<usize>,
}

impl Sparse {
    /// The nonzeros of `m`.
    pub fn of(m: &DMatrix<f64>) -> Sparse {
        let mut entries = Vec::new();
        let mut start = vec![0];
        for column in m.column_iter() {
            entries.extend(
                column
                    .iter()
                    .enumerate()
                    .filter(|(_, x)| **x != 0.0)
                    .map(|(i, &x)| (i, x)),
            );
            start.push(entries.len());
        }
        Sparse {
            rows: m.nrows(),
            entries,
            start,
        }
    }

    /// Rows (and columns: the matrices here are square).
    pub fn size(&self) -> usize {
        self.rows
    }

    /// c times this matrix.
    pub fn scaled(&self, c: f64) -> Sparse {
        Sparse {
            entries: self.entries.iter().map(|&(i, x)| (i, c * x)).collect(),
            ..self.clone()
        }
    }

    /// (row, value) of the nonzeros of column `j`.
    pub fn column(&self, j: usize) -> &[(usize, f64)] {
        &self.entries[self.start[j]..self.start[j + 1]]
    }

    /// `out` = c · r · self, with the rows of column k of `r` below
    /// `lead(k)` the only ones that may be nonzero (the rest are skipped,
    /// and stay zero in `out` where every column feeding them is zero).
    pub fn right_product(
        &self,
        r: &DMatrix<f64>,
        c: f64,
        lead: impl Fn(usize) -> usize,
        out: &mut DMatrix<f64>,
    ) {
        out.fill(0.0);
        let (height, from) = (r.nrows(), r.as_slice());
        let to = out.as_mut_slice();
        for (j, column) in to.chunks_exact_mut(height).enumerate() {
            for &(k, x) in self.column(j) {
                let rows = lead(k);
                let cx = c * x;
                let source = &from[k * height..k * height + rows];
                for (o, f) in column[..rows].iter_mut().zip(source) {
                    *o += cx * f;
                }
            }
        }
    }

    /// r · self, every row of `r` taken.
    pub fn times(&self, r: &DMatrix<f64>) -> DMatrix<f64> {
        let mut out = DMatrix::zeros(r.nrows(), self.start.len() - 1);
        let rows = r.nrows();
        self.right_product(r, 1.0, |_| rows, &mut out);
        out
    }

    /// ‖·‖₁: the largest column sum of |entries|.
    pub fn norm1(&self) -> f64 {
        (0..self.start.len() - 1)
            .map(|j| self.column(j).iter().map(|(_, x)| x.abs()).sum::<f64>())
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::Sparse;
    use nalgebra::DMatrix;

    /// A product by the nonzeros equals the dense product within round-off,
    /// on a matrix with a third of its entries zero.
    #[test]
    fn products_match_dense() {
        let a = DMatrix::from_fn(7, 7, |i, j| {
            if (i + 2 * j) % 3 == 0 {
                0.0
            } else {
                (i as f64 - 1.3 * j as f64).sin()
            }
        });
        let r = DMatrix::from_fn(5, 7, |i, j| (0.7 * i as f64 + j as f64).cos());
        let sparse = Sparse::of(&a);
        let diff = (sparse.times(&r) - &r * &a).abs().max();
        assert!(diff <= 1e-15, "off by {diff}");
        let dense_norm = a.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
        assert_eq!(sparse.norm1(), dense_norm);
        assert_eq!(sparse.scaled(2.0).norm1(), 2.0 * dense_norm);
    }
}
