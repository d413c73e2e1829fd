//! M⁻¹K and M⁻¹C of one configuration stored by columns in vector blocks
//! ([`super::super::lanes`]), for the rates of a map step's ends and the
//! orders of the Taylor series (SPEC §13).
//!
//! At each end of a quiet sub-step the quiet test needs ü, u⃛ and u⁗ of
//! every floor ([`super::super::bound::Stack`]), each one product of the
//! same form,
//!
//! ```text
//! r_i = b_i − Σ_j ((M⁻¹K)_ij x_j + (M⁻¹C)_ij y_j),
//! ```
//!
//! (x, y) = (u, u̇), (u̇, ü), (ü, u⃛) and b_i = (M⁻¹q)_i − a_g, −ȧ_g, −σa_g;
//! each order k of the series ([`super::super::taylor`]) needs the same
//! with (x, y) = (u_k, u̇_k) and b_i = (M⁻¹q)_i − a_0 at k = 0, −a_k above
//! ([`Columns::rate_into`]).
//! Row by row on the nonzeros ([`super::System::row`]), each r_i is a short
//! serial sum with an index per term; here a block of [`LANES`] rows goes
//! column by column, its LANES sums together. A zero entry subtracts a
//! zero, which leaves a nonzero sum as it is, so each r_i is the row-wise
//! sum on the nonzeros bit for bit (a zero sum may change its sign); the
//! columns before a block's first nonzero and after its last are skipped.
//! The work grows as n² against the nonzeros' n, which pays while a
//! block's column (two vector operations) costs less than a row's few
//! indexed terms: for the rows met here, and always below the map's own
//! 2n × (3n + 2) product that comes with it.

use nalgebra::DMatrix;

use super::super::lanes::{LANES, blocks};

/// M⁻¹K and M⁻¹C in blocks of [`LANES`] rows, each block its columns
/// ((M⁻¹K)_·j, (M⁻¹C)_·j) for each floor j.
#[derive(Debug, Clone)]
pub struct Columns {
    dofs: usize,
    blocks: Vec<f64>,
    /// Per block, the floors j from the first to the last whose columns
    /// have a nonzero in its rows: a floor couples only to its storeys'
    /// other floors and its contacts and links, so the columns outside
    /// subtract only zeros and are passed over.
    spans: Vec<std::ops::Range<usize>>,
}

/// n rounded up to whole blocks of [`LANES`] rows: the length of a buffer
/// into which [`Columns::rate_into`] stores every block whole.
pub fn padded(n: usize) -> usize {
    n.next_multiple_of(LANES)
}

impl Columns {
    /// From M⁻¹K and M⁻¹C (n × n).
    pub fn of(stiffness: &DMatrix<f64>, damping: &DMatrix<f64>) -> Columns {
        let n = stiffness.nrows();
        // Column 2j is K's column j, 2j + 1 is C's.
        let order: Vec<usize> = (0..2 * n).collect();
        let entry = |r, c: usize| {
            if c.is_multiple_of(2) {
                stiffness[(r, c / 2)]
            } else {
                damping[(r, c / 2)]
            }
        };
        let spans = (0..n.div_ceil(LANES))
            .map(|b| {
                let rows = b * LANES..((b + 1) * LANES).min(n);
                let coupled = |j: &usize| {
                    rows.clone()
                        .any(|r| entry(r, 2 * j) != 0.0 || entry(r, 2 * j + 1) != 0.0)
                };
                let first = (0..n).find(coupled).unwrap_or(0);
                let last = (0..n).rfind(coupled).map_or(first, |j| j + 1);
                first..last
            })
            .collect();
        Columns {
            dofs: n,
            blocks: blocks(n, &order, entry),
            spans,
        }
    }

    /// r_i = b_i − Σ_j ((M⁻¹K)_ij x_j + (M⁻¹C)_ij y_j) into `out`, with
    /// b_i = load_i − g (or −g without a load), the terms in the order of j.
    pub fn rate(&self, (x, y): (&[f64], &[f64]), load: Option<&[f64]>, g: f64, out: &mut Vec<f64>) {
        let n = self.dofs;
        let (x, y) = (&x[..n], &y[..n]);
        out.clear();
        // Every block's lanes as one store of known length, the last
        // block's past n cut off after.
        self.sums(
            |span| x[span.clone()].iter().copied().zip(y[span].iter().copied()),
            (load, g),
            |_, s| out.extend_from_slice(s),
        );
        out.truncate(n);
    }

    /// [`Columns::rate`] into `out[..n]`: a Taylor coefficient's column of
    /// the series ([`super::super::taylor`]), whose rows are the same sums.
    /// Where `out` reaches past n to the end of the last block of [`LANES`]
    /// rows ([`padded`]), that block's lanes are stored whole, as every
    /// other block's (a store of known length, not a copy of n mod LANES),
    /// and its lanes past n hold no row.
    pub fn rate_into(
        &self,
        (x, y): (&[f64], &[f64]),
        load: Option<&[f64]>,
        g: f64,
        out: &mut [f64],
    ) {
        let n = self.dofs;
        let (x, y) = (&x[..n], &y[..n]);
        self.sums(
            |span| x[span.clone()].iter().copied().zip(y[span].iter().copied()),
            (load, g),
            |start, s| match out.get_mut(start..start + LANES) {
                Some(lanes) => lanes.copy_from_slice(s),
                None => out[start..n].copy_from_slice(&s[..n - start]),
            },
        );
    }

