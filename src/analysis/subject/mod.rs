//! The subject of a study (SPEC §12, §13): what a suite, an IDA and their
//! shards run, written once for the physical pair and for a row.
//!
//! SPEC §13 makes one stack possible: the pair is the one-storey case of
//! the row. A study asks its subject, never its type, for:
//!
//! - each record's plan at a scale s and intensity IM·s ([`Subject::plan_at`]):
//!   the pair's Π-groups under that record
//!   ([`crate::model::physical::Physical::under_record`]), the row's scale
//!   alone;
//! - the runs of a planned record, with contact and with every joint open
//!   ([`Subject::runs`]): what a shard's part carries;
//! - that record's result rebuilt from its runs ([`Subject::record`]), the
//!   same whether the runs were made here or read back from a part;
//! - the buildings and joints ([`Subject::buildings`], [`Subject::joints`])
//!   and the period an intensity Sa(T) takes by default
//!   ([`Subject::default_period`]);
//! - a record's demands in SI, per building and per joint
//!   ([`Subject::demands`], [`demands::Demands`]);
//! - what a record's runs cost before they start ([`Subject::work`]), for
//!   the shards' balance, and what identifies the subject in a shard's
//!   fingerprint ([`Subject::describe`]).
//!
//! The pair ([`pair`]) keeps its own exact solver in Π form, mapped to SI by
//! its `[physical]` table; the row ([`row`]) runs the matrix-map solver.
//! [`runs`] plans and runs a suite, or every level of an IDA, over either.

pub mod demands;
pub mod pair;
pub mod row;
pub mod runs;

use serde::Serialize;
use serde::de::DeserializeOwned;

use self::demands::{Building, Column, Demands, Joint, JointRecord};
use super::shard::Fingerprint;
use super::suite::{Scaling, SuiteRunError};
use crate::model::suite::SuiteMember;

/// The buildings a study runs records on: the physical pair or a row.
pub trait Subject: Sync {
    /// What one record runs at (its scale and intensity, and what the
    /// subject derives from them).
    type Plan: Clone + std::fmt::Debug + Send + Sync;
    /// A planned record's runs, with contact and with every joint open, as
    /// a shard's part carries them.
    type Runs: Serialize + DeserializeOwned + Send;
    /// One record's result: its runs and its demands in SI.
    type Run: Send;
    /// What a worker keeps from record to record (the row's linear maps).
    type Caches: Default + Send;
    /// Why a record cannot be planned or run.
    type Error: Send + From<SuiteRunError>;

    /// How the records are scaled (SPEC §12).
    fn scaling(&self) -> &Scaling;

    /// A record's plan at scale `scale`, where its intensity is `intensity` (g).
    fn plan_at(
        &self,
        member: &SuiteMember,
        scale: f64,
        intensity: f64,
    ) -> Result<Self::Plan, Self::Error>;

    /// The planned record's runs: with contact, and with every joint open
    /// (the run with contact itself where it had no impact).
    fn runs(
        &self,
        member: &SuiteMember,
        plan: &Self::Plan,
        caches: &mut Self::Caches,
    ) -> Result<Self::Runs, Self::Error>;

    /// The record's result from its runs ([`Subject::runs`]).
    fn record(&self, member: &SuiteMember, plan: &Self::Plan, runs: Self::Runs) -> Self::Run;

    /// The buildings, left to right.
    fn buildings(&self) -> Vec<Building>;

    /// The joints, left to right: joint j between buildings j and j + 1.
    fn joints(&self) -> Vec<Joint>;

    /// T (s) of Sa(T) when a study names none: the leftmost building's T₁.
    fn default_period(&self) -> f64 {
        self.buildings()[0].period_s
    }

    /// Whether a building can collapse (SPEC §15): a row with P-Δ.
    fn can_collapse(&self) -> bool {
        false
    }

    /// A record's demands in SI, per building and per joint.
    fn demands(&self, run: &Self::Run) -> Demands;

    /// The demands a suite's statistics summarise, each with its key, unit
    /// and one value per record of `runs` (SPEC §12): the pair's `left.`,
    /// `right.` and joint demands, a row's `NAME.`, `no_pounding.NAME.` and
    /// `jointN.` ([`crate::analysis::suite_statistics::SuiteStatistics::of`]).
    fn columns(&self, runs: &[Self::Run]) -> Vec<Column>;

    /// Whether the record's run with contact had an impact.
    fn pounded(&self, run: &Self::Run) -> bool;

    /// Per joint, what the separation at a probability reads of a record
    /// (SPEC §12): its gap that prevents pounding, the code rules and each
    /// paired floor's separate peaks, from its run without contact
    /// ([`crate::analysis::separation::joint_separations`]).
    fn joint_records(&self, run: &Self::Run) -> Vec<JointRecord>;

    /// The estimated work of [`Subject::runs`], in the shards' units.
    fn work(&self, member: &SuiteMember, plan: &Self::Plan) -> f64;

    /// What identifies the subject named `name` in a shard's fingerprint.
    fn describe(&self, f: &mut Fingerprint, name: &str);
}
