//! `pounding gap --buildings --suite`: a row's separation report in every
//! format, per joint the separation study and per record each joint's gap
//! that prevents pounding and code rules (m) (SPEC §12, §13).

use std::fmt::Write as _;

use serde::Serialize;

use super::{RECORD_COLUMNS, record_cells, study_table};
use crate::analysis::gap::JointGap;
use crate::analysis::separation::JointSeparation;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteRun};
use crate::cli::output::num;
use crate::cli::suite::row::RowHeader;
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// The report of a row's separation `joints` over the suite's `runs` of
/// `case` (suite `suite`).
pub fn report<'a>(
    case: &'a RowSuiteCase,
    suite: &'a str,
    runs: &[RowSuiteRun],
    joints: Vec<JointSeparation>,
    elapsed_ms: f64,
) -> RowSeparationReport<'a> {
    RowSeparationReport {
        row: RowHeader::new(case, suite),
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
        joints,
        elapsed_ms,
    }
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
pub struct RowSeparationReport<'a> {
    #[serde(flatten)]
    row: RowHeader<'a>,
    records: Vec<RecordRow>,
    /// Per joint, left to right: the separation study over the records.
    joints: Vec<JointSeparation>,
    elapsed_ms: f64,
}

impl Report for RowSeparationReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = RECORD_COLUMNS.to_vec();
        h.extend([
            "joint",
            "left",
            "right",
            "min_gap_m",
            "abs_m",
            "srss_m",
            "ddc_m",
            "impacts_at_gap",
        ]);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for r in &self.records {
            for (j, joint) in r.joints.iter().enumerate() {
                let g = &joint.gap;
                let mut cells = record_cells(
                    crate::cli::suite::row::UNITS,
                    &r.record,
                    r.scale,
                    &self.row.scaling.measure,
                    r.intensity_g,
                );
                cells.extend([
                    format!("joint{}", j + 1),
                    g.left.clone(),
                    g.right.clone(),
                    num(g.min_gap),
                    num(g.abs),
                    num(g.srss),
                    num(g.ddc),
                    joint.impacts_at_gap.to_string(),
                ]);
                rows.push(cells);
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
