//! `pounding gap --suite`: the separation that prevents pounding with a
//! chosen probability over a suite of records, beside the code rules
//! (SPEC §11, §12). Each record's Π_d,min (in m) comes from its run without
//! contact ([`crate::analysis::suite`]); the study of those values is
//! [`crate::analysis::separation`]. This module parses, runs and prints.

use std::fmt::Write as _;

use serde::Serialize;

use super::CliError;
use super::description::Provenance;
use super::output::{Emit, num};
use super::suite::{Ran, SuiteArgs, run_or_shard};
use crate::analysis::separation::{
    RecordGap, SeparationStudy, parse_probabilities, probability_of_pounding, study,
};
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// The probabilities reported when `--probability` is not given.
pub const DEFAULT_PROBABILITIES: &str = "0.5,0.84,0.9";

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

/// The probabilities of `--probability` ([`DEFAULT_PROBABILITIES`] when
/// `None`), each in (0, 1).
pub fn probabilities(probability: Option<&str>) -> Result<Vec<f64>, CliError> {
    parse_probabilities(
        "--probability",
        probability.unwrap_or(DEFAULT_PROBABILITIES),
    )
    .map_err(|e| usage(e.to_string()))
}

/// Runs the suite of `suite_args` and reports the separation at each of
/// `probability` (a list, [`DEFAULT_PROBABILITIES`] when `None`), its typed
/// report handed to `emit`.
pub fn report_with(
    suite_args: &SuiteArgs,
    probability: Option<&str>,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let probabilities = probabilities(probability)?;
    let suite = suite_args.suite.as_str();
    let Some(Ran {
        preset,
        case,
        runs,
        elapsed_ms,
    }) = run_or_shard(suite_args, "gap")?
    else {
        return Ok(());
    };
    let records: Vec<RecordGap> = runs.iter().map(RecordGap::of).collect();
    if let Some(r) = runs.iter().find(|r| !r.free.completed) {
        return Err(CliError::Failed(format!(
            "record `{}`: the run without contact stopped before its end; its minimum gap \
             covers only the part that was run",
            r.name
        )));
    }
    let gaps: Vec<f64> = records.iter().map(|r| r.min_gap).collect();
    let gap_m = case.physical.gap;
    let report = SeparationReport {
        provenance: Provenance::new(&preset.name, UNITS),
        suite,
        measure: case.scaling.measure.to_string(),
        level_g: case.scaling.level,
        gap_m,
        pounding_probability_at_gap: probability_of_pounding(&gaps, gap_m),
        records: runs
            .iter()
            .map(|r| RecordRow {
                record: r.name.clone(),
                scale: r.scale,
                intensity_g: r.intensity,
                min_gap_m: r.min_gap_m(),
                free_peak_left_m: r.free_si.left.peak_displacement_m,
                free_peak_right_m: r.free_si.right.peak_displacement_m,
                impacts_at_gap: r.result.impacts.len(),
            })
            .collect(),
        study: study(&records, &probabilities),
        elapsed_ms,
    };
    emit(&report)
}

const UNITS: &str = "m for gaps and peak drifts, g for intensities";

/// One record: its scaling, Π_d,min and separate peaks (m).
#[derive(Debug, Serialize)]
struct RecordRow {
    record: String,
    scale: f64,
    intensity_g: f64,
    /// Π_d,min of SPEC §11 in m.
    min_gap_m: f64,
    /// Peak drifts of the separate buildings (the run without contact).
    free_peak_left_m: f64,
    free_peak_right_m: f64,
    /// Impacts of the run at the preset's own gap.
    impacts_at_gap: usize,
}

/// `pounding gap --suite` in every format.
#[derive(Debug, Serialize)]
struct SeparationReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    suite: &'a str,
    measure: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    level_g: Option<f64>,
    /// The preset's own gap (m).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    gap_m: f64,
    /// The fraction of records whose Π_d,min exceeds it.
    pounding_probability_at_gap: f64,
    records: Vec<RecordRow>,
    study: SeparationStudy,
    elapsed_ms: f64,
}

impl Report for SeparationReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        vec![
            "version",
            "units",
            "record",
            "scale",
            "intensity_measure",
            "intensity_g",
            "min_gap_m",
            "free_peak_left_m",
            "free_peak_right_m",
            "impacts_at_gap",
        ]
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        self.records
            .iter()
            .map(|r| {
                vec![
                    env!("CARGO_PKG_VERSION").to_string(),
                    UNITS.to_string(),
                    r.record.clone(),
                    num(r.scale),
                    self.measure.clone(),
                    num(r.intensity_g),
                    num(r.min_gap_m),
                    num(r.free_peak_left_m),
                    num(r.free_peak_right_m),
                    r.impacts_at_gap.to_string(),
                ]
            })
            .collect()
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let st = &self.study;
        let scaling = match self.level_g {
            Some(x) => format!("each record scaled to {} = {} g", self.measure, num(x)),
            None => "records at their list's scale".to_string(),
        };
        let _ = writeln!(
            s,
            "separation over suite {} ({} records), preset {}; {scaling}",
            self.suite, st.records, self.provenance.preset
        );
        study_table(&mut s, st, self.gap_m, self.pounding_probability_at_gap);
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}

/// A separation study (SPEC §12) as a table: the minimum gaps' median and
/// fit, the gap at each probability, P(pounding) at the preset's gap
/// `gap_m` (m) and the code rules; for a pair, or for one joint of a row.
pub fn study_table(
    s: &mut String,
    st: &SeparationStudy,
    gap_m: f64,
    pounding_probability_at_gap: f64,
) {
    let _ = writeln!(
        s,
        "Π_d,min of each record from its run without contact (SPEC §11): median {} mm{}",
        g4(st.median_min_gap * 1e3),
        st.lognormal.map_or(String::new(), |f| format!(
            ", lognormal median {} mm, β = {:.3}",
            g4(f.median * 1e3),
            f.dispersion
        ))
    );
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "{:>11}  {:>22}  {:>14}",
        "probability", "gap d_(⌈pN⌉) mm", "lognormal mm"
    );
    for a in &st.at_probability {
        let _ = writeln!(
            s,
            "{:>11}  {:>22}  {:>14}",
            num(a.probability),
            g4(a.empirical * 1e3),
            a.lognormal.map_or("-".to_string(), |v| g4(v * 1e3))
        );
    }
    let _ = writeln!(s);
    let pounded = (pounding_probability_at_gap * st.records as f64).round() as usize;
    let _ = writeln!(
        s,
        "at the preset's gap of {} mm: P(pounding) = {} ({} of {} records)",
        g4(gap_m * 1e3),
        g4(pounding_probability_at_gap),
        pounded,
        st.records
    );
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "code rules (SPEC §11) on each record's separate peaks, and on the median peaks \
         ({} mm, {} mm; ρ = {:.3}):",
        g4(st.median_peaks[0] * 1e3),
        g4(st.median_peaks[1] * 1e3),
        st.correlation
    );
    let _ = writeln!(
        s,
        "{:<5} {:>16} {:>18} {:>12}  enough at probability",
        "rule", "holds (records)", "on medians mm", "P(pounding)"
    );
    for r in &st.rules {
        let enough = if r.sufficient_at.is_empty() {
            "none of those asked".to_string()
        } else {
            r.sufficient_at
                .iter()
                .map(|p| num(*p))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let _ = writeln!(
            s,
            "{:<5} {:>16} {:>18} {:>12}  {}",
            r.rule,
            format!("{:.0} %", 100.0 * r.holds),
            g4(r.at_median_peaks * 1e3),
            g4(r.pounding_probability),
            enough
        );
    }
}
