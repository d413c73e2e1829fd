//! A row of buildings as a [`Subject`] (SPEC §12 with §13): a row under a
//! suite of records.
//!
//! **The same buildings under every record.** A row is physical already
//! (SI, SPEC §13), so record j, scaled by s_j, is the ground motion
//! ü_g(t) = s_j a_j(t) (m/s², linear between samples) under the row as
//! the preset gives it. The run lasts the record and a free tail of four
//! times the longest fundamental period ([`default_tail`]), the length
//! `pounding run --buildings` gives it, by the exact method. So each record's
//! run is bit for bit `pounding run --buildings PRESET --excitation
//! record:PATH --scale s_j`: both build the ground by
//! [`Ground::from_record`] and run [`run_row`](crate::solver::buildings::run_row) with the same options.
//!
//! **Intensity.** As for the pair (SPEC §12, [`crate::analysis::suite::Scaling`]):
//! at a level X (g) of an intensity measure IM, s_j = X / IM(record j);
//! without a level, each record runs at its suite list's scale.
//! [`row_intensity`] gives Sa its period when the command line asks for
//! `sa` alone: T₁ of the leftmost building, to four significant digits.
//!
//! **The run without contact.** Each record also runs with every joint's
//! gap infinite ([`Row::apart`]): its per-joint gap that prevents pounding
//! ([`joint_gaps`]) and its demands without pounding. When the run with
//! contact had no impact it is that motion already, and stands for it.
//! Otherwise it is that motion up to the first contact onset, and the run
//! apart continues from there ([`crate::solver::buildings::Checkpoint`]):
//! `pounding run --buildings` of the row apart to rounding (each peak
//! within 1e-12 of its own value, `tests/buildings_checkpoint.rs`).
//!
//! **Demands per record** ([`RowDemands`]): per building the largest storey
//! drift ratio max_i |Δ_i|/h_i, the largest floor absolute acceleration
//! max_i |ü_i + ü_g| (g) and the largest residual drift max_i
//! |(1 − α)(Δ_i − z_i)| (m) at the end (SPEC §13); per joint the impacts,
//! the largest impact force (kN) over its floor pairs and the gap that
//! prevents pounding (m). Their statistics over the suite are SPEC §12's
//! ([`crate::analysis::suite_statistics::SuiteStatistics`]).

use serde::{Deserialize, Serialize};

use super::Subject;
use super::demands::{Building, BuildingDemand, Column, Demands, Joint, JointDemand, JointRecord};
use crate::analysis::gap::{CodeRules, JointGap, floor_peaks, joint_gaps, joint_modes};
use crate::analysis::shard::Fingerprint;
use crate::analysis::suite::{Scaling, SuiteRunError};
use crate::analysis::work;
use crate::model::buildings::matrices::{default_tail, periods};
use crate::model::buildings::{Ground, Row};
use crate::model::intensity::IntensityMeasure;
use crate::model::record::STANDARD_GRAVITY;
use crate::model::suite::SuiteMember;
use crate::output::report::float_or_inf;
use crate::solver::buildings::{
    MapCache, RowError, RowOptions, RowRun, run_row_from, run_row_keeping,
};

/// A row suite study: the buildings and how the records are scaled.
#[derive(Debug, Clone, PartialEq)]
pub struct RowSuiteCase {
    pub row: Row,
    pub scaling: Scaling,
}

/// Sa at the leftmost building's fundamental period T₁, rounded to four
/// significant digits (0.2874 s for block-and-frame): the measure `--im sa`
/// names for a row, whose buildings have no one period. Rounded, it is
/// written in full in every report, and `--im sa:0.2874` is the same measure.
pub fn row_intensity(row: &Row) -> IntensityMeasure {
    let t1 = periods(&row.buildings[0])[0];
    IntensityMeasure::Sa {
        period: format!("{t1:.3e}").parse().unwrap_or(t1),
    }
}

/// Why a row suite cannot be run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RowSuiteError {
    /// A record cannot be scaled (its intensity is 0).
    #[error(transparent)]
    Scaling(#[from] SuiteRunError),
    /// A record's run failed (a runaway run).
    #[error("record `{record}`: {error}")]
    Run { record: String, error: RowError },
}

