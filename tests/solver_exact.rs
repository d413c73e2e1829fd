//! The exact (event-driven) method against what is known independently:
//! the DOPRI5 reference with event location (it shares no code with the
//! solver), the closed-form elastic response, the Kelvin restitution of an
//! isolated impact, and conservation of momentum. Then its guards: the event
//! cap and the non-finite check turn runaways into reported stops.

mod common;

use pounding::model::params::CONTACT_TOLERANCE;
use pounding::model::{ContactModel, Excitation, Method, Params, SET1, SET2};
use pounding::reference::{ReferenceOptions, reference};
use pounding::solver::exact::{ExactOptions, simulate};
use pounding::solver::{FullHistory, RunResult, StopReason, relative_peak_error};

fn exact(p: &Params) -> RunResult {
    simulate(p, &ExactOptions::default(), &mut ())
}

/// Exact at contact tolerance `contact_tolerance` against the reference at
/// tolerance 1e-13: the four peaks to `tolerance` (relative), the same
/// impact count, and each impact's onset and approach velocity to `timing`.
fn agrees_with_reference_at(
    name: &str,
    p: &Params,
    contact_tolerance: f64,
    tolerance: f64,
    timing: f64,
) {
    let options = ExactOptions {
        contact_tolerance,
        ..ExactOptions::default()
    };
    let r = simulate(p, &options, &mut ());
    assert!(r.completed && r.stop.is_none(), "{name}: {:?}", r.stop);
    assert_eq!(r.method, Method::Exact);
    let q = reference(p, &ReferenceOptions::with_tolerance(1e-13));
    assert!(q.completed, "{name}: reference incomplete");
    let err = relative_peak_error(&r.peaks(), &q.peaks);
    assert!(
        err < tolerance,
        "{name}: peaks {:?} vs {:?}: {err:.2e}",
        r.peaks(),
        q.peaks
    );
    assert_eq!(r.impacts.len(), q.impacts.len(), "{name}: impact count");
    for (a, b) in r.impacts.iter().zip(&q.impacts) {
        assert!(
            (a.start - b.start).abs() < timing,
            "{name}: onset {} vs {}",
            a.start,
            b.start
        );
        let dv = (a.approach_velocity - b.approach_velocity).abs();
        assert!(
            dv < timing,
            "{name}: v0 {} vs {}",
            a.approach_velocity,
            b.approach_velocity
        );
    }
    assert!(
        r.energy.residual < 1e-10,
        "{name}: energy residual {:.1e}",
        r.energy.residual
    );
}

/// [`agrees_with_reference_at`] the default contact tolerance, with onsets
/// and approach velocities to 1e-8.
fn agrees_with_reference(name: &str, p: &Params, tolerance: f64) {
    agrees_with_reference_at(name, p, CONTACT_TOLERANCE, tolerance, 1e-8);
}

#[test]
fn presets_agree_with_the_reference_to_1e_8() {
    for (name, p) in [("set1", SET1), ("set2", SET2)] {
        for model in ContactModel::PAPER {
            agrees_with_reference(
                &format!("{name} {model}"),
                &Params { model, ..p.clone() },
                1e-8,
            );
        }
    }
}

#[test]
fn the_paper_counts_nine_impacts_on_set1() {
    assert_eq!(exact(&SET1).impacts.len(), 9);
}

