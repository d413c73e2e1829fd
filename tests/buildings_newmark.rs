//! Newmark-β on a row (SPEC §5, §13) converges to the exact method at
//! second order as Δt halves: yielding, and contact onsets located per
//! floor pair.

use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, RowRun, run_newmark, run_row};

fn error(a: &RowRun, b: &RowRun) -> f64 {
    let mut worst = 0.0f64;
    for (fa, fb) in a.floors.iter().zip(&b.floors) {
        let scale = fb.iter().fold(0.0f64, |m, f| m.max(f.displacement));
        for (x, y) in fa.iter().zip(fb) {
            worst = worst.max((x.displacement - y.displacement).abs() / scale);
        }
    }
    worst
}

#[test]
fn newmark_converges_to_the_exact_method_at_second_order() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load("block-and-frame").unwrap();
    let duration = 4.0;
    let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
    assert!(exact.impacts() > 0);
    let errors: Vec<f64> = [4e-4, 2e-4, 1e-4, 5e-5]
        .iter()
        .map(|&dt| {
            let nm = run_newmark(&row, &ground, duration, dt).unwrap();
            let counts: Vec<usize> = nm.pairs.iter().map(|p| p.impacts.len()).collect();
            let want: Vec<usize> = exact.pairs.iter().map(|p| p.impacts.len()).collect();
            assert_eq!(counts, want, "Δt = {dt}");
            error(&nm, &exact)
        })
        .collect();
    println!("errors {errors:?}");
    for w in errors.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((1.6..2.6).contains(&order), "order {order}: {errors:?}");
    }
    assert!(errors[0] < 1e-3, "{errors:?}");
}
