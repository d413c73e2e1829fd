//! Intensity measures (SPEC §12): Sa(T) from the exact Nigam–Jennings
//! recurrence against an independent integration (classical Runge–Kutta at
//! 500 sub-steps a sample, the peaks located by bisection on the step
//! itself), against the closed form of a constant load, and its scaling.

use std::f64::consts::PI;
use std::time::Instant;

use pounding::model::intensity::{IntensityMeasure, SA_DAMPING, spectral_acceleration};
use pounding::model::record::{self, Record, STANDARD_GRAVITY};
use pounding::model::simulated::Simulation;

/// ü + 2ξωu̇ + ω²u = −a(t), a linear between samples: one RK4 step of
/// length h from (u, v) at time τ into the interval starting at `a0`.
fn rk4(state: (f64, f64), tau: f64, h: f64, a0: f64, slope: f64, w: f64, xi: f64) -> (f64, f64) {
    let f = |t: f64, (u, v): (f64, f64)| (v, -(a0 + slope * t) - 2.0 * xi * w * v - w * w * u);
    let add = |(u, v): (f64, f64), (ku, kv): (f64, f64), c: f64| (u + c * ku, v + c * kv);
    let k1 = f(tau, state);
    let k2 = f(tau + 0.5 * h, add(state, k1, 0.5 * h));
    let k3 = f(tau + 0.5 * h, add(state, k2, 0.5 * h));
    let k4 = f(tau + h, add(state, k3, h));
    (
        state.0 + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
        state.1 + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1),
    )
}

/// ω² max |u| by RK4 with `substeps` a sample; where u̇ changes sign within a
/// sub-step the root is bisected on a shortened RK4 step from its start.
fn reference_sa(a: &[f64], dt: f64, period: f64, substeps: usize) -> f64 {
    let (w, xi) = (2.0 * PI / period, SA_DAMPING);
    let h = dt / substeps as f64;
    let mut state = (0.0, 0.0);
    let mut peak = 0.0f64;
    for pair in a.windows(2) {
        let slope = (pair[1] - pair[0]) / dt;
        for i in 0..substeps {
            let tau = i as f64 * h;
            let next = rk4(state, tau, h, pair[0], slope, w, xi);
            if state.1 * next.1 < 0.0 {
                let (mut lo, mut hi) = (0.0, h);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    let v = rk4(state, tau, mid, pair[0], slope, w, xi).1;
                    if (v < 0.0) == (state.1 < 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let u = rk4(state, tau, 0.5 * (lo + hi), pair[0], slope, w, xi).0;
                peak = peak.max(u.abs());
            }
            state = next;
            peak = peak.max(state.0.abs());
        }
    }
    w * w * peak
}

fn simulated_record() -> Record {
    let sim = Simulation {
        duration: 8.0,
        ..Simulation::default()
    };
    sim.record("sim", 11, 1)
}

#[test]
fn sa_agrees_with_an_independent_integration_to_1e_9() {
    let r = simulated_record();
    for period in [0.2, 0.5, 1.0, 3.0] {
        let exact = spectral_acceleration(&r.acceleration, r.dt, period, SA_DAMPING);
        let reference = reference_sa(&r.acceleration, r.dt, period, 500);
        let error = (exact / reference - 1.0).abs();
        assert!(
            error < 1e-9,
            "T = {period}: {exact} vs {reference} ({error:e})"
        );
        eprintln!("T = {period} s: relative difference {error:.1e}");
    }
}

#[test]
fn a_peak_between_samples_is_located_not_sampled() {
    // A constant load a0 from rest: the first peak of |u|, at t = π/ω_d,
    // is (a0/ω²)(1 + e^{−ξπ/√(1−ξ²)}); with T = 0.77 s that is t = 0.3855 s,
    // between the samples at 0.38 and 0.39 s.
    let a = vec![2.0; 101];
    let xi = SA_DAMPING;
    let want = 2.0 * (1.0 + (-xi * PI / (1.0 - xi * xi).sqrt()).exp());
    let got = spectral_acceleration(&a, 0.01, 0.77, xi);
    assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
    // The same response read at the samples only falls short.
    let (w, wd) = (2.0 * PI / 0.77, 2.0 * PI / 0.77 * (1.0 - xi * xi).sqrt());
    let sampled = (0..101)
        .map(|k| {
            let t = k as f64 * 0.01;
            let u = 2.0 / (w * w)
                * (1.0
                    - (-xi * w * t).exp()
                        * ((wd * t).cos() + xi / (1.0 - xi * xi).sqrt() * (wd * t).sin()));
            w * w * u.abs()
        })
        .fold(0.0f64, f64::max);
    assert!(sampled < want * (1.0 - 1e-5), "{sampled} vs {want}");
}

#[test]
fn scaling_a_record_scales_pga_and_sa() {
    let r = simulated_record();
    let s = 2.5;
    let scaled = Record::from_samples(
        "scaled",
        r.dt,
        r.acceleration.iter().map(|a| a * s).collect(),
    );
    for im in [
        IntensityMeasure::Pga,
        IntensityMeasure::parse("sa:0.3").unwrap(),
        IntensityMeasure::parse("sa:2").unwrap(),
    ] {
        let (one, many) = (im.measure(&r), im.measure(&scaled));
        assert!(
            (many / (s * one) - 1.0).abs() < 1e-12,
            "{im}: {one} × {s} vs {many}"
        );
    }
    // PGA in g of the simulated record: its target 0.3 g.
    assert!((IntensityMeasure::Pga.measure(&r) - 0.3).abs() < 1e-15);
}

#[test]
fn sa_of_the_shipped_record_is_in_g_and_quick() {
    let shipped = concat!(env!("CARGO_MANIFEST_DIR"), "/presets/synthetic.at2");
    let r = record::load(shipped).unwrap();
    let sa = IntensityMeasure::Sa { period: 0.4 };
    let t = Instant::now();
    let value = sa.measure(&r);
    let elapsed = t.elapsed();
    let direct = spectral_acceleration(&r.acceleration, r.dt, 0.4, SA_DAMPING) / STANDARD_GRAVITY;
    assert_eq!(value, direct);
    // A 5 %-damped oscillator near the record's 2.5 Hz amplifies its 0.3 g.
    assert!(value > 0.3 && value < 3.0, "{value}");
    eprintln!("Sa(0.4 s) of {} samples: {elapsed:?}", r.acceleration.len());
}