/// Near-grazing points of the Figure 8–10 spectra, where Newmark at
/// Δτ = 0.001 is off by up to 3e-3 (Π_ω1 = 0.6, μ = 1.5 has a fourth impact
/// at an approach velocity of about 0.066).
#[test]
fn grazing_cases_agree_with_the_reference_to_1e_8() {
    let cases = [
        (0.6, 1.5, 0.5, 0.2),
        (0.6, 1.5, 0.5, 1.5),
        (0.45, 1.5, 0.1, 0.2),
        (0.75, 4.0, 0.5, 0.2),
        (1.3, 1.5, 0.9, 0.2),
        (2.0, 10.0, 0.5, 0.2),
    ];
    for (omega1, mu, mass_ratio, gap) in cases {
        let p = Params {
            omega1,
            omega2: mu * omega1,
            mass_ratio,
            gap,
            ..SET1
        };
        let name = format!("Π_ω1={omega1} μ={mu} Π_m={mass_ratio} Π_d={gap}");
        // At the default tolerance the peaks hold to 1e-8 (measured: 5e-12 at
        // worst). A near-grazing impact turns the small velocity errors left
        // by earlier contacts into a timing error about 1/v₀ times larger:
        // at Π_ω1 = 0.6, μ = 1.5 (v₀ ≈ 0.066) onsets are off by 1.1e-8 at
        // 1e-11, 8e-10 at 1e-12 and 4e-10 at 1e-14 (the reference's own
        // difference between 1e-13 and 1e-14). So timings are held to 1e-7
        // here, and to 1e-8 at a contact tolerance of 1e-14.
        agrees_with_reference_at(&name, &p, CONTACT_TOLERANCE, 1e-8, 1e-7);
        agrees_with_reference_at(&name, &p, 1e-14, 1e-8, 1e-8);
    }
}

/// Runs for peaks only (no energy integrals, as spectra and maps make them)
/// step through quiet stretches by transition matrix instead of series; where
/// the right structure is four or more times as fast as the left, first over
/// segments sized to the slow one, the fast one bounded by its steady response
/// and its free vibration's energy. They meet the reference as the full runs
/// do, with impacts (the fast structure ringing after each) and without, and
/// agree with the full runs of the same parameters to round-off.
#[test]
fn peaks_only_runs_over_long_quiet_segments_agree_with_the_reference() {
    let peaks_only = ExactOptions {
        energy: false,
        ..ExactOptions::default()
    };
    let cases = [
        // (Π_ω1, μ, Π_d): no impact; 32 impacts; a yielding left structure.
        (2.82, 7.4, 0.2),
        (2.02, 8.2, 0.2),
        (0.5, 10.0, 0.2),
        (1.05, 10.0, f64::INFINITY),
    ];
    for (omega1, mu, gap) in cases {
        let p = Params {
            omega1,
            omega2: mu * omega1,
            gap,
            ..SET1
        };
        let name = format!("Π_ω1={omega1} μ={mu} Π_d={gap}");
        let r = simulate(&p, &peaks_only, &mut ());
        assert!(r.completed, "{name}: {:?}", r.stop);
        let q = reference(&p, &ReferenceOptions::with_tolerance(1e-13));
        let err = relative_peak_error(&r.peaks(), &q.peaks);
        assert!(
            err < 1e-8,
            "{name}: {:?} vs {:?}: {err:.2e}",
            r.peaks(),
            q.peaks
        );
        assert_eq!(r.impacts.len(), q.impacts.len(), "{name}: impact count");
        let full = exact(&p);
        let err = relative_peak_error(&r.peaks(), &full.peaks());
        assert!(err < 1e-11, "{name}: peaks-only against full: {err:.2e}");
        assert_eq!(r.impacts.len(), full.impacts.len(), "{name}");
    }
}

/// ẍ + 2ζωẋ + ω²x = −sin τ from rest, in closed form (the reference's, checked there).
fn closed_form(omega: f64, zeta: f64, tau: f64) -> f64 {
    pounding::reference::closed_form::LinearOscillator::new(omega, zeta, 1.0, 0.0, 0.0)
        .displacement(tau)
}

