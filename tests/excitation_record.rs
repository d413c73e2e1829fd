//! Recorded ground motions (SPEC §9): the shipped synthetic `.AT2` file, a
//! short piecewise-linear record against the reference, and Newmark's
//! convergence towards the exact method under it.

use std::sync::Arc;

use pounding::model::record::{Record, intern, load};
use pounding::model::{Excitation, Method, Params, RecordMotion, SET1, synthetic};
use pounding::reference::{ReferenceOptions, reference};
use pounding::solver::{exact_options, newmark_options, relative_peak_error, simulate, solve};

const SHIPPED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/presets/synthetic.at2");

#[test]
fn the_shipped_file_is_the_generator_s_output_and_reads_back() {
    let text = std::fs::read_to_string(SHIPPED).unwrap();
    assert_eq!(
        text,
        synthetic::at2_text(),
        "regenerate presets/synthetic.at2"
    );
    let r = load(SHIPPED).unwrap();
    assert_eq!(r.acceleration.len(), synthetic::SAMPLES);
    assert_eq!(r.dt, synthetic::DT);
    // PGA 0.3 g, to the 8 digits written.
    assert!((r.peak / 9.80665 - 0.3).abs() < 1e-7, "{}", r.peak);
    // Dominant frequency near the filter's 2.5 Hz (5π rad/s).
    assert!(
        r.dominant_omega() > 8.0 && r.dominant_omega() < 25.0,
        "{}",
        r.dominant_omega()
    );
}

/// A short record: 40 samples at DT = 0.05 s of a decaying two-tone signal.
fn short_record() -> Arc<Record> {
    let a: Vec<f64> = (0..40)
        .map(|k| {
            let t = k as f64 * 0.05;
            3.0 * (-0.5 * t).exp() * ((5.0 * t).sin() + 0.4 * (13.0 * t).cos())
        })
        .collect();
    intern(Record::from_samples("short", 0.05, a))
}

fn under_record(model: &str) -> Params {
    let motion = RecordMotion::new(short_record());
    let mut p = Params {
        excitation: Excitation::Record(motion),
        record_omega: 5.0,
        cycles: 2,
        method: Method::Exact,
        ..SET1
    };
    p.set("model", model).unwrap();
    p.validate().unwrap();
    p
}

#[test]
fn exact_and_reference_agree_under_a_piecewise_linear_record() {
    for model in [
        "improved-kelvin",
        "kelvin",
        "hertz",
        "hunt-crossley",
        "jankowski",
    ] {
        let p = under_record(model);
        // Linear and without contact, then with pounding and yield (set 1).
        for q in [
            Params {
                yield1: f64::INFINITY,
                yield2: f64::INFINITY,
                gap: f64::INFINITY,
                ..p.clone()
            },
            p,
        ] {
            let exact = solve(&q, &mut ());
            assert!(exact.completed);
            // The balance checks the motion after the record too (g = 0 from its last sample).
            assert!(
                exact.energy.residual < 1e-9,
                "{model}: {:e}",
                exact.energy.residual
            );
            let r = reference(&q, &ReferenceOptions::for_params(&q, 1e-12));
            assert!(r.completed);
            assert_eq!(exact.impacts.len(), r.impacts.len(), "{model}");
            let e = relative_peak_error(&exact.peaks(), &r.peaks);
            assert!(e < 1e-8, "{model} gap={}: {e:e}", q.gap);
        }
    }
    // The run is the record (39 · 0.05 s · 5 rad/s) plus two cycles.
    let p = under_record("kelvin");
    assert!((p.tau_end() - (39.0 * 0.05 * 5.0 + 4.0 * std::f64::consts::PI)).abs() < 1e-12);
}

/// Newmark converges to the exact method at second order under a record:
/// linear between samples, and zero after the last one (a jump), so the
/// driver ends a step on every sample. Δτ = 0.0137 puts no sample on the
/// step grid by itself (spacing 0.05 s · 5 rad/s = 0.25).
#[test]
fn newmark_converges_at_second_order_under_a_record() {
    let p = Params {
        yield1: f64::INFINITY,
        yield2: f64::INFINITY,
        gap: f64::INFINITY,
        ..under_record("kelvin")
    };
    let truth = pounding::solver::exact::simulate(&p, &exact_options(&p), &mut ()).peaks();
    let err = |dt: f64| {
        let q = Params { dt, ..p.clone() };
        relative_peak_error(&simulate(&q, &newmark_options(&q), &mut ()).peaks(), &truth)
    };
    let (coarse, fine) = (err(0.0137), err(0.0137 / 2.0));
    let order = (coarse / fine).log2();
    eprintln!("record: order {order} ({coarse:e}, {fine:e})");
    assert!(
        order > 1.8 && order < 2.2,
        "order {order} ({coarse:e}, {fine:e})"
    );
}

/// Malformed `.AT2` files through the command line: exit 2, one line naming the file and line.
#[test]
fn malformed_files_exit_2_naming_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let good = std::fs::read_to_string(SHIPPED).unwrap();
    let cases = [
        (
            "wrong-npts.at2",
            good.replacen("NPTS=  1000", "NPTS=  1001", 1),
            "line 204",
        ),
        (
            "missing-dt.at2",
            good.replacen(", DT=   0.0100 SEC", "", 1),
            "line 4",
        ),
        (
            "not-number.at2",
            good.replacen("1.4220998E-3", "1.42x", 1),
            "line 5",
        ),
        ("empty.at2", String::new(), "line 1"),
    ];
    for (name, text, line) in cases {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
            .args(["run", "--excitation", &format!("record:{}", path.display())])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(name) && err.contains(line), "{name}: {err}");
    }
}
