//! Records scaled to a target spectrum (analysis::record_scaling) and chosen
//! for it (analysis::record_selection): a record scaled to its own spectrum
//! gets 1, to twice it 2; the least-squares factor is exp(mean(ln S_T −
//! ln Sa)) worked by hand; a suite sitting at 90 % of the target at one
//! period passes and at 89.9 % fails there; the common factor lifts the
//! suite to exactly 90 % where it binds; a selection keeps K per event and
//! the factor limit, and takes a record planted to match the target.

use std::path::Path;

use pounding::analysis::record_scaling::{
    Binding, Code, Design, PeriodRange, check, least_squares, record_spectrum, scale,
};
use pounding::analysis::record_selection::{Candidate, Limits, select};
use pounding::model::intensity::{SA_DAMPING, spectral_acceleration};
use pounding::model::record::STANDARD_GRAVITY;
use pounding::model::suite::{SuiteMember, SuiteSpec};
use pounding::model::target_spectrum::TargetSpectrum;

const T1: f64 = 0.5;

fn suite(n: usize) -> Vec<SuiteMember> {
    SuiteSpec::parse(&format!("synthetic:{n}@7"))
        .unwrap()
        .load()
        .unwrap()
}

/// A table target with a row at each period of the default grid around
/// T1, its values `values`; the design with `code`.
fn table_design(dir: &Path, name: &str, values: &[f64], code: Code) -> Design {
    let periods = Design::log_grid(T1, PeriodRange::default());
    assert_eq!(periods.len(), values.len());
    let text: String = periods
        .iter()
        .zip(values)
        .map(|(t, v)| format!("{t} {v}\n"))
        .collect();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let target = TargetSpectrum::parse(&format!("file:{}", path.display())).unwrap();
    let design = Design::new(target, code, T1, PeriodRange::default()).unwrap();
    assert_eq!(design.grid(), periods, "the table's rows are the grid");
    design
}

fn grid() -> Vec<f64> {
    Design::log_grid(T1, PeriodRange::default())
}

#[test]
fn a_record_scaled_to_its_own_spectrum_gets_one_and_to_twice_it_two() {
    let dir = tempfile::tempdir().unwrap();
    let members = suite(1);
    let own = record_spectrum(&members[0], &grid());
    for (k, want) in [(1.0, 1.0), (2.0, 2.0)] {
        let values: Vec<f64> = own.iter().map(|s| k * s).collect();
        let design = table_design(dir.path(), &format!("own{k}.txt"), &values, Code::Asce7);
        let m = scale(&design, &members).unwrap();
        let r = &m.records[0];
        assert!(
            (r.least_squares_factor - want).abs() < 1e-12,
            "{}",
            r.least_squares_factor
        );
        assert!(r.ln_misfit < 1e-12, "{}", r.ln_misfit);
        // One record at its own (doubled) spectrum meets the 90 % line: c = 1.
        assert_eq!(m.common_factor, 1.0);
        assert_eq!(m.binding, Binding::Fit);
        assert!((r.ratio_at_period - 1.0).abs() < 1e-12);
    }
}

#[test]
fn the_least_squares_factor_is_the_mean_log_ratio_worked_by_hand() {
    let members = suite(3);
    let target = TargetSpectrum::parse("ec8:ag=0.25,ground=C,type=1").unwrap();
    let design = Design::new(target.clone(), Code::Ec8, T1, PeriodRange::default()).unwrap();
    let periods = design.grid();
    // The grid: 50 periods even in ln T over 0.1–1 s, T1 = 0.5 s and the
    // corners T_B = 0.2 s and T_C = 0.6 s inside it.
    assert_eq!(periods.len(), 53);
    assert_eq!(periods[0], 0.1);
    assert_eq!(*periods.last().unwrap(), 1.0);
    for t in [0.2, 0.5, 0.6] {
        assert!(periods.contains(&t), "{t}");
    }
    let m = scale(&design, &members).unwrap();
    for (member, r) in members.iter().zip(&m.records) {
        let rec = &member.record;
        let mut sum = 0.0;
        let mut residuals = Vec::new();
        for &t in &periods {
            let sa =
                spectral_acceleration(&rec.acceleration, rec.dt, t, SA_DAMPING) / STANDARD_GRAVITY;
            let res = target.sa(t).unwrap().ln() - sa.ln();
            sum += res;
            residuals.push(res);
        }
        let ln_f = sum / periods.len() as f64;
        let misfit = (residuals.iter().map(|r| (r - ln_f).powi(2)).sum::<f64>()
            / periods.len() as f64)
            .sqrt();
        assert!(
            (r.least_squares_factor / ln_f.exp() - 1.0).abs() < 1e-12,
            "{} vs {}",
            r.least_squares_factor,
            ln_f.exp()
        );
        assert!((r.ln_misfit - misfit).abs() < 1e-12);
        assert!((r.factor / (m.common_factor * r.least_squares_factor) - 1.0).abs() < 1e-15);
    }
    // least_squares itself on three numbers: exp(mean(ln 2, ln 4, ln 8)) = 4.
    let (f, misfit) = least_squares(&[2.0, 4.0, 8.0], &[1.0, 1.0, 1.0]).unwrap();
    assert!((f - 4.0).abs() < 1e-12);
    let want = ((2f64.ln().powi(2) * 2.0) / 3.0).sqrt();
    assert!((misfit - want).abs() < 1e-12);
    assert_eq!(least_squares(&[1.0, 1.0], &[1.0, 0.0]), None);
}

