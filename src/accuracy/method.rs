//! The schemes a work-precision row can measure.

use serde::Serialize;

use crate::model::Params;
use crate::reference::{ReferenceOptions, reference};
use crate::solver::exact::{self, ContactExtremes, ExactOptions};
use crate::solver::{SolverOptions, simulate};

/// One way of computing a run's four peaks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Method {
    /// Newmark at fixed Δτ, contact noticed at step ends ([`SolverOptions::plain`]).
    NewmarkPlain,
    /// Newmark with located contact onset and end ([`SolverOptions::located`]).
    NewmarkLocated,
    /// Located contact plus sub-steps inside contact so that Π_ωcon·h ≤ 0.005
    /// (the project default, [`SolverOptions::default`]).
    NewmarkSubstepped,
    /// The exact (event-driven) method at this contact tolerance, peaks only.
    Exact(f64),
    /// The adaptive DOPRI5 reference at this tolerance.
    Reference(f64),
}

impl Method {
    /// The Newmark variants, in the order of the table.
    pub const NEWMARK: [Method; 3] = [
        Method::NewmarkPlain,
        Method::NewmarkLocated,
        Method::NewmarkSubstepped,
    ];

    pub fn name(&self) -> &'static str {
        match self {
            Method::NewmarkPlain => "newmark-plain",
            Method::NewmarkLocated => "newmark-located",
            Method::NewmarkSubstepped => "newmark-substep",
            Method::Exact(_) => "exact",
            Method::Reference(_) => "reference",
        }
    }

    /// [Π_u1, Π_v1, Π_u2, Π_v2] of one run of `p` (Newmark at `p.dt`).
    pub fn peaks(&self, p: &Params) -> [f64; 4] {
        let newmark = |o: SolverOptions| simulate(p, &o, &mut ()).peaks();
        match *self {
            Method::NewmarkPlain => newmark(SolverOptions::plain()),
            Method::NewmarkLocated => newmark(SolverOptions::located()),
            Method::NewmarkSubstepped => newmark(crate::solver::newmark_options(p)),
            Method::Exact(tol) => exact::simulate(
                p,
                &ExactOptions {
                    energy: false,
                    absolute_acceleration: false,
                    contact_tolerance: tol,
                    extremes: ContactExtremes::None,
                    ..ExactOptions::default()
                },
                &mut (),
            )
            .peaks(),
            Method::Reference(tol) => reference(p, &ReferenceOptions::with_tolerance(tol)).peaks,
        }
    }
}

/// max over the four peaks of |p − p_ref| / |p_ref| (absolute where p_ref = 0):
/// the solver's [`relative_peak_error`](crate::solver::relative_peak_error), by value.
pub fn max_relative_error(peaks: [f64; 4], truth: [f64; 4]) -> f64 {
    crate::solver::relative_peak_error(&peaks, &truth)
}
