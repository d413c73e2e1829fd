//! One study stack over a [`Subject`] (SPEC §12, §13): the pair as the
//! `two-buildings` preset's `[physical]` table and the same pair written as
//! two one-storey buildings (the row preset `two-buildings`) give the same
//! demands, record by record, through the one generic code path: a suite,
//! every level of an IDA, the counts of a limit state and the gap at a
//! probability per joint. A study cut into shards and its parts' runs read
//! back (the parts' own encoding) rebuilds the whole study bit for bit, for
//! either subject.

use pounding::analysis::fragility::LevelCount;
use pounding::analysis::ida::{counts, fragilities};
use pounding::analysis::limit_state::{LimitParser, LimitState, Target};
use pounding::analysis::risk::{Focus, picture};
use pounding::analysis::separation::{JointSeparation, gap_at_probability, joint_separations};
use pounding::analysis::shard::partition;
use pounding::analysis::shard::partition::units_of;
use pounding::analysis::shard::suite::{compute, rebuild, unit_work};
use pounding::analysis::subject::Subject;
use pounding::analysis::subject::demands::Demands;
use pounding::analysis::subject::row::RowSuiteCase;
use pounding::analysis::subject::runs::{plan, plan_levels, run_levels, run_suite};
use pounding::analysis::suite::{Scaling, SuiteCase};
use pounding::analysis::suite_statistics::SuiteStatistics;
use pounding::model::buildings::load;
use pounding::model::intensity::IntensityMeasure;
use pounding::model::physical::Physical;
use pounding::model::preset::builtin;
use pounding::model::suite::{SuiteMember, SuiteSpec};
use pounding::model::{Method, Params};

const TOLERANCE: f64 = 1e-9;

fn scaling(level: Option<f64>) -> Scaling {
    Scaling {
        measure: IntensityMeasure::Pga,
        level,
        collective: false,
    }
}

/// The `two-buildings` pair by its `[physical]` table, exact method.
fn pair(level: Option<f64>) -> SuiteCase {
    let preset = builtin("two-buildings").unwrap();
    SuiteCase {
        physical: Physical::from_table(preset.physical.as_ref().unwrap()).unwrap(),
        settings: Params {
            method: Method::Exact,
            ..preset.params.clone()
        },
        scaling: scaling(level),
    }
}

/// The same pair as two one-storey buildings.
fn row(level: Option<f64>) -> RowSuiteCase {
    RowSuiteCase {
        row: load("two-buildings").unwrap(),
        scaling: scaling(level),
    }
}

fn members() -> Vec<SuiteMember> {
    SuiteSpec::parse("synthetic:4@3")
        .and_then(|s| s.load())
        .unwrap()
}

/// Every record's demands at every level, through the generic stack.
fn ida_demands<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    levels: &[f64],
) -> Vec<Vec<Demands>>
where
    S::Error: std::fmt::Debug,
{
    let plans = plan_levels(subject, members, levels).unwrap();
    run_levels(subject, members, &plans, &|_| {})
        .unwrap()
        .iter()
        .map(|level| level.iter().map(|r| subject.demands(r)).collect())
        .collect()
}

fn close(what: &str, a: f64, b: f64, scale: f64) {
    assert!(
        (a - b).abs() <= TOLERANCE * scale.max(1.0),
        "{what}: pair {a} against row {b}"
    );
}

/// The demands of the pair and of the row, record by record, to 1e-9 (of
/// the demand's size where it exceeds 1).
fn same_demands(pair: &Demands, row: &Demands) {
    assert_eq!(pair.buildings.len(), 2);
    assert_eq!(row.buildings.len(), 2);
    for (side, (p, r)) in [
        ("with contact", (&pair.buildings, &row.buildings)),
        ("apart", (&pair.no_pounding, &row.no_pounding)),
    ] {
        for (i, (a, b)) in p.iter().zip(r).enumerate() {
            close(
                &format!("{side} {i} drift"),
                a.peak_drift_m,
                b.peak_drift_m,
                1.0,
            );
            close(
                &format!("{side} {i} ductility"),
                a.ductility,
                b.ductility,
                b.ductility,
            );
            close(
                &format!("{side} {i} acceleration"),
                a.acceleration_g,
                b.acceleration_g,
                b.acceleration_g,
            );
            assert_eq!((a.collapsed, a.cut_short), (b.collapsed, b.cut_short));
        }
    }
    let (a, b) = (&pair.joints[0], &row.joints[0]);
    assert_eq!(a.impacts, b.impacts, "impacts");
    close("force kN", a.max_force_kn, b.max_force_kn, b.max_force_kn);
    close("gap that prevents pounding", a.min_gap_m, b.min_gap_m, 1.0);
}

