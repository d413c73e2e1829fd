//! The width of the vector blocks of a map step (SPEC §13): the map
//! ([`super::propagator::Map`]) and M⁻¹K, M⁻¹C ([`super::system::Columns`])
//! are stored by columns in blocks of this many rows, so that each block's
//! sums advance together, one vector operation per column.

/// Rows per block: one AVX-512 vector of f64, or two AVX2 vectors.
pub const LANES: usize = 8;

/// The entries of an n-row matrix's columns, in blocks of [`LANES`] rows
/// (the last padded with zeros), each block its columns in the order
/// `columns` gives them: what [`super::propagator::Map`] and
/// [`super::system::Columns`] store.
pub fn blocks(rows: usize, columns: &[usize], entry: impl Fn(usize, usize) -> f64) -> Vec<f64> {
    let count = rows.div_ceil(LANES);
    let mut out = Vec::with_capacity(count * columns.len() * LANES);
    for b in 0..count {
        for &c in columns {
            out.extend(
                (b * LANES..(b + 1) * LANES).map(|r| if r < rows { entry(r, c) } else { 0.0 }),
            );
        }
    }
    out
}
