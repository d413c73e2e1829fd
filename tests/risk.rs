//! The risk picture (`analysis::risk`) is made of the suite runs `pounding
//! suite`, `ida` and `gap --suite` make: at each level its drift statistics
//! and pounding counts are those of the suite at that level, and its Π_d,min
//! are those of the suite at the design level, also when the design level is
//! not one of the IDA's levels; a `keep_going` that says no stops it.

use pounding::analysis::risk::{Kept, risk};
use pounding::analysis::statistics::Summary;
use pounding::analysis::subject::runs::{plan, run_suite};
use pounding::analysis::suite::{Scaling, SuiteCase, SuiteRun};
use pounding::model::intensity::IntensityMeasure;
use pounding::model::physical::Physical;
use pounding::model::preset::builtin;
use pounding::model::suite::{SuiteMember, SuiteSpec};
use pounding::model::{Method, Params};

fn case() -> (SuiteCase, Vec<SuiteMember>) {
    let preset = builtin("two-buildings").unwrap();
    let physical = Physical::from_table(preset.physical.as_ref().unwrap()).unwrap();
    let case = SuiteCase {
        physical,
        settings: Params {
            method: Method::Exact,
            ..preset.params.clone()
        },
        scaling: Scaling {
            measure: IntensityMeasure::Sa { period: 0.95 },
            level: None,
            collective: false,
        },
    };
    let members = SuiteSpec::parse("synthetic:8").unwrap().load().unwrap();
    (case, members)
}

fn suite_at(case: &SuiteCase, members: &[SuiteMember], level: f64) -> Vec<SuiteRun> {
    let at = SuiteCase {
        scaling: Scaling {
            level: Some(level),
            ..case.scaling
        },
        ..case.clone()
    };
    let plans = plan(&at, members).unwrap();
    run_suite(&at, members, &plans, &|_| ()).unwrap()
}

#[test]
fn the_picture_is_the_suites_at_each_level_and_at_the_design_level() {
    let (case, members) = case();
    let levels = [0.05, 0.1, 0.2];
    let design = 0.15;
    let mut kept = Kept::default();
    let p = risk(&case, &members, design, &levels, &|| true, &mut kept)
        .unwrap()
        .unwrap();
    assert_eq!((p.records, p.drift.len(), p.pounding.len()), (8, 3, 3));
    assert_eq!(p.gap_m, case.physical.gap);
    for (l, &level) in levels.iter().enumerate() {
        let runs = suite_at(&case, &members, level);
        let left = |free: bool| {
            let v: Vec<f64> = runs
                .iter()
                .map(|r| {
                    let si = if free { &r.free_si } else { &r.si };
                    si.left.peak_displacement_m
                })
                .collect();
            Summary::of(&v)
        };
        assert_eq!(p.drift[l].level, level);
        assert_eq!(p.drift[l].pounding, left(false), "level {level}");
        assert_eq!(p.drift[l].free, left(true), "level {level}");
        let pounded = runs.iter().filter(|r| r.pounded()).count();
        assert_eq!((p.pounding[l].runs, p.pounding[l].exceeded), (8, pounded));
    }
    let gaps: Vec<f64> = suite_at(&case, &members, design)
        .iter()
        .map(SuiteRun::min_gap_m)
        .collect();
    assert_eq!(p.min_gaps_m, gaps);
    // The design level among the levels: its runs are the IDA's.
    let q = risk(
        &case,
        &members,
        0.1,
        &levels,
        &|| true,
        &mut Kept::default(),
    )
    .unwrap()
    .unwrap();
    let at = suite_at(&case, &members, 0.1);
    assert_eq!(
        q.min_gaps_m,
        at.iter().map(SuiteRun::min_gap_m).collect::<Vec<_>>()
    );
}

#[test]
fn a_keep_going_that_says_no_stops_the_picture() {
    let (case, members) = case();
    let asked = std::cell::Cell::new(0);
    let stop_after_one = || {
        asked.set(asked.get() + 1);
        asked.get() < 2
    };
    let p = risk(
        &case,
        &members,
        0.3,
        &[0.1, 0.2, 0.3, 0.4, 0.5],
        &stop_after_one,
        &mut Kept::default(),
    )
    .unwrap();
    assert!(p.is_none());
    assert_eq!(asked.get(), 2);
}
