//! `pounding ida` of the pair: its report in every format, the rows of
//! `pounding suite` at each level.

use std::fmt::Write as _;

use serde::Serialize;

use super::{IdaRan, LevelReport};
use crate::analysis::ida::LimitStateFragility;
use crate::analysis::suite::{SuiteCase, SuiteRun};
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::description::Provenance;
use crate::cli::study_tables::closing_tables;
use crate::cli::suite::SuiteRow;
use crate::model::Method;
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// The report of the pair's IDA `ran` of `case` (preset `preset`, suite `suite`).
pub(super) fn report<'a>(
    preset: &'a str,
    suite: &'a str,
    case: &SuiteCase,
    ran: IdaRan<SuiteRun>,
) -> IdaReport<'a> {
    IdaReport {
        provenance: Provenance::new(preset, UNITS),
        suite,
        model: case.settings.model.name(),
        method: case.settings.method,
        measure: case.scaling.measure.to_string(),
        scaled_as_a_whole: case.scaling.as_a_whole(),
        records_per_level: ran.records,
        levels: ran.levels(|r| SuiteStatistics::of(case, r), SuiteRow::of),
        fragility: ran.fragility,
        elapsed_ms: ran.elapsed_ms,
    }
}

const UNITS: &str = "SI (m, m/s, g, kN, kJ) for the demands, g for intensities; \
                     Π-groups of SPEC §1 under `pi`";

/// `pounding ida` in every format.
#[derive(Debug, Serialize)]
pub(super) struct IdaReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    suite: &'a str,
    model: &'static str,
    method: Method,
    measure: String,
    /// Set when the levels scale the suite as a whole ([`crate::analysis::suite::Scaling::as_a_whole`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    scaled_as_a_whole: Option<String>,
    records_per_level: usize,
    levels: Vec<LevelReport<SuiteRow>>,
    /// Per limit state: counts at each level and the maximum-likelihood
    /// lognormal fragility (SPEC §12), with pounding and without.
    fragility: Vec<LimitStateFragility>,
    elapsed_ms: f64,
}

impl Report for IdaReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units", "level_g"];
        h.extend(SuiteRow::csv_header());
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let lines = |l: &LevelReport<SuiteRow>| {
            let cells = l.records.iter().map(|r| r.csv_cells(&self.measure));
            (l.level_g, cells.collect())
        };
        super::level_rows(UNITS, self.levels.iter().map(lines))
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "IDA of suite {} ({} records) at {} levels of {}, preset {}: {}, {} method",
            self.suite,
            self.records_per_level,
            self.levels.len(),
            self.measure,
            self.provenance.preset,
            self.model,
            self.method.name()
        );
        if let Some(words) = &self.scaled_as_a_whole {
            let _ = writeln!(s, "{words}");
        }
        let _ = writeln!(s);
        // One line per level: the medians that matter, with the 16–84 % band of drift.
        let _ = writeln!(
            s,
            "{:>8} {:>8} {:>22} {:>8} {:>8} {:>22} {:>8} {:>10}",
            "level g",
            "pounded",
            "left u mm (16–84 %)",
            "left μ",
            "left A g",
            "right u mm (16–84 %)",
            "right μ",
            "d_min mm"
        );
        for l in &self.levels {
            let st = &l.statistics;
            let get = |key: &str| {
                st.demands
                    .iter()
                    .find(|d| d.demand == key)
                    .map(|d| d.summary)
            };
            let band = |key: &str, unit: f64| {
                get(key).map_or(String::new(), |d| {
                    format!(
                        "{} ({}–{})",
                        g4(d.median * unit),
                        g4(d.p16 * unit),
                        g4(d.p84 * unit)
                    )
                })
            };
            let median =
                |key: &str, unit: f64| get(key).map_or(String::new(), |d| g4(d.median * unit));
            let _ = writeln!(
                s,
                "{:>8} {:>8} {:>22} {:>8} {:>8} {:>22} {:>8} {:>10}",
                g4(l.level_g),
                format!("{}/{}", st.pounded, st.records),
                band("left.peak_displacement_m", 1e3),
                median("left.ductility", 1.0),
                median("left.peak_absolute_acceleration_g", 1.0),
                band("right.peak_displacement_m", 1e3),
                median("right.ductility", 1.0),
                median("min_gap_m", 1e3)
            );
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
