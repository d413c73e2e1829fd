//! A Newmark run never hangs and never hides a non-finite state: inputs that
//! once looped for ever return with a reported stop or a flagged result,
//! and each cap of `RunCaps` stops a run at the documented point.
//!
//! Also the invariant of the driver's single `accept`: the run's summary is
//! exactly what its accepted states imply, whichever loop (the free phase's
//! tight loop or the general step) produced them, and it does not depend on
//! the observer.

use std::sync::mpsc;
use std::thread;
use std::time::Duration;

use pounding::model::{ContactModel, Excitation, Params, SET1, SET2};
use pounding::solver::newmark::peaks::{hermite_extremum, resolved_steps};
use pounding::solver::{
    ContactSubsteps, Decimated, FullHistory, Method, RunCaps, RunResult, SolverOptions, StopReason,
    simulate,
};

/// Runs `p` on a worker thread and fails (instead of hanging the suite) if it
/// has not returned within a minute. A guard against hangs, not a timing:
/// each of these runs returns in milliseconds.
fn run_guarded(p: Params, options: SolverOptions) -> RunResult {
    let (send, receive) = mpsc::channel();
    let run = p.clone();
    thread::spawn(move || {
        let _ = send.send(simulate(&run, &options, &mut ()));
    });
    receive
        .recv_timeout(Duration::from_secs(60))
        .unwrap_or_else(|_| panic!("the run did not return: {p:?}"))
}

/// The numbers a caller prints: all finite, whatever happened to the state.
fn assert_reported_numbers_finite(r: &RunResult, label: &str) {
    assert!(
        r.peaks().iter().all(|v| v.is_finite())
            && r.max_force.is_finite()
            && r.min_force.is_finite()
            && r.tau_end.is_finite(),
        "{label}: {r:?}"
    );
}

/// The inputs that used to loop for ever: the state became NaN at the first
/// impact, `pen <= 0` was false for NaN so contact never ended, and every
/// step was halved twenty times and accepted unconverged. With the default
/// options each now stops, and says why; with the plain scheme each returns
/// too, stopped or with every number finite.
#[test]
fn inputs_that_used_to_hang_return_flagged() {
    use StopReason::{NonFinite, RetryCap};
    let cases = [
        // k̄ = m̄ Π_ωcon² overflows: the contact force is infinite at onset.
        (
            "contact_omega=1e300",
            Params {
                contact_omega: 1e300,
                ..SET1
            },
            NonFinite,
        ),
        // 4Π_m/h² overflows once the contact step is halved.
        (
            "mass_ratio=1e300",
            Params {
                mass_ratio: 1e300,
                ..SET1
            },
            NonFinite,
        ),
        // The improved Kelvin dashpot 3(1−e)/(2e) overflows.
        (
            "restitution=1e-100",
            Params {
                restitution: 1e-100,
                ..SET1
            },
            NonFinite,
        ),
        // A subnormal mass: Newton cannot converge at any step size.
        (
            "mass_ratio=1e-320",
            Params {
                mass_ratio: 1e-320,
                ..SET1
            },
            RetryCap,
        ),
        // Π_ω1 h = 1e97: Newmark's undamped high-frequency mode, excited by
        // the first contact, grows to 1e162 and overflows at the second.
        (
            "omega1=1e100",
            Params {
                omega1: 1e100,
                ..SET1
            },
            NonFinite,
        ),
    ];
    for (label, p, reason) in cases {
        let r = run_guarded(p.clone(), SolverOptions::default());
        assert_eq!(r.method, Method::Newmark);
        let stop = r.stop.unwrap_or_else(|| panic!("{label}: no stop: {r:?}"));
        assert_eq!(stop.reason, reason, "{label}");
        assert!(!r.completed, "{label}");
        // Stopped at the last accepted state, after the first onset (5.02) and before τ_end.
        assert_eq!(stop.tau, r.tau_end, "{label}");
        assert!(
            stop.tau > 5.0 && stop.tau < SET1.tau_end(),
            "{label}: {stop}"
        );
        assert!(r.unreliable().is_some(), "{label}");
        assert_reported_numbers_finite(&r, label);
        assert!(r.energy.residual.is_finite(), "{label}");

        let plain = run_guarded(p, SolverOptions::plain());
        if let Some(stop) = plain.stop {
            assert_eq!(stop.tau, plain.tau_end, "{label} plain");
            assert_reported_numbers_finite(&plain, label);
        } else {
            // Π_ω1 = 1e100 at the plain Δτ throughout: the left structure
            // stays a rigid wall (|x1| ~ 1e-199) and the run completes.
            assert!(plain.is_finite(), "{label} plain: {plain:?}");
        }
    }
}

