//! `pounding`: two adjacent inelastic SDOF structures under sinusoidal ground
//! acceleration, colliding through a Kelvin or improved Kelvin contact
//! element, in Buckingham-Π dimensionless form (see `SPEC.md` of the project).
//!
//! The physics is a library that knows nothing of terminals. Its parts,
//! from the bottom up (no module imports one above it):
//! - [`output`]: writing files and streams by one set of rules (atomic
//!   replacement, streaming to devices, broken pipes), and number formats;
//! - [`numerics`]: generic integrators (the DOPRI5 pair) and the normal
//!   distribution, knowing no physics;
//! - [`model`]: the ten Π-groups and run settings ([`model::Params`], one
//!   parameter table), the bilinear spring, the contact laws, the excitation
//!   and presets;
//! - [`solver`]: two methods, Newmark-β with located contact and the exact
//!   event-driven method, picked by [`solver::solve`] from the set's
//!   `method`, reporting to an [`solver::Observer`] and returning a
//!   [`solver::RunResult`];
//! - [`mod@reference`]: an independent DOPRI5 solution, the error axis of every check;
//! - [`analysis`]: what is built from many runs (spectra, similarity, the
//!   gap, and a suite's fragility and separation at a probability);
//! - [`accuracy`]: work-precision tables and the stress test;
//! - [`figure`]: the paper's figures and the scenes as SVG or PNG files.
//!
//! The front ends sit on top and are compiled only with the default `app`
//! feature (which brings clap, crossterm, ratatui and indicatif): `cli`,
//! the command line, and `tui`, the terminal explorer. Without it,
//! `cargo build --lib --no-default-features` builds the physics alone. The
//! `commands` feature alone compiles `cli`'s commands (their arguments,
//! plans and typed reports) without a terminal: no explorer, no progress
//! bar. The Python module is built on it.
//!
//! ```
//! use pounding::{model::SET1, solver};
//! let result = solver::run(&SET1);
//! assert_eq!(result.impacts.len(), 9); // the paper's nine poundings
//! ```

pub mod accuracy;
pub mod analysis;
#[cfg(feature = "commands")]
pub mod cli;
pub mod figure;
pub mod model;
pub mod numerics;
pub mod output;
pub mod reference;
pub mod solver;
#[cfg(feature = "app")]
pub mod tui;
