//! The run of a row's buildings apart continued from the run with contact's
//! state just before its first contact onset (SPEC §13,
//! [`Checkpoint`]) against the run apart from t = 0.
//!
//! Up to the first onset the two rows obey the same equations, so the two
//! runs apart differ by rounding only: the run with contact takes some
//! sub-steps before the onset by the series where the run apart takes its
//! map, and the continuation splits one sub-step at the onset. Every peak
//! (each floor's |u|, |u̇|, |ü + ü_g|, each storey's |Δ|, Δ/h and ductility,
//! each facing pair's largest u_A − u_B, each link's force, stroke and
//! rate) agrees within 1e-12 of its own value; the residual drifts,
//! differences of much larger drifts, within 1e-14 m; the end state within
//! 1e-12 of the run's peak displacement or velocity (the end state may have
//! decayed far below the scale at which round-off accumulates). A wrong
//! state carried over (a branch, a plastic offset, a peak so far) would
//! differ by the order of the motion itself.
//!
//! Over 1,000 random cases of the proptest (760 of them pounding) the
//! largest differences seen were 9.3e-14 (a peak), 1.8e-15 m (a residual
//! drift) and 1.7e-14 (the end state), so the tolerances are round-off
//! with a margin.

mod common;

use proptest::prelude::*;

use pounding::model::ContactModel;
use pounding::model::buildings::{self, Ground, Row};
use pounding::model::simulated::Simulation;
use pounding::solver::buildings::{
    Checkpoint, MapCache, PairResult, RowOptions, RowRun, run_row, run_row_from, run_row_keeping,
};

/// Relative agreement of every peak.
const PEAKS: f64 = 1e-12;
/// Absolute agreement of the residual drifts (m).
const RESIDUAL: f64 = 1e-14;

/// The run of a row with contact and its checkpoint, and the runs of its
/// buildings apart continued from it and from t = 0.
struct Runs {
    with: RowRun,
    checkpoint: Option<Checkpoint>,
    continued: RowRun,
    fresh: RowRun,
}

/// The run of `row` keeping its checkpoint (the same run as without), and
/// the runs apart continued from it and from t = 0.
fn runs(row: &Row, ground: &Ground, options: &RowOptions) -> Runs {
    let (with, checkpoint) =
        run_row_keeping(row, ground, options, &mut MapCache::default()).expect("runs");
    assert_eq!(
        same(&with),
        same(&run_row(row, ground, options).expect("runs"))
    );
    let apart = row.apart();
    let continued = run_row_from(
        &apart,
        ground,
        options,
        &mut MapCache::default(),
        checkpoint.as_ref(),
    )
    .expect("runs");
    let fresh = run_row(&apart, ground, options).expect("runs");
    Runs {
        with,
        checkpoint,
        continued,
        fresh,
    }
}

/// A run as text: two runs are the same to the bit when their texts are
/// (an impact still open at the end has NaN, which no `==` equals).
fn same(run: &RowRun) -> String {
    format!("{run:?}")
}

/// The first onset of any contact element of a run with contact (s).
fn first_onset(run: &RowRun) -> Option<f64> {
    earliest(run.pairs.iter().chain(&run.bumpers))
}

/// The first onset among the impacts of `elements` (s).
fn earliest<'a>(elements: impl IntoIterator<Item = &'a PairResult>) -> Option<f64> {
    elements
        .into_iter()
        .flat_map(|p| &p.impacts)
        .map(|i| i.start)
        .reduce(f64::min)
}

fn record(seed: u64, duration: f64) -> pounding::model::record::Record {
    Simulation {
        dt: 0.005,
        duration,
        ..Default::default()
    }
    .record("random", seed, 1)
}