#[test]
fn linear_structures_follow_the_closed_form_to_1e_12() {
    let p = Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        method: Method::Exact,
        ..SET1
    };
    let mut h = FullHistory::default();
    let r = simulate(&p, &ExactOptions::default(), &mut h);
    assert!(r.impacts.is_empty() && !r.left.yielded && !r.right.yielded);
    assert!(
        h.samples.len() > 50_000,
        "one sample per Δτ: {}",
        h.samples.len()
    );
    let mut worst: f64 = 0.0;
    for s in &h.samples {
        worst = worst
            .max((s.x[0] - closed_form(p.omega1, p.damping, s.tau)).abs())
            .max((s.x[1] - closed_form(p.omega2, p.damping, s.tau)).abs());
    }
    assert!(worst < 1e-12, "largest error {worst:.2e}");
    // Peaks are the continuous maxima: no sample exceeds them, and the closed
    // form's maximum on a fine grid is matched.
    let fine = (0..=2_000_000)
        .map(|k| closed_form(p.omega1, p.damping, k as f64 * p.tau_end() / 2e6).abs())
        .fold(0.0, f64::max);
    assert!(
        (r.left.peak_displacement - fine).abs() < 1e-9,
        "{} vs {fine}",
        r.left.peak_displacement
    );
    assert!(
        h.samples
            .iter()
            .all(|s| s.x[0].abs() <= r.left.peak_displacement)
    );
}

/// Two free masses (Π_ω = 0, no damping, no ground motion) meeting at unit
/// speed: the Kelvin element returns exactly the e it was built from,
/// ζ = −ln e/√(π² + ln² e) (SPEC §4), and momentum is conserved.
#[test]
fn kelvin_restitution_of_an_isolated_impact_to_1e_9() {
    for e in [0.1, 0.4, 0.8, 1.0] {
        for mass_ratio in [0.5, 2.0] {
            let p = common::isolated_impact(ContactModel::Kelvin, e, mass_ratio);
            let options = ExactOptions {
                excitation: Excitation::None,
                initial_velocity: [1.0, 0.0],
                ..ExactOptions::default()
            };
            let mut h = FullHistory::default();
            let r = simulate(&p, &options, &mut h);
            assert_eq!(r.impacts.len(), 1);
            let got = r.impacts[0].restitution;
            assert!((got - e).abs() < 1e-9, "e={e} Π_m={mass_ratio}: {got}");
            let end = h.samples.last().unwrap();
            let momentum = mass_ratio * end.v[0] + end.v[1];
            assert!((momentum - mass_ratio).abs() < 1e-12, "{momentum}");
        }
    }
}

#[test]
fn the_event_cap_turns_a_runaway_into_a_reported_stop() {
    let options = ExactOptions {
        max_events: Some(5),
        ..ExactOptions::default()
    };
    let r = simulate(&SET1, &options, &mut ());
    let stop = r.stop.expect("stopped");
    assert_eq!(stop.reason, StopReason::EventCap);
    assert!(!r.completed && stop.tau > 0.0 && stop.tau < SET1.tau_end());
    assert!(r.unreliable().is_some());
}

/// Two identical structures with no gap move together: δ ≡ 0, a tangency
/// along the whole run. It must end, without a spurious impact storm.
#[test]
fn structures_moving_together_at_zero_gap_finish() {
    let p = Params {
        mass_ratio: 1.0,
        omega1: 1.5,
        omega2: 1.5,
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: 0.0,
        cycles: 2,
        ..SET1
    };
    let r = exact(&p);
    assert!(r.completed, "{:?}", r.stop);
    assert!(r.impacts.len() <= 1, "{} impacts", r.impacts.len());
}

/// Values outside the accepted ranges, built directly: the run stops where
/// the state stops being finite, or completes with finite numbers, and
/// never hangs.
#[test]
fn hostile_values_stop_or_finish_finite() {
    let cases = [
        Params {
            contact_omega: 1e300,
            ..SET1
        },
        Params {
            mass_ratio: 1e300,
            ..SET1
        },
        Params {
            restitution: 1e-100,
            ..SET1
        },
        Params {
            mass_ratio: 1e-320,
            ..SET1
        },
        Params {
            omega1: 1e100,
            ..SET1
        },
    ];
    for p in cases {
        let r = exact(&p);
        match r.stop {
            Some(stop) => assert!(stop.tau.is_finite() && stop.reason != StopReason::Cancelled),
            None => assert!(r.is_finite(), "{p}: {:?}", r.peaks()),
        }
    }
}

