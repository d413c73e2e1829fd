//! The separation at a probability for each joint of a row, over a suite
//! (SPEC §12 with §13), and the code rules on it.
//!
//! For joint J between buildings A and B, record j gives from its run
//! without contact the gap that prevents pounding at that joint,
//!
//! ```text
//! d_J,j = max(0, max over paired floors (i, k) and over t of u_A,i(t) − u_B,k(t))   (SPEC §13)
//! ```
//!
//! ([`super::row_gap::joint_gaps`]). Over the N records sorted d_(1) ≤ … ≤ d_(N),
//! the gap that prevents pounding at J with probability p is d_(⌈pN⌉), with
//! its lognormal fit beside it ([`super::separation`], as for the pair).
//!
//! A code rule R (ABS, SRSS, DDC of SPEC §11) at a joint is, as `gap
//! --buildings` reports it, the largest over the paired floors of the rule
//! on the two floors' separate peaks, with DDC's ρ from the two buildings'
//! first-mode frequencies and their mean ξ ([`joint_modes`]). It holds for
//! record j when R_j ≥ d_J,j. On the median peaks it is the largest over the
//! paired floors of the rule on each floor's median peaks over the records;
//! the study's `median_peaks` are those of the paired floor where ABS on
//! them is largest.

use serde::Serialize;

use super::gap::CodeRules;
use super::row_gap::{floor_peaks, joint_modes};
use super::row_suite::RowSuiteRun;
use super::separation::{SeparationStudy, median, probability_of_pounding, study_of};
use crate::model::buildings::Row;

/// One joint's separation over a suite.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointSeparation {
    pub left: String,
    pub right: String,
    /// The joint's gap at rest in the preset (m; may be infinite).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub gap_m: f64,
    /// The fraction of records whose d_J,j exceeds it.
    pub pounding_probability_at_gap: f64,
    pub study: SeparationStudy,
}

/// The separation at each of `probabilities` (each in (0, 1)) for every
/// joint of `row` over the suite's `runs` (module docs).
///
/// # Panics
/// If `runs` is empty or a probability is not in (0, 1).
pub fn joint_separations(
    row: &Row,
    runs: &[RowSuiteRun],
    probabilities: &[f64],
) -> Vec<JointSeparation> {
    let facing = row.facing_floors();
    (0..row.joints.len())
        .map(|j| {
            let (wa, wb, xi) = joint_modes(row, j);
            let gaps: Vec<f64> = runs
                .iter()
                .map(|r| r.demands.joints[j].gap.min_gap)
                .collect();
            let record_rules: Vec<CodeRules> = runs
                .iter()
                .map(|r| {
                    let g = &r.demands.joints[j].gap;
                    CodeRules {
                        absolute_sum: g.abs,
                        srss: g.srss,
                        double_difference: g.ddc,
                        ..CodeRules::of(0.0, 0.0, wa, wb, xi)
                    }
                })
                .collect();
            // The rules on each paired floor's median peaks, the largest
            // over the floors; the peaks of the floor where ABS is largest.
            let mut at_median = CodeRules::of(0.0, 0.0, wa, wb, xi);
            let mut median_peaks = [0.0; 2];
            for pair in facing.iter().filter(|p| p.joint == j) {
                let peaks: Vec<(f64, f64)> =
                    runs.iter().map(|r| floor_peaks(&r.free, pair)).collect();
                let ua = median(peaks.iter().map(|p| p.0));
                let ub = median(peaks.iter().map(|p| p.1));
                let rules = CodeRules::of(ua, ub, wa, wb, xi);
                if rules.absolute_sum > at_median.absolute_sum {
                    median_peaks = [ua, ub];
                }
                at_median = CodeRules {
                    absolute_sum: at_median.absolute_sum.max(rules.absolute_sum),
                    srss: at_median.srss.max(rules.srss),
                    double_difference: at_median.double_difference.max(rules.double_difference),
                    ..at_median
                };
            }
            let gap_m = row.joints[j].gap;
            JointSeparation {
                left: row.buildings[j].name.clone(),
                right: row.buildings[j + 1].name.clone(),
                gap_m,
                pounding_probability_at_gap: probability_of_pounding(&gaps, gap_m),
                study: study_of(&gaps, &record_rules, at_median, median_peaks, probabilities),
            }
        })
        .collect()
}
