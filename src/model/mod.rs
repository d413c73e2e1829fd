//! The physical model: parameters (SPEC §1), bilinear springs (§3), contact
//! laws (§4, §10), the excitation (§2, §9), recorded ground motions and presets.

pub mod buildings;
pub mod contact;
pub mod excitation;
pub mod family;
pub mod grid;
pub mod hysteresis;
pub mod intensity;
pub mod method;
pub mod params;
pub mod physical;
pub mod preset;
pub mod record;
pub mod simulated;
pub mod spectrum_spec;
pub mod suite;
pub mod synthetic;
pub mod target_spectrum;

pub use contact::{ContactLaw, ContactModel};
pub use excitation::{Excitation, Pulse, RecordMotion, Rotation};
pub use hysteresis::{Bilinear, SpringState};
pub use method::Method;
pub use params::{ParamError, Params, SET1, SET2};
pub use preset::{Preset, PresetError};
