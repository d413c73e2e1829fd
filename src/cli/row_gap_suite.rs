//! `pounding gap --buildings PRESET --suite SUITE`: per joint of a row, the
//! separation that prevents pounding with a chosen probability over a suite
//! of records, beside the code rules (SPEC §11, §12, §13). Each record's
//! per-joint gap comes from its run without contact
//! ([`crate::analysis::row_suite`]); the study of those values is
//! [`crate::analysis::row_separation`]. This module parses, runs and prints.

use std::fmt::Write as _;

use serde::Serialize;

use super::CliError;
use super::gap_suite::{probabilities, study_table};
use super::output::{Emit, num};
use super::row_suite::{RowHeader, RowRan, RowStudyArgs, run};
use crate::analysis::row_gap::JointGap;
use crate::analysis::row_separation::{JointSeparation, joint_separations};
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// Runs the row suite of `study` and reports, per joint, the
/// separation at each of `probability` ([`super::gap_suite::DEFAULT_PROBABILITIES`] when
/// `None`), its typed report handed to `emit`.
pub fn report_with(
    study: &RowStudyArgs,
    probability: Option<&str>,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let probabilities = probabilities(probability)?;
    let Some(RowRan {
        case,
        runs,
        elapsed_ms,
        ..
    }) = run(study, "gap")?
    else {
        return Ok(());
    };
    let report = RowSeparationReport {
        row: RowHeader::new(&case, study.suite),
        records: runs
            .iter()
            .map(|r| RecordRow {
                record: r.name.clone(),
                scale: r.scale,
                intensity_g: r.intensity,
                joints: r
                    .demands
                    .joints
                    .iter()
                    .map(|j| RecordJoint {
                        impacts_at_gap: j.impacts,
                        gap: j.gap.clone(),
                    })
                    .collect(),
            })
            .collect(),
        joints: joint_separations(&case.row, &runs, &probabilities),
        elapsed_ms,
    };
    emit(&report)
}

/// One record at one joint: its gap that prevents pounding and code rules
/// (m), and its impacts at the preset's gap.
#[derive(Debug, Serialize)]
struct RecordJoint {
    #[serde(flatten)]
    gap: JointGap,
    impacts_at_gap: usize,
}

/// One record: its scaling and each joint's gaps.
#[derive(Debug, Serialize)]
struct RecordRow {
    record: String,
    scale: f64,
    intensity_g: f64,
    joints: Vec<RecordJoint>,
}

/// `pounding gap --buildings --suite` in every format.
#[derive(Debug, Serialize)]
struct RowSeparationReport<'a> {
    #[serde(flatten)]
    row: RowHeader<'a>,
    records: Vec<RecordRow>,
    /// Per joint, left to right: the separation study over the records.
    joints: Vec<JointSeparation>,
    elapsed_ms: f64,
}

impl Report for RowSeparationReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        vec![
            "version",
            "units",
            "record",
            "scale",
            "intensity_measure",
            "intensity_g",
            "joint",
            "left",
            "right",
            "min_gap_m",
            "abs_m",
            "srss_m",
            "ddc_m",
            "impacts_at_gap",
        ]
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for r in &self.records {
            for (j, joint) in r.joints.iter().enumerate() {
                let g = &joint.gap;
                rows.push(vec![
                    env!("CARGO_PKG_VERSION").to_string(),
                    super::row_suite::UNITS.to_string(),
                    r.record.clone(),
                    num(r.scale),
                    self.row.scaling.measure.clone(),
                    num(r.intensity_g),
                    format!("joint{}", j + 1),
                    g.left.clone(),
                    g.right.clone(),
                    num(g.min_gap),
                    num(g.abs),
                    num(g.srss),
                    num(g.ddc),
                    joint.impacts_at_gap.to_string(),
                ]);
            }
        }
        rows
    }

    fn table(&self) -> String {
        let mut s = String::new();
        self.row
            .table(self.records.len(), &self.row.scaling.words(), &mut s);
        for (j, joint) in self.joints.iter().enumerate() {
            let _ = writeln!(s);
            let _ = writeln!(
                s,
                "joint{} {}–{} (gap {} mm): per record the largest u_{} − u_{} over its paired floors",
                j + 1,
                joint.left,
                joint.right,
                g4(joint.gap_m * 1e3),
                joint.left,
                joint.right
            );
            let paired = self
                .records
                .first()
                .is_some_and(|r| !r.joints[j].gap.floors.is_empty());
            if !paired {
                let _ = writeln!(
                    s,
                    "no floors pair up at this joint (none at the same elevation within 1 mm): \
                     it cannot pound, and needs no gap"
                );
            }
            study_table(
                &mut s,
                &joint.study,
                joint.gap_m,
                joint.pounding_probability_at_gap,
            );
        }
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}
