//! The demands of SPEC §6 ("Demands for performance studies"): the peak
//! absolute acceleration A_i = max |ẍ_i + g|, the ductility μ_i = Π_u/Π_uy,
//! the residual displacement r_i = (1 − Π_α)(x_i − z_i) at τ_end and the
//! hysteretic energy E_h,i = ∫ f_s ẋ dτ − f_s²/(2k), against closed forms
//! and the independent reference solver.

use std::sync::Arc;

use pounding::model::record::{Record, intern};
use pounding::model::{ContactModel, Excitation, Method, Params, RecordMotion, SET1};
use pounding::reference::closed_form::LinearOscillator;
use pounding::reference::{ReferenceOptions, reference};
use pounding::solver::exact::{self, ExactOptions};
use pounding::solver::{exact_options, newmark_options, run_for_sweep, simulate, solve};

/// Both structures linear and apart (yield = gap = inf), under `excitation`.
fn linear(excitation: Excitation, cycles: u32) -> Params {
    let p = Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        excitation,
        record_omega: 5.0,
        cycles,
        method: Method::Exact,
        ..SET1
    };
    p.validate().unwrap();
    p
}

/// max |f| over [t0, t1], located independently of the solver: f sampled at
/// n + 1 points, and each sign change of its derivative `df` between two
/// samples refined by bisection (80 halvings) to an extremum; the ends count.
fn max_abs(f: &dyn Fn(f64) -> f64, df: &dyn Fn(f64) -> f64, t0: f64, t1: f64, n: usize) -> f64 {
    let mut best = f(t0).abs().max(f(t1).abs());
    let at = |k: usize| t0 + (t1 - t0) * k as f64 / n as f64;
    for k in 0..n {
        let (mut lo, mut hi) = (at(k), at(k + 1));
        best = best.max(f(hi).abs());
        let (dlo, dhi) = (df(lo), df(hi));
        if dlo * dhi >= 0.0 {
            continue;
        }
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if (df(mid) < 0.0) == (dlo < 0.0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        best = best.max(f(0.5 * (lo + hi)).abs());
    }
    best
}

/// The damped oscillator ẍ + 2ζω ẋ + ω² x = −(a + b t) in closed form from
/// (x₀, ẋ₀) at t = 0 (the equation of SPEC §2 divided by the mass, on one
/// piece of a piecewise-linear g): the particular part P + Q t with
/// Q = −b/ω², P = −(a + 2ζω Q)/ω², and the free vibration e^{−σt}(C cos ω_d t +
/// E sin ω_d t), σ = ζω, ω_d = ω√(1 − ζ²). Returns t ↦ (x, ẋ).
fn piece(omega: f64, zeta: f64, a: f64, b: f64, x0: f64, v0: f64) -> impl Fn(f64) -> (f64, f64) {
    let w2 = omega * omega;
    let q = -b / w2;
    let p = -(a + 2.0 * zeta * omega * q) / w2;
    let sigma = zeta * omega;
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let c = x0 - p;
    let e = (v0 - q + sigma * c) / wd;
    move |t: f64| {
        let decay = (-sigma * t).exp();
        let (s, co) = (wd * t).sin_cos();
        let x = p + q * t + decay * (c * co + e * s);
        let v = q + decay * ((e * wd - sigma * c) * co - (c * wd + sigma * e) * s);
        (x, v)
    }
}

/// A short record: 30 samples at DT = 0.04 s of a chirp under a rising then
/// falling envelope (ω_p = 5 rad/s: 0.2 in τ between samples), ending away from 0
/// so that g jumps to 0 after its last sample.
fn short_record() -> Arc<Record> {
    let a: Vec<f64> = (0..30)
        .map(|k| {
            let t = k as f64 * 0.04;
            2.0 * t * (1.5 - 0.8 * t) * (4.0 * t + 3.0 * t * t).cos() + 0.3
        })
        .collect();
    intern(Record::from_samples("demands", 0.04, a))
}

/// A linear structure under a record: A = max |ẍ + g| = max |2ζω ẋ + ω² x|
/// over the record and the free vibration after it, by the closed form on
/// each piece between samples (g linear there, 0 after the last), agrees
/// with the exact method to 1e-12 (relative).
#[test]
fn linear_absolute_acceleration_under_a_record_is_the_closed_form() {
    let p = linear(Excitation::Record(RecordMotion::new(short_record())), 2);
    let g = p.ground();
    let r = solve(&p, &mut ());
    assert!(r.completed);
    let tau_end = p.tau_end();
    for (i, omega) in [(0, p.omega1), (1, p.omega2)] {
        let zeta = p.damping;
        let (mut x, mut v) = (0.0, 0.0);
        let (mut t0, mut peak) = (0.0f64, 0.0f64);
        while t0 < tau_end {
            let t1 = g.next_break(t0).min(tau_end);
            // g on the piece: its value and slope at the middle (linear inside).
            let mid = 0.5 * (t0 + t1);
            let [g_mid, slope] = g.phasor(mid);
            let (a, b) = (g_mid - slope * (mid - t0), slope);
            let motion = piece(omega, zeta, a, b, x, v);
            let absolute = |t: f64| {
                let (x, v) = motion(t);
                -(2.0 * zeta * omega * v + omega * omega * x)
            };
            let rate = |t: f64| {
                let (x, v) = motion(t);
                let accel = -(a + b * t) - 2.0 * zeta * omega * v - omega * omega * x;
                -(2.0 * zeta * omega * accel + omega * omega * v)
            };
            let n = ((t1 - t0) / 0.005).ceil() as usize;
            peak = peak.max(max_abs(&absolute, &rate, 0.0, t1 - t0, n));
            (x, v) = motion(t1 - t0);
            t0 = t1;
        }
        let found = r.structure(i).peak_absolute_acceleration;
        let err = (found - peak).abs() / peak;
        assert!(err <= 1e-12, "structure {i}: {found} vs {peak}: {err:e}");
    }
}

/// A linear structure under g = sin τ from rest: A against the closed-form
/// from-rest solution (reference::closed_form), its maximum located by
/// sampling and root refinement, to 1e-12. Started on its steady state
/// instead (x₀ = B, ẋ₀ = A of x_p = A sin τ + B cos τ), the motion is the
/// steady state alone, x = X sin(τ + φ), and |ẍ + g| = |2ξω ẋ + ω² x| has the
/// amplitude X ω² √(1 + (2ξ/ω)²) (forcing frequency 1): the exact method's
/// A is that, to 1e-12.
#[test]
fn linear_absolute_acceleration_under_a_sine_is_the_closed_form() {
    let p = linear(Excitation::Sine, 3);
    let r = solve(&p, &mut ());
    let zeta = p.damping;
    for (i, omega) in [(0, p.omega1), (1, p.omega2)] {
        let o = LinearOscillator::new(omega, zeta, 1.0, 0.0, 0.0);
        let absolute =
            |t: f64| -(2.0 * zeta * omega * o.velocity(t) + omega * omega * o.displacement(t));
        let rate = |t: f64| {
            let v = o.velocity(t);
            let accel = -t.sin() - 2.0 * zeta * omega * v - omega * omega * o.displacement(t);
            -(2.0 * zeta * omega * accel + omega * omega * v)
        };
        let peak = max_abs(&absolute, &rate, 0.0, p.tau_end(), 20_000);
        let found = r.structure(i).peak_absolute_acceleration;
        let err = (found - peak).abs() / peak;
        assert!(err <= 1e-12, "structure {i}: {found} vs {peak}: {err:e}");
    }
    // On the steady state from the start.
    let steady = |omega: f64| {
        let detune = omega * omega - 1.0;
        let d = detune * detune + (2.0 * zeta * omega).powi(2);
        // x_p = A sin τ + B cos τ: x(0) = B, ẋ(0) = A.
        let (a, b) = (-detune / d, 2.0 * zeta * omega / d);
        let amplitude = 1.0 / d.sqrt();
        [
            b,
            a,
            amplitude * omega * omega * (1.0 + (2.0 * zeta / omega).powi(2)).sqrt(),
        ]
    };
    let ([x1, v1, a1], [x2, v2, a2]) = (steady(p.omega1), steady(p.omega2));
    let r = exact::simulate(
        &p,
        &ExactOptions {
            initial_displacement: [x1, x2],
            initial_velocity: [v1, v2],
            ..exact_options(&p)
        },
        &mut (),
    );
    for (i, expected) in [(0, a1), (1, a2)] {
        let found = r.structure(i).peak_absolute_acceleration;
        let err = (found - expected).abs() / expected;
        assert!(err <= 1e-12, "steady {i}: {found} vs {expected}: {err:e}");
    }
}

/// Kelvin with e = 0.1 (ζ ≈ 0.59 > 1/2): the pounding force is largest at
/// onset, where its dashpot term jumps from 0 to c v₀. The reference solver
/// (which tracks |ẍ + g| on both sides of every event) finds the left
/// structure's A at an impact's start; the exact method's A agrees with it
/// to 1e-9 (relative), and Newmark's (which counts both one-sided values at
/// its located onsets) to 1e-3.
#[test]
fn a_kelvin_onset_jump_counts_in_the_peak_absolute_acceleration() {
    let p = Params {
        model: ContactModel::Kelvin,
        restitution: 0.1,
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        method: Method::Exact,
        cycles: 4,
        ..SET1
    };
    p.validate().unwrap();
    let exact = solve(&p, &mut ());
    assert!(!exact.impacts.is_empty());
    let r = reference(&p, &ReferenceOptions::for_params(&p, 1e-12));
    assert!(r.completed);
    let at = r.peak_absolute_acceleration_at[0];
    assert!(
        r.impacts.iter().any(|imp| (imp.start - at).abs() < 1e-9),
        "A1 at τ = {at}, not at an onset"
    );
    let expected = r.peak_absolute_acceleration[0];
    let found = exact.left.peak_absolute_acceleration;
    let err = (found - expected).abs() / expected;
    assert!(err < 1e-9, "exact {found} vs reference {expected}: {err:e}");
    let newmark = solve(
        &Params {
            method: Method::Newmark,
            ..p.clone()
        },
        &mut (),
    );
    let err = (newmark.left.peak_absolute_acceleration - expected).abs() / expected;
    eprintln!("A1 = {expected} at τ = {at}; newmark error {err:e}");
    assert!(err < 1e-3, "newmark: {err:e}");
}

/// Residual displacement: exactly 0 for an elastic structure (both methods);
/// for set 1's yielding left structure, (1 − Π_α)(x − z) of the reference's
/// final state to 1e-8 (exact) and 1e-4 (Newmark, Δτ = 0.001).
#[test]
fn residual_displacement_is_the_final_plastic_offset() {
    let p = Params {
        method: Method::Exact,
        ..SET1
    };
    let exact = solve(&p, &mut ());
    let newmark = simulate(&p, &newmark_options(&p), &mut ());
    // Set 1's right structure does not yield; make it elastic outright too.
    for q in [
        p.clone(),
        Params {
            yield2: f64::INFINITY,
            ..p.clone()
        },
    ] {
        assert_eq!(solve(&q, &mut ()).right.residual_displacement, 0.0);
    }
    let elastic = linear(Excitation::Sine, 2);
    for r in [
        solve(&elastic, &mut ()),
        simulate(&elastic, &newmark_options(&elastic), &mut ()),
    ] {
        assert_eq!(r.left.residual_displacement, 0.0);
        assert_eq!(r.right.residual_displacement, 0.0);
    }
    let reference = reference(&p, &ReferenceOptions::for_params(&p, 1e-12));
    let expected = (1.0 - p.alpha) * (reference.final_state[0] - reference.final_elastic_part[0]);
    assert!(exact.left.yielded && expected.abs() > 0.1, "{expected}");
    let found = exact.left.residual_displacement;
    assert!((found - expected).abs() < 1e-8, "{found} vs {expected}");
    let found = newmark.left.residual_displacement;
    assert!(
        (found - expected).abs() < 1e-4,
        "newmark {found} vs {expected}"
    );
}

/// Hysteretic energy: per-structure spring works sum to E_spring (1e-13
/// relative); E_h is the spring work less f_s²/(2k) with f_s from the
/// reference's final state (1e-8 relative); 0 to round-off (1e-12 of the
/// input) for elastic structures; Newmark agrees with the exact method to
/// 1e-4 at Δτ = 0.001; where the exact method did not integrate the work
/// (a sweep's run), it is NaN, as A is.
#[test]
fn hysteretic_energy_is_the_spring_work_less_the_stored_energy() {
    let p = Params {
        method: Method::Exact,
        ..SET1
    };
    let exact = solve(&p, &mut ());
    let e = &exact.energy;
    let sum = e.spring_by_structure[0] + e.spring_by_structure[1];
    assert!(
        (sum - e.spring).abs() <= 1e-13 * e.spring.abs(),
        "{sum} vs {}",
        e.spring
    );
    let reference = reference(&p, &ReferenceOptions::for_params(&p, 1e-12));
    let stiffness = [p.mass_ratio * p.omega1 * p.omega1, p.omega2 * p.omega2];
    for (i, k) in stiffness.into_iter().enumerate() {
        let (x, z) = (
            reference.final_state[2 * i],
            reference.final_elastic_part[i],
        );
        let force = p.alpha * k * x + (1.0 - p.alpha) * k * z;
        let expected = e.spring_by_structure[i] - force * force / (2.0 * k);
        let found = exact.structure(i).hysteretic_energy;
        assert!(
            (found - expected).abs() <= 1e-8 * e.spring.abs(),
            "structure {i}: {found} vs {expected}"
        );
    }
    // Set 1's left structure yields and dissipates; its right one does not.
    assert!(exact.left.hysteretic_energy > 1.0);
    assert!(exact.right.hysteretic_energy.abs() < 1e-12 * e.input);
    let newmark = simulate(&p, &newmark_options(&p), &mut ());
    let nm = &newmark.energy;
    assert!((nm.spring_by_structure[0] + nm.spring_by_structure[1] - nm.spring).abs() < 1e-13);
    let err = (newmark.left.hysteretic_energy - exact.left.hysteretic_energy).abs()
        / exact.left.hysteretic_energy;
    assert!(err < 1e-4, "newmark vs exact: {err:e}");
    let elastic = linear(Excitation::Sine, 2);
    for r in [
        solve(&elastic, &mut ()),
        simulate(&elastic, &newmark_options(&elastic), &mut ()),
    ] {
        for i in 0..2 {
            let h = r.structure(i).hysteretic_energy;
            assert!(
                h.abs() < 1e-12 * r.energy.max_input,
                "{:?} {i}: {h:e}",
                r.method
            );
        }
    }
    let sweep = run_for_sweep(&p, pounding::solver::exact::ContactExtremes::None);
    assert!(sweep.left.hysteretic_energy.is_nan());
    assert!(sweep.left.peak_absolute_acceleration.is_nan());
    // The demands that need no integral are there (the sweep's run takes other
    // segments, quiet ones among them: equal to round-off).
    let (swept, full) = (
        sweep.left.residual_displacement,
        exact.left.residual_displacement,
    );
    assert!((swept - full).abs() < 1e-12, "{swept} vs {full}");
}

/// Ductility: Π_u/Π_uy, ∞ for an elastic structure.
#[test]
fn ductility_is_the_peak_over_the_yield_displacement() {
    let p = Params {
        method: Method::Exact,
        yield2: f64::INFINITY,
        ..SET1
    };
    let r = solve(&p, &mut ());
    assert_eq!(r.left.ductility, r.left.peak_displacement / p.yield1);
    assert!(r.left.ductility > 1.0);
    assert_eq!(r.right.ductility, f64::INFINITY);
}

/// Newmark's A converges to the exact method's as Δτ shrinks (set 1, with
/// pounding and yield): the error at Δτ = 0.0005 is below a third of that
/// at 0.002 and below 1e-4.
#[test]
fn newmark_absolute_acceleration_converges_to_the_exact_one() {
    let p = Params {
        method: Method::Exact,
        ..SET1
    };
    let truth = solve(&p, &mut ()).left.peak_absolute_acceleration;
    let err = |dt: f64| {
        let q = Params {
            dt,
            method: Method::Newmark,
            ..p.clone()
        };
        (solve(&q, &mut ()).left.peak_absolute_acceleration - truth).abs() / truth
    };
    let (coarse, fine) = (err(0.002), err(0.0005));
    eprintln!("A1: {coarse:e} at Δτ = 0.002, {fine:e} at 0.0005");
    assert!(fine < coarse / 3.0 && fine < 1e-4, "{coarse:e} {fine:e}");
}
