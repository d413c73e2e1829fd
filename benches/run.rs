//! One run of each paper preset (both contact models), peaks only and with
//! the full history, with Newmark's default options; with the exact method
//! for the peaks and impacts alone (as a spectrum point runs) and for a full
//! run (its energy quadrature and every contact extreme, as `run`); and set 1
//! without pounding.
//! `cargo bench --bench run`. The default spectrum is in `benches/spectrum.rs`.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::model::{ContactModel, Params, SET1, SET2};
use pounding::solver::exact::{self, ContactExtremes, ExactOptions};
use pounding::solver::{FullHistory, SolverOptions, simulate};
use std::hint::black_box;

fn runs(c: &mut Criterion) {
    let options = SolverOptions::default();
    let mut group = c.benchmark_group("run");
    for (name, base) in [("set1", SET1), ("set2", SET2)] {
        for model in ContactModel::ALL {
            let p = Params {
                model,
                ..base.clone()
            };
            group.bench_function(format!("{name}/{model}/peaks-only"), |b| {
                b.iter(|| simulate(black_box(&p), &options, &mut ()))
            });
            let sweep = ExactOptions {
                energy: false,
                absolute_acceleration: false,
                extremes: ContactExtremes::None,
                ..ExactOptions::default()
            };
            group.bench_function(format!("{name}/{model}/exact"), |b| {
                b.iter(|| exact::simulate(black_box(&p), &sweep, &mut ()))
            });
            let with_energy = ExactOptions::default();
            group.bench_function(format!("{name}/{model}/exact-with-energy"), |b| {
                b.iter(|| exact::simulate(black_box(&p), &with_energy, &mut ()))
            });
            let steps = (p.tau_end() / p.dt) as usize + 1024;
            group.bench_function(format!("{name}/{model}/full-history"), |b| {
                b.iter(|| {
                    let mut history = FullHistory::with_capacity(steps);
                    simulate(black_box(&p), &options, &mut history);
                    history
                })
            });
        }
    }
    // No pounding (Π_d = ∞): every step but the last is the free phase's tight loop.
    let free = Params {
        gap: f64::INFINITY,
        ..SET1
    };
    group.bench_function("set1/no-pounding/peaks-only", |b| {
        b.iter(|| simulate(black_box(&free), &options, &mut ()))
    });
    group.finish();
}

criterion_group!(benches, runs);
criterion_main!(benches);
