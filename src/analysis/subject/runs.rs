//! A suite, or every level of an IDA, planned and run over a [`Subject`]
//! (SPEC §12).
//!
//! A level's runs are those of the suite scaled to that level, bit for bit:
//! both scale each record by [`scaled`](crate::analysis::suite::scaled)
//! (or, for a suite scaled as a whole, [`level_scales`]) from the same
//! measurement and run [`Subject::runs`].

use super::Subject;
use crate::analysis::ida::over_levels;
use crate::analysis::suite::{level_scales, raw_intensity, scales};
use crate::model::suite::SuiteMember;

/// Every record's plan under the subject's scaling, before any run: a record
/// that cannot be scaled, or whose plan is out of range, fails at once and
/// names the record.
pub fn plan<S: Subject>(subject: &S, members: &[SuiteMember]) -> Result<Vec<S::Plan>, S::Error> {
    let scales = scales(members, subject.scaling())?;
    members
        .iter()
        .zip(scales)
        .map(|(m, (scale, intensity))| subject.plan_at(m, scale, intensity))
        .collect()
}

/// The plans of every record at every level, level by level. Each record's
/// intensity measure is taken once, not once per level: Sa(T) is a pass of
/// the Nigam–Jennings map over the whole record.
pub fn plan_levels<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    levels: &[f64],
) -> Result<Vec<Vec<S::Plan>>, S::Error> {
    let scaling = subject.scaling();
    let raws: Vec<f64> = members
        .iter()
        .map(|m| raw_intensity(m, &scaling.measure))
        .collect::<Result<_, _>>()?;
    levels
        .iter()
        .map(|&level| {
            level_scales(members, &raws, level, scaling.collective)
                .into_iter()
                .zip(members)
                .map(|((scale, intensity), m)| subject.plan_at(m, scale, intensity))
                .collect()
        })
        .collect()
}

/// One planned record run and its result built.
pub fn run_one<S: Subject>(
    subject: &S,
    member: &SuiteMember,
    plan: &S::Plan,
    caches: &mut S::Caches,
) -> Result<S::Run, S::Error> {
    let runs = subject.runs(member, plan, caches)?;
    Ok(subject.record(member, plan, runs))
}

/// Runs every (level, record) pair in parallel as one pool of work, each
/// worker keeping its caches; the runs come back level by level, in suite
/// order, or the first failure in that order. `done` is told of each
/// finished run (progress).
pub fn run_levels<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    plans: &[Vec<S::Plan>],
    done: &(dyn Fn(&S::Run) + Sync),
) -> Result<Vec<Vec<S::Run>>, S::Error> {
    run_all(subject, members, plans.len(), |l, j| &plans[l][j], done)
        .into_iter()
        .map(|level| level.into_iter().collect())
        .collect()
}

/// Runs every planned record in parallel, in suite order ([`run_levels`]
/// at one level).
pub fn run_suite<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    plans: &[S::Plan],
    done: &(dyn Fn(&S::Run) + Sync),
) -> Result<Vec<S::Run>, S::Error> {
    run_all(subject, members, 1, |_, j| &plans[j], done)
        .into_iter()
        .flatten()
        .collect()
}

/// Record j at level l, planned by `plan(l, j)`, for every level and record.
fn run_all<'a, S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    levels: usize,
    plan: impl Fn(usize, usize) -> &'a S::Plan + Sync + Send,
    done: &(dyn Fn(&S::Run) + Sync),
) -> Vec<Vec<Result<S::Run, S::Error>>>
where
    S::Plan: 'a,
{
    over_levels(levels, members.len(), S::Caches::default, |caches, l, j| {
        let run = run_one(subject, &members[j], plan(l, j), caches);
        if let Ok(r) = &run {
            done(r);
        }
        run
    })
}
