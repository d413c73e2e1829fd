//! The row's time history (SPEC §13), kept for drawing the row: it changes
//! nothing the run reports, and each recorded state is the state a run
//! stopped at that time ends in.

use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, run_row};

#[test]
fn the_trace_changes_nothing_and_its_points_are_the_run_states() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.5);
    let row = buildings::load("block-and-frame").unwrap();
    let duration = ground.end() + 2.0;
    let plain = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
    let traced = run_row(
        &row,
        &ground,
        &RowOptions {
            trace: true,
            ..RowOptions::lasting(duration)
        },
    )
    .unwrap();
    assert!(plain.impacts() > 10, "{} impacts", plain.impacts());
    let trace = traced.trace.clone().expect("asked for");
    // Bit for bit the same run otherwise.
    assert_eq!(
        Reported(&traced),
        Reported(&plain),
        "a trace changes the run"
    );
    assert_eq!(trace.dofs, row.dofs());
    assert_eq!(trace.times[0], 0.0);
    assert!(trace.times.windows(2).all(|w| w[1] > w[0]));
    assert_eq!(*trace.times.last().unwrap(), duration);
    assert_eq!(
        trace.point(trace.times.len() - 1),
        &plain.final_displacement[..]
    );
    // A record sample in the strong motion: the run stopped there ends in
    // the recorded state, bit for bit (the same sub-steps lead to it).
    let dt = record.dt;
    for sample in [300usize, 500, 700] {
        let t = ground.pieces(duration)[sample].t0;
        assert!((t - sample as f64 * dt).abs() < 1e-9);
        let k = trace
            .times
            .iter()
            .position(|&s| s == t)
            .expect("a sample end");
        let short = run_row(&row, &ground, &RowOptions::lasting(t)).unwrap();
        assert_eq!(trace.point(k), &short.final_displacement[..], "t = {t}");
        // Between recorded times, a straight line; at them, the values.
        assert_eq!(trace.at(t), trace.point(k).to_vec());
        let mid = 0.5 * (trace.times[k] + trace.times[k + 1]);
        let expected: Vec<f64> = trace
            .point(k)
            .iter()
            .zip(trace.point(k + 1))
            .map(|(a, b)| a + 0.5 * (b - a))
            .collect();
        for (a, b) in trace.at(mid).iter().zip(&expected) {
            assert!(
                (a - b).abs() <= 1e-12 * b.abs().max(1e-3),
                "{a} against {b}"
            );
        }
    }
    // The sub-steps are at most the record's step apart while it lasts.
    let longest = trace
        .times
        .windows(2)
        .filter(|w| w[1] <= ground.end())
        .map(|w| w[1] - w[0])
        .fold(0.0, f64::max);
    assert!(longest <= dt * (1.0 + 1e-9), "longest sub-step {longest}");
}

/// A run without its trace, for comparison.
#[derive(Debug)]
struct Reported<'a>(&'a pounding::solver::buildings::RowRun);

impl PartialEq for Reported<'_> {
    fn eq(&self, other: &Self) -> bool {
        let (a, b) = (self.0, other.0);
        a.floors == b.floors
            && a.pairs == b.pairs
            && a.final_displacement == b.final_displacement
            && a.final_velocity == b.final_velocity
            && a.max_relative == b.max_relative
    }
}
