//! The default set-1 spectrum (291 points of Π_ω1 = 0.1:3.0:0.01, μ = 2.25,
//! with its no-pounding baseline), from an empty baseline cache each time:
//! measured per method (the exact method is the default of spectra).

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::analysis::baseline::BaselineCache;
use pounding::analysis::grid::Grid;
use pounding::analysis::sweep::{curve_specs, sweep};
use pounding::model::{Method, Params, SET1};

fn default_spectrum(c: &mut Criterion) {
    let grid = Grid::default().values();
    let mut group = c.benchmark_group("spectrum");
    group.sample_size(10);
    for method in Method::ALL {
        let p = Params { method, ..SET1 };
        let specs = curve_specs(&p, p.mu(), None).unwrap();
        group.bench_function(format!("set1_default_291_points/{method}"), |b| {
            b.iter(|| sweep(&specs, &grid, &mut BaselineCache::new()))
        });
    }
    group.finish();
}

criterion_group!(benches, default_spectrum);
criterion_main!(benches);
