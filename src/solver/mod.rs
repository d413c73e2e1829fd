//! The time integrators, and pluggable observers. Two production methods
//! share the model, the observers and [`RunResult`], not their stepping:
//! Newmark-β with γ = 1/2, β = 1/4 and located contact (SPEC §5), the paper's
//! method; and [`exact`], event-driven with the free motion in closed form.
//!
//! - [`dispatch`]: [`solve`] and [`run`] pick the method a parameter set names;
//! - [`exact`]: the event-driven method;
//! - [`newmark`]: the Newmark run: one step of the coupled 2-DOF system,
//!   contact onset and separation located inside a step, and the driver
//!   (a loop over free and contact phases, one accounting of every step);
//! - [`observer`]: what gets recorded (nothing, a full history, a decimated one);
//! - [`result`]: what a run reports (SPEC §6).

pub mod buildings;
pub mod dispatch;
pub mod exact;
pub mod newmark;
pub mod observer;
pub mod result;

pub use crate::model::Method;
pub use dispatch::{
    error_vs_exact, exact_options, newmark_options, relative_peak_error, run, run_for_sweep, solve,
};
pub use newmark::{ContactSubsteps, RunCaps, SolverOptions, simulate};
pub use observer::{CsvHistory, Decimated, FullHistory, Observer, Sample};
pub use result::{
    ENERGY_TOLERANCE, EnergyBalance, Impact, RunResult, Stop, StopReason, StructurePeaks,
};
