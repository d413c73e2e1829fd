//! Studies on a row of buildings (SPEC §12 with §13), through the library:
//! a suite's record is bit for bit the row's own run under that record
//! and scale, and its run apart that of the buildings apart to rounding
//! (it continues from the run with contact's state at the first onset,
//! [`pounding::solver::buildings::Checkpoint`]: every peak within 1e-12 of
//! its own value, the residual drifts within 1e-14 m); a fragility fitted
//! on a row's IDA is the maximum-likelihood fit of the counts its records
//! give; the separation at a probability per joint is the order statistic
//! of the records' gaps, each of which is what `gap --buildings` measures
//! for that record, within 1e-12.

mod common;

use pounding::analysis::fragility::{self, LevelCount};
use pounding::analysis::gap::row_gap;
use pounding::analysis::ida::fragilities;
use pounding::analysis::ida::over_levels;
use pounding::analysis::limit_state::LimitParser;
use pounding::analysis::separation::gap_at_probability;
use pounding::analysis::separation::joint_separations;
use pounding::analysis::statistics::Summary;
use pounding::analysis::subject::row::{RowCaches, RowSuiteCase, RowSuiteRun, row_intensity};
use pounding::analysis::subject::runs::{plan, plan_levels, run_levels, run_one, run_suite};
use pounding::analysis::suite::Scaling;
use pounding::analysis::suite_statistics::SuiteStatistics;
use pounding::model::buildings::matrices::{default_tail, periods};
use pounding::model::buildings::{Ground, Row, load};
use pounding::model::intensity::IntensityMeasure;
use pounding::model::suite::{SuiteMember, SuiteSpec};
use pounding::solver::buildings::{RowOptions, RowRun, run_row};

fn members(count: usize) -> Vec<SuiteMember> {
    SuiteSpec::parse(&format!("synthetic:{count}"))
        .and_then(|s| s.load())
        .unwrap()
}

/// The suite's runs of `m` under `c`, as `suite --buildings` plans and
/// makes them.
fn suite_runs(c: &RowSuiteCase, m: &[SuiteMember]) -> Vec<RowSuiteRun> {
    run_suite(c, m, &plan(c, m).unwrap(), &|_| {}).unwrap()
}

fn case(row: &str, level: f64) -> RowSuiteCase {
    RowSuiteCase {
        row: load(row).unwrap(),
        scaling: Scaling {
            measure: IntensityMeasure::Pga,
            level: Some(level),
            collective: false,
        },
    }
}

/// Every field of two runs but the counts of the maps cache (a study keeps
/// its maps across records and makes fewer).
fn same_motion(a: &RowRun, b: &RowRun) {
    assert_eq!(a.floors, b.floors);
    assert_eq!(a.pairs, b.pairs);
    assert_eq!(a.max_relative, b.max_relative);
    assert_eq!(a.final_displacement, b.final_displacement);
    assert_eq!(a.final_velocity, b.final_velocity);
    assert_eq!(a.duration.to_bits(), b.duration.to_bits());
    assert_eq!(
        (a.map_steps, a.series_steps, a.configurations),
        (b.map_steps, b.series_steps, b.configurations)
    );
}

/// Two runs of the same motion to rounding: their impacts the same, every
/// peak within 1e-12 of its own value, the residual drifts within 1e-14 m
/// and the end states within 1e-12 of the peaks.
fn close_motion(a: &RowRun, b: &RowRun) {
    assert_eq!(a.impacts(), b.impacts());
    let (peaks, residual, end) = common::motion_differences(a, b);
    assert!(
        peaks < 1e-12 && residual < 1e-14 && end < 1e-12,
        "{peaks:e} {residual:e} m {end:e}"
    );
}

/// The run `pounding run --buildings` makes of a record at scale s.
fn own_run(row: &Row, member: &SuiteMember, scale: f64) -> RowRun {
    let ground = Ground::from_record(&member.record, scale);
    let duration = ground.end() + default_tail(row);
    run_row(row, &ground, &RowOptions::lasting(duration)).unwrap()
}

