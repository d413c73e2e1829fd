//! `pounding ida --buildings` of a row: its report in every format, the
//! records of `pounding suite --buildings` at each level (SPEC §13).

use std::fmt::Write as _;

use serde::Serialize;

use super::{IdaRan, LevelReport};
use crate::analysis::ida::LimitStateFragility;
use crate::analysis::limit_state::LimitState;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteRun};
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::study_tables::closing_tables;
use crate::cli::suite::row::{RowHeader, RowSuiteRow, UNITS};
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// The report of the row's IDA `ran` of `case` (suite `suite`).
pub(super) fn report<'a>(
    case: &'a RowSuiteCase,
    suite: &'a str,
    ran: IdaRan<RowSuiteRun>,
) -> RowIdaReport<'a> {
    RowIdaReport {
        row: RowHeader::new(case, suite),
        scaled_as_a_whole: case.scaling.as_a_whole(),
        records_per_level: ran.records,
        levels: ran.levels(|r| SuiteStatistics::of(case, r), RowSuiteRow::of),
        limit_states: ran.states,
        fragility: ran.fragility,
        elapsed_ms: ran.elapsed_ms,
    }
}

/// `pounding ida --buildings` in every format.
#[derive(Debug, Serialize)]
pub(super) struct RowIdaReport<'a> {
    #[serde(flatten)]
    row: RowHeader<'a>,
    /// Set when the levels scale the suite as a whole ([`crate::analysis::suite::Scaling::as_a_whole`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    scaled_as_a_whole: Option<String>,
    records_per_level: usize,
    levels: Vec<LevelReport<RowSuiteRow>>,
    /// The limit states, in the order of `fragility`.
    limit_states: Vec<LimitState>,
    /// Per limit state: counts at each level and the maximum-likelihood
    /// lognormal fragility (SPEC §12), with pounding and without.
    fragility: Vec<LimitStateFragility>,
    elapsed_ms: f64,
}

impl Report for RowIdaReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units", "level_g"];
        h.extend(RowSuiteRow::CSV_COLUMNS);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let measure = &self.row.scaling.measure;
        let lines = |l: &LevelReport<RowSuiteRow>| {
            let lines = l.records.iter().flat_map(|r| r.csv_lines(measure));
            (l.level_g, lines.collect())
        };
        super::level_rows(UNITS, self.levels.iter().map(lines))
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "IDA at {} levels of {}, {} records a level",
            self.levels.len(),
            self.row.scaling.measure,
            self.records_per_level
        );
        let scaling = self.scaled_as_a_whole.clone().unwrap_or_else(|| {
            format!(
                "each record scaled to every level of {}",
                self.row.scaling.measure
            )
        });
        self.row.table(self.records_per_level, &scaling, &mut s);
        let _ = writeln!(s);
        // One line per level: who pounded, each building's median drift
        // (16–84 %) and acceleration, each joint's median gap needed.
        let _ = write!(s, "{:>8} {:>8}", "level g", "pounded");
        for b in &self.row.buildings {
            let _ = write!(
                s,
                " {:>24} {:>8}",
                format!("{} drift % (16–84)", b.name()),
                "A g"
            );
        }
        for (j, _) in self.row.joints.iter().enumerate() {
            let _ = write!(s, " {:>12}", format!("j{} d_min mm", j + 1));
        }
        let _ = writeln!(s);
        for l in &self.levels {
            let st = &l.statistics;
            let get = |key: &str| {
                st.demands
                    .iter()
                    .find(|d| d.demand == key)
                    .map(|d| d.summary)
            };
            let _ = write!(
                s,
                "{:>8} {:>8}",
                g4(l.level_g),
                format!("{}/{}", st.pounded, st.records)
            );
            for b in &self.row.buildings {
                let drift =
                    get(&format!("{}.max_drift_ratio", b.name())).map_or(String::new(), |d| {
                        format!(
                            "{} ({}–{})",
                            g4(d.median * 100.0),
                            g4(d.p16 * 100.0),
                            g4(d.p84 * 100.0)
                        )
                    });
                let acc = get(&format!("{}.max_absolute_acceleration_g", b.name()))
                    .map_or(String::new(), |d| g4(d.median));
                let _ = write!(s, " {drift:>24} {acc:>8}");
            }
            for (j, _) in self.row.joints.iter().enumerate() {
                let gap = get(&format!("joint{}.min_gap_m", j + 1))
                    .map_or(String::new(), |d| g4(d.median * 1e3));
                let _ = write!(s, " {gap:>12}");
            }
            let _ = writeln!(s);
        }
        let levels: Vec<(f64, &SuiteStatistics)> = self
            .levels
            .iter()
            .map(|l| (l.level_g, &l.statistics))
            .collect();
        closing_tables(&mut s, &self.fragility, &levels, self.elapsed_ms);
        s
    }
}