/// One building's demands in one run (SPEC §13), the largest over its
/// storeys and floors. A building that collapsed (SPEC §15) has drift,
/// acceleration and residual drift ∞ in that run, and exceeds every limit
/// state of its own; the others' peaks are those up to the collapse.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BuildingDemands {
    pub name: String,
    /// max_i |Δ_i|/h_i.
    #[serde(serialize_with = "float_or_inf")]
    pub max_drift_ratio: f64,
    /// max_i |ü_i + ü_g|, g.
    #[serde(serialize_with = "float_or_inf")]
    pub max_absolute_acceleration_g: f64,
    /// max_i |(1 − α)(Δ_i − z_i)| at the end, m.
    #[serde(serialize_with = "float_or_inf")]
    pub max_residual_drift_m: f64,
    /// max_i |Δ_i| (m), and max_i |Δ_i|/Δ_y,i, up to the end of the run
    /// (a collapse's instant; `collapsed` says so): read by the studies
    /// written over a [`Subject`], not reported.
    #[serde(skip)]
    pub max_drift_m: f64,
    #[serde(skip)]
    pub max_ductility: f64,
    /// Impacts at the joints on either side of it.
    pub impacts: usize,
    /// The largest impact force on it, kN (0 without impacts).
    pub max_force_kn: f64,
    /// It collapsed in this run (SPEC §15).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub collapsed: bool,
    /// Another building collapsed, and the run stopped there: these peaks
    /// are those up to that instant.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub cut_short: bool,
}

/// One joint's demands in one record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointDemands {
    /// Impacts over its floor pairs.
    pub impacts: usize,
    /// The largest impact force over its floor pairs, kN (0 without impacts).
    pub max_force_kn: f64,
    /// The joint's buildings, its gap that prevents pounding (m) and the
    /// code rules, from the run without contact ([`joint_gaps`]).
    #[serde(flatten)]
    pub gap: JointGap,
}

/// The demands of one record: with pounding, and without (the same
/// buildings apart).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RowDemands {
    pub pounded: bool,
    pub impacts: usize,
    pub joints: Vec<JointDemands>,
    pub buildings: Vec<BuildingDemands>,
    pub no_pounding: Vec<BuildingDemands>,
}

/// One record of a row suite, run.
#[derive(Debug, Clone, PartialEq)]
pub struct RowSuiteRun {
    pub name: String,
    pub samples: usize,
    /// Sample interval (s).
    pub dt: f64,
    /// The factor s on the record's accelerations, and IM of the scaled record (g).
    pub scale: f64,
    pub intensity: f64,
    /// Length of the runs (s): the record and the free tail.
    pub duration: f64,
    /// The run with contact, as `run --buildings` makes it.
    pub run: RowRun,
    /// The run without contact (the run itself when it had no impact).
    pub free: RowRun,
    pub demands: RowDemands,
}

/// The ground motion of a member at scale `s`: s·a(t) in m/s², linear
/// between samples, as `--excitation record:PATH --scale s` builds it.
pub fn ground_of(member: &SuiteMember, scale: f64) -> Ground {
    Ground::from_record(&member.record, scale)
}

/// The length of a row's run under `ground` (s): the motion and four times
/// the longest fundamental period ([`default_tail`]).
pub fn run_length(row: &Row, ground: &Ground) -> f64 {
    ground.end() + default_tail(row)
}

/// The linear maps of the row and of its buildings apart, kept from record
/// to record by one worker ([`MapCache`]: the runs are bit for bit those of
/// fresh caches, and faster).
#[derive(Debug, Default)]
pub struct RowCaches {
    with_contact: MapCache,
    apart: MapCache,
}

/// The two runs of one member at scale `scale`: with contact, and apart
/// (the run with contact itself when it had no contact, hard or bumper). Up to the first
/// contact onset the two have the same motion, so the run apart continues
/// from the run with contact's state there ([`run_row_from`]): the same
/// results to rounding, without the repeated part.
pub fn member_runs(
    row: &Row,
    member: &SuiteMember,
    scale: f64,
    caches: &mut RowCaches,
) -> Result<(RowRun, RowRun), RowSuiteError> {
    let failed = |error| RowSuiteError::Run {
        record: member.name.clone(),
        error,
    };
    let ground = ground_of(member, scale);
    let options = RowOptions::lasting(run_length(row, &ground));
    let (run, checkpoint) =
        run_row_keeping(row, &ground, &options, &mut caches.with_contact).map_err(failed)?;
    // Without any contact (a bumper's counts: its forces act) the run is
    // the buildings' run apart.
    let free = if run.contacts() == 0 {
        run.clone()
    } else {
        let apart = row.apart();
        run_row_from(
            &apart,
            &ground,
            &options,
            &mut caches.apart,
            checkpoint.as_ref(),
        )
        .map_err(failed)?
    };
    Ok((run, free))
}

/// One member's record of the suite from its two runs ([`member_runs`]),
/// as a suite builds it and as a merge of shards rebuilds it.
pub fn member_run(
    row: &Row,
    member: &SuiteMember,
    (scale, intensity): (f64, f64),
    run: RowRun,
    free: RowRun,
) -> RowSuiteRun {
    let demands = RowDemands::of(row, &run, &free);
    RowSuiteRun {
        name: member.name.clone(),
        samples: member.record.acceleration.len(),
        dt: member.record.dt,
        scale,
        intensity,
        duration: run.duration,
        run,
        free,
        demands,
    }
}

