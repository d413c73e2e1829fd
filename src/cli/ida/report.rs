//! `pounding ida`'s report in every format, for the pair and a row: at each
//! level the records of `pounding suite` at that level and their
//! statistics, and the fragility of each limit state (SPEC §12).

use serde::Serialize;

use super::{IdaRan, LevelReport};
use crate::analysis::ida::LimitStateFragility;
use crate::analysis::limit_state::LimitState;
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::output::num;
use crate::cli::spelling::{IdaOpening, Spelling, StudyHead};
use crate::cli::study_tables::closing_tables;
use crate::cli::suite::report::csv_rows;
use crate::output::report::Report;

/// `pounding ida` in every format.
#[derive(Serialize)]
#[serde(bound = "")]
pub struct IdaReport<'a, S: Spelling> {
    #[serde(flatten)]
    head: StudyHead<'a, S::IdaHead>,
    /// Set when the levels scale the suite as a whole ([`crate::analysis::suite::Scaling::as_a_whole`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    scaled_as_a_whole: Option<String>,
    records_per_level: usize,
    levels: Vec<LevelReport<S::Record>>,
    /// The limit states, in the order of `fragility` (a row's; the pair's
    /// are named in `fragility` alone).
    #[serde(skip_serializing_if = "Option::is_none")]
    limit_states: Option<Vec<LimitState>>,
    /// Per limit state: counts at each level and the maximum-likelihood
    /// lognormal fragility (SPEC §12), with pounding and without.
    fragility: Vec<LimitStateFragility>,
    elapsed_ms: f64,
    /// The intensity measure's name, in every CSV line.
    #[serde(skip)]
    measure: String,
}

/// The report of the IDA `ran` of `subject` (named `name`, suite `suite`).
pub fn report<'a, S: Spelling>(
    subject: &'a S,
    name: &'a str,
    suite: &'a str,
    ran: IdaRan<S::Run>,
) -> IdaReport<'a, S> {
    IdaReport {
        head: StudyHead::of(subject, name, suite, S::IDA_UNITS, subject.ida_head()),
        scaled_as_a_whole: subject.scaling().as_a_whole(),
        records_per_level: ran.records,
        levels: ran.levels(|r| SuiteStatistics::of(subject, r), S::record_row),
        limit_states: S::NAMES_LIMIT_STATES.then_some(ran.states),
        fragility: ran.fragility,
        elapsed_ms: ran.elapsed_ms,
        measure: subject.scaling().measure.to_string(),
    }
}

impl<S: Spelling> IdaReport<'_, S> {
    /// Each level (g) with its statistics.
    fn statistics(&self) -> Vec<(f64, &SuiteStatistics)> {
        let levels = self.levels.iter();
        levels.map(|l| (l.level_g, &l.statistics)).collect()
    }
}

impl<S: Spelling> Report for IdaReport<'_, S> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units", "level_g"];
        h.extend(S::record_columns());
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let measure = &self.measure;
        let lines = |l: &LevelReport<S::Record>| {
            let lines = l.records.iter().flat_map(|r| S::record_lines(r, measure));
            (vec![num(l.level_g)], lines.collect())
        };
        csv_rows(S::IDA_UNITS, self.levels.iter().map(lines))
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let opening = IdaOpening {
            head: &self.head,
            scaled_as_a_whole: self.scaled_as_a_whole.as_deref(),
            records_per_level: self.records_per_level,
            levels: self.levels.len(),
        };
        S::ida_opening(&opening, &mut s);
        s.push('\n');
        let levels = self.statistics();
        S::levels_table(&self.head.buildings, &levels, &mut s);
        closing_tables(&mut s, &self.fragility, &levels, self.elapsed_ms);
        s
    }
}
