//! A linear elastic structure (yield = inf, gap = inf) under g = sin τ against
//! the closed-form solution of ẍ + 2ζωẋ + ω²x = −sin τ from rest:
//! steady state x_p = A sin τ + B cos τ with D = (ω²−1)² + (2ζω)²,
//! A = −(ω²−1)/D, B = 2ζω/D, plus the transient
//! e^{−ζωτ}(C1 cos ω_d τ + C2 sin ω_d τ), ω_d = ω√(1−ζ²), C1 = −B,
//! C2 = (ζωC1 − A)/ω_d (x(0) = ẋ(0) = 0). Both structures obey it: the left
//! one's equation is the same divided by Π_m (SPEC §2).

use pounding::model::{Params, SET1};
use pounding::solver::{FullHistory, SolverOptions, simulate};

fn exact(omega: f64, zeta: f64, tau: f64) -> f64 {
    let d = (omega * omega - 1.0).powi(2) + (2.0 * zeta * omega).powi(2);
    let a = -(omega * omega - 1.0) / d;
    let b = 2.0 * zeta * omega / d;
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let c1 = -b;
    let c2 = (zeta * omega * c1 - a) / wd;
    a * tau.sin()
        + b * tau.cos()
        + (-zeta * omega * tau).exp() * (c1 * (wd * tau).cos() + c2 * (wd * tau).sin())
}

fn elastic(dt: f64) -> Params {
    Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        dt,
        cycles: 4,
        ..SET1
    }
}

/// Largest error of x1 and x2 over the history.
fn max_error(dt: f64) -> f64 {
    let p = elastic(dt);
    let mut h = FullHistory::default();
    let r = simulate(&p, &SolverOptions::default(), &mut h);
    assert!(!r.left.yielded && !r.right.yielded && r.impacts.is_empty());
    h.samples
        .iter()
        .map(|s| {
            let e1 = (s.x[0] - exact(p.omega1, p.damping, s.tau)).abs();
            let e2 = (s.x[1] - exact(p.omega2, p.damping, s.tau)).abs();
            e1.max(e2)
        })
        .fold(0.0, f64::max)
}

#[test]
fn error_falls_fourfold_per_halving() {
    let e = [0.02, 0.01, 0.005].map(max_error);
    eprintln!("elastic errors {e:?}");
    // Newmark average acceleration: phase error (ωh)²/12 per radian.
    assert!(e[2] < 2e-4, "{e:?}");
    for k in 0..2 {
        let ratio = e[k] / e[k + 1];
        assert!((3.8..=4.2).contains(&ratio), "ratio {ratio} from {e:?}");
    }
}

#[test]
fn default_step_matches_closed_form_peak() {
    // At Δτ = 0.001 the peak displacement agrees with the closed form to 1e-5.
    let p = elastic(0.001);
    let r = simulate(&p, &SolverOptions::default(), &mut ());
    let exact_peak = |omega: f64| {
        (0..=200_000)
            .map(|i| exact(omega, p.damping, p.tau_end() * i as f64 / 200_000.0).abs())
            .fold(0.0, f64::max)
    };
    let (e1, e2) = (exact_peak(p.omega1), exact_peak(p.omega2));
    assert!(
        (r.left.peak_displacement - e1).abs() < 1e-5 * e1,
        "{} vs {e1}",
        r.left.peak_displacement
    );
    assert!(
        (r.right.peak_displacement - e2).abs() < 1e-5 * e2,
        "{} vs {e2}",
        r.right.peak_displacement
    );
}