#[test]
fn the_pair_and_its_two_one_storey_buildings_name_the_same_buildings_and_joint() {
    let (p, r) = (pair(None), row(None));
    let (pb, rb) = (p.buildings(), r.buildings());
    for (a, b) in pb.iter().zip(&rb) {
        close("T1", a.period_s, b.period_s, 1.0);
    }
    // The leftmost building is the frame, T1 = 0.95 s, in both.
    close("default period", p.default_period(), 0.95, 1.0);
    close("default period", r.default_period(), 0.95, 1.0);
    assert_eq!(p.joints()[0].gap_m, r.joints()[0].gap_m);
    assert_eq!(p.joints()[0].gap_m, 0.025);
}

#[test]
fn a_suite_gives_the_same_demands_for_the_pair_and_its_row() {
    let m = members();
    let (p, r) = (pair(Some(0.3)), row(Some(0.3)));
    let pair_runs = run_suite(&p, &m, &plan(&p, &m).unwrap(), &|_| {}).unwrap();
    let row_runs = run_suite(&r, &m, &plan(&r, &m).unwrap(), &|_| {}).unwrap();
    let mut pounded = 0;
    for (a, b) in pair_runs.iter().zip(&row_runs) {
        assert_eq!((a.scale, a.intensity), (b.scale, b.intensity));
        let (da, db) = (p.demands(a), r.demands(b));
        same_demands(&da, &db);
        pounded += usize::from(da.joints[0].impacts > 0);
    }
    assert!(pounded > 0, "25 mm apart at 0.3 g, some record pounds");
}

#[test]
fn an_ida_its_limit_state_counts_and_the_separation_are_the_same_for_both() {
    let m = members();
    let levels = [0.1, 0.3];
    let pair_levels = ida_demands(&pair(None), &m, &levels);
    let row_levels = ida_demands(&row(None), &m, &levels);
    for (a, b) in pair_levels
        .iter()
        .flatten()
        .zip(row_levels.iter().flatten())
    {
        same_demands(a, b);
    }
    // The counts of the limit states "pounding" and "left drift > 20 mm"
    // at each level, as an IDA's fragility fits them.
    let limit: [fn(&Demands) -> bool; 2] = [
        |d| d.joints[0].impacts > 0,
        |d| d.buildings[0].peak_drift_m > 0.02,
    ];
    for exceeds in limit {
        let pc: Vec<LevelCount> = counts(&levels, &pair_levels, exceeds);
        let rc: Vec<LevelCount> = counts(&levels, &row_levels, exceeds);
        assert_eq!(pc, rc);
    }
    // The gap at 10 % and 50 % per joint, over the records at 0.3 g.
    let gaps = |at: &[Demands]| -> Vec<f64> { at.iter().map(|d| d.joints[0].min_gap_m).collect() };
    for probability in [0.1, 0.5] {
        let (a, b) = (
            gap_at_probability(&gaps(&pair_levels[1]), probability),
            gap_at_probability(&gaps(&row_levels[1]), probability),
        );
        close("gap at a probability", a, b, 1.0);
    }
}

/// The limit states of the pair in its spelling and of its row in the
/// row's, the same demands read: pounding, either's and the frame's
/// acceleration, the impact force, the frame's ductility.
fn same_limit_states() -> [(LimitState, LimitState); 6] {
    let p = LimitParser::pair();
    let r = LimitParser::row(&load("two-buildings").unwrap());
    let one = |s: Vec<LimitState>| s.into_iter().next().unwrap();
    let frame = |index| Target::Building {
        index,
        name: ["frame", "block"][index].into(),
    };
    let left = Target::Building {
        index: 0,
        name: "left".into(),
    };
    [
        (p.pounding(), r.pounding()),
        (
            one(p.acceleration("0.3g").unwrap()),
            one(r.acceleration("0.3g").unwrap()),
        ),
        (
            one(p.acceleration("left:0.25g").unwrap()),
            one(r.acceleration("frame:0.25g").unwrap()),
        ),
        (
            one(p.acceleration("right:0.2g").unwrap()),
            one(r.acceleration("block:0.2g").unwrap()),
        ),
        (one(p.force("200").unwrap()), one(r.force("200").unwrap())),
        (
            LimitState::Ductility {
                building: left,
                value: 0.1,
            },
            LimitState::Ductility {
                building: frame(0),
                value: 0.1,
            },
        ),
    ]
}