/// A NaN in the state stops the run at the last finite state, and nothing
/// non-finite reaches the summary.
#[test]
fn a_non_finite_state_stops_the_run_at_the_last_finite_one() {
    // Π_ωcon = 1e300: k̄ overflows, and the first contact step is NaN.
    let p = Params {
        contact_omega: 1e300,
        ..SET1
    };
    let mut history = FullHistory::default();
    let r = simulate(&p, &SolverOptions::located(), &mut history);
    let stop = r.stop.expect("a stop");
    assert_eq!(stop.reason, StopReason::NonFinite);
    // The same trajectory as the finite run up to the first onset (5.0212 in
    // set 1), where the contact force is infinite: the onset is not accepted
    // and the run stops at the step before it.
    let onset = simulate(&SET1, &SolverOptions::located(), &mut ()).impacts[0].start;
    assert!(r.impacts.is_empty());
    assert!(stop.tau < onset && stop.tau > onset - SET1.dt, "{stop}");
    assert_reported_numbers_finite(&r, "contact_omega=1e300");
    assert!(r.energy.residual.is_finite());
    // The observer saw only finite states, the last one at the stop.
    let last = history.samples.last().unwrap();
    assert_eq!(last.tau, stop.tau);
    assert!(
        history
            .samples
            .iter()
            .all(|s| s.channels().iter().all(|v| v.is_finite()))
    );
}

/// A non-finite initial state (Π_ω1 = 1e300: k1 overflows) stops at τ = 0.
#[test]
fn a_non_finite_start_stops_at_zero() {
    let p = Params {
        omega1: 1e300,
        ..SET1
    };
    let r = run_guarded(p, SolverOptions::default());
    let stop = r.stop.expect("a stop");
    assert_eq!(
        (stop.reason, stop.tau, r.steps),
        (StopReason::NonFinite, 0.0, 0)
    );
}

/// A Δτ that τ_end + Δτ rounds away can never finish: stopped at once.
#[test]
fn a_step_below_round_off_stops_at_once() {
    for dt in [1e-20, 0.0, -1e-3, f64::NAN] {
        let p = Params { dt, ..SET1 };
        let r = run_guarded(p, SolverOptions::default());
        let stop = r.stop.unwrap_or_else(|| panic!("dt={dt}: {r:?}"));
        assert_eq!(
            (stop.reason, stop.tau, r.steps),
            (StopReason::StepCap, 0.0, 0)
        );
    }
}

/// The step cap is checked every 1024 accepted steps: a cap of 4000 stops
/// the run after 4096, at the state reached then.
#[test]
fn the_step_cap_stops_at_the_next_checkpoint() {
    let options = SolverOptions {
        caps: Some(RunCaps {
            steps: 4_000,
            impacts: usize::MAX,
            retries: usize::MAX,
        }),
        ..SolverOptions::default()
    };
    let mut history = FullHistory::default();
    let r = simulate(&SET1, &options, &mut history);
    let stop = r.stop.expect("a stop");
    assert_eq!(stop.reason, StopReason::StepCap);
    assert_eq!(r.steps, 4 * 1024);
    assert_eq!(history.samples.len(), 4 * 1024 + 1);
    assert_eq!(history.samples.last().unwrap().tau, stop.tau);
    assert_eq!(r.tau_end, stop.tau);
    // All free steps of Δτ, before the first impact at τ ≈ 5.02.
    assert!(r.impacts.is_empty());
    assert!((stop.tau - 4096.0 * SET1.dt).abs() < 1e-9, "{stop}");
}

