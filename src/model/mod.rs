//! The physical model: parameters (SPEC §1), bilinear springs (§3), contact
//! laws (§4), the excitation (§2) and presets.

pub mod contact;
pub mod excitation;
pub mod family;
pub mod grid;
pub mod hysteresis;
pub mod method;
pub mod params;
pub mod physical;
pub mod preset;
pub mod spectrum_spec;

pub use contact::{ContactLaw, ContactModel};
pub use excitation::{Excitation, Rotation};
pub use hysteresis::{Bilinear, SpringState};
pub use method::Method;
pub use params::{ParamError, Params, SET1, SET2};
pub use preset::{Preset, PresetError};
