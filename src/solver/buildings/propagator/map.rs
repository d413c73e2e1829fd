//! The map of a sub-step out of contact (SPEC §13) stored by columns, so
//! that applying it is a few vector operations per state entry.
//!
//! The map is the rows of (u, u̇) of e^{𝒜h}, 2n × (3n + 2), applied to the
//! augmented state w = (u, u̇, a_g, ȧ_g, M⁻¹q) of [`super`]:
//!
//! ```text
//! x_r(h) = G_r,a a + G_r,ȧ ȧ + Σ_j (X_rj u_j + Y_rj u̇_j + Q_rj (M⁻¹q)_j),   r < 2n.
//! ```
//!
//! Taken row by row, each output is one serial sum of 3n + 2 products,
//! whose additions wait on each other. Here the outputs are cut into
//! blocks of [`LANES`] rows, and each block's entries are stored column
//! by column: the block's LANES sums advance together, one vector
//! multiply-and-add per column. Each output still adds its terms in the
//! row-major order above, grouped as (X u + Y u̇) + Q M⁻¹q per j, so its
//! value is the row-major product's bit for bit.

use nalgebra::DMatrix;

use super::super::lanes::{LANES, blocks};

/// The rows of (u, u̇) of e^{𝒜h} in blocks of [`LANES`] rows, the last
/// padded with zero rows; each block is its columns in the order of w,
/// a_g and ȧ_g first, then (u_j, u̇_j, (M⁻¹q)_j) for each floor j.
#[derive(Debug, Clone)]
pub struct Map {
    /// Floors n: the map has 2n rows and 3n + 2 columns.
    dofs: usize,
    /// The blocks, each (3n + 2) · LANES long.
    blocks: Vec<f64>,
}

impl Map {
    /// From the map as a matrix, 2n × (3n + 2)
    /// ([`super::super::bound::Bounds::with_map`]).
    pub fn of(map: &DMatrix<f64>) -> Map {
        let rows = map.nrows();
        let dofs = rows / 2;
        assert_eq!(map.ncols(), 3 * dofs + 2, "a map of (u, u̇) rows");
        // The columns of w in each block's order: a_g, ȧ_g, then (u_j, u̇_j, q_j).
        let order: Vec<usize> = [2 * dofs, 2 * dofs + 1]
            .into_iter()
            .chain((0..dofs).flat_map(|j| [j, dofs + j, 2 * dofs + 2 + j]))
            .collect();
        Map {
            dofs,
            blocks: blocks(rows, &order, |r, c| map[(r, c)]),
        }
    }
}

/// (u, u̇) after the map from (u, u̇) under ground (a, ȧ) and load M⁻¹q.
pub fn apply(
    map: &Map,
    (u, v): (&[f64], &[f64]),
    (a, rate): (f64, f64),
    load: &[f64],
    (u1, v1): (&mut [f64], &mut [f64]),
) {
    let n = map.dofs;
    let (u, v, load) = (&u[..n], &v[..n], &load[..n]);
    let width = (3 * n + 2) * LANES;
    for (b, block) in map.blocks.chunks_exact(width).enumerate() {
        let (ground, floors) = block.split_at(2 * LANES);
        let (ga, gr) = ground.split_at(LANES);
        let mut s: [f64; LANES] = std::array::from_fn(|l| ga[l] * a + gr[l] * rate);
        for (column, ((&x, &y), &q)) in floors
            .chunks_exact(3 * LANES)
            .zip(u.iter().zip(v).zip(load))
        {
            let column: &[f64; 3 * LANES] = column.try_into().expect("a block's columns");
            let (cx, rest) = column.split_at(LANES);
            let (cy, cq) = rest.split_at(LANES);
            for l in 0..LANES {
                s[l] += cx[l] * x + cy[l] * y + cq[l] * q;
            }
        }
        for (l, s) in s.into_iter().enumerate() {
            let r = b * LANES + l;
            if r < n {
                u1[r] = s;
            } else if r < 2 * n {
                v1[r - n] = s;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Map, apply};
    use nalgebra::DMatrix;
    use proptest::prelude::*;

    /// The row-major product the blocks replace: each row's serial sum.
    fn by_rows(
        map: &DMatrix<f64>,
        (u, v): (&[f64], &[f64]),
        (a, rate): (f64, f64),
        load: &[f64],
    ) -> Vec<f64> {
        let n = u.len();
        (0..2 * n)
            .map(|r| {
                let mut s = map[(r, 2 * n)] * a + map[(r, 2 * n + 1)] * rate;
                for j in 0..n {
                    s += map[(r, j)] * u[j]
                        + map[(r, n + j)] * v[j]
                        + map[(r, 2 * n + 2 + j)] * load[j];
                }
                s
            })
            .collect()
    }

    /// n floors, a 2n × (3n + 2) map of entries across six decades, and
    /// (u, u̇, M⁻¹q) and the ground (a, ȧ).
    fn case() -> impl Strategy<Value = (DMatrix<f64>, [Vec<f64>; 3], (f64, f64))> {
        (1usize..14).prop_flat_map(|n| {
            let entry = (-1.0f64..1.0, -3.0f64..3.0).prop_map(|(x, e)| x * 10f64.powf(e));
            let state = || prop::collection::vec(-1.0f64..1.0, n);
            (
                prop::collection::vec(entry, 2 * n * (3 * n + 2)),
                [state(), state(), state()],
                (-1.0f64..1.0, -1.0f64..1.0),
            )
                .prop_map(move |(m, s, g)| (DMatrix::from_vec(2 * n, 3 * n + 2, m), s, g))
        })
    }

    proptest! {
        /// On random maps of 1 to 13 floors (the blocks full, padded, or
        /// a single partial one) and random states, the blocked product
        /// is the row-major product bit for bit: each output adds the same
        /// terms in the same order.
        #[test]
        fn the_blocks_give_the_row_major_product_bit_for_bit(
            (m, [u, v, load], ground) in case(),
        ) {
            let n = u.len();
            let (mut u1, mut v1) = (vec![f64::NAN; n], vec![f64::NAN; n]);
            apply(&Map::of(&m), (&u, &v), ground, &load, (&mut u1, &mut v1));
            let want = by_rows(&m, (&u, &v), ground, &load);
            let got: Vec<f64> = u1.iter().chain(&v1).copied().collect();
            prop_assert_eq!(
                got.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                want.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
            );
        }
    }

    /// The map of two floors moving freely over h: u(h) = u + h u̇, u̇ fixed,
    /// the ground and load columns picked out one by one; exact in floats.
    #[test]
    fn picks_each_column() {
        let n = 2;
        let h = 0.5;
        let mut m = DMatrix::<f64>::zeros(2 * n, 3 * n + 2);
        for i in 0..n {
            m[(i, i)] = 1.0;
            m[(i, n + i)] = h;
            m[(n + i, n + i)] = 1.0;
        }
        m[(0, 2 * n)] = 2.0;
        m[(3, 2 * n + 1)] = 4.0;
        m[(1, 2 * n + 2)] = 8.0;
        let (mut u1, mut v1) = (vec![0.0; n], vec![0.0; n]);
        apply(
            &Map::of(&m),
            (&[1.0, 2.0], &[3.0, 4.0]),
            (0.25, 0.125),
            &[1.0, 0.0],
            (&mut u1, &mut v1),
        );
        // u: 1 + 0.5·3 + 2·0.25, 2 + 0.5·4 + 8·1 (floor 0's load on u_1);
        // u̇: 3, 4 + 4·0.125.
        assert_eq!(u1, [3.0, 12.0]);
        assert_eq!(v1, [3.0, 4.5]);
    }
}
