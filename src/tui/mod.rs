//! The terminal explorer (`pounding`, `pounding tui`): two parameter panes,
//! live charts of the runs they describe, Kelvin against improved Kelvin,
//! spectra, and preset recall.
//!
//! - [`app`]: the state and what a key does to it (pure);
//! - [`fields`]: the rows of a parameter pane and their nudge steps;
//! - [`event`]: terminal input, worker results and signals as one channel;
//! - [`worker`]: the solver on a background thread, latest wins;
//! - [`ui`] and [`views`]: drawing, a pure function of the state;
//! - [`terminal`]: setup, restore (on quit, panic, SIGTERM), synchronized frames;
//! - [`explorer`]: the main loop wiring them;
//! - [`export`]: the active run as CSV.

pub mod app;
pub mod event;
pub mod explorer;
pub mod export;
pub mod fields;
pub mod terminal;
pub mod ui;
pub mod views;
pub mod worker;