/// The impact cap stops the run at the onset past the cap; the impacts
/// before it are those of the uncapped run, bit for bit.
#[test]
fn the_impact_cap_stops_at_the_onset_past_it() {
    let full = simulate(&SET1, &SolverOptions::default(), &mut ());
    assert!(full.impacts.len() > 4, "{}", full.impacts.len());
    let options = SolverOptions {
        caps: Some(RunCaps {
            steps: usize::MAX,
            impacts: 3,
            retries: usize::MAX,
        }),
        ..SolverOptions::default()
    };
    let r = simulate(&SET1, &options, &mut ());
    let stop = r.stop.expect("a stop");
    assert_eq!(stop.reason, StopReason::EventCap);
    assert_eq!(r.impacts.len(), 4);
    assert_eq!(stop.tau, full.impacts[3].start);
    assert_eq!(r.impacts[..3], full.impacts[..3]);
}

/// The retry cap bounds a run whose contact steps never converge.
#[test]
fn the_retry_cap_stops_a_run_that_will_not_converge() {
    // Improved Kelvin with e = 1e-100: the dashpot coefficient 3(1−e)/(2e)
    // overflows and Newton fails at every step size.
    let p = Params {
        restitution: 1e-100,
        model: ContactModel::ImprovedKelvin,
        ..SET1
    };
    let options = SolverOptions {
        caps: Some(RunCaps {
            steps: usize::MAX,
            impacts: usize::MAX,
            retries: 5,
        }),
        ..SolverOptions::default()
    };
    let r = run_guarded(p, options);
    let stop = r.stop.expect("a stop");
    assert_eq!(stop.reason, StopReason::RetryCap, "{r:?}");
    assert_eq!(r.step_retries, 6);
}

/// The default caps leave every preset run alone.
#[test]
fn presets_meet_no_cap() {
    for base in [SET1, SET2] {
        for model in ContactModel::ALL {
            let p = Params {
                model,
                ..base.clone()
            };
            for options in [
                SolverOptions::default(),
                SolverOptions::located(),
                SolverOptions::plain(),
            ] {
                let r = simulate(&p, &options, &mut ());
                assert!(r.completed && r.stop.is_none(), "{model}: {:?}", r.stop);
                assert_eq!(r.unreliable(), None, "{model}");
            }
        }
    }
}

/// The run does not depend on what observes it: peaks only, the full
/// history and a decimated one give the same result, bit for bit.
#[test]
fn the_result_does_not_depend_on_the_observer() {
    for base in [SET1, SET2] {
        for model in ContactModel::ALL {
            let p = Params {
                model,
                ..base.clone()
            };
            let options = SolverOptions::default();
            let bare = simulate(&p, &options, &mut ());
            let full = simulate(&p, &options, &mut FullHistory::default());
            let decimated = simulate(&p, &options, &mut Decimated::new(300, p.tau_end()));
            // Everything but the wall-clock-free summary is compared.
            assert_eq!(bare, full, "{model}");
            assert_eq!(bare, decimated, "{model}");
        }
    }
}

