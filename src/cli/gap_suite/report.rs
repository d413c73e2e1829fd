//! `pounding gap --suite`'s report in every format, for the pair and a row:
//! per joint the separation study over the suite, and per record each
//! joint's gap that prevents pounding (m) (SPEC §11, §12).

use std::fmt::Write as _;

use serde::Serialize;

use super::{RECORD_COLUMNS, record_cells};
use crate::analysis::separation::JointSeparation;
use crate::cli::description::Provenance;
use crate::cli::spelling::{GapOpening, Spelling};
use crate::output::report::Report;

/// `pounding gap --suite` in every format.
#[derive(Serialize)]
#[serde(bound = "")]
pub struct SeparationReport<'a, S: Spelling> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    suite: &'a str,
    #[serde(flatten)]
    head: S::GapHead,
    records: Vec<S::GapRecord>,
    #[serde(flatten)]
    tail: S::GapTail,
    elapsed_ms: f64,
    /// The intensity measure's name, in every CSV line.
    #[serde(skip)]
    measure: String,
}

/// The report of each joint's separation `joints` over the suite's `runs`
/// of `subject` (named `name`, suite `suite`).
pub fn report<'a, S: Spelling>(
    subject: &'a S,
    name: &'a str,
    suite: &'a str,
    runs: &[S::Run],
    joints: Vec<JointSeparation>,
    elapsed_ms: f64,
) -> SeparationReport<'a, S> {
    let (head, tail) = subject.gap_parts(joints);
    SeparationReport {
        provenance: Provenance::new(subject.preset(name), S::GAP_UNITS),
        suite,
        head,
        records: runs.iter().map(S::gap_record).collect(),
        tail,
        elapsed_ms,
        measure: subject.scaling().measure.to_string(),
    }
}

impl<S: Spelling> Report for SeparationReport<'_, S> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = RECORD_COLUMNS.to_vec();
        h.extend(S::GAP_COLUMNS);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for r in &self.records {
            let (record, scale, intensity_g, lines) = S::gap_lines(r);
            for line in lines {
                let units = S::GAP_UNITS;
                let mut cells = record_cells(units, record, scale, &self.measure, intensity_g);
                cells.extend(line);
                rows.push(cells);
            }
        }
        rows
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let opening = GapOpening {
            preset: self.provenance.preset,
            suite: self.suite,
            head: &self.head,
            records: &self.records,
            tail: &self.tail,
        };
        S::gap_table(&opening, &mut s);
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}
