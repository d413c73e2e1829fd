//! The instruments of `pounding bench` and `pounding stress`, on small inputs.

use pounding::accuracy::method::{Method, max_relative_error};
use pounding::accuracy::stress::corner_cases;
use pounding::accuracy::work_precision::{Row, meets_target};
use pounding::model::SET1;

#[test]
fn relative_error_is_the_largest_of_four() {
    let e = max_relative_error([1.0, 2.0, 3.0, 4.0], [1.0, 2.2, 3.0, 4.0]);
    assert!((e - 0.2 / 2.2).abs() < 1e-15);
}

/// Located Newmark at Δτ = 0.001 on set 1 is within 5e-4 of the reference
/// (measured 3.9e-4 for Kelvin, 1.6e-4 improved Kelvin) and the sub-stepped
/// scheme within the 1e-5 target.
#[test]
fn set1_errors_at_default_step() {
    let truth = Method::Reference(1e-13).peaks(&SET1);
    let located = max_relative_error(Method::NewmarkLocated.peaks(&SET1), truth);
    let substep = max_relative_error(Method::NewmarkSubstepped.peaks(&SET1), truth);
    assert!(located < 5e-4 && located > 1e-6, "{located}");
    assert!(substep < 1e-5, "{substep}");
}

#[test]
fn target_applies_to_default_step_only() {
    let row = |dt, ms, err| Row {
        preset: "set1".into(),
        model: "kelvin".into(),
        method: "newmark-located",
        dt: Some(dt),
        tolerance: None,
        ms_per_run: ms,
        max_rel_error: err,
        order: None,
    };
    assert_eq!(meets_target(&row(0.002, 1.0, 1e-6)), None);
    assert_eq!(meets_target(&row(0.001, 1.0, 1e-6)), Some(true));
    assert_eq!(meets_target(&row(0.001, 3.0, 1e-6)), Some(false));
    assert_eq!(meets_target(&row(0.001, 1.0, 2e-5)), Some(false));
}

/// The stability corners: average acceleration keeps the discrete energy of a
/// linear undamped system at Δτ up to 10 (Π_ω2·Δτ = 23.6): the energy
/// residual (measured against the initial energy) stays at round-off.
/// (Whether the reported, interpolated peaks stay within the amplitude is the
/// stress command's `AmplitudeBound` check.)
#[test]
fn unconditional_stability_keeps_discrete_energy() {
    let cases: Vec<_> = corner_cases()
        .into_iter()
        .filter(|c| c.name.starts_with("linear free"))
        .collect();
    assert_eq!(cases.len(), 3);
    for c in &cases {
        let r = pounding::solver::simulate(&c.params, &c.options, &mut ());
        assert!(r.is_finite() && r.completed, "{}", c.name);
        assert!(
            r.energy.residual < 1e-12,
            "{}: {}",
            c.name,
            r.energy.residual
        );
    }
}
