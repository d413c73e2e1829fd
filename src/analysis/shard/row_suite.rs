//! Suites on a row of buildings as shards (`suite --buildings`, `ida
//! --buildings`; SPEC §12, §13): a unit is one record's runs at one plan
//! (scale, intensity), so an IDA's units are its (level, record) pairs. A
//! part carries the unit's two row runs (with contact and apart), from which
//! the record's row is rebuilt as the unsharded suite builds it
//! ([`member_run`]).
//!
//! The fingerprint covers the row as resolved (every building, storey and
//! joint), the scaling, the records' samples and every plan, as a pair
//! suite's does.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::fingerprint::Fingerprint;
use super::suite::add_records;
use crate::analysis::row_suite::{
    RowCaches, RowSuiteCase, RowSuiteError, RowSuiteRun, member_run, member_runs,
};
use crate::analysis::work;
use crate::model::buildings::Row;
use crate::model::buildings::matrices::default_tail;
use crate::model::suite::SuiteMember;
use crate::solver::buildings::RowRun;

/// One unit: a record (an index into the suite) at its (scale, intensity).
pub type RowUnit = (usize, (f64, f64));

/// What a part carries of one unit.
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

/// The fingerprint of a row study `command` on `row_name`: the case (the
/// resolved row and its scaling), every record's samples, every unit and
/// whatever else the command reports from its request (`extra`: levels,
/// limit states).
pub fn fingerprint(
    command: &str,
    row_name: &str,
    case: &RowSuiteCase,
    members: &[SuiteMember],
    units: &[RowUnit],
    extra: &impl std::fmt::Debug,
) -> Fingerprint {
    let mut f = Fingerprint::new(command);
    f.add_str("buildings");
    f.add_str(row_name);
    f.add_debug(case);
    add_records(&mut f, members);
    f.add_debug(&units);
    f.add_debug(extra);
    f
}

/// The work of each unit, for the partition.
pub fn unit_work(row: &Row, members: &[SuiteMember], units: &[RowUnit]) -> Vec<f64> {
    units
        .iter()
        .map(|&(j, _)| {
            let r = &members[j].record;
            record_seconds(row, r.acceleration.len(), r.dt)
        })
        .collect()
}

/// The runs of the units `mine` (indices into `units`), in parallel with one
/// map cache per worker, in that order; the first failure in that order.
pub fn compute(
    row: &Row,
    members: &[SuiteMember],
    units: &[RowUnit],
    mine: &[usize],
) -> Result<Vec<RowMemberRuns>, RowSuiteError> {
    let runs: Vec<_> = mine
        .par_iter()
        .map_init(RowCaches::default, |caches, &i| {
            let (j, (scale, _)) = units[i];
            member_runs(row, &members[j], scale, caches)
                .map(|(run, free)| RowMemberRuns { run, free })
        })
        .collect();
    runs.into_iter().collect()
}

/// Every unit's record from its runs, in order.
pub fn rebuild(
    row: &Row,
    members: &[SuiteMember],
    units: &[RowUnit],
    runs: Vec<RowMemberRuns>,
) -> Vec<RowSuiteRun> {
    units
        .iter()
        .zip(runs)
        .map(|(&(j, plan), r)| member_run(row, &members[j], plan, r.run, r.free))
        .collect()
}
