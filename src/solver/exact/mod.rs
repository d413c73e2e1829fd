//! The exact method: event-driven, closed form out of contact (SPEC §2–4).
//!
//! Out of contact each structure is a linear oscillator with constant
//! coefficients on its current branch of the bilinear law, driven by the
//! ground; its motion is known in closed form. Here that closed form is
//! carried as its Taylor series about the start of each segment, generated
//! by the equation of motion itself and summed to round-off
//! ([`dynamics`]). The same recurrence, with the pounding force's
//! coefficients added, integrates the short contact phases to a tolerance
//! set on the contact's own scale.
//!
//! The Hertz-type laws (SPEC §10) are not analytic at contact onset; their
//! contact phases are stepped by an embedded Runge–Kutta pair instead
//! ([`contact_rk`]), each step handed on as a polynomial segment.
//!
//! Everything that changes the equations is an event located on the series
//! to round-off ([`roots`]): contact onset and separation, yield, unloading.
//! Peaks are the true maxima, located at the zeros of the rates ([`peaks`]), the
//! peak absolute accelerations of SPEC §6 among them ([`acceleration`]). The loop and
//! its accounting are in [`driver`]; the energy balance in [`energy`].
//! A free segment in which bounds show that nothing can happen (no event, no
//! new peak) is advanced by a precomputed transition matrix instead
//! ([`quiet`]), which is most of a run.
//!
//! The excitation enters only through its Taylor coefficients and the
//! instants where it changes formula ([`crate::model::Excitation::taylor`]
//! and [`next_break`](crate::model::Excitation::next_break)), so pulses and
//! piecewise-linear records fit without touching the method.
//!
//! ```
//! use pounding::{model::SET1, solver::exact};
//! let r = exact::simulate(&SET1, &exact::ExactOptions::default(), &mut ());
//! assert_eq!(r.impacts.len(), 9);
//! ```

pub mod acceleration;
pub mod contact_rk;
pub mod driver;
pub mod dynamics;
pub mod energy;
pub mod linear_map;
pub mod peaks;
pub mod quiet;
pub mod roots;
pub mod sample;
pub mod sample_peaks;
pub mod sample_run;
pub mod sample_settle;
pub mod sample_work;
pub mod segment;
pub mod series;

pub use driver::{ContactExtremes, ExactOptions, simulate};
