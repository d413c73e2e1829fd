//! The risk of pounding of one pair of buildings, or of one joint of a row,
//! over a suite, in one picture (SPEC §11, §12, §13): what the explorer's
//! risk scene draws, written once over the [`Subject`].
//!
//! Every record of the suite runs at every intensity level x_1 < … < x_L
//! (an IDA, [`super::ida`]) and at a design level X (when X is not one of
//! the levels, its runs are added). From those runs:
//!
//! - at the design level, Π_d,min of each record in m (SPEC §11, from its
//!   run without contact), whence the probability of pounding at a gap d,
//!   the fraction of records with Π_d,min > d
//!   ([`separation::probability_of_pounding`]);
//! - at each level, the median and the 16th and 84th percentiles of one
//!   building's peak drift (the pair's left; a row's building of
//!   [`Focus`], by default the joint's taller, [`RowRiskCase::taller_of`]),
//!   with pounding and without contact ([`Summary`]);
//! - the pounding fragility P(pounding | IM = x) fitted on the counts of
//!   records that pounded at each level ([`fragility::fit`]), or why
//!   there is none;
//! - for a subject whose buildings can collapse (SPEC §15), the collapse
//!   fragility fitted the same way on the records in which a building
//!   collapsed.
//!
//! The runs are those of `pounding ida` and `pounding gap --suite` with the
//! same buildings, settings and measure: all three plan them by
//! [`plan_levels`] and run them by [`run_one`].
//!
//! **Runs kept from picture to picture** ([`Kept`]). The explorer draws a
//! coarse picture (a few records at a few levels), then the full one, and
//! the full one again with bridging levels when its fit needs them
//! ([`crate::analysis::fragility::bridging_levels`]). With each record
//! scaled on its own (s_j = x / IM_j, SPEC §12), a record's run at a level
//! is the same in every pass, so each pass runs only the (level, record)
//! pairs no earlier pass ran, and each worker keeps its linear maps from
//! pass to pass (the runs are bit for bit those of fresh caches,
//! [`crate::solver::buildings::MapCache`]).

use std::collections::HashMap;
use std::sync::Mutex;

use rayon::prelude::*;

use super::fragility::{self, Fragility, LevelCount};
use super::ida;
use super::separation;
use super::statistics::Summary;
use super::subject::Subject;
use super::subject::demands::Demands;
use super::subject::row::{RowSuiteCase, RowSuiteError};
use super::subject::runs::{plan_levels, run_one};
use super::suite::{Scaling, SuiteCase, SuiteRunError};
use crate::model::buildings::Row;
use crate::model::intensity::IntensityMeasure;
use crate::model::suite::SuiteMember;

/// The left building's peak drift (m) at one level, over the records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelDrift {
    /// The level x (g).
    pub level: f64,
    /// With pounding.
    pub pounding: Summary,
    /// The same buildings without contact (gap = ∞).
    pub free: Summary,
}

/// The risk picture of a pair over a suite (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct RiskPicture {
    /// Records run at each level.
    pub records: usize,
    /// The design level X (g).
    pub design_level: f64,
    /// Π_d,min of each record at the design level (m), in suite order.
    pub min_gaps_m: Vec<f64>,
    /// The pair's own gap d (m).
    pub gap_m: f64,
    /// The IDA of the left building's peak drift, level by level.
    pub drift: Vec<LevelDrift>,
    /// Records that pounded at each level.
    pub pounding: Vec<LevelCount>,
    /// P(pounding | IM = x) fitted on [`RiskPicture::pounding`], or why not.
    pub fragility: Fragility,
    /// What the drift IDA follows, and its unit (`left drift [mm]`).
    pub drift_title: String,
    /// For a row with a P-Δ building (SPEC §15): the records in which a
    /// building collapsed at each level, and P(collapse | IM) fitted on them.
    pub collapse: Option<CollapseCounts>,
}

/// Records that collapsed at each level and their fragility (SPEC §15):
/// its median θ is the collapse intensity Ŝ_CT.
#[derive(Debug, Clone, PartialEq)]
pub struct CollapseCounts {
    pub counts: Vec<LevelCount>,
    pub fragility: Fragility,
}

impl RiskPicture {
    /// P(pounding) at the pair's own gap at the design level (SPEC §12).
    pub fn probability_at_gap(&self) -> f64 {
        separation::probability_of_pounding(&self.min_gaps_m, self.gap_m)
    }

    /// Records whose Π_d,min exceeds the pair's gap at the design level.
    pub fn pounded_at_gap(&self) -> usize {
        self.min_gaps_m.iter().filter(|&&d| d > self.gap_m).count()
    }

