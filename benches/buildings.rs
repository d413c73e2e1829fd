//! Rows of buildings (SPEC §13) by the exact method: block-and-frame (3 + 8
//! storeys, 5 mm apart) under a simulated 2,000-sample record (about 30
//! impacts at the block's roof, yielding), and three-in-series (17 storeys)
//! under an 8,000-sample one. `cargo bench --bench buildings`;
//! `pounding bench --buildings NAME --excitation synthetic:N` prints the
//! work-precision rows beside the reference.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::model::buildings::{self, Ground};
use pounding::model::simulated::{DEFAULT_SEED, Simulation};
use pounding::solver::buildings::{RowOptions, run_row};
use std::hint::black_box;

fn ground(samples: usize) -> Ground {
    let record = Simulation {
        dt: 0.005,
        duration: 0.005 * (samples - 1) as f64,
        ..Default::default()
    }
    .record(&format!("synthetic:{samples}"), DEFAULT_SEED, 1);
    Ground::from_record(&record, 1.0)
}

fn rows(c: &mut Criterion) {
    for (name, samples) in [("block-and-frame", 2000), ("three-in-series", 8000)] {
        let row = buildings::load(name).expect("a shipped row");
        let g = ground(samples);
        let options = RowOptions::lasting(g.end() + 4.0);
        c.bench_function(&format!("exact {name} synthetic:{samples}"), |b| {
            b.iter(|| black_box(run_row(&row, &g, &options).expect("runs")))
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = rows
}
criterion_main!(benches);