/// Runs the three runs of `row` under a record at `scale`, checks that the
/// checkpoint is taken at the first onset and that the continuation agrees
/// with the run from t = 0, and prints the differences.
fn check(row: &Row, seed: u64, scale: f64) -> Runs {
    let ground = Ground::from_record(&record(seed, 4.0), scale);
    let options = RowOptions::lasting(ground.end() + 1.0);
    let runs = runs(row, &ground, &options);
    let Runs {
        with,
        checkpoint,
        continued,
        fresh,
    } = &runs;
    let onset = first_onset(with);
    assert_eq!(checkpoint.as_ref().map(Checkpoint::time), onset);
    assert_eq!(
        continued.collapse.map(|c| (c.building, c.storey)),
        fresh.collapse.map(|c| (c.building, c.storey))
    );
    let d = common::motion_differences(continued, fresh);
    assert!(d.0 < PEAKS, "peaks differ by {:e}", d.0);
    assert!(d.1 < RESIDUAL, "residual drifts differ by {:e} m", d.1);
    assert!(d.2 < PEAKS, "end states differ by {:e}", d.2);
    println!(
        "{} under record {seed} at {scale}: peaks {:e}, residual drifts {:e} m, end state {:e}",
        row.name, d.0, d.1, d.2
    );
    runs
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Random rows, records, scales and contact laws (both of the paper's
    /// and a Hertz-type one, stepped by Runge–Kutta in contact).
    #[test]
    fn the_continued_run_apart_is_the_run_from_rest(
        stiffness in 0.5f64..2.0,
        yield_factor in 0.3f64..3.0,
        gap in 0.002f64..0.05,
        model in prop::sample::select(vec![
            ContactModel::Kelvin,
            ContactModel::ImprovedKelvin,
            ContactModel::HuntCrossley,
        ]),
        seed in 1u64..1000,
        scale in 0.3f64..3.0,
    ) {
        check(&common::scaled_block_and_frame(stiffness, yield_factor, gap, model), seed, scale);
    }
}

/// A row with P-Δ, up to and past its collapse (SPEC §15): the storeys'
/// geometric stiffness acts in both rows, and a collapse apart comes at
/// the same instant.
#[test]
fn a_row_with_p_delta_continues() {
    let row = buildings::load("block-and-frame-pdelta").expect("shipped");
    let mut collapsed = 0;
    for (seed, scale) in [(3, 1.0), (5, 2.0), (8, 3.0), (13, 5.0)] {
        collapsed += usize::from(check(&row, seed, scale).fresh.collapse.is_some());
    }
    assert!(collapsed > 0, "no collapse apart");
}

/// The retrofit preset: its bumper (1 mm from the frame) closes before the
/// joint's own pairs, so the checkpoint is the bumper's first onset; its
/// linear link acts in both rows.
#[test]
fn a_row_with_a_bumper_and_a_link_continues() {
    let row = buildings::load("block-and-frame-retrofit").expect("shipped");
    for (seed, scale) in [(2, 0.5), (4, 1.0), (6, 2.0)] {
        let runs = check(&row, seed, scale);
        let bumper = earliest(&runs.with.bumpers);
        assert!(bumper.is_some());
        assert_eq!(runs.checkpoint.map(|c| c.time()), bumper);
    }
}

/// A run continued with its energy balance, trace and link forces kept
/// carries them over: the same sub-step ends as from rest, the same
/// displacements there and the same energy terms, to rounding.
#[test]
fn the_energy_and_the_trace_continue() {
    let row = buildings::load("block-and-frame-retrofit").expect("shipped");
    let ground = Ground::from_record(&record(7, 4.0), 1.5);
    let options = RowOptions {
        energy: true,
        trace: true,
        forces: true,
        ..RowOptions::lasting(ground.end() + 1.0)
    };
    let Runs {
        checkpoint,
        continued,
        fresh,
        ..
    } = runs(&row, &ground, &options);
    assert!(checkpoint.is_some());
    let d = common::motion_differences(&continued, &fresh);
    assert!(d.0 < PEAKS && d.1 < RESIDUAL && d.2 < PEAKS, "{d:?}");
    let (a, b) = (continued.trace.expect("kept"), fresh.trace.expect("kept"));
    assert_eq!(a.times, b.times);
    let scale = b.displacement.iter().fold(0.0f64, |m, u| m.max(u.abs()));
    let trace = a
        .displacement
        .iter()
        .zip(&b.displacement)
        .map(|(p, q)| (p - q).abs())
        .fold(0.0, f64::max)
        / scale;
    assert!(trace < PEAKS, "traces differ by {trace:e}");
    let (a, b) = (continued.energy.expect("kept"), fresh.energy.expect("kept"));
    let input = b.max_input;
    for (what, x, y) in [
        ("input", a.input, b.input),
        ("kinetic", a.kinetic, b.kinetic),
        ("damping", a.damping, b.damping),
        ("spring", a.spring, b.spring),
        ("link", a.link, b.link),
    ] {
        assert!(
            (x - y).abs() < 1e-10 * input,
            "{what}: {x} against {y} (input {input})"
        );
    }
    let (a, b) = (continued.forces.expect("kept"), fresh.forces.expect("kept"));
    assert_eq!(a.links.len(), b.links.len());
    for (x, y) in a.links.iter().zip(&b.links) {
        assert_eq!(x[0], y[0]);
        let (p, q) = (x.last().expect("points"), y.last().expect("points"));
        assert_eq!(p.0, q.0);
    }
}

/// A row with a fluid viscous damper keeps no checkpoint (its steps are
/// sized by an error estimate, not only by rounding), and a checkpoint
/// continues only its own buildings apart, under its own ground and
/// options: anything else runs from t = 0, bit for bit.
#[test]
fn a_checkpoint_continues_only_the_twin_it_fits() {
    let damper = buildings::load_with("block-and-frame-retrofit", &["link1.exponent=0.5".into()])
        .expect("shipped");
    let ground = Ground::from_record(&record(4, 2.0), 1.0);
    let options = RowOptions::lasting(ground.end() + 0.5);
    let damped = runs(&damper, &ground, &options);
    assert!(first_onset(&damped.with).is_some());
    assert!(damped.checkpoint.is_none());

    let row = buildings::load("block-and-frame").expect("shipped");
    let ground = Ground::from_record(&record(4, 4.0), 1.0);
    let options = RowOptions::lasting(ground.end() + 1.0);
    let checkpoint = runs(&row, &ground, &options).checkpoint.expect("it pounds");
    let apart = row.apart();
    assert!(checkpoint.fits(&apart, &ground, &options));
    let stiffer = buildings::load_with("block-and-frame", &["frame.damping=0.06".into()])
        .expect("shipped")
        .apart();
    let other = Ground::from_record(&record(4, 4.0), 1.1);
    let longer = RowOptions::lasting(ground.end() + 2.0);
    for (twin, ground, options) in [
        (&row, &ground, &options),
        (&stiffer, &ground, &options),
        (&apart, &other, &options),
        (&apart, &ground, &longer),
    ] {
        assert!(!checkpoint.fits(twin, ground, options));
        let from = run_row_from(
            twin,
            ground,
            options,
            &mut MapCache::default(),
            Some(&checkpoint),
        )
        .expect("runs");
        assert_eq!(
            same(&from),
            same(&run_row(twin, ground, options).expect("runs"))
        );
    }
}
