//! Buildings in a row (SPEC §13): lumped-mass shear buildings side by side,
//! pounding where floors of neighbours stand at the same elevation.
//!
//! - [`row`]: the row as read, building by building, and its floor pairs;
//! - [`preset`]: the TOML preset and its one-line errors;
//! - [`load`](mod@load): a preset by built-in name or path, with `--set` edits;
//! - [`builtin`]: the presets shipped under `presets/buildings/`;
//! - [`matrices`]: mass, initial stiffness and Rayleigh damping, and the modes;
//! - [`keys`]: reading a preset's tables and numbers;
//! - [`limits`]: the bounds of the contact elements;
//! - [`edit`]: `--set` edits of a preset, checked as the file is;
//! - [`contact`]: the contact law of one floor pair in physical form;
//! - [`retrofit`]: bumpers and links (SPEC §14), as contact elements and links;
//! - [`retrofit_preset`]: their keys in a preset, checked;
//! - [`ground`]: the ground acceleration a row is shaken by.

pub mod builtin;
pub mod contact;
pub mod edit;
pub mod ground;
pub mod keys;
pub mod limits;
pub mod load;
pub mod matrices;
pub mod preset;
pub mod retrofit;
pub mod retrofit_preset;
pub mod row;

pub use ground::Ground;
pub use load::{load, load_with};
pub use preset::{BuildingsError, parse};
pub use retrofit::{Bumper, ContactElement, Link, LinkElement};
pub use row::{Building, FloorPair, Joint, PDelta, Row};
