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

use nalgebra::DMatrix;

/// Largest ‖X/2ˢ‖₁ the polynomial takes.
const REACH: f64 = 0.5;
/// Degree of the Taylor polynomial.
const DEGREE: usize = 16;

/// e^X.
pub fn exponential(x: &DMatrix<f64>) -> DMatrix<f64> {
    let d = x.nrows();
    let norm = x.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
    let s = if norm > REACH {
        (norm / REACH).log2().ceil() as i32
    } else {
        0
    };
    let x = x * 0.5f64.powi(s);
    let identity = DMatrix::<f64>::identity(d, d);
    let x2 = &x * &x;
    let x3 = &x2 * &x;
    let x4 = &x2 * &x2;
    // 1/k! for k ≤ 16.
    let mut inverse = [1.0f64; DEGREE + 1];
    for k in 1..=DEGREE {
        inverse[k] = inverse[k - 1] / k as f64;
    }
    let block = |j: usize| {
        let c = &inverse[4 * j..];
        &identity * c[0] + &x * c[1] + &x2 * c[2] + &x3 * c[3]
    };
    let mut r = &identity * inverse[DEGREE];
    for j in (0..DEGREE / 4).rev() {
        r = &x4 * r + block(j);
    }
    for _ in 0..s {
        r = &r * &r;
    }
    r
}

#[cfg(test)]
mod tests {
    use super::exponential;
    use nalgebra::DMatrix;

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
