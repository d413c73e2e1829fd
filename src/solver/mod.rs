//! The time integrator: Newmark-β with γ = 1/2, β = 1/4 (SPEC §5), contact
//! event location, and pluggable observers.
//!
//! - [`newmark`]: the Newmark run: one step of the coupled 2-DOF system,
//!   contact onset and separation located inside a step, and the driver
//!   (a loop over free and contact phases, one accounting of every step);
//! - [`observer`]: what gets recorded (nothing, a full history, a decimated one);
//! - [`result`]: what a run reports (SPEC §6).

pub mod newmark;
pub mod observer;
pub mod result;

pub use crate::model::Method;
pub use newmark::{ContactSubsteps, RunCaps, SolverOptions, run, simulate};
pub use observer::{Decimated, FullHistory, Observer, Sample};
pub use result::{
    ENERGY_TOLERANCE, EnergyBalance, Impact, RunResult, Stop, StopReason, StructurePeaks,
};
