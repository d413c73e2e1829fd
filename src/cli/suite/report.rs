//! `pounding suite`'s report in every format, for the pair and a row: per
//! record its demands as the subject spells them ([`Spelling`]), and their
//! statistics over the suite (SPEC §12).

use std::fmt::Write as _;

use serde::Serialize;

use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::description::ScalingReport;
use crate::cli::spelling::{Spelling, StudyHead};
use crate::cli::study_tables::over_suite_table;
use crate::output::report::Report;

/// `pounding suite` in every format.
#[derive(Serialize)]
#[serde(bound = "")]
pub struct SuiteReport<'a, S: Spelling> {
    #[serde(flatten)]
    head: StudyHead<'a, S::Buildings>,
    scaling: ScalingReport,
    records: Vec<S::Record>,
    statistics: SuiteStatistics,
    elapsed_ms: f64,
}

/// The report of the suite `runs` of `subject` (named `name`, suite `suite`).
pub fn report<'a, S: Spelling>(
    subject: &'a S,
    name: &'a str,
    suite: &'a str,
    runs: &[S::Run],
    elapsed_ms: f64,
) -> SuiteReport<'a, S> {
    SuiteReport {
        head: StudyHead::of(
            subject,
            name,
            suite,
            S::SUITE_UNITS,
            subject.described_buildings(),
        ),
        scaling: ScalingReport::of(subject.scaling()),
        records: runs.iter().map(S::record_row).collect(),
        statistics: SuiteStatistics::of(subject, runs),
        elapsed_ms,
    }
}

/// The CSV rows of a study's records, each of `lines` after the version,
/// the units `units` and the cells `lead` (`ida`'s level).
pub fn csv_rows(
    units: &str,
    lines: impl IntoIterator<Item = (Vec<String>, Vec<Vec<String>>)>,
) -> Vec<Vec<String>> {
    let mut rows = Vec::new();
    for (lead, lines) in lines {
        for line in lines {
            let mut row = vec![env!("CARGO_PKG_VERSION").to_string(), units.to_string()];
            row.extend(lead.iter().cloned());
            row.extend(line);
            rows.push(row);
        }
    }
    rows
}

impl<S: Spelling> Report for SuiteReport<'_, S> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units"];
        h.extend(S::record_columns());
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let measure = &self.scaling.measure;
        let lines = self.records.iter().map(|r| S::record_lines(r, measure));
        csv_rows(S::SUITE_UNITS, [(Vec::new(), lines.flatten().collect())])
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let words = self.scaling.words();
        S::suite_opening(&self.head, self.records.len(), &words, &mut s);
        S::records_table(&self.records, &mut s);
        over_suite_table(&mut s, &self.statistics);
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}
