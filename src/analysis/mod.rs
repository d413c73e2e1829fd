//! Studies built from many runs: spectra (SPEC §7), physical units and
//! self-similarity (SPEC §8).
//!
//! - [`spectrum`]: one point (pounding run, baseline, region);
//! - [`grid`]: the Π_ω1 grid `START:STOP:STEP`;
//! - [`family`]: one curve per value of a key (`mass_ratio=0.1,0.5,0.9`);
//! - [`baseline`]: the no-pounding baseline and its cache;
//! - [`sweep`]: the engine that computes every curve in parallel;
//! - [`spectrum_spec`]: a preset's `[spectrum]` table;
//! - [`physical`]: physical units to Π-groups and back (SPEC §8);
//! - [`similarity`]: spectra at several excitation levels and their master curve.

pub mod baseline;
pub mod family;
pub mod grid;
pub mod similarity;
pub mod spectrum;
pub mod spectrum_spec;
pub mod sweep;
