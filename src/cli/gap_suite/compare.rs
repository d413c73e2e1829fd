//! `pounding gap --suite S --buildings ROW --compare ROW2,…`: the same
//! separation study (the same records, scaling and probabilities) run on
//! each variant of a row, a retrofit say, and reported side by side (SPEC
//! §11, §12, §14; [`crate::cli::compare`]).
//!
//! Each variant's report is bit for bit the report `gap --suite
//! --buildings` makes of it alone (but its wall time); the summary beside
//! them gives, per joint and variant, its gap at rest d and P(pounding)
//! there (the fraction of records whose Π_d,min exceeds d), the gap that
//! prevents pounding with each probability p, d_(⌈pN⌉) of the records
//! sorted by Π_d,min (with its lognormal estimate when there is a fit), and
//! the code rules ABS, SRSS and DDC on the median separate peaks, each with
//! the fraction of records for which it holds (R_j ≥ Π_d,min,j).

use std::fmt::Write as _;

use serde::Serialize;

use super::report::{SeparationReport, report};
use super::{Separated, separated};
use crate::analysis::separation::{GapAtProbability, JointSeparation, RuleOnSuite};
use crate::analysis::subject::row::RowSuiteCase;
use crate::cli::CliError;
use crate::cli::compare::{Compared, Ran, SideBySide, compare};
use crate::cli::output::{Emit, num};
use crate::cli::subject::Study;
use crate::cli::suite::SuiteArgs;
use crate::model::buildings::Row;
use crate::model::params::echo::g4;

/// Runs the separation study of `args` at `probabilities` on its row and
/// on every `--compare` row, and hands the side-by-side report to `emit`.
pub(super) fn gap(
    args: &SuiteArgs,
    probabilities: Vec<f64>,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let study = GapCompare {
        args,
        probabilities,
    };
    compare(&study, &args.compare_request(), emit)
}

/// The separation study asked for, at its probabilities.
struct GapCompare<'a> {
    args: &'a SuiteArgs,
    probabilities: Vec<f64>,
}

impl Compared for GapCompare<'_> {
    type Variant = Study<RowSuiteCase>;
    type Summary = Summary;
    type Report<'a>
        = SeparationReport<'a, RowSuiteCase>
    where
        Self: 'a;
    const STUDY: &'static str = "separation study";

    fn load(&self, name: &str) -> Result<Study<RowSuiteCase>, CliError> {
        self.args.variant(name)
    }

    fn row(study: &Study<RowSuiteCase>) -> &Row {
        &study.subject.row
    }

    fn run<'a>(&'a self, study: &'a Study<RowSuiteCase>) -> Ran<Summary, Self::Report<'a>> {
        let Some(Separated {
            runs,
            joints,
            elapsed_ms,
        }) = separated(study, self.args, &self.probabilities)?
        else {
            return Ok(None);
        };
        let summary = Summary::of(&joints);
        let suite = &self.args.suite;
        let report = report(
            &study.subject,
            &study.name,
            suite,
            &runs,
            joints,
            elapsed_ms,
        );
        Ok(Some((summary, report)))
    }
}

/// One joint of a variant over the suite.
#[derive(Debug, Serialize)]
pub(super) struct JointSummary {
    /// `joint1 block–frame`.
    joint: String,
    /// Its gap at rest (m), and the fraction of records that pound there.
    gap_m: f64,
    pounding_probability_at_gap: f64,
    /// The gap that prevents pounding at each probability asked (m).
    at_probability: Vec<GapAtProbability>,
    /// ABS, SRSS, DDC over the suite, as `gap --suite` reports them.
    rules: Vec<RuleOnSuite>,
}

/// What the side-by-side summary gives of one variant: each joint's
/// separation, left to right.
#[derive(Debug, Serialize)]
pub(super) struct Summary {
    joints: Vec<JointSummary>,
}

impl Summary {
    fn of(joints: &[JointSeparation]) -> Summary {
        let joints = joints
            .iter()
            .enumerate()
            .map(|(j, joint)| JointSummary {
                joint: format!("joint{} {}–{}", j + 1, joint.left, joint.right),
                gap_m: joint.gap_m,
                pounding_probability_at_gap: joint.pounding_probability_at_gap,
                at_probability: joint.study.at_probability.clone(),
                rules: joint.study.rules.clone(),
            })
            .collect();
        Summary { joints }
    }
}

/// A length in m as the table writes it, in mm to four digits (`inf` when infinite).
fn mm(v: f64) -> String {
    if v.is_finite() { g4(v * 1e3) } else { num(v) }
}

impl SideBySide for Summary {
    const HEADING: &'static str = "side by side: per joint the gap at rest and P(pounding) there, the gap (mm) that \
         prevents pounding with probability p, d_(⌈pN⌉), and the code rules on the median \
         peaks (mm), each with the share of records for which it holds";

    /// One block per joint, one line per variant in it: the gap at rest
    /// and P(pounding) there, the gap at each probability, and each code
    /// rule on the median peaks with the share of records it holds for.
    fn table(variants: &[(&str, &Summary)], width: usize, s: &mut String) {
        let Some((_, first)) = variants.first() else {
            return;
        };
        for (j, joint) in first.joints.iter().enumerate() {
            let _ = writeln!(s);
            let _ = writeln!(s, "{}", joint.joint);
            let _ = write!(s, "{:<width$} {:>8} {:>9}", "variant", "gap mm", "P(pound)");
            for a in &joint.at_probability {
                let _ = write!(s, " {:>10}", format!("p = {}", num(a.probability)));
            }
            for r in &joint.rules {
                let _ = write!(s, " {:>16}", format!("{} mm", r.rule));
            }
            let _ = writeln!(s);
            for (name, summary) in variants {
                let at = &summary.joints[j];
                let _ = write!(
                    s,
                    "{name:<width$} {:>8} {:>9}",
                    mm(at.gap_m),
                    g4(at.pounding_probability_at_gap)
                );
                for a in &at.at_probability {
                    let _ = write!(s, " {:>10}", mm(a.empirical));
                }
                for r in &at.rules {
                    let rule = format!("{} ({:.0} %)", mm(r.at_median_peaks), 100.0 * r.holds);
                    let _ = write!(s, " {rule:>16}");
                }
                let _ = writeln!(s);
            }
        }
    }
}
