//! The time integrators, and pluggable observers. Two production methods
//! share the model, the observers and [`RunResult`], not their stepping:
//! Newmark-β with γ = 1/2, β = 1/4 and located contact (SPEC §5), the paper's
//! method; and [`exact`], event-driven with the free motion in closed form.
//!
//! - [`dispatch`]: [`solve`] and [`run`] pick the method a parameter set names;
//! - [`exact`]: the event-driven method;
//! - [`newmark`]: one step of the coupled 2-DOF system (exact branch solve out
//!   of contact, Newton with the consistent tangent in contact);
//! - [`events`]: locating contact onset and separation inside a step;
//! - [`simulate`]: the run driver (steps, events, sub-steps in contact, energy);
//! - [`observer`]: what gets recorded (nothing, a full history, a decimated one);
//! - [`result`]: what a run reports (SPEC §6).

pub mod dispatch;
pub mod events;
pub mod exact;
pub mod newmark;
pub mod observer;
pub mod result;
pub mod simulate;

pub use crate::model::Method;
pub use dispatch::{
    error_vs_exact, exact_options, newmark_options, relative_peak_error, run, run_for_sweep, solve,
};
pub use observer::{CsvHistory, Decimated, FullHistory, Observer, Sample};
pub use result::{
    ENERGY_TOLERANCE, EnergyBalance, Impact, RunResult, Stop, StopReason, StructurePeaks,
};
pub use simulate::{ContactSubsteps, SolverOptions, simulate};