#[test]
fn the_limit_states_and_their_fragility_are_the_same_for_both() {
    let m = members();
    let levels = [0.1, 0.2, 0.4];
    let (p, r) = (pair(None), row(None));
    let pair_runs = run_levels(&p, &m, &plan_levels(&p, &m, &levels).unwrap(), &|_| {}).unwrap();
    let row_runs = run_levels(&r, &m, &plan_levels(&r, &m, &levels).unwrap(), &|_| {}).unwrap();
    let (ps, rs): (Vec<_>, Vec<_>) = same_limit_states().into_iter().unzip();
    let pf = fragilities(&p, &levels, &pair_runs, &ps);
    let rf = fragilities(&r, &levels, &row_runs, &rs);
    // Each subject's own spelling.
    let labels = |f: &[pounding::analysis::ida::LimitStateFragility]| -> Vec<String> {
        f.iter().map(|f| f.limit_state.clone()).collect()
    };
    assert_eq!(
        labels(&pf),
        [
            "pounding",
            "acceleration>0.3g (either)",
            "acceleration>0.25g (left)",
            "acceleration>0.2g (right)",
            "force>200kN",
            "ductility>0.1 (left)"
        ]
    );
    assert_eq!(
        labels(&rf),
        [
            "pounding (any)",
            "acceleration>0.3g (any)",
            "acceleration>0.25g (frame)",
            "acceleration>0.2g (block)",
            "force>200kN (any)",
            "ductility>0.1 (frame)"
        ]
    );
    let mut between = 0;
    for (a, b) in pf.iter().zip(&rf) {
        assert_eq!(a.counts, b.counts, "{}", a.limit_state);
        assert_eq!(
            a.no_pounding_counts, b.no_pounding_counts,
            "{}",
            a.limit_state
        );
        assert_eq!(a.fragility, b.fragility, "{}", a.limit_state);
        assert_eq!(a.no_pounding_fragility, b.no_pounding_fragility);
        between += a
            .counts
            .iter()
            .filter(|c| c.exceeded > 0 && c.exceeded < c.runs)
            .count();
    }
    // The counts tell the records apart: some level of some limit state
    // has records on either side.
    assert!(between > 0, "{pf:?}");
    // The counts are those of the demands read directly.
    let pounded: Vec<usize> = row_runs
        .iter()
        .map(|at| {
            at.iter()
                .filter(|x| r.demands(x).joints[0].impacts > 0)
                .count()
        })
        .collect();
    let counted: Vec<usize> = rf[0].counts.iter().map(|c| c.exceeded).collect();
    assert_eq!(counted, pounded);
}

#[test]
fn the_risk_picture_is_the_same_for_the_pair_and_its_row() {
    let m = members();
    let focus = Focus {
        joint: 0,
        building: 0,
    };
    let levels = [0.1, 0.3];
    let p = picture(&pair(None), focus, &m, 0.2, &levels, &|| true)
        .unwrap()
        .unwrap();
    let r = picture(&row(None), focus, &m, 0.2, &levels, &|| true)
        .unwrap()
        .unwrap();
    assert_eq!((p.records, p.gap_m), (r.records, r.gap_m));
    assert_eq!(p.pounding, r.pounding);
    assert_eq!(p.fragility, r.fragility);
    assert_eq!(p.collapse, r.collapse);
    for (a, b) in p.min_gaps_m.iter().zip(&r.min_gaps_m) {
        close("gap at the design level", *a, *b, 1.0);
    }
    for (a, b) in p.drift.iter().zip(&r.drift) {
        for (x, y) in [(a.pounding, b.pounding), (a.free, b.free)] {
            close("median drift", x.median, y.median, 1.0);
            close("16th percentile drift", x.p16, y.p16, 1.0);
            close("84th percentile drift", x.p84, y.p84, 1.0);
        }
    }
    // The titles name each subject's own building.
    assert_eq!(p.drift_title, "left drift [mm]");
    assert_eq!(r.drift_title, "frame drift [mm]");
}

