//! The exact event-driven method for a row of shear buildings (SPEC §13).
//!
//! Between events the motion of the row is linear, M ü + C u̇ + K u = q − M 1 ü_g(t),
//! with K and q fixed by the configuration (which storeys yield, which floor
//! pairs are in contact) and ü_g one smooth piece of the ground motion
//! (ä_g = σ a_g on it: a line under a record, a sine). So the state is
//! advanced in closed form:
//!
//! - out of contact, over a sub-step of fixed length h, by the matrix
//!   exponential of the augmented system ([`propagator`]), made once per
//!   (configuration, h, σ) and cached;
//! - wherever something may happen inside the sub-step (a storey may yield
//!   or unload, a floor pair may touch, a floor's peak may be passed), and
//!   through every contact phase of the Kelvin family, by the Taylor series of the same motion
//!   ([`taylor`]), which carries the improved Kelvin law's δδ̇ term exactly;
//!   events and peaks are roots of polynomials on it ([`poly`]);
//! - through a contact phase of a Hertz-type law (SPEC §10), whose force is
//!   not analytic at δ = 0, by steps of an embedded Runge–Kutta pair
//!   ([`contact_rk`]), each written as polynomials so that the same
//!   machinery finds events and peaks on it;
//! - in a row with a fluid viscous damper (SPEC §14), whose force
//!   c_l|Δv|^α sgn Δv is not analytic at Δv = 0 and acts at every instant,
//!   by steps that carry the configuration's linear motion exactly and
//!   collocate only the dampers' forces ([`damper_collocation`]), for the
//!   whole run, each reversal of Δv an event ([`damper`]).
//!
//! One storey each gives the SDOF pair of SPEC §2.
//!
//! - [`layout`]: the row's constant matrices and storeys, once per run;
//! - [`config`]: the configuration (branches, contacts) and its cache key;
//! - [`event_function`]: each event's function, linear in the state;
//! - [`system`]: the linear system of one configuration;
//! - [`sparse`]: its augmented matrix by the nonzeros, for cheap products;
//! - [`expm`]: the matrix exponential of its maps;
//! - [`propagator`]: the cache of maps out of contact, and a map step;
//! - [`lanes`]: the vector blocks a map step is stored in;
//! - [`sweep`]: the growth of the map over a sub-step, for the quiet test;
//! - [`quintic`]: the quintic Hermite of a quantity's ends, which clears a
//!   sub-step of a gap, a yield drift or a peak that the cubic of
//!   [`hermite`] cannot;
//! - [`link`]: links across the joints (SPEC §14), linear and fluid viscous;
//! - [`damper`]: the fluid viscous dampers (α < 1), their reversals events;
//! - [`damper_collocation`]: their steps, by exponential collocation;
//! - [`damper_radau`]: their implicit step through a Hertz-type contact;
//! - [`peaks`]: the envelopes a run reports;
//! - [`reach`]: how far each floor moves over a series step, to pass over
//!   quantities that cannot reach their events or peaks there;
//! - [`energy`]: the energy balance, by quadrature on the Taylor steps;
//! - [`result`]: what a run returns;
//! - [`profile`]: why sub-steps took the series, and where the time went;
//! - [`driver`]: the loop over sub-steps and events;
//! - [`newmark`]: Newmark-β on the row, the second method.

pub mod bound;
pub mod config;
pub mod contact_rk;
pub mod damper;
pub mod damper_collocation;
pub mod damper_radau;
pub mod driver;
pub mod energy;
pub mod event_function;
pub mod expm;
pub mod hermite;
pub mod lanes;
pub mod layout;
pub mod link;
pub mod link_peaks;
pub mod newmark;
pub mod peaks;
pub mod poly;
pub mod power_series;
pub mod profile;
pub mod propagator;
pub mod quintic;
pub mod reach;
pub mod result;
pub mod sparse;
pub mod sweep;
pub mod system;
pub mod taylor;

pub use driver::{
    Checkpoint, MapCache, RowError, RowOptions, run_row, run_row_cached, run_row_from,
    run_row_keeping,
};
pub use energy::RowEnergy;
pub use link::LinkResult;
pub use newmark::{default_step, max_step, run_newmark};
pub use profile::{Cause, RowProfile};
pub use result::{Collapse, FloorPeaks, ForceHistory, PairImpact, PairResult, RowRun, RowTrace};
