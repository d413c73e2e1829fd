//! Incremental dynamic analysis of a row of buildings (SPEC §12 with §13),
//! and the fragility of each limit state fitted on it.
//!
//! Every record runs at every level x_1 < … < x_L, scaled so that its
//! intensity measure equals the level; a level's runs are those of the row
//! suite at that level ([`super::row_suite`]), bit for bit: both scale by
//! [`level_scales`] from the same measurement and run [`run_member`]. At level l,
//! k_l of the n_l records exceed a limit state ([`RowLimitState`]); the counts
//! give P(exceed | IM = x) = Φ(ln(x/θ)/β) by maximum likelihood
//! ([`fragility::fit`](super::fragility::fit), Baker 2015, SPEC §12), and the same fit on the runs
//! without contact sits beside it.

use super::ida::{LimitStateFragility, fragility_of, over_levels};
use super::row_limit_state::RowLimitState;
use super::row_suite::{RowCaches, RowSuiteCase, RowSuiteError, RowSuiteRun, run_member};
use super::suite::{level_scales, raw_intensity};
use crate::model::suite::SuiteMember;

/// Each record's (scale, intensity) at every level, level by level. Each
/// record's intensity measure is taken once, not once per level.
pub fn plan_levels(
    case: &RowSuiteCase,
    members: &[SuiteMember],
    levels: &[f64],
) -> Result<Vec<Vec<(f64, f64)>>, RowSuiteError> {
    let raws: Vec<f64> = members
        .iter()
        .map(|m| raw_intensity(m, &case.scaling.measure))
        .collect::<Result<_, _>>()?;
    Ok(levels
        .iter()
        .map(|&level| level_scales(members, &raws, level, case.scaling.collective))
        .collect())
}

/// Runs every (level, record) pair in parallel as one pool of work; the
/// runs come back level by level, in suite order, or the first failure.
/// `done` is told of each finished run (progress).
pub fn run_levels(
    case: &RowSuiteCase,
    members: &[SuiteMember],
    plans: &[Vec<(f64, f64)>],
    done: &(dyn Fn(&RowSuiteRun) + Sync),
) -> Result<Vec<Vec<RowSuiteRun>>, RowSuiteError> {
    over_levels(
        plans.len(),
        members.len(),
        RowCaches::default,
        |caches, l, j| {
            let run = run_member(&case.row, &members[j], plans[l][j], caches);
            if let Ok(r) = &run {
                done(r);
            }
            run
        },
    )
    .into_iter()
    .map(|level| level.into_iter().collect())
    .collect()
}

/// The fragility of every limit state over an IDA's runs (`runs[l]` at
/// `levels[l]`), in the order given, with the buildings apart beside each
/// but pounding (which they never reach).
pub fn fragilities(
    levels: &[f64],
    runs: &[Vec<RowSuiteRun>],
    states: &[RowLimitState],
) -> Vec<LimitStateFragility> {
    states
        .iter()
        .map(|state| {
            fragility_of(
                state.label(),
                levels,
                runs,
                |r: &RowSuiteRun| state.exceeded(&r.demands.buildings),
                (!state.is_pounding())
                    .then_some(|r: &RowSuiteRun| state.exceeded(&r.demands.no_pounding)),
            )
        })
        .collect()
}