    /// The empirical P(pounding) against the gap (m) as a step line from
    /// d = 0 to `end`: the fraction of records with Π_d,min > d, which
    /// drops at each Π_d,min (the point at d = Π_d,min takes the value
    /// after the drop, as the fraction does).
    pub fn probability_curve(&self, end: f64) -> Vec<(f64, f64)> {
        let mut sorted = self.min_gaps_m.clone();
        sorted.sort_by(f64::total_cmp);
        let p = |d: f64| separation::probability_of_pounding(&sorted, d);
        let mut points = vec![(0.0, p(0.0))];
        for w in sorted.chunk_by(|a, b| a == b) {
            let d = w[0];
            if d > 0.0 && d < end {
                points.push((d, p(d - d * f64::EPSILON)));
                points.push((d, p(d)));
            }
        }
        points.push((end, p(end)));
        points
    }
}

/// The levels to run: `levels`, and the design level after them where it
/// is not one of them; and the design level's index among them.
pub fn with_design_level(levels: &[f64], design_level: f64) -> (Vec<f64>, usize) {
    let mut all = levels.to_vec();
    let design = levels
        .iter()
        .position(|&x| x == design_level)
        .unwrap_or_else(|| {
            all.push(design_level);
            levels.len()
        });
    (all, design)
}

/// Which joint's pounding a picture counts and which building's drift its
/// IDA follows (0 and 0, the left building, for the pair).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Focus {
    pub joint: usize,
    pub building: usize,
}

/// What pictures of one subject under one suite and measure keep for the
/// next (module docs): each record's demands at each level it ran, keyed
/// by the level's bits, the record's place in the suite and its name, and
/// each worker's caches. Give it only to pictures of the same subject and
/// scaling whose member lists agree on their common records.
pub struct Kept<C> {
    demands: HashMap<(u64, usize, String), Demands>,
    caches: Vec<Mutex<C>>,
}

impl<C> Default for Kept<C> {
    fn default() -> Self {
        Kept {
            demands: HashMap::new(),
            caches: Vec::new(),
        }
    }
}

impl<C> Kept<C> {
    /// (level, record) runs held.
    pub fn len(&self) -> usize {
        self.demands.len()
    }

    pub fn is_empty(&self) -> bool {
        self.demands.is_empty()
    }
}

/// The risk picture of the pair (its left building, its one joint), with
/// the runs of earlier pictures ([`Kept`]).
pub fn risk(
    case: &SuiteCase,
    members: &[SuiteMember],
    design_level: f64,
    levels: &[f64],
    keep_going: &dyn Fn() -> bool,
    kept: &mut Kept<<SuiteCase as Subject>::Caches>,
) -> Result<Option<RiskPicture>, SuiteRunError> {
    let focus = Focus {
        joint: 0,
        building: 0,
    };
    let range = (design_level, levels);
    picture_kept(case, focus, members, range, keep_going, kept)
}

/// What the picture of a row is of: the row, the joint whose pounding it
/// counts, the building whose drift it follows, and the measure records
/// are scaled by.
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

/// The risk picture of a row, at its joint and building, with the runs of
/// earlier pictures ([`Kept`]).
pub fn row_risk(
    case: &RowRiskCase,
    members: &[SuiteMember],
    design_level: f64,
    levels: &[f64],
    keep_going: &dyn Fn() -> bool,
    kept: &mut Kept<<RowSuiteCase as Subject>::Caches>,
) -> Result<Option<RiskPicture>, RowSuiteError> {
    let suite = RowSuiteCase {
        row: case.row.clone(),
        scaling: Scaling {
            measure: case.measure,
            level: None,
            collective: false,
        },
    };
    let focus = Focus {
        joint: case.joint,
        building: case.building,
    };
    let range = (design_level, levels);
    picture_kept(&suite, focus, members, range, keep_going, kept)
}

/// Runs every record at every level and at the design level, in parallel
/// chunks, while `keep_going()` holds (asked between chunks); the picture,
/// or `None` when stopped. A record that cannot be planned (zero
/// intensity, Π-groups out of range) fails the whole picture, naming it,
/// before any run; a run that fails (a row's runaway), at its chunk.
///
/// `levels` must be ascending and > 0, `design_level` > 0.
pub fn picture<S: Subject>(
    subject: &S,
    focus: Focus,
    members: &[SuiteMember],
    design_level: f64,
    levels: &[f64],
    keep_going: &dyn Fn() -> bool,
) -> Result<Option<RiskPicture>, S::Error> {
    let range = (design_level, levels);
    picture_kept(
        subject,
        focus,
        members,
        range,
        keep_going,
        &mut Kept::default(),
    )
}

