//! The exact method's quiet samples of a record (the linear map of
//! `solver::exact::sample`) against the same runs with every interval on the
//! segments' series (`ExactOptions::quiet_samples = false`): peaks, demands,
//! impacts and energy agree to round-off, with and without pounding and
//! yielding; events at a sample boundary and contacts inside one interval
//! are located as before; peaks between samples are located, not sampled.

use pounding::model::record::intern;
use pounding::model::simulated::{DEFAULT_SEED, Simulation};
use pounding::model::{Excitation, Params, RecordMotion, SET1};
use pounding::solver::RunResult;
use pounding::solver::dispatch::exact_options;
use pounding::solver::exact::{self, ContactExtremes, ExactOptions};

fn shipped() -> Excitation {
    Excitation::parse(concat!(
        "record:",
        env!("CARGO_MANIFEST_DIR"),
        "/presets/synthetic.at2"
    ))
    .expect("presets/synthetic.at2 reads")
}

fn simulated() -> Excitation {
    let r = Simulation {
        dt: 0.005,
        duration: 10.0,
        ..Default::default()
    }
    .record("quiet-samples-test", DEFAULT_SEED, 2);
    Excitation::Record(RecordMotion::new(intern(r)))
}

fn peaks_only(p: &Params) -> ExactOptions {
    ExactOptions {
        energy: false,
        absolute_acceleration: false,
        extremes: ContactExtremes::None,
        ..exact_options(p)
    }
}

/// Both paths of `p` under `options`.
fn both(p: &Params, options: &ExactOptions) -> (RunResult, RunResult) {
    let series = ExactOptions {
        quiet_samples: false,
        ..options.clone()
    };
    (
        exact::simulate(p, options, &mut ()),
        exact::simulate(p, &series, &mut ()),
    )
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a.is_nan() && b.is_nan()) || (a - b).abs() <= tol * a.abs().max(b.abs()).max(1.0)
}

/// Everything a run reports, compared at `tol` (relative, absolute below 1).
fn assert_agree(label: &str, quiet: &RunResult, series: &RunResult, tol: f64) {
    assert!(quiet.completed && series.completed, "{label}");
    assert_eq!(
        quiet.impacts.len(),
        series.impacts.len(),
        "{label}: impacts"
    );
    for (i, (a, b)) in quiet.peaks().iter().zip(series.peaks()).enumerate() {
        assert!(close(*a, b, tol), "{label}: peak {i} {a} vs {b}");
    }
    for i in 0..2 {
        let (a, b) = (quiet.structure(i), series.structure(i));
        for (what, x, y) in [
            (
                "A",
                a.peak_absolute_acceleration,
                b.peak_absolute_acceleration,
            ),
            ("residual", a.residual_displacement, b.residual_displacement),
            ("E_h", a.hysteretic_energy, b.hysteretic_energy),
        ] {
            assert!(close(x, y, tol), "{label}: {what} of {i}: {x} vs {y}");
        }
        assert_eq!(a.yielded, b.yielded, "{label}");
    }
    for (a, b) in quiet.impacts.iter().zip(&series.impacts) {
        assert!(
            close(a.start, b.start, tol) && close(a.end, b.end, tol),
            "{label}: {a:?} vs {b:?}"
        );
        // v₀² = 2 δ̈ (max δ − 0) near a graze, where v₀ itself carries
        // round-off of the state divided by v₀: compare the square.
        assert!(
            close(
                a.approach_velocity.powi(2),
                b.approach_velocity.powi(2),
                tol
            ),
            "{label}: v₀ {} vs {}",
            a.approach_velocity,
            b.approach_velocity
        );
        assert!(close(a.peak_force, b.peak_force, 1e-10), "{label}");
    }
    match (
        quiet.max_relative_displacement,
        series.max_relative_displacement,
    ) {
        (Some(a), Some(b)) => assert!(close(a, b, tol), "{label}: Π_d,min {a} vs {b}"),
        (a, b) => assert_eq!(a, b, "{label}"),
    }
    let (e, f) = (&quiet.energy, &series.energy);
    for (what, x, y) in [
        ("input", e.input, f.input),
        ("damping", e.damping, f.damping),
        ("spring", e.spring, f.spring),
        ("contact", e.contact, f.contact),
    ] {
        assert!(close(x, y, 1e-11), "{label}: E_{what} {x} vs {y}");
    }
    assert!(
        e.residual.is_nan() || e.residual < 1e-9,
        "{label}: residual {}",
        e.residual
    );
}

#[test]
fn quiet_samples_agree_with_the_series_with_and_without_pounding_and_yielding() {
    for (name, excitation) in [("synthetic.at2", shipped()), ("simulated", simulated())] {
        let base = Params { excitation, ..SET1 };
        let cases = [
            (
                "elastic apart",
                Params {
                    yield1: f64::INFINITY,
                    yield2: f64::INFINITY,
                    gap: f64::INFINITY,
                    ..base.clone()
                },
            ),
            (
                "inelastic apart",
                Params {
                    gap: f64::INFINITY,
                    ..base.clone()
                },
            ),
            ("pounding", base.clone()),
            (
                "pounding, elastic",
                Params {
                    yield1: f64::INFINITY,
                    yield2: f64::INFINITY,
                    ..base.clone()
                },
            ),
            // α = 0: no stiffness once yielded, the load Q/m an input of
            // its own in the map and the tight loop.
            (
                "pounding, perfectly plastic",
                Params {
                    alpha: 0.0,
                    ..base.clone()
                },
            ),
            // Kelvin (the force jumps at onset) and a wide gap (few impacts).
            (
                "kelvin, wide gap",
                Params {
                    model: pounding::model::ContactModel::Kelvin,
                    gap: 1.0,
                    ..base.clone()
                },
            ),
        ];
        for (case, p) in cases {
            for (run, options) in [("peaks", peaks_only(&p)), ("full", exact_options(&p))] {
                let (quiet, series) = both(&p, &options);
                assert_agree(&format!("{name}, {case}, {run}"), &quiet, &series, 1e-13);
            }
        }
    }
}

