//! The gap that prevents pounding, per joint of a row (SPEC §13, §11): for
//! two one-storey buildings it is the SDOF pair's Π_d,min in metres; a row
//! with each joint's gap just above it never pounds there, just below it does.

use pounding::analysis::gap::minimum_gap;
use pounding::analysis::gap::row_gap;
use pounding::model::buildings::{self, Ground};
use pounding::model::preset::builtin;
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, run_row};

const G: f64 = 9.80665;

#[test]
fn one_storey_rows_give_the_pairs_minimum_gap() {
    let p = builtin("two-buildings").unwrap().params;
    let (ap, omega_p) = (0.5 * G, 2.0 * std::f64::consts::PI);
    let le = ap / (omega_p * omega_p);
    let want = minimum_gap(&p).exact * le;
    let row = buildings::load("two-buildings").unwrap();
    let ground = Ground::sine(ap, omega_p, 8.0);
    let got = row_gap(&row, &ground, 8.0, "sine").unwrap().joints[0].min_gap;
    assert!((got - want).abs() < 1e-10, "{got} {want}");
}

#[test]
fn a_gap_just_above_the_minimum_never_closes() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let duration = ground.end() + 2.0;
    let row = buildings::load("three-in-series").unwrap();
    let gaps = row_gap(&row, &ground, duration, "record").unwrap();
    for (factor, pounds) in [(1.0 + 1e-6, false), (0.99, true)] {
        let mut r = row.clone();
        for (j, g) in r.joints.iter_mut().zip(&gaps.joints) {
            j.gap = g.min_gap * factor;
        }
        let run = run_row(&r, &ground, &RowOptions::lasting(duration)).unwrap();
        for j in 0..r.joints.len() {
            let impacts: usize = r
                .pairs()
                .iter()
                .zip(&run.pairs)
                .filter(|(p, _)| p.joint == j)
                .map(|(_, x)| x.impacts.len())
                .sum();
            assert_eq!(
                impacts > 0,
                pounds,
                "joint {j}, gap × {factor}: {impacts} impacts"
            );
        }
    }
}
