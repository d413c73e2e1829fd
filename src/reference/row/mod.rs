//! An independent reference for rows of buildings (SPEC §13), the error
//! axis of `bench --buildings`. It shares no code with
//! [`crate::solver::buildings`]: the equations are written again
//! ([`motion`], forces straight from each storey's and pair's law), and
//! integrated by an adaptive Dormand–Prince 5(4) pair ([`rk`]) at a tight
//! tolerance, with every event and turning point located by retaking the
//! step to it ([`integrate`]). It carries every contact law, the Hertz-type
//! ones included.

pub mod integrate;
pub mod motion;
pub mod rk;

pub use integrate::{RowReference, reference_row};
