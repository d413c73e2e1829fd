//! Newmark-β on a row (SPEC §5, §13) converges to the exact method at
//! second order as Δt halves: yielding, and contact onsets located per
//! floor pair.

use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, RowRun, run_newmark, run_row};

fn error(a: &RowRun, b: &RowRun) -> f64 {
    let mut worst = 0.0f64;
    for (fa, fb) in a.floors.iter().zip(&b.floors) {
        let scale = fb.iter().fold(0.0f64, |m, f| m.max(f.displacement));
        for (x, y) in fa.iter().zip(fb) {
            worst = worst.max((x.displacement - y.displacement).abs() / scale);
        }
    }
    worst
}

#[test]
fn newmark_converges_to_the_exact_method_at_second_order() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load("block-and-frame").unwrap();
    let duration = 4.0;
    let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
    assert!(exact.impacts() > 0);
    let errors: Vec<f64> = [4e-4, 2e-4, 1e-4, 5e-5]
        .iter()
        .map(|&dt| {
            let nm = run_newmark(&row, &ground, duration, dt).unwrap();
            let counts: Vec<usize> = nm.pairs.iter().map(|p| p.impacts.len()).collect();
            let want: Vec<usize> = exact.pairs.iter().map(|p| p.impacts.len()).collect();
            assert_eq!(counts, want, "Δt = {dt}");
            error(&nm, &exact)
        })
        .collect();
    println!("errors {errors:?}");
    for w in errors.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((1.6..2.6).contains(&order), "order {order}: {errors:?}");
    }
    assert!(errors[0] < 1e-3, "{errors:?}");
}

/// Largest peak difference of |u|, |u̇| and |Δ| per floor, relative to the
/// largest of each in its building (the measure of `pounding bench`).
fn peak_error(a: &RowRun, b: &RowRun) -> f64 {
    let mut worst = 0.0f64;
    for (fa, fb) in a.floors.iter().zip(&b.floors) {
        let top = |f: fn(&pounding::solver::buildings::FloorPeaks) -> f64| {
            fb.iter().map(f).fold(0.0f64, f64::max)
        };
        let (su, sv, sd) = (
            top(|f| f.displacement),
            top(|f| f.velocity),
            top(|f| f.drift),
        );
        for (x, y) in fa.iter().zip(fb) {
            worst = worst
                .max((x.displacement - y.displacement).abs() / su)
                .max((x.velocity - y.velocity).abs() / sv)
                .max((x.drift - y.drift).abs() / sd);
        }
    }
    worst
}

/// The default step keeps Newmark's phase drift (∝ Δt²·duration) that of
/// 5e-5 s over 10 s, in whole steps per record sample: on the 17-storey
/// row under an 8,000-sample record (44.7 s) it is within 1e-5 of the
/// exact method, where 5e-5 s is 3.8e-5 off.
#[test]
fn the_default_step_keeps_a_long_record_within_1e_5() {
    use pounding::model::simulated::Simulation;
    use pounding::solver::buildings::default_step;
    let record = Simulation::synthetic("synthetic:8000", 8000).unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load("three-in-series").unwrap();
    let duration = ground.end() + pounding::model::buildings::matrices::default_tail(&row);
    let dt = default_step(&row, duration, &ground);
    let per_sample = record.dt / dt;
    assert!(
        (per_sample - per_sample.round()).abs() < 1e-9,
        "{per_sample} steps a sample"
    );
    assert!(dt <= 5e-5 * (10.0 / duration).sqrt() && dt > 0.99 * 5e-5 * (10.0 / duration).sqrt());
    // Short runs keep 5e-5 s (a whole number of them per 5 ms sample).
    assert_eq!(default_step(&row, 8.0, &ground), 5e-5);
    let sine = Ground::sine(3.0, 6.0, 30.0);
    assert_eq!(default_step(&row, 40.0, &sine), 2.5e-5);
    let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
    let nm = run_newmark(&row, &ground, duration, dt).unwrap();
    let counts = |r: &RowRun| r.pairs.iter().map(|p| p.impacts.len()).collect::<Vec<_>>();
    assert_eq!(counts(&nm), counts(&exact));
    let e = peak_error(&nm, &exact);
    assert!(e < 1e-5, "error {e} at Δt = {dt}");
}

/// Under each cycloidal pulse of SPEC §9 (a_p = 0.5 g, T_p = 1 s, then 2 s
/// of free vibration), Newmark at its default step has the exact method's
/// impacts per pair and is within 1e-4 of its peaks, and doubling the step
/// multiplies the error by 4 (order 2): the type B pulse's initial velocity
/// −V_p starts both methods, and the jump of ü_g at a type C pulse's end is
/// a step's end. Measured at 5e-5 s: 6.8e-6 (A), 4.6e-6 (B), 8.8e-6 (C1),
/// 8.9e-5 (C2, the block's first-floor velocity, which peaks in an impact).
#[test]
fn under_each_pulse_newmark_converges_at_second_order() {
    use pounding::model::excitation::Pulse;
    use pounding::solver::buildings::default_step;
    let row = buildings::load("block-and-frame").unwrap();
    let (ap, omega) = (0.5 * 9.80665, 2.0 * std::f64::consts::PI);
    let counts = |r: &RowRun| r.pairs.iter().map(|p| p.impacts.len()).collect::<Vec<_>>();
    for pulse in [Pulse::A, Pulse::B, Pulse::c(1), Pulse::c(2)] {
        let ground = Ground::from_pulse(pulse, ap, omega);
        let duration = ground.end() + 2.0;
        let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
        assert!(exact.impacts() > 0, "{pulse:?}");
        let dt = default_step(&row, duration, &ground);
        let nm = run_newmark(&row, &ground, duration, dt).unwrap();
        assert_eq!(counts(&nm), counts(&exact), "{pulse:?}");
        let e = peak_error(&nm, &exact);
        let coarse = peak_error(
            &run_newmark(&row, &ground, duration, 2.0 * dt).unwrap(),
            &exact,
        );
        let order = (coarse / e).log2();
        println!("{pulse:?}: {e:e} at {dt} s, order {order:.3}");
        assert!(e < 1e-4, "{pulse:?}: error {e}");
        assert!((1.8..2.2).contains(&order), "{pulse:?}: order {order}");
    }
}

/// A step beyond the contact's period (19 ms on block-and-frame; 5 ms is
/// about a quarter of it, under the record's sample interval) leaves
/// Newton unable to resolve an impact: the run stops with the time and
/// a message that names the iteration and a smaller --dt, not "runaway".
#[test]
fn a_step_newton_cannot_resolve_says_newmark_did_not_converge() {
    use pounding::solver::buildings::RowError;
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load("block-and-frame").unwrap();
    let e = run_newmark(&row, &ground, 5.0, 5e-3).unwrap_err();
    let RowError::Unconverged(t) = e else {
        panic!("expected Unconverged, got {e:?}");
    };
    // The first hard impacts come at about 1.52 s (the exact run's).
    assert!((1.5..1.6).contains(&t), "t = {t}");
    let text = e.to_string();
    assert!(
        text.contains("did not converge") && text.contains("--dt"),
        "{text}"
    );
}