/// Each impact's peak force and penetration and the run's force extremes
/// are searches on the motion's series, not part of the motion: a run that
/// skips them (a spectrum's) or locates the forces only (a map's) has the
/// same peaks and impacts bit for bit, the forces it locates are the full
/// run's, and what it skips is NaN, never a value that looks measured. The
/// located extremes bound the reference's, which are taken at its step
/// ends, from above, and closely.
#[test]
fn contact_extremes_are_located_only_when_asked_and_change_nothing_else() {
    use pounding::solver::exact::ContactExtremes;
    let with = |p: &Params, extremes| {
        let options = ExactOptions {
            energy: false,
            extremes,
            ..ExactOptions::default()
        };
        simulate(p, &options, &mut ())
    };
    for (name, base) in [("set1", SET1), ("set2", SET2)] {
        for model in ContactModel::PAPER {
            let p = Params {
                model,
                ..base.clone()
            };
            let all = with(&p, ContactExtremes::All);
            let forces = with(&p, ContactExtremes::Forces);
            let none = with(&p, ContactExtremes::None);
            for r in [&forces, &none] {
                assert_eq!(r.peaks(), all.peaks(), "{name} {model}");
                assert_eq!(r.impacts.len(), all.impacts.len(), "{name} {model}");
                for (a, b) in r.impacts.iter().zip(&all.impacts) {
                    assert_eq!(
                        (a.start, a.end, a.approach_velocity, a.separation_velocity),
                        (b.start, b.end, b.approach_velocity, b.separation_velocity)
                    );
                }
            }
            assert_eq!(
                (forces.max_force, forces.min_force),
                (all.max_force, all.min_force)
            );
            for (a, b) in forces.impacts.iter().zip(&all.impacts) {
                assert_eq!(a.peak_force, b.peak_force);
                assert!(a.max_penetration.is_nan() && b.max_penetration > 0.0);
            }
            assert!(none.max_force.is_nan() && none.min_force.is_nan());
            assert!(
                none.impacts
                    .iter()
                    .all(|i| i.peak_force.is_nan() && i.max_penetration.is_nan())
            );
            let q = reference(&p, &ReferenceOptions::with_tolerance(1e-13));
            let (hi, lo) = (all.max_force, all.min_force);
            assert!(
                q.max_force <= hi * (1.0 + 1e-12) && hi <= q.max_force * (1.0 + 1e-4),
                "{name} {model}: max force {hi} vs the reference's {}",
                q.max_force
            );
            assert!(
                lo <= q.min_force + 1e-12 * hi,
                "{name} {model}: min force {lo} vs the reference's {}",
                q.min_force
            );
        }
    }
}

/// A parameter set's `contact_tolerance` is the one the method runs with,
/// through the entry point every command uses: set 2 with improved Kelvin
/// meets the reference to 1e-12 at 1e-14 (9e-14 measured), and at the
/// default 1e-11 to 1e-10 but not to 1e-12 (3e-11 measured).
#[test]
fn a_parameter_sets_contact_tolerance_is_the_methods() {
    let base = Params {
        method: Method::Exact,
        model: ContactModel::ImprovedKelvin,
        ..SET2
    };
    let truth = reference(&base, &ReferenceOptions::with_tolerance(1e-14));
    let error = |tolerance: f64| {
        let p = Params {
            contact_tolerance: tolerance,
            ..base.clone()
        };
        relative_peak_error(&pounding::solver::run(&p).peaks(), &truth.peaks)
    };
    assert_eq!(base.contact_tolerance, CONTACT_TOLERANCE);
    let (tight, default) = (error(1e-14), error(CONTACT_TOLERANCE));
    assert!(tight < 1e-12, "at 1e-14: {tight:.1e}");
    assert!(
        default < 1e-10 && default > 1e-12,
        "at the default: {default:.1e}"
    );
}
