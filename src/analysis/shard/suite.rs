//! Suites as shards (`suite`, `ida`, `map --suite`), for the pair and for a
//! row alike ([`Subject`]): a unit is one record's runs under one plan (a
//! record, a (level, record) pair) or, for a suite map, cells of every
//! record. A part carries each unit's runs with contact and with every
//! joint open ([`Subject::runs`]), from which the record's result is
//! rebuilt as the unsharded suite builds it ([`Subject::record`]).
//!
//! The fingerprint of a suite study covers the subject as resolved, the
//! records themselves (each one's name, scale, sample interval and every
//! sample, so that a record file edited between the shards and the merge is
//! caught) and every unit's plan.

use rayon::prelude::*;

use super::fingerprint::Fingerprint;
use crate::analysis::subject::Subject;
use crate::model::suite::SuiteMember;

/// One unit: a record (an index into the suite) and its plan.
pub type Unit<'a, P> = (usize, &'a P);

/// The fingerprint of a suite study `command` on the subject named `name`:
/// the subject, every record's samples, every unit and whatever else the
/// command reports from its request (`extra`: axes, levels, limit states).
pub fn fingerprint<S: Subject>(
    command: &str,
    name: &str,
    subject: &S,
    members: &[SuiteMember],
    units: &[Unit<S::Plan>],
    extra: &impl std::fmt::Debug,
) -> Fingerprint {
    let mut f = Fingerprint::new(command);
    subject.describe(&mut f, name);
    add_records(&mut f, members);
    f.add_debug(&units);
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

/// The work of each unit, for the partition.
pub fn unit_work<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    units: &[Unit<S::Plan>],
) -> Vec<f64> {
    units
        .iter()
        .map(|&(j, plan)| subject.work(&members[j], plan))
        .collect()
}

/// The runs of the units `mine` (indices into `units`), in parallel with
/// one set of caches per worker, in that order; the first failure in that
/// order.
pub fn compute<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    units: &[Unit<S::Plan>],
    mine: &[usize],
) -> Result<Vec<S::Runs>, S::Error> {
    let runs: Vec<_> = mine
        .par_iter()
        .map_init(S::Caches::default, |caches, &i| {
            let (j, plan) = units[i];
            subject.runs(&members[j], plan, caches)
        })
        .collect();
    runs.into_iter().collect()
}

/// Every unit's record from its runs, in order.
pub fn rebuild<S: Subject>(
    subject: &S,
    members: &[SuiteMember],
    units: &[Unit<S::Plan>],
    runs: Vec<S::Runs>,
) -> Vec<S::Run> {
    units
        .iter()
        .zip(runs)
        .map(|(&(j, plan), r)| subject.record(&members[j], plan, r))
        .collect()
}
