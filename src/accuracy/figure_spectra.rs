//! Accuracy over the paper's spectra: every point of the ten curves of
//! Figures 7–10 (Π_ω1 = 0.10 … 3.00 in steps of 0.01, each with and without
//! pounding), one method against the reference at a tight tolerance, with
//! its peaks refined on the dense output. This is where grazing impacts
//! live, so it is the test of uniform accuracy that single presets are not.

use rayon::prelude::*;
use serde::Serialize;

use crate::analysis::baseline::BaselineCache;

use crate::analysis::spectrum::{at_omega, baseline_params};
use crate::analysis::sweep::{CurveSpec, curve_specs, sweep};
use crate::model::spectrum_spec::PresetSpectrum;
use crate::model::{Method, Params, preset};
use crate::reference::{ReferenceOptions, reference};
use crate::solver::exact::ContactExtremes;
use crate::solver::{relative_peak_error, run_for_sweep};

/// The presets of Figures 7–10, in order.
pub const FIGURE_PRESETS: [&str; 4] = [
    "fig7",
    "fig8-gap",
    "fig9-mass-ratio",
    "fig10-frequency-ratio",
];

/// Tolerance of the reference the errors are measured against.
pub const REFERENCE_TOLERANCE: f64 = 1e-12;

/// The curves of each figure preset with `method`: (preset name, curve specs, grid).
fn figure_curves(method: Method) -> Vec<(&'static str, Vec<CurveSpec>, Vec<f64>)> {
    FIGURE_PRESETS
        .iter()
        .map(|&name| {
            let preset = preset::builtin(name).expect("figure presets are built in");
            let own = PresetSpectrum::of(preset.spectrum.as_ref(), preset.params.clone())
                .expect("built-in spectrum tables are valid");
            let p = Params {
                method,
                ..preset.params.clone()
            };
            let curves = curve_specs(&p, own.mu, own.family.as_ref()).expect("built-in curves");
            (name, curves, own.grid.values())
        })
        .collect()
}

/// Every run of the ten curves: the pounding run of each grid point and its
/// no-pounding twin, for `method`.
pub fn figure_runs(method: Method) -> Vec<(String, Params)> {
    let mut runs = Vec::new();
    for (name, curves, grid) in figure_curves(method) {
        for curve in curves {
            for &omega1 in &grid {
                let q = at_omega(&curve.params, omega1, curve.mu);
                let label = format!(
                    "{name} {} Π_ω1={omega1:.2}",
                    curve_label(&curve.params, curve.mu)
                );
                let free = baseline_params(&q);
                runs.push((label.clone(), q));
                runs.push((format!("{label} no pounding"), free));
            }
        }
    }
    runs
}

fn curve_label(p: &Params, mu: f64) -> String {
    format!("Π_m={} μ={mu} Π_d={}", p.mass_ratio, p.gap)
}

/// The verdict over the ten curves.
#[derive(Debug, Clone, Serialize)]
pub struct SpectraAccuracy {
    pub method: Method,
    pub runs: usize,
    pub max_rel_error: f64,
    /// The point where the largest error occurred.
    pub worst: String,
    /// Points whose error exceeds 1e-7 (the exact method's target).
    pub above_1e_7: usize,
    /// Points with a different impact count than the reference.
    pub impact_count_mismatches: usize,
}

/// Runs every point with `method` and with the reference, in parallel.
pub fn measure(method: Method) -> SpectraAccuracy {
    let runs = figure_runs(method);
    let errors: Vec<(f64, bool)> = runs
        .par_iter()
        .map(|(_, p)| {
            let r = run_for_sweep(p, ContactExtremes::None);
            let q = reference(p, &ReferenceOptions::with_tolerance(REFERENCE_TOLERANCE));
            (
                relative_peak_error(&r.peaks(), &q.peaks),
                r.impacts.len() != q.impacts.len(),
            )
        })
        .collect();
    let (worst_index, max) =
        errors.iter().enumerate().fold(
            (0, 0.0),
            |(wi, w), (i, (e, _))| if *e > w { (i, *e) } else { (wi, w) },
        );
    SpectraAccuracy {
        method,
        runs: runs.len(),
        max_rel_error: max,
        worst: runs
            .get(worst_index)
            .map(|r| r.0.clone())
            .unwrap_or_default(),
        above_1e_7: errors.iter().filter(|(e, _)| *e > 1e-7).count(),
        impact_count_mismatches: errors.iter().filter(|(_, m)| *m).count(),
    }
}

/// Wall time of the ten curves with `method`, computed as `pounding spectrum`
/// does (in parallel, each figure's no-pounding baselines shared), in seconds.
pub fn time_all_curves(method: Method) -> f64 {
    let figures = figure_curves(method);
    let start = std::time::Instant::now();
    for (_, curves, grid) in &figures {
        std::hint::black_box(sweep(curves, grid, &mut BaselineCache::new()));
    }
    start.elapsed().as_secs_f64()
}
