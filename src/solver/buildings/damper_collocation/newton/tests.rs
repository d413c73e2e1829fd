use nalgebra::{DMatrix, DVector};

use super::super::responses::AtNodes;
use super::super::{Element, Law, STAGES};
use super::{Factors, Rows, fill};

/// A damper and `products` contacts' products of the improved Kelvin law,
/// the dampers first as the step makes them.
fn elements(products: usize) -> Vec<Element> {
    let damper = Element {
        left: 2,
        right: 6,
        left_rate: 2.5e-6,
        right_rate: 3.3e-6,
        law: Law::Damper {
            damping: 4e6,
            exponent: 0.35,
        },
    };
    let product = |k: usize| Element {
        left: k,
        right: k + 3,
        left_rate: 2e-6,
        right_rate: 3e-6,
        law: Law::Product {
            gap: 5e-3,
            coefficient: 1.7e9,
        },
    };
    std::iter::once(damper)
        .chain((0..products).map(product))
        .collect()
}

/// Responses at the nodes and rows linearized at an iterate, their values
/// spread over decades and both signs, for the elements `elements`.
fn linearized(elements: &[Element]) -> (AtNodes, Rows) {
    let m = STAGES * elements.len();
    let value = |k: usize| ((k * 7919) % 1013) as f64 / 1013.0 - 0.4;
    let nodes = AtNodes {
        stroke: DMatrix::from_fn(m, m, |r, q| 1e-7 * value(r * m + q)),
        rate: DMatrix::from_fn(m, m, |r, q| 3e-5 * value(r * m + q + 17)),
    };
    let mut rows = Rows::default();
    rows.reset(elements);
    for r in 0..m {
        match elements[r % elements.len()].law {
            Law::Damper { .. } => rows.diagonal[r] = 1e-4 * (1.0 + value(r)),
            Law::Product { coefficient, .. } => {
                rows.diagonal[r] = 1.0;
                rows.coefficient[r] = coefficient;
                rows.rate[r] = 0.2 * value(r + 5);
                rows.stretch[r] = 1e-4 * value(r + 11);
            }
        }
    }
    (nodes, rows)
}

/// A damper alone and a damper with one to five products: each case's
/// number of products, elements and linearization ([`linearized`]).
fn cases() -> impl Iterator<Item = (usize, Vec<Element>, AtNodes, Rows)> {
    (0..=5).map(|products| {
        let elements = elements(products);
        let (nodes, rows) = linearized(&elements);
        (products, elements, nodes, rows)
    })
}

/// The Jacobian that [`fill`] writes, each kind's rows in a loop of its
/// own, is the collocated equations' entry by entry, to the bit:
/// J_rq = −Δv_r[ℓ_q] + ψ'(X_r)[r = q] on a damper's row and
/// −h(δ̇_r Δu_r[ℓ_q] + δ_r Δv_r[ℓ_q]) + [r = q] on a product's, for a
/// damper alone and a damper with one to five products.
#[test]
fn the_jacobian_is_the_collocated_equations_entry_by_entry() {
    for (products, elements, nodes, rows) in cases() {
        let m = STAGES * elements.len();
        let mut jacobian = vec![f64::NAN; m * m];
        fill(&nodes, &rows, &mut jacobian);
        for q in 0..m {
            for r in 0..m {
                let (s, v) = (nodes.stroke[(r, q)], nodes.rate[(r, q)]);
                let mut expected = match elements[r % elements.len()].law {
                    Law::Damper { .. } => -v,
                    Law::Product { .. } => {
                        -rows.coefficient[r] * (rows.rate[r] * s + rows.stretch[r] * v)
                    }
                };
                if r == q {
                    expected += rows.diagonal[r];
                }
                assert_eq!(
                    jacobian[q * m + r].to_bits(),
                    expected.to_bits(),
                    "{products} products, entry ({r}, {q})"
                );
            }
        }
    }
}

/// The factors on the stack (one to five elements) solve J x = b as the
/// heap's LU of the same Jacobian does, to the bit, and x solves it: the
/// residual J x − b within 1e-12 of |J||x|, for a damper with up to five
/// products (six elements, past the stack's sizes, on the heap alone).
#[test]
fn the_factors_on_the_stack_solve_as_the_heaps_to_the_bit() {
    for (products, elements, nodes, rows) in cases() {
        let m = STAGES * elements.len();
        let mut jacobian = DMatrix::zeros(m, m);
        fill(&nodes, &rows, jacobian.as_mut_slice());
        let b = DVector::from_fn(m, |r, _| (r as f64 - 3.5) * 1e3);
        let mut heap = b.clone();
        assert!(jacobian.clone().lu().solve_mut(&mut heap));
        let factors = Factors::of(&nodes, &rows);
        assert_eq!(
            matches!(factors, Factors::Any(_)),
            elements.len() > 5,
            "{products} products: the stack's sizes"
        );
        let mut x = b.clone();
        assert!(factors.solve_mut(&mut x));
        let bits = |v: &DVector<f64>| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&x), bits(&heap), "{products} products");
        let residual = (&jacobian * &x - &b).amax();
        let scale = jacobian.abs().max() * x.amax();
        assert!(
            residual <= 1e-12 * scale,
            "{products} products: residual {residual:e} of {scale:e}"
        );
    }
}
