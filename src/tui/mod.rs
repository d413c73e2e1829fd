//! The terminal explorer (`pounding`, `pounding tui`): two parameter panes,
//! live charts of the runs they describe with a time cursor and zoom, Kelvin
//! against improved Kelvin, set 1 against set 2, spectra, the impact table,
//! physical units, preset recall and the risk of pounding over a suite.
//!
//! After the ratatui templates: state and input apart from drawing, all I/O
//! as effects run by the main loop.
//!
//! - [`app`]: the dispatcher, what each key does (pure);
//! - [`scene`]: the scene, cursor, zoom and overlay;
//! - [`text_field`]: the one text-entry type;
//! - [`jobs`] and [`worker`]: what to compute, on a background thread, latest wins;
//! - [`risk_job`]: the risk scene's suite, a coarse pass then the whole;
//! - [`row_pane`], [`row_fields`], [`row_job`], [`playback`]: the buildings
//!   scene's row and its edits, its runs, and playing them in time;
//! - [`trace`]: the history decimated to the visible window;
//! - [`effects`], [`export`], [`presets`]: saving, exporting, figures, the preset list;
//! - [`fields`], [`physical`]: the pane rows in Π-groups or physical units;
//! - [`event`]: terminal input, results and signals as one channel;
//! - [`layout`], [`ui`], [`views`], [`look`]: drawing, a pure function of the state;
//! - [`keys`]: every key and the help's lines;
//! - [`pace`]: when to draw (a quick job's result with its key, one frame);
//! - [`terminal`]: set-up and restore, synchronized frames;
//! - [`gapfill`], [`short_codes`], [`cursor`]: fewer bytes per frame
//!   (unchanged cells for cursor moves, short colour codes and moves);
//! - [`explorer`]: the main loop wiring them.

pub mod app;
pub mod cursor;
pub mod effects;
pub mod event;
pub mod explorer;
pub mod export;
pub mod fields;
pub mod fit;
pub mod gapfill;
pub mod jobs;
pub mod keys;
pub mod layout;
pub mod look;
pub mod map_grid;
pub mod pace;
pub mod physical;
pub mod playback;
pub mod presets;
pub mod risk_job;
pub mod row_fields;
pub mod row_file;
pub mod row_job;
pub mod row_keys;
pub mod row_pane;
pub mod scene;
pub mod short_codes;
pub mod terminal;
pub mod text_field;
pub mod trace;
pub mod ui;
pub mod views;
pub mod worker;
