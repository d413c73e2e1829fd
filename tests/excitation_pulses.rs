//! Linear structures (no yield, no contact) under each cycloidal pulse of
//! SPEC §9, against their closed-form response, and the pulses' self-similarity (SPEC §8).

use pounding::model::physical::{G, Physical};
use pounding::model::{Excitation, Method, Params, Pulse, SET1};
use pounding::solver::{FullHistory, exact_options, newmark_options, simulate, solve};

/// x(τ), ẋ(τ) of ẍ + 2ζωẋ + ω²x = −g(τ), from x(0) = 0, ẋ(0) = v₀, with
/// g = a sin(τ + θ) on [0, T] and 0 after: on [0, T] the steady state
/// a(A sin(τ+θ) + B cos(τ+θ)), A = −(ω²−1)/D, B = 2ζω/D, D = (ω²−1)² + (2ζω)²,
/// plus e^{−ζωτ}(C cos ω_d τ + E sin ω_d τ) matching the start; after T, free
/// vibration from the state at T.
fn closed_form(omega: f64, zeta: f64, v0: f64, a: f64, theta: f64, end: f64, tau: f64) -> [f64; 2] {
    let sigma = zeta * omega;
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let free = |x0: f64, v0: f64, t: f64| -> [f64; 2] {
        let (s, c) = (wd * t).sin_cos();
        let decay = (-sigma * t).exp();
        let e = (v0 + sigma * x0) / wd;
        [
            decay * (x0 * c + e * s),
            decay * ((e * wd - sigma * x0) * c - (x0 * wd + sigma * e) * s),
        ]
    };
    let d = (omega * omega - 1.0).powi(2) + (2.0 * zeta * omega).powi(2);
    let (big_a, big_b) = (-(omega * omega - 1.0) / d, 2.0 * zeta * omega / d);
    let forced = |t: f64| -> [f64; 2] {
        let (s, c) = (t + theta).sin_cos();
        [a * (big_a * s + big_b * c), a * (big_a * c - big_b * s)]
    };
    let start = forced(0.0);
    let during = |t: f64| {
        let p = forced(t);
        let h = free(-start[0], v0 - start[1], t);
        [p[0] + h[0], p[1] + h[1]]
    };
    if tau <= end {
        during(tau)
    } else {
        let s = during(end);
        free(s[0], s[1], tau - end)
    }
}

fn linear(excitation: Excitation) -> Params {
    Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        excitation,
        method: Method::Exact,
        cycles: 4,
        dt: 0.01,
        ..SET1
    }
}

/// (amplitude, phase θ) of each pulse written as a sin(τ + θ).
fn sinusoid(p: Pulse) -> (f64, f64) {
    match p {
        Pulse::A => (1.0, 0.0),
        Pulse::B => (-1.0, 0.0),
        Pulse::C { phase, .. } => (1.0, phase + std::f64::consts::FRAC_PI_2),
    }
}

#[test]
fn cn_phases_are_the_spec_values() {
    let Pulse::C { phase: p1, .. } = Pulse::c(1) else {
        unreachable!()
    };
    let Pulse::C { phase: p2, .. } = Pulse::c(2) else {
        unreachable!()
    };
    assert!(
        (p1 - 0.21898).abs() < 5e-6 && (p2 - 0.12873).abs() < 5e-6,
        "{p1} {p2}"
    );
    // The ground comes back to rest and to zero displacement at the pulse's end.
    for n in [1, 2] {
        let e = Excitation::Pulse(Pulse::c(n));
        let [_, v, u] = e.ground(Pulse::c(n).end());
        assert!(v.abs() < 1e-14 && u.abs() < 1e-13, "C{n}: {v} {u}");
    }
    // Type A: one-sided velocity 1 − cos τ, displacement 2π at the end.
    let [_, v, u] = Excitation::Pulse(Pulse::A).ground(7.0);
    assert!(v.abs() < 1e-15 && (u - 2.0 * std::f64::consts::PI).abs() < 1e-14);
}

