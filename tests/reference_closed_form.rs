//! The reference integrator against exact solutions it shares nothing with:
//! the linear oscillator in closed form, and the Kelvin contact's restitution.

use pounding::model::{ContactModel, Excitation, Params, SET1};
use pounding::reference::closed_form::{LinearOscillator, peak};
use pounding::reference::{ReferenceOptions, reference};

fn linear(p: Params) -> Params {
    Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        ..p.clone()
    }
}

/// Elastic, no pounding, sine from rest: final state and all four peaks
/// within 1e-10 (relative) of the closed form at tolerance 1e-13.
#[test]
fn elastic_response_matches_closed_form() {
    let p = linear(SET1);
    let r = reference(&p, &ReferenceOptions::default());
    let tau_end = p.tau_end();
    let exact = [
        LinearOscillator::new(p.omega1, p.damping, 1.0, 0.0, 0.0),
        LinearOscillator::new(p.omega2, p.damping, 1.0, 0.0, 0.0),
    ];
    for (i, o) in exact.iter().enumerate() {
        let x = o.displacement(tau_end);
        let v = o.velocity(tau_end);
        assert!(
            (r.final_state[2 * i] - x).abs() < 1e-10,
            "x{i}: {} vs {x}",
            r.final_state[2 * i]
        );
        assert!((r.final_state[2 * i + 1] - v).abs() < 1e-10, "v{i}");
        let pu = peak(|t| o.displacement(t), tau_end);
        let pv = peak(|t| o.velocity(t), tau_end);
        assert!(
            (r.peaks[2 * i] - pu).abs() < 1e-10 * pu,
            "Π_u{i}: {} vs {pu}",
            r.peaks[2 * i]
        );
        assert!(
            (r.peaks[2 * i + 1] - pv).abs() < 1e-10 * pv,
            "Π_v{i}: {} vs {pv}",
            r.peaks[2 * i + 1]
        );
    }
    assert!(r.completed && r.impacts.is_empty() && r.yielded == [false, false]);
}

/// The global error falls with the tolerance: 1e-8 → error ≈ 1e-8 or less, 1e-12 → ≤ 1e-11.
#[test]
fn error_follows_tolerance() {
    let p = linear(Params {
        omega1: 1.5,
        omega2: 3.375,
        ..SET1
    });
    let o = LinearOscillator::new(p.omega2, p.damping, 1.0, 0.0, 0.0);
    let exact = o.displacement(p.tau_end());
    for (tol, bound) in [(1e-8, 1e-7), (1e-10, 1e-9), (1e-12, 1e-11)] {
        let r = reference(&p, &ReferenceOptions::with_tolerance(tol));
        let err = (r.final_state[2] - exact).abs();
        assert!(err < bound, "tol {tol}: error {err}");
    }
}

/// Kelvin contact between two free, undamped masses (Π_ω = 0, no excitation):
/// the contact ends at δ = 0 after half a damped period π/(Π_ωcon√(1−ζ²))
/// with separation/approach = e exactly (SPEC §4's ζ is chosen for that).
#[test]
fn kelvin_restitution_is_exact_for_free_masses() {
    for e in [0.1, 0.4, 0.9] {
        let p = Params {
            omega1: 0.0,
            omega2: 0.0,
            damping: 0.0,
            gap: 0.0,
            restitution: e,
            model: ContactModel::Kelvin,
            cycles: 1,
            yield1: f64::INFINITY,
            yield2: f64::INFINITY,
            ..SET1
        };
        let options = ReferenceOptions {
            excitation: Excitation::None,
            initial_velocity: [1.0, 0.0],
            ..Default::default()
        };
        let r = reference(&p, &options);
        assert_eq!(r.impacts.len(), 1, "e = {e}");
        let imp = r.impacts[0];
        let achieved = imp.separation_velocity / imp.approach_velocity;
        assert!((achieved - e).abs() < 1e-10, "e = {e}: achieved {achieved}");
        let zeta = -e.ln() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
        let duration = std::f64::consts::PI / (p.contact_omega * (1.0 - zeta * zeta).sqrt());
        assert!(((imp.end - imp.start) - duration).abs() < 1e-10, "e = {e}");
        // Momentum Π_m·1 is conserved: Π_m v1 + v2 = Π_m at the end.
        let momentum = p.mass_ratio * r.final_state[1] + r.final_state[3];
        assert!((momentum - p.mass_ratio).abs() < 1e-12);
    }
}

/// A yielding spring under slow cyclic motion: the reference reports yielding
/// exactly when the closed-form elastic peak exceeds Π_uy.
#[test]
fn yield_detected_only_beyond_yield_displacement() {
    let elastic = linear(SET1);
    let o = LinearOscillator::new(elastic.omega1, elastic.damping, 1.0, 0.0, 0.0);
    let pu = peak(|t| o.displacement(t), elastic.tau_end());
    for (uy, yields) in [(pu * 1.01, false), (pu * 0.99, true)] {
        let p = Params {
            yield1: uy,
            ..elastic.clone()
        };
        let r = reference(&p, &ReferenceOptions::default());
        assert_eq!(r.yielded[0], yields, "Π_uy1 = {uy}, elastic peak {pu}");
    }
}
