//! Convergence order with pounding: for set 1 and set 2 and both
//! contact models, the error of the four peaks (Π_u1, Π_v1, Π_u2, Π_v2)
//! against the same solver at Δτ/64 falls by 3–5× per halving of Δτ between
//! Δτ = 0.004 and 0.001: Newmark's second order survives contact, because the
//! contact instants are located and the step is split there.

use pounding::model::{ContactModel, Params, SET1, SET2};
use pounding::solver::{SolverOptions, simulate};

fn peaks(p: &Params, dt: f64, options: &SolverOptions) -> [f64; 4] {
    let q = Params { dt, ..p.clone() };
    simulate(&q, options, &mut ()).peaks()
}

fn max_error(a: [f64; 4], b: [f64; 4]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Errors at the three steps against the same solver at Δτ = 0.001/64.
fn errors(p: &Params, options: &SolverOptions, steps: [f64; 3]) -> [f64; 3] {
    let reference = peaks(p, 0.001 / 64.0, options);
    steps.map(|dt| max_error(peaks(p, dt, options), reference))
}

fn check_order(options: SolverOptions, label: &str, steps: [f64; 3]) {
    for (name, set) in [("set1", SET1), ("set2", SET2)] {
        for model in ContactModel::PAPER {
            let p = Params {
                model,
                ..set.clone()
            };
            let e = errors(&p, &options, steps);
            let ratios = [e[0] / e[1], e[1] / e[2]];
            eprintln!("{label} {name} {model}: errors {e:?} ratios {ratios:.2?}");
            for r in ratios {
                assert!(
                    (3.0..=5.0).contains(&r),
                    "{label} {name} {model}: errors {e:?}, ratios {ratios:?}"
                );
            }
        }
    }
}

/// The project's solver (located contact, ⌈Π_ωcon/5⌉ sub-steps in contact).
/// Measured ratios 3.90–4.13; errors at Δτ = 0.001 between 1.2e-6 and 5.5e-6.
#[test]
fn second_order_with_located_contact_and_substeps() {
    check_order(SolverOptions::default(), "default", [0.004, 0.002, 0.001]);
}

/// Located contact at the paper's Δτ inside contact too. At Δτ = 0.004 a set-2
/// Kelvin contact gets only ~16 steps (Π_ωcon Δτ = 0.2) and is pre-asymptotic
/// (ratio 5.7), so this scheme is checked one halving finer.
#[test]
fn second_order_with_located_contact_at_plain_step() {
    check_order(SolverOptions::located(), "located", [0.002, 0.001, 0.0005]);
}
