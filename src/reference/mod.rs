//! An independent reference solution, the error axis of the
//! work-precision table. It shares no code path with [`crate::solver`]: the
//! equations of SPEC §2–4 are written again as a first-order system
//! ([`system`]), integrated by an adaptive Dormand–Prince 5(4) pair with
//! dense output ([`dopri5`]) at a tight tolerance, from event to event
//! ([`events`]: contact onset and separation, yield and unloading of each
//! bilinear spring), so that the right-hand side is smooth inside every step.
//! Peaks are continuous maxima, located on the dense output ([`integrate`]).
//! [`closed_form`] gives exact solutions of the linear cases it is tested against.
//!
//! ```
//! use pounding::{model::SET1, reference::{reference, ReferenceOptions}};
//! let r = reference(&SET1, &ReferenceOptions::with_tolerance(1e-10));
//! assert_eq!(r.impacts.len(), 9);
//! ```

pub mod closed_form;
pub use crate::numerics::dopri5;
pub mod events;
pub mod integrate;
pub mod row;
pub mod system;

pub use integrate::{
    DEFAULT_TOLERANCE, ReferenceImpact, ReferenceOptions, ReferenceResult, reference,
};