#[test]
fn a_suite_record_is_the_rows_own_run_bit_for_bit() {
    let c = case("block-and-frame", 0.3);
    let m = members(4);
    let scales = plan(&c, &m).unwrap();
    let runs = run_suite(&c, &m, &scales, &|_| {}).unwrap();
    let apart = c.row.apart();
    for (r, member) in runs.iter().zip(&m) {
        // s = X / PGA, and the scaled record's PGA is the level.
        assert_eq!(r.scale, 0.3 / (member.record.peak / 9.80665));
        assert!((r.intensity - 0.3).abs() <= 1e-15, "{}", r.intensity);
        same_motion(&r.run, &own_run(&c.row, member, r.scale));
        assert!(
            r.demands.pounded,
            "5 mm apart at 0.3 g, every record pounds"
        );
        close_motion(&r.free, &own_run(&apart, member, r.scale));
        // The demands are the run's largest, exactly.
        let frame = &r.run.floors[1];
        let drift = frame.iter().map(|f| f.drift_ratio).fold(0.0, f64::max);
        assert_eq!(r.demands.buildings[1].max_drift_ratio, drift);
        let force = r
            .run
            .pairs
            .iter()
            .map(|p| p.max_force())
            .fold(0.0, f64::max);
        assert_eq!(r.demands.joints[0].max_force_kn, force / 1e3);
        assert_eq!(r.demands.joints[0].impacts, r.run.impacts());
    }
    // A record run alone, with fresh caches, is the same record.
    let alone = run_one(&c, &m[2], &scales[2], &mut RowCaches::default()).unwrap();
    same_motion(&alone.run, &runs[2].run);
    assert_eq!(alone.demands, runs[2].demands);
}

#[test]
fn statistics_are_those_of_the_records_demands() {
    let c = case("three-in-series", 0.2);
    let m = members(5);
    let runs = suite_runs(&c, &m);
    let st = SuiteStatistics::of(&c, &runs);
    assert_eq!(st.records, 5);
    let tall: Vec<f64> = runs
        .iter()
        .map(|r| r.demands.buildings[2].max_drift_ratio)
        .collect();
    let key = format!("{}.max_drift_ratio", c.row.buildings[2].name);
    let d = st.demands.iter().find(|d| d.demand == key).unwrap();
    assert_eq!(d.summary, Summary::of(&tall));
    let gaps: Vec<f64> = runs
        .iter()
        .map(|r| r.demands.joints[1].gap.min_gap)
        .collect();
    let d = st
        .demands
        .iter()
        .find(|d| d.demand == "joint2.min_gap_m")
        .unwrap();
    assert_eq!(d.summary, Summary::of(&gaps));
}

#[test]
fn a_rows_fragility_is_the_maximum_likelihood_fit_of_its_counts() {
    let c = case("block-and-frame", 0.1);
    let m = members(6);
    let levels = [0.1, 0.2, 0.3, 0.4];
    let plans = plan_levels(&c, &m, &levels).unwrap();
    let runs = run_levels(&c, &m, &plans, &|_| {}).unwrap();
    // Level l's records are the suite's at that level, bit for bit.
    let at = case("block-and-frame", 0.3);
    let suite = suite_runs(&at, &m);
    for (a, b) in runs[2].iter().zip(&suite) {
        same_motion(&a.run, &b.run);
    }
    let parser = LimitParser::row(&c.row);
    let states = parser.drift("frame:0.005").unwrap();
    let fits = fragilities(&c, &levels, &runs, &states);
    let counts: Vec<LevelCount> = levels
        .iter()
        .zip(&runs)
        .map(|(&level, at)| LevelCount {
            level,
            runs: at.len(),
            exceeded: at
                .iter()
                .filter(|r| r.demands.buildings[1].max_drift_ratio > 0.005)
                .count(),
        })
        .collect();
    assert_eq!(fits[0].counts, counts);
    assert_eq!(fits[0].fragility, fragility::fit(&counts));
    assert_eq!(fits[0].limit_state, "drift>0.005 (frame)");
    // The same counts of the runs without contact.
    let free: Vec<usize> = runs
        .iter()
        .map(|at| {
            at.iter()
                .filter(|r| r.demands.no_pounding[1].max_drift_ratio > 0.005)
                .count()
        })
        .collect();
    let without: Vec<usize> = fits[0]
        .no_pounding_counts
        .as_ref()
        .unwrap()
        .iter()
        .map(|c| c.exceeded)
        .collect();
    assert_eq!(without, free);
    // The drift grows with the level: the counts do not fall.
    assert!(counts.windows(2).all(|w| w[0].exceeded <= w[1].exceeded));
    assert!(counts[3].exceeded > counts[0].exceeded, "{counts:?}");
}