impl BuildingDemands {
    /// Every building's demands in `run` of `row` (a run of the row itself,
    /// or of [`Row::apart`], whose floor pairs are none: no impacts).
    pub fn of(row: &Row, run: &RowRun) -> Vec<BuildingDemands> {
        let pairs = row.pairs();
        row.buildings
            .iter()
            .zip(&run.floors)
            .enumerate()
            .map(|(i, (b, floors))| {
                let largest = |f: fn(&crate::solver::buildings::FloorPeaks) -> f64| {
                    floors.iter().map(f).fold(0.0, f64::max)
                };
                let touching = pairs
                    .iter()
                    .zip(&run.pairs)
                    .filter(|(p, _)| p.left == i || p.right == i);
                let (impacts, force) = touching.fold((0, 0.0_f64), |(n, f), (_, r)| {
                    (n + r.impacts.len(), f.max(r.max_force()))
                });
                let collapsed = run.collapse.is_some_and(|c| c.building == i);
                // A collapsed building's demands are ∞ (SPEC §15).
                let or_infinite = |v: f64| if collapsed { f64::INFINITY } else { v };
                BuildingDemands {
                    name: b.name.clone(),
                    max_drift_ratio: or_infinite(largest(|f| f.drift_ratio)),
                    max_absolute_acceleration_g: or_infinite(
                        largest(|f| f.absolute_acceleration) / STANDARD_GRAVITY,
                    ),
                    max_residual_drift_m: or_infinite(largest(|f| f.residual_drift.abs())),
                    max_drift_m: largest(|f| f.drift),
                    max_ductility: largest(|f| f.ductility),
                    impacts,
                    max_force_kn: force / 1e3,
                    collapsed,
                    cut_short: run.collapse.is_some() && !collapsed,
                }
            })
            .collect()
    }
}

impl RowDemands {
    /// The demands of `row` from its run with contact and its run apart.
    pub fn of(row: &Row, run: &RowRun, free: &RowRun) -> RowDemands {
        let pairs = row.pairs();
        let joints = joint_gaps(row, free)
            .into_iter()
            .enumerate()
            .map(|(j, gap)| {
                let at_joint = pairs.iter().zip(&run.pairs).filter(|(p, _)| p.joint == j);
                let (impacts, force) = at_joint.fold((0, 0.0_f64), |(n, f), (_, r)| {
                    (n + r.impacts.len(), f.max(r.max_force()))
                });
                JointDemands {
                    impacts,
                    max_force_kn: force / 1e3,
                    gap,
                }
            })
            .collect();
        RowDemands {
            pounded: run.impacts() > 0,
            impacts: run.impacts(),
            joints,
            buildings: BuildingDemands::of(row, run),
            no_pounding: BuildingDemands::of(row, free),
        }
    }
}

/// A demand of a building: its key and unit, and how it is read.
type BuildingColumn = (&'static str, &'static str, fn(&BuildingDemands) -> f64);

const BUILDING_DEMANDS: [BuildingColumn; 4] = [
    ("max_drift_ratio", "", |d| d.max_drift_ratio),
    ("max_absolute_acceleration_g", "g", |d| {
        d.max_absolute_acceleration_g
    }),
    ("max_residual_drift_m", "m, absolute", |d| {
        d.max_residual_drift_m
    }),
    ("max_force_kn", "kN", |d| d.max_force_kn),
];

/// A demand of a joint: its key and unit, and how it is read.
type JointColumn = (&'static str, &'static str, fn(&JointDemands) -> f64);

const JOINT_DEMANDS: [JointColumn; 3] = [
    ("impacts", "", |d| d.impacts as f64),
    ("max_force_kn", "kN", |d| d.max_force_kn),
    ("min_gap_m", "m", |d| d.gap.min_gap),
];

/// The demands of a row suite's statistics (SPEC §12): per building
/// (`block.max_drift_ratio`, …, and the same without pounding under
/// `no_pounding.block.…`) and per joint (`joint1.max_force_kn`, …).
fn columns(runs: &[RowSuiteRun]) -> Vec<Column> {
    let mut columns = Vec::new();
    let Some(first) = runs.first().map(|r| &r.demands) else {
        return columns;
    };
    for (prefix, free) in [("", false), ("no_pounding.", true)] {
        for (i, b) in first.buildings.iter().enumerate() {
            for (key, unit, get) in BUILDING_DEMANDS {
                if free && key == "max_force_kn" {
                    continue;
                }
                let values = runs
                    .iter()
                    .map(|r| {
                        let d = &r.demands;
                        get(&if free { &d.no_pounding } else { &d.buildings }[i])
                    })
                    .collect();
                columns.push((format!("{prefix}{}.{key}", b.name), unit, values));
            }
        }
    }
    for j in 0..first.joints.len() {
        for (key, unit, get) in JOINT_DEMANDS {
            let values = runs.iter().map(|r| get(&r.demands.joints[j])).collect();
            columns.push((format!("joint{}.{key}", j + 1), unit, values));
        }
    }
    columns
}

