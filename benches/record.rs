//! The exact method under a record against its floor, the plain
//! Nigam–Jennings pass over the same samples ([`pounding::accuracy::floor`]):
//! set 1 elastic apart, inelastic apart and pounding, peaks only (peaks and
//! impacts, as a sweep runs) and full (energy, absolute accelerations, every
//! contact extreme), under presets/synthetic.at2 (1,000 samples at 0.01 s)
//! and a simulated 8,001-sample record (40 s at 0.005 s, seed 1).
//! `cargo bench --bench record`; `pounding bench --excitation record:PATH`
//! prints the same side by side with the ratios.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::accuracy::floor::NigamJennings;
use pounding::accuracy::record_speed::{cases, runs};
use pounding::model::record::intern;
use pounding::model::simulated::{DEFAULT_SEED, Simulation};
use pounding::model::{Excitation, Params, RecordMotion, SET1};
use pounding::solver::exact;
use std::hint::black_box;

fn records() -> Vec<(&'static str, Excitation)> {
    let shipped = Excitation::parse(concat!(
        "record:",
        env!("CARGO_MANIFEST_DIR"),
        "/presets/synthetic.at2"
    ))
    .expect("presets/synthetic.at2 reads");
    let long = Simulation {
        dt: 0.005,
        duration: 40.0,
        ..Default::default()
    }
    .record("synthetic-8001", DEFAULT_SEED, 1);
    vec![
        ("synthetic.at2", shipped),
        (
            "simulated-8001",
            Excitation::Record(RecordMotion::new(intern(long))),
        ),
    ]
}

fn record_runs(c: &mut Criterion) {
    let mut group = c.benchmark_group("record");
    for (name, excitation) in records() {
        let base = Params { excitation, ..SET1 };
        let floor = NigamJennings::new(&base).expect("a record");
        group.bench_function(format!("{name}/floor"), |b| {
            b.iter(|| black_box(&floor).peaks())
        });
        for (case, p) in cases(&base) {
            for (run, options) in runs(&p) {
                group.bench_function(format!("{name}/{case}/{run}"), |b| {
                    b.iter(|| exact::simulate(black_box(&p), &options, &mut ()))
                });
            }
        }
    }
    group.finish();
}

criterion_group!(benches, record_runs);
criterion_main!(benches);