/// The elastic pair apart, full run: the peaks by the map are those of the
/// closed form (the series path sums it to round-off) within 1e-12.
#[test]
fn elastic_peaks_match_the_series_to_1e_12() {
    let p = Params {
        excitation: shipped(),
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        ..SET1
    };
    let (quiet, series) = both(&p, &exact_options(&p));
    for (a, b) in quiet.peaks().iter().zip(series.peaks()) {
        assert!((a - b).abs() <= 1e-12 * b, "{a} vs {b}");
    }
}

/// The gap for which the first onset falls on τ_k, by Newton's method on
/// the onset instant τ_s(gap) (dgap/dτ_s = x1' − x2' = v₀ at the onset).
fn gap_with_onset_at(base: &Params, from: f64, tau_k: f64) -> Option<f64> {
    let mut gap = from;
    for _ in 0..8 {
        let p = Params {
            gap,
            ..base.clone()
        };
        let r = exact::simulate(&p, &peaks_only(&p), &mut ());
        let first = r.impacts.first()?;
        let miss = tau_k - first.start;
        if miss.abs() < 1e-13 * tau_k {
            return Some(gap);
        }
        gap += first.approach_velocity * miss;
    }
    None
}

#[test]
fn an_onset_within_1e_9_of_a_sample_is_located_as_before() {
    let base = Params {
        excitation: shipped(),
        ..SET1
    };
    let Excitation::Record(m) = base.ground() else {
        unreachable!()
    };
    let h = m.record.dt * m.omega;
    let first = exact::simulate(&base, &peaks_only(&base), &mut ()).impacts[0];
    let k = (first.start / h).round();
    let gap = [k, k - 1.0, k + 1.0]
        .iter()
        .find_map(|&k| gap_with_onset_at(&base, base.gap, k * h).map(|g| (g, k * h)));
    let (gap, tau_k) = gap.expect("a gap with its onset on a sample");
    for shift in [-1e-9, -1e-10, 0.0, 1e-10, 1e-9] {
        // The onset about `shift` after τ_k: the gap moved by v₀ · shift.
        let p = Params {
            gap: gap + first.approach_velocity * shift,
            ..base.clone()
        };
        for options in [peaks_only(&p), exact_options(&p)] {
            let (quiet, series) = both(&p, &options);
            let label = format!("shift {shift}");
            assert_agree(&label, &quiet, &series, 1e-13);
            // Located as before: the two paths' onsets agree to round-off of τ.
            assert!((quiet.impacts[0].start - series.impacts[0].start).abs() < 1e-14 * tau_k);
            let onset = quiet.impacts[0].start;
            assert!(
                (onset - (tau_k + shift)).abs() < 1e-2 * shift.abs() + 1e-12,
                "{label}: onset {onset} vs τ_k + shift {}",
                tau_k + shift
            );
        }
    }
}

#[test]
fn a_contact_inside_one_interval_and_peaks_between_samples_are_located() {
    // Without contact: the maximum of x1 − x2 (Π_d,min) falls between samples.
    let base = Params {
        excitation: shipped(),
        gap: f64::INFINITY,
        ..SET1
    };
    let (quiet, series) = both(&base, &peaks_only(&base));
    assert_agree("apart", &quiet, &series, 1e-13);
    let dmin = quiet.max_relative_displacement.expect("no contact");
    // A gap a hair below it: a grazing contact that begins and ends inside one interval.
    let Excitation::Record(m) = base.ground() else {
        unreachable!()
    };
    let h = m.record.dt * m.omega;
    let p = Params {
        gap: dmin - 1e-6,
        ..base.clone()
    };
    for options in [peaks_only(&p), exact_options(&p)] {
        let (quiet, series) = both(&p, &options);
        assert_agree("graze", &quiet, &series, 1e-13);
        let first = &quiet.impacts[0];
        assert!(
            (first.start / h).floor() == (first.end / h).floor(),
            "contact {first:?} spans a sample at spacing {h}"
        );
    }
    // The peaks exceed every sampled value: the floor's sampled peaks of the
    // elastic pair lie below them, strictly for at least one.
    let elastic = Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        ..base.clone()
    };
    let exact_peaks = exact::simulate(&elastic, &peaks_only(&elastic), &mut ()).peaks();
    let floor = pounding::accuracy::floor::NigamJennings::new(&elastic)
        .expect("a record")
        .peaks();
    let mut strictly = false;
    for (f, e) in floor.iter().zip(exact_peaks) {
        assert!(*f <= e * (1.0 + 1e-12), "{f} > {e}");
        strictly |= *f < e * (1.0 - 1e-9);
    }
    assert!(strictly, "every peak fell on a sample");
}
