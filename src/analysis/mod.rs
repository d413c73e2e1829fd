//! Studies built from many runs: spectra (SPEC §7), physical units and
//! self-similarity (SPEC §8), the gap that prevents pounding (SPEC §11),
//! suites of records and their statistics: fragility and the separation at
//! a probability (SPEC §12).
//!
//! - [`spectrum`]: one point (pounding run, baseline, region);
//! - [`grid`], [`family`], [`spectrum_spec`]: what a spectrum is asked for
//!   (they live in the model, beside the parameters they check, so that a
//!   preset's `[spectrum]` table is checked when the preset is read);
//! - [`baseline`]: the no-pounding baseline and its cache;
//! - [`batch`]: many points' pounding runs and missing baselines in one
//!   parallel pass, for [`sweep`] and [`map`];
//! - [`sweep`]: the engine that computes every curve in parallel;
//! - [`map`]: region maps over two parameters (any Π key or μ);
//! - [`gap`]: the gap that prevents pounding and the code rules (SPEC §11),
//!   for the pair and for each joint of a row (SPEC §13);
//! - [`ida`]: every record at every intensity level, and the fragility of
//!   each limit state fitted on it (SPEC §12);
//! - [`limit_state`]: what a run of the pair or a row must do to count as
//!   exceeding, per building or any (SPEC §12, §13, §15);
//! - [`fragility`]: lognormal fragility by maximum likelihood (SPEC §12);
//! - [`separation`]: the gap at a probability over a suite, per joint of
//!   the pair or a row, and the code rules on it (SPEC §12);
//! - [`physical`](crate::model::physical): physical units to Π-groups and back (SPEC §8);
//! - [`similarity`]: spectra at several excitation levels and their master curve;
//! - [`demands`]: a run's demands (SPEC §6) in SI;
//! - [`suite`]: one pair of physical buildings under a suite of records,
//!   each scaled to an intensity (SPEC §12), [`statistics`], the median,
//!   percentiles and dispersion of a demand over a suite, and
//!   [`suite_statistics`], those of every demand a subject names;
//! - [`risk`]: the risk picture of the pair, or of one joint of a row, over
//!   a suite ([`subject`]): P(pounding) against the gap, the IDA of one
//!   building's drift and the pounding (and collapse) fragility;
//! - [`subject`]: what a study runs records on, the physical pair or a row
//!   of buildings (SPEC §12, §13), and the suite and the IDA's levels
//!   planned and run over either ([`subject::runs`]);
//! - [`suite_map`]: P(pounding) and the median amplification over two
//!   physical quantities of the buildings, under a suite (SPEC §12);
//! - [`shard`]: a sweep cut into shards balanced by estimated work, and
//!   their parts merged;
//! - [`record_scaling`], [`record_selection`]: records scaled to a
//!   target spectrum by the codes' rules (EC8, ASCE 7), and chosen for it
//!   from a collection;
//! - [`buildings_report`]: what `pounding run --buildings` reports of a row's
//!   run (SPEC §13), per building, floor and floor pair;
//! - [`work`]: what one run costs, estimated before it starts (the shards'
//!   balance, the commands' bound on long requests, their progress bars).

pub mod baseline;
pub mod batch;
pub mod buildings_report;
pub mod demands;
pub mod fragility;
pub mod gap;
pub mod ida;
pub mod limit_state;
pub mod map;
pub mod record_scaling;
pub mod record_selection;
pub mod retrofit_report;
pub mod risk;
pub mod separation;
pub mod shard;
pub mod similarity;
pub mod spectrum;
pub mod statistics;
pub mod subject;
pub mod suite;
pub mod suite_map;
pub mod suite_statistics;
pub mod sweep;
pub mod work;

pub use crate::model::{family, grid, spectrum_spec};
