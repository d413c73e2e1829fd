//! Suites as shards (`suite`, `ida`, `map --suite`): their units are runs
//! of one record under one plan (a record, a (level, record) pair) or, for
//! a suite map, cells of every record. A part carries each record's two
//! runs (with and without contact), from which the row is rebuilt as the
//! unsharded suite builds it.
//!
//! The fingerprint of a suite study covers the records themselves: each
//! one's name, scale, sample interval and every sample, so that a record
//! file edited between the shards and the merge is caught.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::fingerprint::Fingerprint;
use crate::analysis::gap::free_params;
use crate::analysis::suite::{MemberPlan, SuiteCase, SuiteRun, member_run, run_member};
use crate::analysis::work;
use crate::model::suite::SuiteMember;
use crate::solver::RunResult;

/// What a part carries of one record's run.
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

/// The fingerprint of a suite study `command`: the preset, the case, every
/// record's samples, every plan and whatever else the command reports
/// from its request (`extra`: axes, levels, limit states).
pub fn fingerprint(
    command: &str,
    preset: &str,
    case: &SuiteCase,
    members: &[SuiteMember],
    plans: &[&MemberPlan],
    extra: &impl std::fmt::Debug,
) -> Fingerprint {
    let mut f = Fingerprint::new(command);
    f.add_str(preset);
    f.add_debug(case);
    add_records(&mut f, members);
    f.add_debug(&plans);
    f.add_debug(extra);
    f
}

/// Every record of a suite into `f`: its name, its list's scale, its
/// sample interval and every sample.
pub fn add_records(f: &mut Fingerprint, members: &[SuiteMember]) {
    for m in members {
        f.add_str(&m.name);
        f.add_f64s(&[m.scale, m.record.dt]);
        f.add_f64s(&m.record.acceleration);
    }
}

/// One record to run: the case (a suite map's cell), the record, its plan.
pub type Pair<'a> = (&'a SuiteCase, &'a SuiteMember, &'a MemberPlan);

/// The runs of the pairs `mine` (indices into `pairs`), in parallel, in that order.
pub fn compute(pairs: &[Pair], mine: &[usize]) -> Vec<MemberRuns> {
    mine.par_iter()
        .map(|&i| {
            let (case, member, plan) = pairs[i];
            let run = run_member(case, member, plan);
            MemberRuns {
                result: run.result,
                free: run.free,
            }
        })
        .collect()
}

/// Every pair's row from its runs, in order.
pub fn rebuild(pairs: &[Pair], runs: Vec<MemberRuns>) -> Vec<SuiteRun> {
    pairs
        .iter()
        .zip(runs)
        .map(|(&(case, member, plan), r)| member_run(case, member, plan, r.result, r.free))
        .collect()
}