#[test]
fn a_suite_at_90_percent_at_one_period_passes_and_at_89_9_fails_there() {
    let dir = tempfile::tempdir().unwrap();
    // Three copies of one record: their mean is its spectrum. The target is
    // that spectrum, but raised at one period so the mean sits at `f` of it.
    let one = suite(1).remove(0);
    let members = vec![one.clone(), one.clone(), one];
    let periods = grid();
    let own = record_spectrum(&members[0], &periods);
    let k = 17;
    for (f, holds) in [(0.9, true), (0.899, false)] {
        let values: Vec<f64> = own
            .iter()
            .enumerate()
            .map(|(i, s)| if i == k { s / f } else { *s })
            .collect();
        let design = table_design(dir.path(), &format!("dip{f}.txt"), &values, Code::Ec8);
        let m = check(&design, &members).unwrap();
        let c = &m.check;
        assert_eq!(c.records, 3);
        assert_eq!(c.min_records, 3);
        assert_eq!(c.at_period_s, periods[k]);
        assert!((c.min_ratio - f).abs() < 1e-12, "{}", c.min_ratio);
        assert_eq!(c.holds, holds, "{:?}", c.failures);
        // A table has no value at T = 0: EC8's (b) is not checked.
        assert_eq!(c.zero_period_target_g, None);
        if !holds {
            assert_eq!(c.failures.len(), 1);
            let why = &c.failures[0];
            assert!(why.contains(&format!("T = {} s", periods[k])), "{why}");
            assert!(why.contains("0.8990"), "{why}");
        }
        assert_eq!(m.binding, Binding::List);
    }
    // Two records are too few for EC8 (at least 3), however well they fit.
    let design = table_design(dir.path(), "own.txt", &own, Code::Ec8);
    let m = check(&design, &members[..2]).unwrap();
    assert!(!m.check.holds);
    assert!(
        m.check.failures[0].contains("at least 3"),
        "{:?}",
        m.check.failures
    );
}

#[test]
fn the_common_factor_lifts_the_suite_to_exactly_90_percent_where_it_binds() {
    let members = suite(11);
    for target in [
        "asce7:SDS=1.2,SD1=0.7,TL=8",
        "ec8:ag=0.35,ground=B,type=1",
        "ec8:ag=0.2,ground=A,type=2,importance=1.4",
    ] {
        let target = TargetSpectrum::parse(target).unwrap();
        let design = Design::new(
            target.clone(),
            Code::of(&target),
            T1,
            PeriodRange::default(),
        )
        .unwrap();
        let m = scale(&design, &members).unwrap();
        let c = &m.check;
        assert!(c.holds, "{target}: {:?}", c.failures);
        assert!(m.common_factor >= 1.0);
        match m.binding {
            Binding::Spectrum { period_s } => {
                assert!((c.min_ratio - 0.9).abs() < 1e-12, "{}", c.min_ratio);
                assert_eq!(c.at_period_s, period_s);
            }
            Binding::ZeroPeriod => {
                let (pga, anchor) = (c.mean_pga_g.unwrap(), c.zero_period_target_g.unwrap());
                assert!((pga / anchor - 1.0).abs() < 1e-12);
                assert!(c.min_ratio >= 0.9 * (1.0 - 1e-12));
            }
            Binding::Fit => assert!(c.min_ratio >= 0.9),
            Binding::List => unreachable!(),
        }
        // The mean is the mean of the scaled spectra, period by period.
        for k in 0..m.periods.len() {
            let mean = m.records.iter().map(|r| r.spectrum[k]).sum::<f64>() / 11.0;
            assert!((mean / m.mean[k] - 1.0).abs() < 1e-14);
            assert!(m.p16[k] <= m.mean[k] * 1.5 && m.p16[k] <= m.p84[k]);
        }
        // Checking the scaled suite as a list gives the same verdict and worst ratio.
        let listed: Vec<SuiteMember> = members
            .iter()
            .zip(&m.records)
            .map(|(mm, r)| SuiteMember {
                scale: r.factor,
                ..mm.clone()
            })
            .collect();
        let again = check(&design, &listed).unwrap();
        assert!(again.check.holds);
        assert!((again.check.min_ratio / c.min_ratio - 1.0).abs() < 1e-12);
    }
}