#[test]
fn exact_matches_the_closed_form_under_every_pulse() {
    for name in ["pulse-a", "pulse-b", "pulse-c1", "pulse-c2"] {
        let excitation: Excitation = name.parse().unwrap();
        let Excitation::Pulse(pulse) = excitation else {
            unreachable!()
        };
        let (a, theta) = sinusoid(pulse);
        let p = linear(excitation.clone());
        let v0 = excitation.initial_velocity();
        let mut h = FullHistory::default();
        let r = solve(&p, &mut h);
        assert!(r.completed);
        let mut worst: f64 = 0.0;
        for s in &h.samples {
            for (i, omega) in [p.omega1, p.omega2].into_iter().enumerate() {
                let [x, v] = closed_form(omega, p.damping, v0[i], a, theta, pulse.end(), s.tau);
                worst = worst.max((s.x[i] - x).abs()).max((s.v[i] - v).abs());
            }
        }
        assert!(worst < 1e-9, "{name}: {worst:e}");
        assert!(h.samples.len() > 2000);
        // Newmark (Δτ = 0.001) agrees to its own accuracy.
        let n = simulate(
            &Params {
                dt: 0.001,
                ..p.clone()
            },
            &newmark_options(&p),
            &mut (),
        );
        let e = pounding::solver::relative_peak_error(&n.peaks(), &r.peaks());
        assert!(e < 2e-4, "{name}: Newmark {e:e}");
        let _ = exact_options(&p);
    }
}

/// SPEC §8 for pulses: the same structures at a_p = 0.2 g and 0.8 g with
/// yield and gap scaled with a_p share every Π-group, so the dimensionless
/// peaks agree whatever the contact law.
#[test]
fn pulses_are_self_similar() {
    for name in ["pulse-a", "pulse-b", "pulse-c1"] {
        for model in ["improved-kelvin", "hertz"] {
            let mut settings = Params {
                method: Method::Exact,
                ..SET1
            };
            settings.set("excitation", name).unwrap();
            settings.set("model", model).unwrap();
            let base = Physical::from_params(&settings, 0.2 * G, 2.0 * std::f64::consts::PI, 1e6);
            let peaks: Vec<[f64; 4]> = [0.2, 0.8]
                .iter()
                .map(|&level| {
                    let p = base.at_level(level * G, true).to_params(&settings).unwrap();
                    let r = solve(&p, &mut ());
                    assert!(r.completed && !r.impacts.is_empty(), "{name} {model}");
                    r.peaks()
                })
                .collect();
            let e = pounding::solver::relative_peak_error(&peaks[0], &peaks[1]);
            assert!(e < 1e-9, "{name} {model}: {e:e}");
        }
    }
}

/// Newmark's observed order against the exact method: the peaks' error at
/// Δτ and Δτ/2 under the type C1 pulse, whose g jumps from cos(3π − φ) to 0 at
/// its end (a step across that jump would be first order; the driver ends a
/// step on it).
#[test]
fn newmark_is_second_order_under_pulse_c1() {
    let p = linear("pulse-c1".parse().unwrap());
    let truth = solve(&p, &mut ()).peaks();
    let err = |dt: f64| {
        let q = Params { dt, ..p.clone() };
        pounding::solver::relative_peak_error(
            &simulate(&q, &newmark_options(&q), &mut ()).peaks(),
            &truth,
        )
    };
    // Δτ chosen so that the pulse's end falls inside a step.
    let (coarse, fine) = (err(0.0137), err(0.0137 / 2.0));
    let order = (coarse / fine).log2();
    eprintln!("pulse-c1: order {order} ({coarse:e}, {fine:e})");
    assert!(
        order > 1.8 && order < 2.2,
        "order {order} ({coarse:e}, {fine:e})"
    );
}
