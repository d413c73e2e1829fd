//! The stress test's invariants on random valid parameters (proptest):
//! finite outputs, closed energy balance, Newton converged, no tension from
//! the improved Kelvin element for e ≥ 0.4 unless the reference shows the
//! model pulls too, and the reference agreeing with Newmark's impact count.

use pounding::accuracy::stress::{Case, Expect, checks};
use pounding::model::{ContactModel, Params};
use pounding::solver::{SolverOptions, simulate};
use proptest::prelude::*;

fn params() -> impl Strategy<Value = Params> {
    (
        (1e-2f64..1e2, 0.2f64..5.0, 0.2f64..10.0),
        (
            prop_oneof![Just(f64::INFINITY), 1e-2f64..10.0],
            prop_oneof![Just(f64::INFINITY), 1e-2f64..10.0],
        ),
        (0.0f64..0.2, 0.0f64..=1.0, 5.0f64..2000.0, 0.05f64..=1.0),
        (
            prop_oneof![Just(f64::INFINITY), 0.0f64..2.0],
            any::<bool>(),
            1u32..4,
        ),
    )
        .prop_map(
            |((m, w1, w2), (uy1, uy2), (xi, a, wc, e), (gap, kelvin, cycles))| Params {
                mass_ratio: m,
                omega1: w1,
                omega2: w2,
                yield1: uy1,
                yield2: uy2,
                damping: xi,
                alpha: a,
                contact_omega: wc,
                restitution: e,
                gap,
                model: if kelvin {
                    ContactModel::Kelvin
                } else {
                    ContactModel::ImprovedKelvin
                },
                method: pounding::model::Method::Newmark,
                cycles,
                dt: 0.001,
                min_impact_velocity: 1e-3,
                ..pounding::model::SET1
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn every_random_run_keeps_the_invariants(p in params()) {
        prop_assume!(p.validate().is_ok());
        let case = Case {
            name: "proptest".into(),
            params: p.clone(),
            options: SolverOptions::default(),
            expect: Expect::Invariants,
        };
        let outcome = checks::check(&case);
        prop_assert!(outcome.passed, "{}: {:?}", p, outcome.failures);
        prop_assert!(outcome.energy_residual <= checks::ENERGY_TOLERANCE);
    }

    /// Peaks are non-negative and at least the size of the state at the end.
    #[test]
    fn peaks_bound_the_response(p in params()) {
        let mut history = pounding::solver::FullHistory::default();
        let r = simulate(&p, &SolverOptions::default(), &mut history);
        let last = history.samples.last().expect("a run records its start");
        prop_assert!(r.left.peak_displacement >= last.x[0].abs());
        prop_assert!(r.right.peak_velocity >= last.v[1].abs());
        prop_assert!(r.peaks().iter().all(|v| *v >= 0.0 && v.is_finite()));
    }
}
