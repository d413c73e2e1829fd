//! Newmark-β with γ = 1/2, β = 1/4 (SPEC §5): the paper's method, run from
//! rest to τ_end.
//!
//! A run is a loop over phases (`driver`): out of contact, whole steps of
//! Δτ in a tight loop; in contact, Newton steps of Δτ/n (`phases`). A step
//! that crosses δ = 0 is handed to the [`policy`]: the plain scheme switches
//! the phase at the step's end, the located one cuts the step at the
//! crossing ([`locate`]). Every accepted state, whichever loop produced it,
//! goes through one `accept`: work integrals, peaks (with the
//! Hermite peaks inside a step, [`peaks`]), impacts, force extremes and the
//! observer. A run stops early, and says where and why, when the observer
//! cancels it, its state stops being finite, or it meets a [`caps`] limit.
//!
//! - [`step`]: one step of the coupled 2-DOF system (exact branch solve out
//!   of contact, Newton with the consistent tangent in contact);
//! - `options`: the numerical choices ([`SolverOptions`]).

mod accept;
pub mod caps;
mod driver;
pub mod locate;
mod options;
pub mod peaks;
mod phases;
pub mod policy;
pub mod step;

pub use caps::RunCaps;
pub use options::{AUTO_CONTACT_PHASE, ContactSubsteps, SolverOptions};
pub use step::{MAX_NEWTON, Phase, State, System};

use crate::model::Params;

use crate::solver::observer::Observer;
use crate::solver::result::RunResult;
use driver::Driver;
use policy::{Located, Plain};

/// Runs the simulation with the default (accurate) options, peaks only.
pub fn run(p: &Params) -> RunResult {
    simulate(p, &SolverOptions::default(), &mut ())
}

/// Runs one simulation of `p`, reporting every accepted state to `observer`.
///
/// Any finite `p` returns: a run whose state stops being finite, or that
/// meets one of its [`RunCaps`], ends early with `completed = false` and
/// [`RunResult::stop`] saying where and why; the observer can cancel it too.
/// [`Params::validate`] keeps the numbers meaningful, not the run finite.
pub fn simulate<O: Observer>(p: &Params, options: &SolverOptions, observer: &mut O) -> RunResult {
    let mut run = Driver::new(p, options, observer);
    if options.locate_contact {
        run.run(&Located, observer);
    } else {
        run.run(&Plain, observer);
    }
    run.finish()
}