/// The subject's study cut into `n` shards: each shard's runs through the
/// parts' own encoding (CBOR), merged and rebuilt, as `show` writes a
/// record's result (Debug: every f64 written to round trip), beside the
/// whole study's.
fn sharded_and_whole<S: Subject>(
    subject: &S,
    m: &[SuiteMember],
    levels: &[f64],
    n: usize,
    show: impl Fn(&S::Run) -> String,
) -> (Vec<String>, Vec<String>)
where
    S::Error: std::fmt::Debug,
{
    let (merged, whole) = sharded_runs(subject, m, levels, n);
    (
        merged.iter().map(&show).collect(),
        whole.iter().map(&show).collect(),
    )
}

/// The subject's runs cut into `n` shards, through the parts' encoding,
/// merged; beside the whole study's runs (levels one after the other).
fn sharded_runs<S: Subject>(
    subject: &S,
    m: &[SuiteMember],
    levels: &[f64],
    n: usize,
) -> (Vec<S::Run>, Vec<S::Run>)
where
    S::Error: std::fmt::Debug,
{
    let plans = plan_levels(subject, m, levels).unwrap();
    let units: Vec<_> = plans.iter().flat_map(|at| at.iter().enumerate()).collect();
    let shard_of = partition(&unit_work(subject, m, &units), n);
    let mut slots: Vec<Option<S::Runs>> = units.iter().map(|_| None).collect();
    for k in 0..n {
        let mine = units_of(&shard_of, k);
        let runs = compute(subject, m, &units, &mine).unwrap();
        let mut bytes = Vec::new();
        ciborium::into_writer(&runs, &mut bytes).unwrap();
        let read: Vec<S::Runs> = ciborium::from_reader(bytes.as_slice()).unwrap();
        for (i, r) in mine.into_iter().zip(read) {
            slots[i] = Some(r);
        }
    }
    let merged = rebuild(
        subject,
        m,
        &units,
        slots.into_iter().map(Option::unwrap).collect(),
    );
    let whole = run_levels(subject, m, &plans, &|_| {}).unwrap();
    (merged, whole.into_iter().flatten().collect())
}

#[test]
fn a_sharded_study_of_either_subject_merges_to_its_whole_run_bit_for_bit() {
    let m = members();
    let levels = [0.1, 0.3];
    let (sharded, whole) = sharded_and_whole(&pair(None), &m, &levels, 3, |r| format!("{r:?}"));
    assert_eq!(sharded, whole, "the pair");
    let block_and_frame = RowSuiteCase {
        row: load("block-and-frame").unwrap(),
        scaling: scaling(None),
    };
    // Every field of the runs but the counts of the maps cache (a worker
    // keeps its maps across records, and makes fewer).
    let (sharded, whole) = sharded_and_whole(&block_and_frame, &m, &levels, 3, |r| {
        let motion = |x: &pounding::solver::buildings::RowRun| {
            format!(
                "{:?}",
                (
                    &x.floors,
                    &x.pairs,
                    &x.max_relative,
                    &x.final_displacement,
                    &x.final_velocity,
                    x.duration,
                    x.collapse,
                )
            )
        };
        format!(
            "{} {} {:?} {} {}",
            r.scale,
            r.intensity,
            r.demands,
            motion(&r.run),
            motion(&r.free)
        )
    });
    assert!(whole.len() == 8);
    assert_eq!(sharded, whole, "block-and-frame");
}

/// The suite's statistics, through the one `SuiteStatistics::of`: the
/// pair's joint demands (`impacts`, `max_force_kn`, `min_gap_m`) are the
/// row's `joint1.…`, to 1e-9, and the same records pound.
#[test]
fn a_suite_s_statistics_are_the_same_for_the_pair_and_its_row() {
    let m = members();
    let (p, r) = (pair(Some(0.3)), row(Some(0.3)));
    let pair_runs = run_suite(&p, &m, &plan(&p, &m).unwrap(), &|_| {}).unwrap();
    let row_runs = run_suite(&r, &m, &plan(&r, &m).unwrap(), &|_| {}).unwrap();
    let (a, b) = (
        SuiteStatistics::of(&p, &pair_runs),
        SuiteStatistics::of(&r, &row_runs),
    );
    assert_eq!((a.records, a.pounded), (b.records, b.pounded));
    assert!(a.pounded > 0);
    let of = |st: &SuiteStatistics, key: &str| {
        st.demands
            .iter()
            .find(|d| d.demand == key)
            .unwrap_or_else(|| panic!("{key}"))
            .summary
    };
    for key in ["impacts", "max_force_kn", "min_gap_m"] {
        let (x, y) = (of(&a, key), of(&b, &format!("joint1.{key}")));
        assert_eq!((x.count, x.zeros), (y.count, y.zeros), "{key}");
        for (what, u, v) in [
            ("median", x.median, y.median),
            ("p16", x.p16, y.p16),
            ("p84", x.p84, y.p84),
            ("dispersion", x.dispersion, y.dispersion),
        ] {
            close(&format!("{key} {what}"), u, v, v.abs());
        }
    }
}

