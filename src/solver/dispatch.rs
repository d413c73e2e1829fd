//! One entry point for both methods: a parameter set names its method
//! ([`Params::method`]), and [`solve`] runs it with that method's
//! production options.

use crate::model::{Method, Params};

use super::exact::{self, ContactExtremes, ExactOptions};
use super::newmark::{SolverOptions, simulate};
use super::observer::Observer;
use super::result::RunResult;

/// Runs `p` (validated) with its own method, reporting to `observer`, with
/// the energy balance of SPEC §6.
pub fn solve<O: Observer>(p: &Params, observer: &mut O) -> RunResult {
    match p.method {
        Method::Newmark => simulate(p, &newmark_options(p), observer),
        Method::Exact => exact::simulate(p, &exact_options(p), observer),
    }
}

/// Newmark's production options with the set's ground motion and the
/// initial velocity it imposes (SPEC §9: ẋ_i(0) = −1 under the type B pulse).
pub fn newmark_options(p: &Params) -> SolverOptions {
    let excitation = p.ground();
    SolverOptions {
        initial_velocity: excitation.initial_velocity(),
        excitation,
        ..SolverOptions::default()
    }
}

/// The exact method's options for the set, as [`newmark_options`].
pub fn exact_options(p: &Params) -> ExactOptions {
    let excitation = p.ground();
    ExactOptions {
        initial_velocity: excitation.initial_velocity(),
        excitation,
        contact_tolerance: p.contact_tolerance,
        ..ExactOptions::default()
    }
}

/// Runs `p` with its own method, peaks only.
pub fn run(p: &Params) -> RunResult {
    solve(p, &mut ())
}

/// Runs `p` for a sweep, where only the peaks, the impacts and the
/// `extremes` asked for are used: the exact method then skips its energy
/// quadrature, the absolute accelerations and the other extremes (Newmark's cost nothing extra and are kept).
pub fn run_for_sweep(p: &Params, extremes: ContactExtremes) -> RunResult {
    match p.method {
        Method::Newmark => simulate(p, &newmark_options(p), &mut ()),
        Method::Exact => exact::simulate(
            p,
            &ExactOptions {
                energy: false,
                absolute_acceleration: false,
                extremes,
                ..exact_options(p)
            },
            &mut (),
        ),
    }
}

/// The largest relative error of the four peaks [Π_u1, Π_v1, Π_u2, Π_v2] of
/// `result` against the exact method's run of the same parameters: the
/// error Newmark actually made, shown beside its result. A peak of zero
/// counts by its absolute error.
pub fn error_vs_exact(p: &Params, result: &RunResult) -> f64 {
    let exact = run_for_sweep(
        &Params {
            method: Method::Exact,
            ..p.clone()
        },
        ContactExtremes::None,
    );
    relative_peak_error(&result.peaks(), &exact.peaks())
}

/// max_k |a_k − b_k| / |b_k| (absolute where b_k = 0).
pub fn relative_peak_error(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| {
            let d = (x - y).abs();
            if *y != 0.0 { d / y.abs() } else { d }
        })
        .fold(0.0, f64::max)
}
