//! The deal of a sweep's units to shards, tested on the partition itself:
//! no shard of a 146 × 91 map carries more than 1.3 times the mean
//! estimated work, whether every cell has its own baseline (Π_ω1 × μ) or
//! whole columns share one (Π_ω1 × Π_d).

use pounding::analysis::map::{Axis, MapPlan};
use pounding::analysis::shard::map::units;
use pounding::analysis::shard::partition::{loads, partition};
use pounding::model::{Method, Params, SET1};

fn worst_over_mean(work: &[f64], n: usize) -> f64 {
    let l = loads(work, &partition(work, n), n);
    let mean = l.iter().sum::<f64>() / n as f64;
    l.iter().cloned().fold(0.0, f64::max) / mean
}

fn plan(y: &str, method: Method) -> MapPlan {
    let p = Params { method, ..SET1 };
    let x = Axis::parse("--x", "omega1=0.1:3.0:0.02").unwrap();
    let y = Axis::parse("--y", y).unwrap();
    let mu = p.mu();
    MapPlan::new(p, mu, x, y).unwrap()
}

#[test]
fn a_146_by_91_map_is_balanced_by_work() {
    for method in [Method::Exact, Method::Newmark] {
        let plan = plan("mu=1:10:0.1", method);
        assert_eq!((plan.x.len(), plan.y.len()), (146, 91));
        let u = units(&plan);
        assert_eq!(u.cells.iter().map(Vec::len).sum::<usize>(), 146 * 91);
        for n in [1, 2, 3, 4, 7, 8, 16, 32, 64, 128] {
            let r = worst_over_mean(&u.work, n);
            assert!(r <= 1.3, "{method:?}, {n} shards: {r}");
        }
    }
    // Columns that share a baseline stay in one shard each.
    let plan = plan("gap=0.1:1:0.01", Method::Exact);
    assert_eq!(plan.y.len(), 91);
    let u = units(&plan);
    assert_eq!(u.cells.len(), 146);
    for n in [1, 2, 3, 4, 7, 8, 16] {
        let r = worst_over_mean(&u.work, n);
        assert!(r <= 1.3, "gap axis, {n} shards: {r}");
    }
}

#[test]
fn high_frequency_cells_count_more() {
    let plan = plan("mu=1:10:0.1", Method::Exact);
    let u = units(&plan);
    // Row-major: the first cell is Π_ω1 = 0.1, μ = 1; the last Π_ω1 = 3, μ = 10.
    assert!(u.work[u.work.len() - 1] > 10.0 * u.work[0]);
    // A count-balanced deal would not be: the shards' cell counts differ.
    let shard_of = partition(&u.work, 4);
    let counts: Vec<usize> = (0..4)
        .map(|k| shard_of.iter().filter(|&&s| s == k).count())
        .collect();
    assert!(counts.iter().max() != counts.iter().min(), "{counts:?}");
}
