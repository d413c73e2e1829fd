//! Sharded sweeps: one study cut into N independent parts that run apart
//! (one task of a Slurm job array each, say) and merge into exactly the
//! output one machine would have written.
//!
//! - [`spec`]: which shard a process runs, `K/N` or from Slurm's array variables;
//! - [`partition`](mod@partition): the study's units dealt to the shards by estimated work;
//! - [`fingerprint`]: one hash of the whole request, so that parts of
//!   different requests are never merged;
//! - [`part`]: the partial result on disk, written atomically and read back
//!   with every check (truncation, header, body);
//! - [`merge`]: a set of parts checked as a whole (one request, no
//!   duplicate, no missing shard) and their results put back in order;
//! - [`map`], [`spectrum`]: what a map's and a spectrum's units are, what
//!   they cost, and the counters a merged sweep reports;
//! - [`suite`]: the units of suite studies on a pair or on a row of
//!   buildings (a record at one plan), and how a record's row is rebuilt
//!   from the runs a part carries.
//!
//! The results carried by a part are the typed results of the library (map
//! cells, spectrum points, …), so a merge builds the same report from the
//! same values as the unsharded command, and writes it with the same
//! writer: equal byte for byte, timing aside.

pub mod fingerprint;
pub mod gap;
pub mod map;
pub mod merge;
pub mod part;
pub mod partition;
pub mod spec;
pub mod spectrum;
pub mod suite;

pub use fingerprint::Fingerprint;
pub use part::{Part, PartError, PartHeader};
pub use partition::partition;
pub use spec::Shard;
