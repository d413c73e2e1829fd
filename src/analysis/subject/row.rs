//! A row of buildings as a [`Subject`] (SPEC §12 with §13): each record,
//! scaled, is the ground motion under the row as its preset gives it, run
//! by the matrix-map solver with contact and with every joint open
//! ([`crate::analysis::row_suite::member_runs`]).

use serde::{Deserialize, Serialize};

use super::Subject;
use super::demands::{Building, BuildingDemand, Demands, Joint, JointDemand};
use crate::analysis::row_suite::{
    BuildingDemands, RowCaches, RowSuiteCase, RowSuiteError, RowSuiteRun, member_run, member_runs,
};
use crate::analysis::shard::Fingerprint;
use crate::analysis::suite::Scaling;
use crate::analysis::work;
use crate::model::buildings::Row;
use crate::model::buildings::matrices::default_tail;
use crate::model::buildings::matrices::periods;
use crate::model::suite::SuiteMember;
use crate::solver::buildings::RowRun;

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
    2.0 * work::row_seconds(row.dofs(), duration, None)
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
