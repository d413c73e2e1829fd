//! The runs a figure needs, with the chosen integrator: full histories for
//! the time-history figures, peaks-only sweeps for the spectra. Every
//! figure computes through these two functions, so the method is chosen in
//! one place.

use crate::analysis::baseline::BaselineCache;
use crate::analysis::similarity::{Level, study};
use crate::analysis::sweep::{Curve, CurveSpec, sweep};
use crate::model::physical::Physical;
use crate::model::{Method, Params};
use crate::solver::{FullHistory, RunResult, solve};

use super::FigureError;

/// One run with every accepted state recorded.
pub fn history(p: &Params, method: Method) -> Result<(RunResult, FullHistory), FigureError> {
    let p = &Params {
        method,
        ..p.clone()
    };
    let mut h = FullHistory::with_capacity((p.tau_end() / p.dt) as usize + 16);
    let r = solve(p, &mut h);
    if let Some(why) = r.unreliable() {
        return Err(FigureError::Run(why));
    }
    Ok((r, h))
}

/// Every curve of a spectrum figure on the Π_ω1 grid `omega1` (SPEC §7).
pub fn spectra(
    specs: &[CurveSpec],
    omega1: &[f64],
    method: Method,
) -> Result<Vec<Curve>, FigureError> {
    let specs: Vec<CurveSpec> = specs
        .iter()
        .map(|s| CurveSpec {
            params: Params {
                method,
                ..s.params.clone()
            },
            ..s.clone()
        })
        .collect();
    Ok(sweep(&specs, omega1, &mut BaselineCache::new()))
}

/// The spectrum of `physical` at each excitation amplitude (SPEC §8).
pub fn levels(
    physical: &Physical,
    settings: &Params,
    amplitudes: &[f64],
    omega1: &[f64],
    mu: f64,
    method: Method,
) -> Result<Vec<Level>, FigureError> {
    let settings = &Params {
        method,
        ..settings.clone()
    };
    study(physical, settings, amplitudes, omega1, mu, true)
        .map_err(|e| FigureError::Input(e.to_string()))
}
