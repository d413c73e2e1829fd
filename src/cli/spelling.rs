//! How each subject spells the suite studies' reports (SPEC §12, §13). The
//! reports of `suite`, `ida` and `gap --suite` are each written once, over
//! any subject (`suite/report.rs`, `ida/report.rs`, `gap_suite/report.rs`);
//! what differs between the physical pair
//! ([`pair`]) and a row ([`row`]) is how each names its buildings, what a
//! record's line holds, and the tables that lay those out, which the
//! subject says here once.
//!
//! The two spellings are the outputs' contract: the pair's per-record
//! demands in SI and in Π under `left`/`right`, a row's per building and
//! per joint by name.

pub mod pair;
pub mod row;

use serde::Serialize;

use super::description::Provenance;
use super::subject::CliSubject;
use crate::analysis::separation::JointSeparation;
use crate::analysis::suite_statistics::SuiteStatistics;

/// How a subject writes the studies' reports.
pub trait Spelling: CliSubject + Sized {
    /// The units line of `suite`'s report.
    const SUITE_UNITS: &'static str;
    /// The units line of `ida`'s report.
    const IDA_UNITS: &'static str;
    /// The units line of `gap --suite`'s report.
    const GAP_UNITS: &'static str;
    /// Whether `ida`'s report lists its limit states beside their
    /// fragilities (a row's do; the pair's name them in the fragilities).
    const NAMES_LIMIT_STATES: bool;
    /// The CSV columns of a record's lines in `gap --suite`, after
    /// [`super::gap_suite::RECORD_COLUMNS`].
    const GAP_COLUMNS: &'static [&'static str];

    /// What the reports say of the buildings, after the method.
    type Buildings: Serialize;
    /// One record, as `suite` (and `ida` at each level) reports it.
    type Record: Serialize;
    /// What `ida` says of the subject and its scaling, after the method.
    type IdaHead: Serialize;
    /// What `gap --suite` says before its records, and after them.
    type GapHead: Serialize;
    type GapTail: Serialize;
    /// One record, as `gap --suite` reports it.
    type GapRecord: Serialize;

    /// The name of the subject in the reports' provenance; `name` is the
    /// study's (the preset's, or `--buildings` as given).
    fn preset<'a>(&'a self, name: &'a str) -> &'a str;
    /// The contact law's and the method's names.
    fn model_method(&self) -> (&'static str, &'static str);
    /// [`Spelling::Buildings`] of this subject.
    fn described_buildings(&self) -> Self::Buildings;
    /// A record's result as the report holds it.
    fn record_row(run: &Self::Run) -> Self::Record;
    /// The CSV columns of a record's lines in `suite` and `ida`, after the
    /// version, the units and (in `ida`) the level.
    fn record_columns() -> Vec<&'static str>;
    /// A record's CSV lines under [`Spelling::record_columns`]; `measure`
    /// names the intensity measure.
    fn record_lines(record: &Self::Record, measure: &str) -> Vec<Vec<String>>;
    /// The opening lines of `suite`'s table, up to the records: `records`
    /// counted, `scaling` the scaling in words.
    fn suite_opening(
        head: &StudyHead<Self::Buildings>,
        records: usize,
        scaling: &str,
        s: &mut String,
    );
    /// The per-record tables of `suite`.
    fn records_table(records: &[Self::Record], s: &mut String);

    /// [`Spelling::IdaHead`] of this subject.
    fn ida_head(&self) -> Self::IdaHead;
    /// The opening lines of `ida`'s table, before its levels.
    fn ida_opening(opening: &IdaOpening<Self::IdaHead>, s: &mut String);
    /// One line per level of `ida`'s table, with its headings: the medians
    /// that matter at each level.
    fn levels_table(head: &Self::IdaHead, levels: &[(f64, &SuiteStatistics)], s: &mut String);

    /// The pair of [`Spelling::GapHead`] and [`Spelling::GapTail`]: each
    /// joint's separation study, before and after the records.
    fn gap_parts(&self, joints: Vec<JointSeparation>) -> (Self::GapHead, Self::GapTail);
    /// A record as `gap --suite` reports it.
    fn gap_record(run: &Self::Run) -> Self::GapRecord;
    /// The record's scale and intensity (g), and its CSV lines under
    /// [`Spelling::GAP_COLUMNS`].
    fn gap_lines(record: &Self::GapRecord) -> (&str, f64, f64, Vec<Vec<String>>);
    /// `gap --suite`'s table, but its wall time.
    fn gap_table(report: &GapOpening<Self>, s: &mut String);
}

/// What every suite study's report says first: which program wrote it, of
/// what, and the buildings.
#[derive(Debug, Serialize)]
pub struct StudyHead<'a, B> {
    #[serde(flatten)]
    pub provenance: Provenance<'a>,
    pub suite: &'a str,
    pub model: &'static str,
    pub method: &'static str,
    #[serde(flatten)]
    pub buildings: B,
}

impl<'a, B> StudyHead<'a, B> {
    /// The head of a report of `subject` named `name` (suite `suite`, in
    /// `units`), saying `buildings` of its buildings.
    pub fn of<S: Spelling>(
        subject: &'a S,
        name: &'a str,
        suite: &'a str,
        units: &'static str,
        buildings: B,
    ) -> Self {
        let (model, method) = subject.model_method();
        StudyHead {
            provenance: Provenance::new(subject.preset(name), units),
            suite,
            model,
            method,
            buildings,
        }
    }
}

/// What `ida`'s table opens with: its head, and how its levels scale the
/// records (set when they scale the suite as a whole).
pub struct IdaOpening<'r, H> {
    pub head: &'r StudyHead<'r, H>,
    pub scaled_as_a_whole: Option<&'r str>,
    pub records_per_level: usize,
    pub levels: usize,
}

/// What `gap --suite`'s table is written from.
pub struct GapOpening<'r, S: Spelling> {
    pub preset: &'r str,
    pub suite: &'r str,
    pub head: &'r S::GapHead,
    pub records: &'r [S::GapRecord],
    pub tail: &'r S::GapTail,
}
