//! The time integrator: Newmark-β with γ = 1/2, β = 1/4 (SPEC §5), contact
//! event location, and pluggable observers.
//!
//! - [`newmark`]: one step of the coupled 2-DOF system (exact branch solve out
//!   of contact, Newton with the consistent tangent in contact);
//! - [`events`]: locating contact onset and separation inside a step;
//! - [`simulate`]: the run driver (steps, events, sub-steps in contact, energy);
//! - [`observer`]: what gets recorded (nothing, a full history, a decimated one);
//! - [`result`]: what a run reports (SPEC §6).

pub mod events;
pub mod exact;
pub mod newmark;
pub mod observer;
pub mod result;
pub mod simulate;

pub use crate::model::Method;
pub use observer::{CsvHistory, Decimated, FullHistory, Observer, Sample};
pub use result::{
    ENERGY_TOLERANCE, EnergyBalance, Impact, RunResult, Stop, StopReason, StructurePeaks,
};
pub use simulate::{ContactSubsteps, SolverOptions, run, simulate};
