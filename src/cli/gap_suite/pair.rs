//! `pounding gap --suite` of the physical pair: its report in every format,
//! the one joint's separation with each record's Π_d,min and separate
//! peaks (m).

use std::fmt::Write as _;

use serde::Serialize;

use super::{RECORD_COLUMNS, record_cells, study_table};
use crate::analysis::separation::{JointSeparation, SeparationStudy};
use crate::analysis::suite::{SuiteCase, SuiteRun};
use crate::cli::description::Provenance;
use crate::cli::output::num;
use crate::output::report::Report;

/// The report of the pair's separation: its one joint of `joints`, over
/// the suite's `runs` of `case` (preset `preset`, suite `suite`).
pub fn report<'a>(
    preset: &'a str,
    suite: &'a str,
    case: &SuiteCase,
    runs: &[SuiteRun],
    joints: Vec<JointSeparation>,
    elapsed_ms: f64,
) -> SeparationReport<'a> {
    let joint = joints.into_iter().next().expect("the pair has one joint");
    SeparationReport {
        provenance: Provenance::new(preset, UNITS),
        suite,
        measure: case.scaling.measure.to_string(),
        level_g: case.scaling.level,
        gap_m: joint.gap_m,
        pounding_probability_at_gap: joint.pounding_probability_at_gap,
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
        study: joint.study,
        elapsed_ms,
    }
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
pub struct SeparationReport<'a> {
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
        let mut h = RECORD_COLUMNS.to_vec();
        h.extend([
            "min_gap_m",
            "free_peak_left_m",
            "free_peak_right_m",
            "impacts_at_gap",
        ]);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        self.records
            .iter()
            .map(|r| {
                let mut cells =
                    record_cells(UNITS, &r.record, r.scale, &self.measure, r.intensity_g);
                cells.extend([
                    num(r.min_gap_m),
                    num(r.free_peak_left_m),
                    num(r.free_peak_right_m),
                    r.impacts_at_gap.to_string(),
                ]);
                cells
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