/// [`picture`] at (design level, levels), running only the (level, record)
/// pairs that `kept` does not hold, and keeping them there. Where the
/// records are scaled together (one factor for the suite, SPEC §12) a
/// record's run depends on the others, and nothing is reused.
pub fn picture_kept<S: Subject>(
    subject: &S,
    focus: Focus,
    members: &[SuiteMember],
    (design_level, levels): (f64, &[f64]),
    keep_going: &dyn Fn() -> bool,
    kept: &mut Kept<S::Caches>,
) -> Result<Option<RiskPicture>, S::Error> {
    let (all, design) = with_design_level(levels, design_level);
    let plans = plan_levels(subject, members, &all)?;
    if subject.scaling().collective {
        kept.demands.clear();
    }
    let key = |l: usize, j: usize| (all[l].to_bits(), j, members[j].name.clone());
    let pairs: Vec<(usize, usize)> = (0..all.len())
        .flat_map(|l| (0..members.len()).map(move |j| (l, j)))
        .filter(|&(l, j)| !kept.demands.contains_key(&key(l, j)))
        .collect();
    let workers = rayon::current_num_threads().max(1);
    if kept.caches.len() < workers {
        kept.caches
            .resize_with(workers, || Mutex::new(S::Caches::default()));
    }
    // A chunk of runs at a time, so that `keep_going` is asked between two
    // chunks on the calling thread (a few milliseconds apart).
    let chunk = 4 * workers;
    for part in pairs.chunks(chunk) {
        if !keep_going() {
            return Ok(None);
        }
        let caches = &kept.caches;
        let done: Vec<Result<Demands, S::Error>> = part
            .par_iter()
            .map(|&(l, j)| {
                // Only this worker takes its own caches: the lock is never contended.
                let worker = rayon::current_thread_index().unwrap_or(0) % caches.len();
                let mut caches = caches[worker].lock().unwrap_or_else(|e| e.into_inner());
                run_one(subject, &members[j], &plans[l][j], &mut caches)
                    .map(|r| subject.demands(&r))
            })
            .collect();
        for (&(l, j), run) in part.iter().zip(done) {
            kept.demands.insert(key(l, j), run?);
        }
    }
    let by_level: Vec<Vec<Demands>> = (0..all.len())
        .map(|l| {
            (0..members.len())
                .map(|j| kept.demands[&key(l, j)].clone())
                .collect()
        })
        .collect();
    let at_design = &by_level[design];
    let ida_runs = &by_level[..levels.len()];
    let drift = levels
        .iter()
        .zip(ida_runs)
        .map(|(&level, at)| {
            let of = |free: bool| {
                let values: Vec<f64> = at
                    .iter()
                    .map(|d| {
                        let b = if free { &d.no_pounding } else { &d.buildings };
                        b[focus.building].peak_drift_m
                    })
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
    let counts = ida::counts(levels, ida_runs, |d: &Demands| {
        d.joints[focus.joint].impacts > 0
    });
    let collapse = subject.can_collapse().then(|| {
        let counts = ida::counts(levels, ida_runs, |d: &Demands| {
            d.buildings.iter().any(|b| b.collapsed)
        });
        CollapseCounts {
            fragility: fragility::fit(&counts),
            counts,
        }
    });
    let building = &subject.buildings()[focus.building];
    Ok(Some(RiskPicture {
        records: members.len(),
        design_level,
        min_gaps_m: at_design
            .iter()
            .map(|d| d.joints[focus.joint].min_gap_m)
            .collect(),
        gap_m: subject.joints()[focus.joint].gap_m,
        drift,
        fragility: fragility::fit(&counts),
        pounding: counts,
        drift_title: format!("{} drift [mm]", building.name),
        collapse,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture(gaps: &[f64], gap: f64) -> RiskPicture {
        RiskPicture {
            records: gaps.len(),
            design_level: 0.3,
            min_gaps_m: gaps.to_vec(),
            gap_m: gap,
            drift: Vec::new(),
            pounding: Vec::new(),
            fragility: Fragility::TooFewRecords,
            drift_title: String::new(),
            collapse: None,
        }
    }

    #[test]
    fn the_curve_steps_down_at_each_minimum_gap() {
        let p = picture(&[0.03, 0.01, 0.03, 0.02], 0.025);
        assert_eq!(p.probability_at_gap(), 0.5);
        assert_eq!(p.pounded_at_gap(), 2);
        let c = p.probability_curve(0.05);
        assert_eq!(
            c,
            [
                (0.0, 1.0),
                (0.01, 1.0),
                (0.01, 0.75),
                (0.02, 0.75),
                (0.02, 0.5),
                (0.03, 0.5),
                (0.03, 0.0),
                (0.05, 0.0)
            ]
        );
    }
}