/// One `accept` for every step: the summary is exactly what the recorded
/// states imply. Π_u (including the Hermite peaks inside steps), the force
/// extremes, the step count and the contact onsets are rebuilt from the
/// history alone and must match the run's own, bit for bit, for both
/// policies, both contact models and sub-stepped contact; most steps come
/// from the free phase's tight loop, the rest from the general step.
#[test]
fn the_summary_is_what_the_accepted_states_imply() {
    for base in [SET1, SET2] {
        for model in ContactModel::ALL {
            for options in [
                SolverOptions::default(),
                SolverOptions::plain(),
                SolverOptions {
                    contact_substeps: ContactSubsteps::Fixed(3),
                    ..SolverOptions::located()
                },
            ] {
                let p = Params {
                    model,
                    ..base.clone()
                };
                let label = format!("{model} locate={}", options.locate_contact);
                let mut history = FullHistory::default();
                let r = simulate(&p, &options, &mut history);
                let samples = &history.samples;
                assert_eq!(r.steps + 1, samples.len(), "{label}");

                // Π_u: the samples and the Hermite extremum of every resolved step
                // in which ẋ changes sign (x and ẋ are continuous across events).
                let resolved = resolved_steps([p.omega1, p.omega2]);
                let mut peak_u = [0.0f64; 2];
                for (i, peak) in peak_u.iter_mut().enumerate() {
                    *peak = samples.iter().fold(0.0, |m, s| m.max(s.x[i].abs()));
                    for w in samples.windows(2) {
                        let (a, b) = (&w[0], &w[1]);
                        let h = b.tau - a.tau;
                        if h <= resolved[i] && a.v[i] * b.v[i] < 0.0 {
                            let x = hermite_extremum(a.x[i], b.x[i], a.v[i], b.v[i], h);
                            *peak = peak.max(x.abs());
                        }
                    }
                }
                assert_eq!(
                    peak_u,
                    [r.left.peak_displacement, r.right.peak_displacement],
                    "{label}"
                );
                // Π_v is at least the sampled maximum (the Hermite part uses ẍ
                // before a force jump at an event, which the history does not keep).
                let sampled_v =
                    [0, 1].map(|i| samples.iter().fold(0.0f64, |m, s| m.max(s.v[i].abs())));
                assert!(r.left.peak_velocity >= sampled_v[0], "{label}");
                assert!(r.right.peak_velocity >= sampled_v[1], "{label}");
                assert!(r.left.peak_velocity - sampled_v[0] < 1e-5, "{label}");

                // Force extremes over the states in contact, from 0.
                let in_contact = samples.iter().filter(|s| s.in_contact);
                let max_force = in_contact.clone().fold(0.0f64, |m, s| m.max(s.fp));
                let min_force = in_contact.fold(0.0f64, |m, s| m.min(s.fp));
                assert_eq!(
                    (r.max_force, r.min_force),
                    (max_force, min_force),
                    "{label}"
                );

                // One impact per entry into contact, opened at that state.
                let onsets: Vec<f64> = samples
                    .windows(2)
                    .filter(|w| !w[0].in_contact && w[1].in_contact)
                    .map(|w| w[1].tau)
                    .collect();
                let starts: Vec<f64> = r.impacts.iter().map(|i| i.start).collect();
                assert_eq!(onsets, starts, "{label}");
                assert!(r.impacts.len() >= 3, "{label}");
            }
        }
    }
}

/// A free vibration (no excitation) runs through the same accounting: with
/// no contact, every step is a tight-loop step but the last.
#[test]
fn free_vibration_accounting() {
    let p = Params {
        gap: f64::INFINITY,
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        damping: 0.0,
        cycles: 1,
        ..SET1
    };
    let options = SolverOptions {
        excitation: Excitation::None,
        initial_velocity: [1.0, -1.0],
        ..SolverOptions::default()
    };
    let r = simulate(&p, &options, &mut ());
    // Undamped elastic: |x| peaks at v₀/Π_ω, to the Hermite interpolant's O((ωh)⁴) and Newmark's period error.
    assert!(
        (r.left.peak_displacement - 1.0 / p.omega1).abs() < 1e-6,
        "{r:?}"
    );
    assert!(
        (r.right.peak_displacement - 1.0 / p.omega2).abs() < 1e-6,
        "{r:?}"
    );
    assert_eq!(r.steps, (p.tau_end() / p.dt).ceil() as usize);
    assert!(r.completed && r.energy.residual < 1e-12, "{r:?}");
}