    /// The sums of [`Columns::rate`], each block's handed to `emit` with the
    /// index of its first row (all its lanes, the last block's past n too),
    /// (x_j, y_j) read from `values(span)` in the order of j. Without a
    /// load every block starts from −g in all its lanes, one vector; with
    /// one, a full block from its b_i as one vector, the last lane by lane.
    #[inline(always)]
    fn sums<I: Iterator<Item = (f64, f64)>>(
        &self,
        values: impl Fn(std::ops::Range<usize>) -> I,
        (load, g): (Option<&[f64]>, f64),
        mut emit: impl FnMut(usize, &[f64; LANES]),
    ) {
        match load {
            None => self.sums_from(&values, |_| [-g; LANES], &mut emit),
            Some(load) => self.sums_from(
                &values,
                |rows| match <&[f64; LANES]>::try_from(&load[rows.clone()]) {
                    Ok(q) => std::array::from_fn(|l| q[l] - g),
                    Err(_) => {
                        let mut s = [-g; LANES];
                        for (s, &q) in s.iter_mut().zip(&load[rows]) {
                            *s = q - g;
                        }
                        s
                    }
                },
                &mut emit,
            ),
        }
    }

    /// Each block's LANES sums from `start(rows)` over the columns of its span.
    #[inline(always)]
    fn sums_from<I: Iterator<Item = (f64, f64)>>(
        &self,
        values: impl Fn(std::ops::Range<usize>) -> I,
        start: impl Fn(std::ops::Range<usize>) -> [f64; LANES],
        mut emit: impl FnMut(usize, &[f64; LANES]),
    ) {
        let n = self.dofs;
        let blocks = self.blocks.chunks_exact(2 * n * LANES);
        for (b, (block, span)) in blocks.zip(&self.spans).enumerate() {
            let rows = b * LANES..((b + 1) * LANES).min(n);
            let mut s = start(rows.clone());
            let block = &block[2 * LANES * span.start..2 * LANES * span.end];
            for (column, (xj, yj)) in block.chunks_exact(2 * LANES).zip(values(span.clone())) {
                let column: &[f64; 2 * LANES] = column.try_into().expect("a block's columns");
                let (k, c) = column.split_at(LANES);
                for l in 0..LANES {
                    s[l] -= k[l] * xj + c[l] * yj;
                }
            }
            emit(rows.start, &s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Columns;
    use nalgebra::DMatrix;
    use proptest::prelude::*;

    /// n floors, M⁻¹K and M⁻¹C with about half their entries zero,
    /// (x, y), a load and g.
    fn case() -> impl Strategy<Value = ([DMatrix<f64>; 2], [Vec<f64>; 3], f64)> {
        (1usize..14).prop_flat_map(|n| {
            let entry = prop_oneof![Just(0.0), 0.0f64..1e6];
            let matrix = move || {
                prop::collection::vec(entry.clone(), n * n)
                    .prop_map(move |m| DMatrix::from_vec(n, n, m))
            };
            let state = || prop::collection::vec(-1.0f64..1.0, n);
            (
                [matrix(), matrix()],
                [state(), state(), state()],
                -1.0f64..1.0,
            )
        })
    }

    proptest! {
        /// On random sparse M⁻¹K, M⁻¹C of 1 to 13 floors the blocks give
        /// the row-wise sum on the nonzeros bit for bit (but the sign of
        /// a zero), with and without a load, into a growing vector and
        /// into a buffer of fixed length.
        #[test]
        fn the_blocks_give_the_sum_on_the_nonzeros_bit_for_bit(
            ([k, c], [x, y, load], g) in case(),
            loaded in any::<bool>(),
        ) {
            let n = x.len();
            let load = loaded.then_some(&load[..]);
            let mut got = Vec::new();
            Columns::of(&k, &c).rate((&x, &y), load, g, &mut got);
            let want: Vec<f64> = (0..n)
                .map(|i| {
                    let mut s = load.map_or(-g, |l| l[i] - g);
                    for j in 0..n {
                        if k[(i, j)] != 0.0 || c[(i, j)] != 0.0 {
                            s -= k[(i, j)] * x[j] + c[(i, j)] * y[j];
                        }
                    }
                    s
                })
                .collect();
            prop_assert_eq!(got.len(), n);
            for (g, w) in got.iter().zip(&want) {
                // Equal as numbers: bit for bit but the sign of a zero.
                prop_assert!(g == w, "{} against {}", g, w);
            }
            // Into a buffer of n and into one past the blocks' end: the
            // first n the same sums; past n, only the last block's lanes
            // may be written, and only where the buffer holds the block.
            let blocks = super::padded(n);
            for len in [n, blocks + 3] {
                let mut pairs = vec![7.0; len];
                Columns::of(&k, &c).rate_into((&x, &y), load, g, &mut pairs);
                for (p, w) in pairs.iter().zip(&want) {
                    prop_assert!(p == w, "{} against {}", p, w);
                }
                prop_assert!(pairs[blocks.min(len)..].iter().all(|&p| p == 7.0));
            }
        }
    }
}
