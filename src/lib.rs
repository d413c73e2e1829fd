//! `pounding`: two adjacent inelastic SDOF structures under sinusoidal ground
//! acceleration, colliding through a Kelvin or improved Kelvin contact
//! element, in Buckingham-Π dimensionless form (see `SPEC.md` of the project).
//!
//! The library knows nothing of terminals. Its parts:
//! - [`model`]: the ten Π-groups and run settings ([`model::Params`]), the
//!   bilinear spring, the contact laws, the excitation and presets;
//! - [`solver`]: Newmark-β with contact event location, driven by
//!   [`solver::simulate`], reporting to an [`solver::Observer`] and
//!   returning a [`solver::RunResult`];
//! - [`analysis`]: what is built from many runs (spectra, similarity);
//! - [`figure`]: the paper's figures and the scenes as SVG or PNG files.
//!
//! ```
//! use pounding::{model::SET1, solver};
//! let result = solver::run(&SET1);
//! assert_eq!(result.impacts.len(), 9); // the paper's nine poundings
//! ```

pub mod accuracy;
pub mod analysis;
pub mod cli;
pub mod figure;
pub mod model;
pub mod output;
pub mod reference;
pub mod solver;
pub mod tui;