/// Two separations' numbers, to 1e-9 (of their size above 1).
fn same_separation(a: &JointSeparation, b: &JointSeparation) {
    assert_eq!(a.gap_m, b.gap_m);
    assert_eq!(a.pounding_probability_at_gap, b.pounding_probability_at_gap);
    let (x, y) = (&a.study, &b.study);
    assert_eq!((x.records, x.zero_gaps), (y.records, y.zero_gaps));
    close("median gap", x.median_min_gap, y.median_min_gap, 1.0);
    for (u, v) in x.at_probability.iter().zip(&y.at_probability) {
        assert_eq!(u.probability, v.probability);
        close("gap at p", u.empirical, v.empirical, 1.0);
        close(
            "lognormal gap at p",
            u.lognormal.unwrap(),
            v.lognormal.unwrap(),
            1.0,
        );
    }
    for k in 0..2 {
        close("median peak", x.median_peaks[k], y.median_peaks[k], 1.0);
    }
    close("ρ", x.correlation, y.correlation, 1.0);
    for (u, v) in x.rules.iter().zip(&y.rules) {
        assert_eq!((u.rule, u.holds), (v.rule, v.holds));
        close(u.rule, u.at_median_peaks, v.at_median_peaks, 1.0);
        assert_eq!(u.sufficient_at, v.sufficient_at, "{}", u.rule);
    }
}

/// The separation at a probability, through the one `joint_separations`:
/// the pair's one joint and its row's joint1 give the same gaps, fit and
/// code rules, to 1e-9.
#[test]
fn the_separation_at_a_probability_is_the_same_for_the_pair_and_its_row() {
    let m = members();
    let (p, r) = (pair(Some(0.3)), row(Some(0.3)));
    let pair_runs = run_suite(&p, &m, &plan(&p, &m).unwrap(), &|_| {}).unwrap();
    let row_runs = run_suite(&r, &m, &plan(&r, &m).unwrap(), &|_| {}).unwrap();
    let probabilities = [0.1, 0.5, 0.9];
    let a = joint_separations(&p, &pair_runs, &probabilities);
    let b = joint_separations(&r, &row_runs, &probabilities);
    assert_eq!((a.len(), b.len()), (1, 1));
    assert!(a[0].study.records == 4 && a[0].study.median_min_gap > 0.025);
    same_separation(&a[0], &b[0]);
}

/// A sharded suite's statistics and separation, of either subject, are
/// its whole run's to the bit.
#[test]
fn a_sharded_suite_and_separation_merge_to_the_whole_study_bit_for_bit() {
    let m = members();
    let probabilities = [0.5, 0.9];
    fn studies<S: Subject>(s: &S, runs: &[S::Run], probabilities: &[f64]) -> String {
        format!(
            "{:?} {:?}",
            SuiteStatistics::of(s, runs),
            joint_separations(s, runs, probabilities)
        )
    }
    let p = pair(Some(0.3));
    let (merged, whole) = sharded_runs(&p, &m, &[0.3], 3);
    assert_eq!(
        studies(&p, &merged, &probabilities),
        studies(&p, &whole, &probabilities)
    );
    let block_and_frame = RowSuiteCase {
        row: load("block-and-frame").unwrap(),
        scaling: scaling(None),
    };
    let (merged, whole) = sharded_runs(&block_and_frame, &m, &[0.3], 3);
    assert_eq!(merged.len(), 4);
    assert_eq!(
        studies(&block_and_frame, &merged, &probabilities),
        studies(&block_and_frame, &whole, &probabilities)
    );
}
