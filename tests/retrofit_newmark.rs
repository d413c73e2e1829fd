//! Newmark-β with bumpers and links (SPEC §5, §14) converges to the exact
//! method as Δt halves: at second order with linear links, and with bumper
//! contacts located per element as the joints' own are.

use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, RowRun, run_newmark, run_row};

/// Largest difference of the floors' peak |u|, relative to each building's
/// largest, and of the links' peak forces, relative to each.
fn error(a: &RowRun, b: &RowRun) -> f64 {
    let mut worst = 0.0f64;
    for (fa, fb) in a.floors.iter().zip(&b.floors) {
        let scale = fb.iter().fold(0.0f64, |m, f| m.max(f.displacement));
        for (x, y) in fa.iter().zip(fb) {
            worst = worst.max((x.displacement - y.displacement).abs() / scale);
        }
    }
    for (x, y) in a.links.iter().zip(&b.links) {
        worst = worst.max((x.max_force - y.max_force).abs() / y.max_force);
    }
    worst
}

/// Largest difference of the floors' displacements at the end, relative to
/// the largest: free of the sampling of peaks at step ends.
fn final_error(a: &RowRun, b: &RowRun) -> f64 {
    let scale = b
        .final_displacement
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    a.final_displacement
        .iter()
        .zip(&b.final_displacement)
        .map(|(x, y)| (x - y).abs() / scale)
        .fold(0.0, f64::max)
}

fn orders(
    sets: &[String],
    measure: fn(&RowRun, &RowRun) -> f64,
    (low, high): (f64, f64),
) -> Vec<f64> {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load_with("block-and-frame-retrofit", sets).unwrap();
    let duration = 4.0;
    let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
    let count = |r: &RowRun| -> Vec<usize> {
        r.pairs
            .iter()
            .chain(&r.bumpers)
            .map(|p| p.impacts.len())
            .collect()
    };
    let errors: Vec<f64> = [4e-4, 2e-4, 1e-4, 5e-5]
        .iter()
        .map(|&dt| {
            let nm = run_newmark(&row, &ground, duration, dt).unwrap();
            assert_eq!(count(&nm), count(&exact), "Δt = {dt}");
            measure(&nm, &exact)
        })
        .collect();
    println!("{sets:?}: errors {errors:?}");
    for w in errors.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((low..high).contains(&order), "order {order}: {errors:?}");
    }
    errors
}

#[test]
fn newmark_converges_at_second_order_with_linear_links() {
    let errors = orders(
        &["joint1.gap=\"inf\"".into(), "link1.stiffness=3e6".into()],
        final_error,
        (1.9, 2.1),
    );
    assert!(errors[0] < 1e-4, "{errors:?}");
}

#[test]
fn newmark_converges_with_bumper_contacts_and_a_link() {
    let errors = orders(&[], error, (1.6, 2.6));
    assert!(errors[0] < 1e-3, "{errors:?}");
}
