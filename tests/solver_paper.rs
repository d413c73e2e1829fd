//! The paper's presets: energy balance, tension, the nine poundings of its
//! Figure 3, and the qualitative findings of its Figures 3–6.

use pounding::model::{ContactModel, Params, SET1, SET2};
use pounding::solver::run;

fn with(set: Params, model: ContactModel) -> Params {
    Params {
        model,
        ..set.clone()
    }
}

#[test]
fn energy_balance_closes() {
    for set in [SET1, SET2] {
        for model in ContactModel::PAPER {
            let r = run(&with(set.clone(), model));
            let e = r.energy;
            assert!(e.residual < 1e-6, "{model}: residual {}", e.residual);
            // The balance is not trivially zero: input, damping and contact work are all sizeable.
            assert!(
                e.max_input > 1.0 && e.damping > 0.5 && e.contact > 0.1,
                "{e:?}"
            );
        }
    }
}

#[test]
fn improved_kelvin_never_pulls_but_kelvin_does() {
    for set in [SET1, SET2] {
        let r = run(&with(set, ContactModel::ImprovedKelvin));
        assert!(
            r.min_force >= -1e-9,
            "improved Kelvin min force {}",
            r.min_force
        );
    }
    let kelvin = run(&with(SET1, ContactModel::Kelvin));
    assert!(
        kelvin.min_force < -1.0,
        "Kelvin min force {}",
        kelvin.min_force
    );
}

#[test]
fn set1_improved_kelvin_pounds_nine_times() {
    let r = run(&SET1);
    assert_eq!(r.impacts.len(), 9);
    // Figure 3(c, d): the left structure yields, the right one stays elastic.
    assert!(r.left.yielded && !r.right.yielded);
    // Peaks (this solver at Δτ = 0.001, converged to ~2e-6, see solver_convergence).
    let expected = [3.22245, 1.89227, 0.47877, 0.83284];
    for (got, want) in r.peaks().into_iter().zip(expected) {
        assert!((got - want).abs() < 2e-5, "{:?} vs {expected:?}", r.peaks());
    }
    for imp in &r.impacts {
        assert!(
            imp.ended
                && imp.approach_velocity > 0.0
                && imp.restitution > 0.3
                && imp.restitution < 0.4
        );
    }
}

#[test]
fn both_models_give_nearly_the_same_displacements() {
    // Figures 4–5: the displacement histories of the two models basically coincide.
    for set in [SET1, SET2] {
        let k = run(&with(set.clone(), ContactModel::Kelvin));
        let ik = run(&with(set, ContactModel::ImprovedKelvin));
        let rel = (k.left.peak_displacement - ik.left.peak_displacement).abs()
            / ik.left.peak_displacement;
        assert!(rel < 0.03, "left Π_u differs by {rel}");
    }
}

#[test]
fn pounding_amplifies_set1_and_suppresses_set2_on_the_left() {
    // Section 3: set 1 lies in the amplification region, set 2 in the suppression region.
    let free = |p: &Params| {
        run(&Params {
            gap: f64::INFINITY,
            ..p.clone()
        })
    };
    let (p1, f1) = (run(&SET1), free(&SET1));
    assert!(p1.left.peak_displacement > 1.02 * f1.left.peak_displacement);
    let (p2, f2) = (run(&SET2), free(&SET2));
    assert!(p2.left.peak_displacement < 0.98 * f2.left.peak_displacement);
    // The right structure's response grows with pounding in both (Figure 5, Figure 7(d)).
    assert!(p2.right.peak_displacement > f2.right.peak_displacement);
}
