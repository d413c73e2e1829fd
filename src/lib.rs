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
//! The user guide (`docs/`, an mdBook) shows the same studies from the
//! command line; below, each from Rust.
//!
//! # A run
//!
//! The paper's parameter set 1 (SPEC §1–§6) by its own method, Newmark-β,
//! and by the exact event-driven method; the two agree to Newmark's
//! second-order error (SPEC §5):
//!
//! ```
//! use pounding::model::{Method, Params, SET1};
//! use pounding::solver;
//!
//! let newmark = solver::run(&SET1);
//! assert_eq!(newmark.impacts.len(), 9); // the paper's nine poundings
//! let exact = solver::run(&Params { method: Method::Exact, ..SET1 });
//! assert_eq!(exact.impacts.len(), 9);
//! let relative = (newmark.left.peak_displacement - exact.left.peak_displacement).abs()
//!     / exact.left.peak_displacement;
//! assert!(relative < 1e-5, "{relative}");
//! ```
//!
//! # A suite
//!
//! The `two-buildings` preset's physical pair (a frame of T1 = 0.95 s,
//! 25 mm from a stiffer block) under 20 simulated records, each scaled so
//! that its Sa(0.95 s) is 0.3 g (SPEC §12), by [`analysis::suite`]; the
//! statistics are those `pounding suite` prints:
//!
//! ```
//! use pounding::analysis::subject::runs::{plan, run_suite};
//! use pounding::analysis::suite_statistics::SuiteStatistics;
//! use pounding::analysis::suite::{Scaling, SuiteCase};
//! use pounding::model::{Method, Params, intensity::IntensityMeasure, physical::Physical};
//! use pounding::model::{preset, suite::SuiteSpec};
//!
//! let preset = preset::builtin("two-buildings").unwrap();
//! let case = SuiteCase {
//!     physical: Physical::from_table(preset.physical.as_ref().unwrap()).unwrap(),
//!     settings: Params { method: Method::Exact, ..preset.params.clone() },
//!     scaling: Scaling {
//!         measure: IntensityMeasure::parse("sa:0.95").unwrap(),
//!         level: Some(0.3),
//!         collective: false,
//!     },
//! };
//! let members = SuiteSpec::parse("synthetic:20").unwrap().load().unwrap();
//! let plans = plan(&case, &members).unwrap();
//! let runs = run_suite(&case, &members, &plans, &|_| {}).unwrap();
//! // Each record scaled to the level: its own Sa(0.95 s) is 0.3 g.
//! assert!(runs.iter().all(|r| (r.intensity - 0.3).abs() < 1e-12));
//! // At 0.3 g the 25 mm joint pounds under every record, and the gap that
//! // would have kept them apart (SPEC §11) is wider than 25 mm in each.
//! assert!(runs.iter().all(|r| r.pounded() && r.min_gap_m() > 0.025));
//! let stats = SuiteStatistics::of(&case, &runs);
//! assert_eq!((stats.records, stats.pounded), (20, 20));
//! ```
//!
//! # A row
//!
//! The `block-and-frame` row (SPEC §13: a 3-storey block 5 mm from an
//! 8-storey frame) under one simulated record, with every joint closed and
//! with every joint open; a floor pair pounds only where the run apart
//! brought the two floors closer than their gap:
//!
//! ```
//! use pounding::model::buildings::{Ground, load, matrices::default_tail};
//! use pounding::model::suite::SuiteSpec;
//! use pounding::solver::buildings::{RowOptions, run_row};
//!
//! let row = load("block-and-frame").unwrap();
//! let record = &SuiteSpec::parse("synthetic:1").unwrap().load().unwrap()[0].record;
//! let ground = Ground::from_record(record, 1.0);
//! let options = RowOptions::lasting(ground.end() + default_tail(&row));
//! let with = run_row(&row, &ground, &options).unwrap();
//! let apart = run_row(&row.apart(), &ground, &options).unwrap();
//! assert_eq!(with.pairs.len(), 3); // floors 1, 2 and 3 of each stand level
//! assert!(apart.pairs.iter().all(|p| p.impacts.is_empty()));
//! let pounded = with.pairs.iter().any(|p| !p.impacts.is_empty());
//! assert!(pounded); // the record's PGA is 0.3 g: every suite at 0.3 g pounds here
//! // The largest approach u_block − u_frame apart, against the 5 mm gap.
//! let closest = apart.max_relative.iter().cloned().fold(f64::MIN, f64::max);
//! assert_eq!(pounded, closest > 0.005, "{closest}");
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