#[test]
fn the_separation_per_joint_is_the_order_statistic_of_each_records_gap() {
    let c = case("block-and-frame", 0.3);
    let m = members(7);
    let runs = suite_runs(&c, &m);
    let seps = joint_separations(&c, &runs, &[0.5, 0.9]);
    assert_eq!(seps.len(), 1);
    let gaps: Vec<f64> = runs
        .iter()
        .map(|r| r.demands.joints[0].gap.min_gap)
        .collect();
    // Every record pounds, so its gap comes from a run apart, which is
    // the run `gap --buildings` makes for that record to rounding.
    for (r, member) in runs.iter().zip(&m) {
        let ground = Ground::from_record(&member.record, r.scale);
        let report = row_gap(&c.row, &ground, ground.end() + default_tail(&c.row), "x").unwrap();
        let (a, b) = (&report.joints[0], &r.demands.joints[0].gap);
        assert_eq!(
            (&a.left, &a.right, &a.floors),
            (&b.left, &b.right, &b.floors)
        );
        for (x, y) in [
            (a.min_gap, b.min_gap),
            (a.abs, b.abs),
            (a.srss, b.srss),
            (a.ddc, b.ddc),
        ] {
            assert!(common::relative(x, y) < 1e-12, "{x} against {y}");
        }
    }
    let study = &seps[0].study;
    let mut sorted = gaps.clone();
    sorted.sort_by(f64::total_cmp);
    // d_(⌈pN⌉): the 4th of 7 at p = 0.5 (the median), the 7th at 0.9.
    assert_eq!(study.at_probability[0].empirical, sorted[3]);
    assert_eq!(
        study.at_probability[0].empirical,
        gap_at_probability(&gaps, 0.5)
    );
    assert_eq!(study.at_probability[1].empirical, sorted[6]);
    // The lognormal fit's median, exp(mean ln d), is its gap at p = 0.5.
    let mean = gaps.iter().map(|d| d.ln()).sum::<f64>() / 7.0;
    let fit = study.lognormal.unwrap();
    assert!((fit.median - mean.exp()).abs() <= 1e-15 * fit.median);
    let at_half = study.at_probability[0].lognormal.unwrap();
    assert!((at_half - fit.median).abs() <= 1e-14 * fit.median);
    // A rule holds for a record when it is at least its gap; ABS always is.
    let abs = &study.rules[0];
    assert_eq!(abs.rule, "ABS");
    assert_eq!(abs.holds, 1.0);
    assert_eq!(seps[0].pounding_probability_at_gap, 1.0);
}

#[test]
fn sa_alone_is_sa_at_the_leftmost_buildings_period() {
    let row = load("block-and-frame").unwrap();
    let t1 = periods(&row.buildings[0])[0];
    assert!((t1 - 0.2874).abs() < 5e-5, "{t1}");
    // Four significant digits: the same measure as `--im sa:0.2874`.
    assert_eq!(row_intensity(&row), IntensityMeasure::Sa { period: 0.2874 });
}

#[test]
fn each_worker_keeps_its_state_and_the_order_is_kept() {
    let runs = over_levels(
        3,
        5,
        || 0usize,
        |seen, l, j| {
            *seen += 1;
            10 * l + j
        },
    );
    assert_eq!(runs.len(), 3);
    assert_eq!(runs[2], [20, 21, 22, 23, 24]);
}

/// A record whose only contacts are a bumper's has its run apart made, as
/// every record with contact has: the bumper's forces acted, so the run
/// with contact is not the buildings' run apart. The retrofit preset (a
/// 4 mm bumper in a 5 mm gap) at 0.05 g: records that touch the bumper and
/// never the hard face.
#[test]
fn a_record_that_touches_only_a_bumper_has_its_run_apart() {
    let c = case("block-and-frame-retrofit", 0.05);
    let m = members(4);
    let runs = suite_runs(&c, &m);
    let apart = c.row.apart();
    let mut seen = 0;
    for (r, member) in runs.iter().zip(&m) {
        if r.run.impacts() == 0 && r.run.contacts() > 0 {
            seen += 1;
            assert!(!r.demands.pounded);
            close_motion(&r.free, &own_run(&apart, member, r.scale));
            assert_ne!(r.free.floors, r.run.floors, "the bumper's forces acted");
        }
    }
    assert!(seen > 0, "no record touched only the bumper");
}
