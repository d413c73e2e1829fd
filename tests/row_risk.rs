//! The risk picture at one joint of a row (SPEC §12 with §13) against runs
//! made one by one: each record's gap that prevents pounding at the design
//! level is `gap --buildings` of that record at that scale (within 1e-12:
//! the study's run apart continues from its run with contact's state at the
//! first onset, [`pounding::solver::buildings::Checkpoint`]; bit for bit
//! where the record does not pound),
//! the drift IDA summarises each run's largest storey drift of the
//! building followed, the counts are the records whose joint had an
//! impact, and the fragility is the maximum-likelihood fit of those counts.

use pounding::analysis::fragility;
use pounding::analysis::gap::row_gap;
use pounding::analysis::risk::{Kept, RowRiskCase, row_risk as risk};
use pounding::analysis::statistics::Summary;
use pounding::analysis::suite::raw_intensity;
use pounding::model::buildings::matrices::default_tail;
use pounding::model::buildings::{Ground, load_with};
use pounding::model::intensity::IntensityMeasure;
use pounding::model::suite::SuiteSpec;
use pounding::solver::buildings::{RowOptions, run_row};

#[test]
fn the_row_picture_is_made_of_the_runs_one_by_one() {
    let members = SuiteSpec::parse("synthetic:6").unwrap().load().unwrap();
    // A wider gap, so that some records pound and some do not.
    let row = load_with("block-and-frame", &["joint1.gap=0.03".into()]).unwrap();
    let case = RowRiskCase {
        joint: 0,
        building: RowRiskCase::taller_of(&row, 0),
        measure: IntensityMeasure::Pga,
        row: row.clone(),
    };
    assert_eq!(case.building, 1);
    let levels = [0.2, 0.4, 0.6];
    let design = 0.3;
    let mut kept = Kept::default();
    let p = risk(&case, &members, design, &levels, &|| true, &mut kept)
        .unwrap()
        .unwrap();
    assert_eq!(p.records, 6);
    assert_eq!(p.gap_m, 0.03);
    assert_eq!(p.drift_title, "frame drift [mm]");
    let run_at = |m: &pounding::model::suite::SuiteMember, x: f64| {
        let scale = x / raw_intensity(m, &case.measure).unwrap();
        let ground = Ground::from_record(&m.record, scale);
        let duration = ground.end() + default_tail(&row);
        (ground, duration)
    };
    // At the design level: each record's gap at the joint, as `gap --buildings`.
    for (m, &d) in members.iter().zip(&p.min_gaps_m) {
        let (ground, duration) = run_at(m, design);
        let report = row_gap(&row, &ground, duration, &m.name).unwrap();
        let gap = report.joints[0].min_gap;
        assert!(
            (d - gap).abs() <= 1e-12 * gap,
            "{}: {d} against {gap}",
            m.name
        );
    }
    // Each level: the counts and the drift summaries of the runs one by one.
    let mut some_pound = false;
    let mut some_not = false;
    for ((&x, count), drift) in levels.iter().zip(&p.pounding).zip(&p.drift) {
        let mut drifts = Vec::new();
        let mut pounded = 0;
        for m in &members {
            let (ground, duration) = run_at(m, x);
            let run = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
            let hit = run.pairs.iter().any(|p| !p.impacts.is_empty());
            pounded += usize::from(hit);
            drifts.push(run.floors[1].iter().map(|f| f.drift).fold(0.0, f64::max));
        }
        assert_eq!(count.level, x);
        assert_eq!(count.runs, 6);
        assert_eq!(count.exceeded, pounded, "level {x}");
        some_pound |= pounded > 0;
        some_not |= pounded < 6;
        assert_eq!(drift.pounding, Summary::of(&drifts), "level {x}");
        assert!(drift.free.median > 0.0);
    }
    assert!(some_pound && some_not, "{:?}", p.pounding);
    assert_eq!(p.fragility, fragility::fit(&p.pounding));
    // Stopped between levels: no picture.
    assert_eq!(
        risk(
            &case,
            &members,
            design,
            &levels,
            &|| false,
            &mut Kept::default()
        )
        .unwrap(),
        None
    );
}

/// The explorer's passes share their runs ([`Kept`]): a coarse picture on
/// a few records and levels, then the full one and the full one with more
/// levels, each given the runs of the passes before it, are the pictures
/// made afresh, equal in every field, and the full ones run only the
/// (level, record) pairs not run before.
#[test]
fn pictures_that_keep_earlier_runs_are_the_pictures_made_afresh() {
    let members = SuiteSpec::parse("synthetic:4").unwrap().load().unwrap();
    let row = load_with("block-and-frame", &["joint1.gap=0.02".into()]).unwrap();
    let case = RowRiskCase {
        joint: 0,
        building: 1,
        measure: IntensityMeasure::Pga,
        row,
    };
    let design = 0.3;
    let mut kept = Kept::default();
    let picture = |members: &[_], levels: &[f64], kept: &mut Kept<_>| {
        risk(&case, members, design, levels, &|| true, kept)
            .unwrap()
            .unwrap()
    };
    let coarse = picture(&members[..2], &[0.2, 0.5], &mut kept);
    assert_eq!(
        coarse,
        picture(&members[..2], &[0.2, 0.5], &mut Kept::default())
    );
    // Two records at the two levels and the design level.
    assert_eq!(kept.len(), 6);
    let levels = [0.1, 0.2, 0.5];
    let full = picture(&members, &levels, &mut kept);
    assert_eq!(full, picture(&members, &levels, &mut Kept::default()));
    assert_eq!(kept.len(), 4 * 4);
    let more = [0.1, 0.2, 0.35, 0.5];
    let bridged = picture(&members, &more, &mut kept);
    assert_eq!(bridged, picture(&members, &more, &mut Kept::default()));
    assert_eq!(kept.len(), 4 * 5);
    assert_eq!(bridged.records, 4);
}
