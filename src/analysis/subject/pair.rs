//! The physical pair as a [`Subject`] (SPEC §12): its `[physical]` table
//! under each record's a_p and ω_p gives that record's Π-groups, run by the
//! pair's own solver ([`crate::solver::solve`]) with contact and by the
//! exact method without it ([`super::super::gap::free_run`]); the results
//! are mapped back to SI ([`crate::analysis::demands::RunSi`]).

use serde::{Deserialize, Serialize};

use super::Subject;
use super::demands::{Building, BuildingDemand, Column, Demands, Joint, JointDemand, JointRecord};
use crate::analysis::demands::DemandsSi;
use crate::analysis::gap::free_params;
use crate::analysis::separation::RecordGap;
use crate::analysis::shard::Fingerprint;
use crate::analysis::suite::{
    MemberPlan, Scaling, SuiteCase, SuiteRun, SuiteRunError, member_params, member_run, runs_of,
};
use crate::analysis::work;
use crate::model::suite::SuiteMember;
use crate::solver::RunResult;

/// What a part carries of one record's runs.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct MemberRuns {
    pub result: RunResult,
    pub free: RunResult,
}

/// Estimated work of one planned record: its run, and its run without
/// contact (exact method) where it has a finite gap.
pub fn member_work(plan: &MemberPlan) -> f64 {
    let p = &plan.params;
    let free = if p.pounding() {
        work::free_run(&free_params(p))
    } else {
        0.0
    };
    work::pounding_run(p).max(work::free_run(p)) + free
}

/// Each demand of SPEC §6 in SI, its key and unit, for statistics.
type DemandColumn = (&'static str, &'static str, fn(&DemandsSi) -> f64);

/// A demand of a record's run as a whole (impacts, force, gap), for statistics.
type RunColumn = (&'static str, &'static str, fn(&SuiteRun) -> f64);

const DEMANDS: [DemandColumn; 6] = [
    ("peak_displacement_m", "m", |d| d.peak_displacement_m),
    ("peak_velocity_m_s", "m/s", |d| d.peak_velocity_m_s),
    ("peak_absolute_acceleration_g", "g", |d| {
        d.peak_absolute_acceleration_g
    }),
    ("ductility", "", |d| d.ductility),
    // The size of the residual drift decides repair, not its side.
    ("residual_displacement_m", "m, absolute", |d| {
        d.residual_displacement_m.abs()
    }),
    ("hysteretic_energy_kj", "kJ", |d| d.hysteretic_energy_kj),
];

const RUN_DEMANDS: [RunColumn; 3] = [
    ("impacts", "", |r| r.result.impacts.len() as f64),
    ("max_force_kn", "kN", SuiteRun::max_force_kn),
    ("min_gap_m", "m", SuiteRun::min_gap_m),
];

impl Subject for SuiteCase {
    type Plan = MemberPlan;
    type Runs = MemberRuns;
    type Run = SuiteRun;
    type Caches = ();
    type Error = SuiteRunError;

    fn scaling(&self) -> &Scaling {
        &self.scaling
    }

    fn plan_at(
        &self,
        member: &SuiteMember,
        scale: f64,
        intensity: f64,
    ) -> Result<MemberPlan, SuiteRunError> {
        Ok(MemberPlan {
            scale,
            intensity,
            params: member_params(self, member, scale)?,
        })
    }

    fn runs(
        &self,
        _: &SuiteMember,
        plan: &MemberPlan,
        _: &mut (),
    ) -> Result<MemberRuns, SuiteRunError> {
        let (result, free) = runs_of(&plan.params);
        Ok(MemberRuns { result, free })
    }

    fn record(&self, member: &SuiteMember, plan: &MemberPlan, runs: MemberRuns) -> SuiteRun {
        member_run(self, member, plan, runs.result, runs.free)
    }

    fn buildings(&self) -> Vec<Building> {
        let phys = &self.physical;
        ["left", "right"]
            .iter()
            .zip(phys.omega)
            .map(|(name, omega)| Building {
                name: name.to_string(),
                period_s: std::f64::consts::TAU / omega,
            })
            .collect()
    }

    fn joints(&self) -> Vec<Joint> {
        vec![Joint {
            left: "left".into(),
            right: "right".into(),
            gap_m: self.physical.gap,
        }]
    }

    fn demands(&self, run: &SuiteRun) -> Demands {
        let building = |d: &DemandsSi| BuildingDemand {
            peak_drift_m: d.peak_displacement_m,
            drift_ratio: None,
            ductility: d.ductility,
            acceleration_g: d.peak_absolute_acceleration_g,
            collapsed: false,
            cut_short: false,
        };
        Demands {
            buildings: vec![building(&run.si.left), building(&run.si.right)],
            joints: vec![JointDemand {
                impacts: run.result.impacts.len(),
                max_force_kn: run.max_force_kn(),
                min_gap_m: run.min_gap_m(),
            }],
            no_pounding: vec![building(&run.free_si.left), building(&run.free_si.right)],
        }
    }

    /// `left.…` and `right.…` of SPEC §6 in SI, then the joint's demands
    /// without a prefix (`impacts`, `max_force_kn`, `min_gap_m`).
    fn columns(&self, runs: &[SuiteRun]) -> Vec<Column> {
        let mut columns = Vec::new();
        for (side, i) in [("left", 0), ("right", 1)] {
            for (key, unit, get) in DEMANDS {
                let values = runs.iter().map(|r| get(&r.demands(i))).collect();
                columns.push((format!("{side}.{key}"), unit, values));
            }
        }
        for (key, unit, get) in RUN_DEMANDS {
            columns.push((key.to_string(), unit, runs.iter().map(get).collect()));
        }
        columns
    }

    fn pounded(&self, run: &SuiteRun) -> bool {
        run.pounded()
    }

    fn joint_records(&self, run: &SuiteRun) -> Vec<JointRecord> {
        vec![JointRecord::from(&RecordGap::of(run))]
    }

    fn work(&self, _: &SuiteMember, plan: &MemberPlan) -> f64 {
        member_work(plan)
    }

    fn describe(&self, f: &mut Fingerprint, name: &str) {
        f.add_str(name);
        f.add_debug(self);
    }
}
