//! Studies built from many runs: spectra (SPEC §7), physical units and
//! self-similarity (SPEC §8).

pub mod spectrum;