/// What a part carries of one record's runs.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RowMemberRuns {
    pub run: RowRun,
    pub free: RowRun,
}

/// Estimated work (s) of one record's two runs on `row` by the exact method
/// ([`work::row_seconds`]): `samples` at interval `dt` (s), and the free tail.
pub fn record_seconds(row: &Row, samples: usize, dt: f64) -> f64 {
    let duration = dt * (samples.max(1) - 1) as f64 + default_tail(row);
    2.0 * work::row_seconds(row, duration, None)
}

impl Subject for RowSuiteCase {
    /// (scale, intensity).
    type Plan = (f64, f64);
    type Runs = RowMemberRuns;
    type Run = RowSuiteRun;
    type Caches = RowCaches;
    type Error = RowSuiteError;

    fn scaling(&self) -> &Scaling {
        &self.scaling
    }

    fn plan_at(
        &self,
        _: &SuiteMember,
        scale: f64,
        intensity: f64,
    ) -> Result<(f64, f64), RowSuiteError> {
        Ok((scale, intensity))
    }

    fn runs(
        &self,
        member: &SuiteMember,
        &(scale, _): &(f64, f64),
        caches: &mut RowCaches,
    ) -> Result<RowMemberRuns, RowSuiteError> {
        let (run, free) = member_runs(&self.row, member, scale, caches)?;
        Ok(RowMemberRuns { run, free })
    }

    fn record(&self, member: &SuiteMember, &plan: &(f64, f64), runs: RowMemberRuns) -> RowSuiteRun {
        member_run(&self.row, member, plan, runs.run, runs.free)
    }

    fn buildings(&self) -> Vec<Building> {
        let row = &self.row;
        row.buildings
            .iter()
            .map(|b| Building {
                name: b.name.clone(),
                period_s: periods(b)[0],
            })
            .collect()
    }

    fn joints(&self) -> Vec<Joint> {
        let b = &self.row.buildings;
        self.row
            .joints
            .iter()
            .enumerate()
            .map(|(j, joint)| Joint {
                left: b[j].name.clone(),
                right: b[j + 1].name.clone(),
                gap_m: joint.gap,
            })
            .collect()
    }

    fn can_collapse(&self) -> bool {
        self.row.can_collapse()
    }

    fn demands(&self, run: &RowSuiteRun) -> Demands {
        let of = |all: &[BuildingDemands]| -> Vec<BuildingDemand> {
            all.iter()
                .map(|b| BuildingDemand {
                    peak_drift_m: b.max_drift_m,
                    drift_ratio: Some(b.max_drift_ratio),
                    ductility: b.max_ductility,
                    acceleration_g: b.max_absolute_acceleration_g,
                    collapsed: b.collapsed,
                    cut_short: b.cut_short,
                })
                .collect()
        };
        Demands {
            buildings: of(&run.demands.buildings),
            joints: run
                .demands
                .joints
                .iter()
                .map(|j| JointDemand {
                    impacts: j.impacts,
                    max_force_kn: j.max_force_kn,
                    min_gap_m: j.gap.min_gap,
                })
                .collect(),
            no_pounding: of(&run.demands.no_pounding),
        }
    }

    fn columns(&self, runs: &[RowSuiteRun]) -> Vec<Column> {
        columns(runs)
    }

    fn pounded(&self, run: &RowSuiteRun) -> bool {
        run.demands.pounded
    }

    fn joint_records(&self, run: &RowSuiteRun) -> Vec<JointRecord> {
        let facing = self.row.facing_floors();
        run.demands
            .joints
            .iter()
            .enumerate()
            .map(|(j, joint)| {
                let (wa, wb, xi) = joint_modes(&self.row, j);
                let g = &joint.gap;
                JointRecord {
                    min_gap: g.min_gap,
                    rules: CodeRules {
                        absolute_sum: g.abs,
                        srss: g.srss,
                        double_difference: g.ddc,
                        ..CodeRules::of(0.0, 0.0, wa, wb, xi)
                    },
                    floors: facing
                        .iter()
                        .filter(|p| p.joint == j)
                        .map(|p| floor_peaks(&run.free, p))
                        .collect(),
                }
            })
            .collect()
    }

    fn work(&self, member: &SuiteMember, _: &(f64, f64)) -> f64 {
        let r = &member.record;
        record_seconds(&self.row, r.acceleration.len(), r.dt)
    }

    fn describe(&self, f: &mut Fingerprint, name: &str) {
        f.add_str("buildings");
        f.add_str(name);
        f.add_debug(self);
    }
}
