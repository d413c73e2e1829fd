//! The risk of pounding at one joint of a row over a suite (SPEC §12 with
//! §13), in the shape of the pair's picture ([`super::risk::RiskPicture`]),
//! so that the explorer's risk scene draws either.
//!
//! Every record runs at every level x_1 < … < x_L and at the design level X
//! as the row's IDA runs it ([`super::subject::runs::plan_levels`],
//! [`super::subject::runs::run_levels`]: the row with contact, and apart when it
//! pounded). From those runs:
//!
//! - at X, each record's gap that prevents pounding at the joint, d_min =
//!   max over its paired floors and over time of u_A − u_B in the run
//!   apart ([`super::row_gap::joint_gaps`]), whence P(pounding at a gap d)
//!   = the fraction of records with d_min > d;
//! - at each level, the median and 16th/84th percentiles of one building's
//!   largest storey drift max_i |Δ_i| (m), with pounding and apart;
//! - the fragility P(the joint pounds | IM = x), fitted by maximum
//!   likelihood on the counts of records whose joint had an impact (its
//!   demands' impacts, [`super::row_suite::JointDemands`]) ([`fragility::fit`]);
//! - for a row with a P-Δ building (SPEC §15), P(collapse | IM = x), fitted
//!   the same way on the records in which a building collapsed.

use super::fragility;
use super::ida;
use super::risk::{CollapseCounts, LevelDrift, RiskPicture, with_design_level};
use super::row_suite::{RowSuiteCase, RowSuiteError, RowSuiteRun};
use super::statistics::Summary;
use super::subject::runs::{plan_levels, run_levels};
use super::suite::Scaling;
use crate::model::buildings::Row;
use crate::model::intensity::IntensityMeasure;
use crate::model::suite::SuiteMember;
use crate::solver::buildings::RowRun;

/// What the picture is of: a row, the joint whose pounding it counts, the
/// building whose drift it follows, and the measure records are scaled by.
#[derive(Debug, Clone, PartialEq)]
pub struct RowRiskCase {
    pub row: Row,
    /// Index of the joint (0: between the first two buildings).
    pub joint: usize,
    /// Index of the building whose drift the IDA follows.
    pub building: usize,
    pub measure: IntensityMeasure,
}

impl RowRiskCase {
    /// The joint's taller building: where pounding concentrates drift
    /// (above the contact), the one the IDA follows by default.
    pub fn taller_of(row: &Row, joint: usize) -> usize {
        let top = |b: usize| {
            let b = &row.buildings[b];
            b.elevation(b.storeys())
        };
        if top(joint + 1) > top(joint) {
            joint + 1
        } else {
            joint
        }
    }
}

/// The largest storey drift max_i |Δ_i| of building `b` in `run` (m).
fn max_drift(run: &RowRun, b: usize) -> f64 {
    run.floors[b].iter().map(|f| f.drift).fold(0.0, f64::max)
}

/// Runs every record at every level and at the design level, while
/// `keep_going()` holds (asked between levels); the picture, or `None`
/// when stopped. `levels` ascending and > 0, `design_level` > 0.
pub fn risk(
    case: &RowRiskCase,
    members: &[SuiteMember],
    design_level: f64,
    levels: &[f64],
    keep_going: &dyn Fn() -> bool,
) -> Result<Option<RiskPicture>, RowSuiteError> {
    let (all, design) = with_design_level(levels, design_level);
    let suite = RowSuiteCase {
        row: case.row.clone(),
        scaling: Scaling {
            measure: case.measure,
            level: None,
            collective: false,
        },
    };
    let plans = plan_levels(&suite, members, &all)?;
    // A level at a time, so that `keep_going` is asked between levels.
    let mut by_level: Vec<Vec<RowSuiteRun>> = Vec::with_capacity(all.len());
    for plan in &plans {
        if !keep_going() {
            return Ok(None);
        }
        let mut level = run_levels(&suite, members, std::slice::from_ref(plan), &|_| {})?;
        by_level.push(level.pop().unwrap_or_default());
    }
    let at_design = &by_level[design];
    let ida_runs = &by_level[..levels.len()];
    let drift = levels
        .iter()
        .zip(ida_runs)
        .map(|(&level, at)| {
            let of = |free: bool| {
                let values: Vec<f64> = at
                    .iter()
                    .map(|r| max_drift(if free { &r.free } else { &r.run }, case.building))
                    .collect();
                Summary::of(&values)
            };
            LevelDrift {
                level,
                pounding: of(false),
                free: of(true),
            }
        })
        .collect();
    let counts = ida::counts(levels, ida_runs, |r: &RowSuiteRun| {
        r.demands.joints[case.joint].impacts > 0
    });
    let fragility = fragility::fit(&counts);
    let collapse = case.row.can_collapse().then(|| {
        let counts = ida::counts(levels, ida_runs, |r: &RowSuiteRun| r.run.collapse.is_some());
        CollapseCounts {
            fragility: fragility::fit(&counts),
            counts,
        }
    });
    let min_gaps_m = at_design
        .iter()
        .map(|r| r.demands.joints[case.joint].gap.min_gap)
        .collect();
    Ok(Some(RiskPicture {
        records: members.len(),
        design_level,
        min_gaps_m,
        gap_m: case.row.joints[case.joint].gap,
        drift,
        pounding: counts,
        fragility,
        drift_title: format!("{} drift [mm]", case.row.buildings[case.building].name),
        collapse,
    }))
}