#[test]
fn bad_ranges_and_periods_are_refused() {
    let ec8 = TargetSpectrum::parse("ec8:ag=0.3,ground=B,type=1").unwrap();
    let e = |r: &str| PeriodRange::parse(r).unwrap_err().to_string();
    assert!(
        e("2:0.2").starts_with("--range 2:0.2: the low end"),
        "{}",
        e("2:0.2")
    );
    assert!(e("0:2").contains("positive"));
    assert!(e("1.2:2").contains("must hold T1"));
    assert!(e("x").contains("LO:HI"));
    let range = PeriodRange::parse("0.2:3").unwrap();
    // 3·2 s = 6 s is past EC8's 4 s.
    let err = Design::new(ec8.clone(), Code::Ec8, 2.0, range)
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("--range 0.2:3: at T1 = 2 s it spans 0.4–6 s") && err.contains("0–4 s"),
        "{err}"
    );
    let err = Design::new(ec8, Code::Ec8, 0.0, PeriodRange::default())
        .unwrap_err()
        .to_string();
    assert!(err.starts_with("--period 0:"), "{err}");
}

#[test]
fn a_selection_keeps_k_per_event_the_factor_limit_and_the_planted_record() {
    let dir = tempfile::tempdir().unwrap();
    let members = suite(12);
    let planted = 7;
    // The target is record 8's own spectrum, at 1.5 times: it fits exactly.
    let own = record_spectrum(&members[planted], &grid());
    let values: Vec<f64> = own.iter().map(|s| 1.5 * s).collect();
    let design = table_design(dir.path(), "planted.txt", &values, Code::Ec8);
    // Events: three quakes of four records each, the planted one in quake 1.
    let candidates: Vec<Candidate> = members
        .iter()
        .enumerate()
        .map(|(j, m)| Candidate {
            member: m.clone(),
            event: Some(format!("quake {}", j % 3)),
        })
        .collect();
    for (count, per_event, max_scale) in [(3, 1, 4.0), (5, 2, 4.0), (6, 2, 2.0), (4, 4, 10.0)] {
        let limits = Limits {
            count,
            max_scale,
            per_event: Some(per_event),
        };
        let s = match select(&design, &candidates, limits) {
            Ok(s) => s,
            Err(e) => panic!("{count} of 12, {per_event} per event, M = {max_scale}: {e}"),
        };
        assert_eq!(s.chosen.len(), count);
        assert!(s.chosen.iter().any(|m| m.name == members[planted].name));
        for event in ["quake 0", "quake 1", "quake 2"] {
            let n = s
                .events
                .iter()
                .filter(|e| e.as_deref() == Some(event))
                .count();
            assert!(n <= per_event, "{n} of {event}");
        }
        for (m, r) in s.chosen.iter().zip(&s.matching.records) {
            assert_eq!(m.scale, r.factor);
            assert!(
                r.factor <= max_scale && r.factor >= 1.0 / max_scale,
                "{}",
                r.factor
            );
        }
        assert!(s.matching.check.holds, "{:?}", s.matching.check.failures);
    }
    // Seven of three events at two per event cannot be: six at most.
    let e = select(
        &design,
        &candidates,
        Limits {
            count: 7,
            max_scale: 4.0,
            per_event: Some(2),
        },
    )
    .unwrap_err();
    assert_eq!(e.available, 6);
    let words = e.to_string();
    assert!(
        words.starts_with("--count 7: only 6 of the 12 records are available")
            && words.contains("6 are beyond 2 per event"),
        "{words}"
    );
    // A factor limit so tight that only the planted record (factor 1.5) fits.
    let e = select(
        &design,
        &candidates,
        Limits {
            count: 2,
            max_scale: 1.0 + 1e-9,
            per_event: None,
        },
    )
    .unwrap_err();
    assert!(e.to_string().contains("need a factor outside"), "{e}");
}
