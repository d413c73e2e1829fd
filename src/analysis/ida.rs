//! Incremental dynamic analysis of a suite (Vamvatsikos and Cornell 2002;
//! SPEC §12), and the fragility of each limit state fitted on it.
//!
//! Every record of the suite runs at every intensity level x_1 < … < x_L,
//! scaled so that its intensity measure equals the level. A level's runs are
//! exactly those of [`suite`](super::suite) at that level: both plan them
//! over the same [`Subject`]
//! ([`plan_levels`](super::subject::runs::plan_levels)) with the same
//! scaling, so a level's rows are bit for bit the suite's, for the pair and
//! for a row alike.
//!
//! At each level l, k_l of the n_l records exceed a limit state
//! ([`LimitState`]); the counts of all levels give the lognormal fragility
//! P(exceed | IM = x) = Φ(ln(x/θ)/β) by maximum likelihood
//! ([`fragility::fit`], Baker 2015). Each record also runs without contact
//! (gap = ∞), so the same fragility of the no-pounding pair sits beside it,
//! and the effect of pounding on a limit state is one comparison.

// Comparisons are written `!(a > b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use std::sync::Mutex;

use rayon::prelude::*;
use serde::Serialize;

use super::fragility::{self, Fragility, LevelCount};
use super::limit_state::LimitState;
use super::subject::Subject;
use super::subject::demands::Demands;

/// `run(state, l, j)` for every level l < `levels` and record j <
/// `records`, in parallel as one pool of work (so that the cores stay busy
/// to the end), returned level by level, in suite order. Each worker
/// thread has its own `state`, made by `init` and kept from run to run (a
/// cache of what the runs share).
pub fn over_levels<R: Send, S: Send>(
    levels: usize,
    records: usize,
    init: impl Fn() -> S,
    run: impl Fn(&mut S, usize, usize) -> R + Sync + Send,
) -> Vec<Vec<R>> {
    let pairs: Vec<(usize, usize)> = (0..levels)
        .flat_map(|l| (0..records).map(move |j| (l, j)))
        .collect();
    let states: Vec<Mutex<S>> = (0..rayon::current_num_threads().max(1))
        .map(|_| Mutex::new(init()))
        .collect();
    let mut runs: Vec<R> = pairs
        .par_iter()
        .map(|&(l, j)| {
            // Only this worker takes its own state: the lock is never contended.
            let worker = rayon::current_thread_index().unwrap_or(0) % states.len();
            let mut state = states[worker].lock().unwrap_or_else(|e| e.into_inner());
            run(&mut state, l, j)
        })
        .collect();
    let mut out = Vec::with_capacity(levels);
    for _ in 0..levels {
        let rest = runs.split_off(records.min(runs.len()));
        out.push(std::mem::replace(&mut runs, rest));
    }
    out
}

/// One limit state's counts over the levels and their fragility, with
/// pounding and for the no-pounding pair.
#[derive(Debug, Clone, Serialize)]
pub struct LimitStateFragility {
    /// `pounding`, `ductility>2 (either)`, …
    pub limit_state: String,
    /// k_l of n_l at each level, with pounding.
    pub counts: Vec<LevelCount>,
    pub fragility: Fragility,
    /// The same for the pair without contact; absent for the pounding limit
    /// state, which that pair never reaches.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub no_pounding_counts: Option<Vec<LevelCount>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub no_pounding_fragility: Option<Fragility>,
}

/// The counts of a limit state at each level: n_l runs, and the k_l of
/// them that exceed it (SPEC §12), for the runs of a pair or of a row.
pub fn counts<R>(levels: &[f64], runs: &[Vec<R>], exceeds: impl Fn(&R) -> bool) -> Vec<LevelCount> {
    levels
        .iter()
        .zip(runs)
        .map(|(&level, at_level)| LevelCount {
            level,
            runs: at_level.len(),
            exceeded: at_level.iter().filter(|r| exceeds(r)).count(),
        })
        .collect()
}

/// The fragility of every limit state over an IDA's runs of `subject`
/// (`runs[l]` at `levels[l]`), in the order given (pounding first, as the
/// parsers give it), with the buildings apart beside each but pounding
/// (which they never reach).
pub fn fragilities<S: Subject>(
    subject: &S,
    levels: &[f64],
    runs: &[Vec<S::Run>],
    states: &[LimitState],
) -> Vec<LimitStateFragility> {
    let demands: Vec<Vec<Demands>> = runs
        .iter()
        .map(|at| at.iter().map(|r| subject.demands(r)).collect())
        .collect();
    states
        .iter()
        .map(|state| {
            fragility_of(
                state.label(),
                levels,
                &demands,
                |d| state.exceeded_by(d),
                (!state.is_pounding()).then_some(|d: &Demands| state.exceeded_apart(d)),
            )
        })
        .collect()
}

/// One limit state's counts and fragility over an IDA's runs (`runs[l]` at
/// `levels[l]`, of a pair or a row): `with` says whether a run exceeds it,
/// `without` whether the same run without contact does (none for the
/// pounding limit state, which that run never reaches).
pub fn fragility_of<R>(
    label: String,
    levels: &[f64],
    runs: &[Vec<R>],
    with: impl Fn(&R) -> bool,
    without: Option<impl Fn(&R) -> bool>,
) -> LimitStateFragility {
    let with = counts(levels, runs, with);
    let without = without.map(|exceeds| counts(levels, runs, exceeds));
    LimitStateFragility {
        limit_state: label,
        fragility: fragility::fit(&with),
        counts: with,
        no_pounding_fragility: without.as_deref().map(fragility::fit),
        no_pounding_counts: without,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_per_level() {
        // Two levels of no runs: the counts still name their levels.
        let c = counts::<()>(&[0.1, 0.2], &[vec![], vec![]], |_| true);
        assert_eq!(c.len(), 2);
        assert_eq!((c[1].level, c[1].runs, c[1].exceeded), (0.2, 0, 0));
    }
}

/// Most intensity levels an IDA may have.
pub const MAX_LEVELS: usize = 1000;

/// The intensity levels (g) of `--levels`: `START:STOP:STEP` (STOP kept
/// when it lies on the grid to within round-off) or a comma-separated list,
/// ascending and > 0. Grid levels START + k·STEP are rounded to 12
/// significant digits, so that 0.05:1:0.05 gives 0.15, the level
/// `suite --level 0.15` runs, not 0.15000000000000002. An error is one line
/// naming the value and what is allowed.
pub fn parse_levels(text: &str) -> Result<Vec<f64>, String> {
    let shown = crate::model::params::echo::text(text);
    let bad = |why: &str| {
        Err(format!(
            "--levels {shown}: {why}; write START:STOP:STEP or a list X1,X2,… of \
             intensities in g, ascending and > 0"
        ))
    };
    let number = |t: &str| t.trim().trim_end_matches('g').trim().parse::<f64>().ok();
    let levels: Vec<f64> = if text.contains(':') {
        let parts: Vec<Option<f64>> = text.split(':').map(number).collect();
        let [Some(start), Some(stop), Some(step)] = parts[..] else {
            return bad("expected three numbers START:STOP:STEP");
        };
        if !(start.is_finite() && stop.is_finite() && step.is_finite()) {
            return bad("START, STOP and STEP must be finite");
        }
        if !(step > 0.0) || stop < start {
            return bad("must have STEP > 0 and START <= STOP");
        }
        let count = ((stop - start) / step + 1e-9).floor() + 1.0;
        if count > MAX_LEVELS as f64 {
            return bad(&format!("has more than {MAX_LEVELS} levels"));
        }
        (0..count as usize)
            .map(|k| {
                let x = start + k as f64 * step;
                format!("{x:.11e}").parse().unwrap_or(x)
            })
            .collect()
    } else {
        let mut v = Vec::new();
        for item in text.split(',') {
            match number(item) {
                Some(x) => v.push(x),
                None => return bad("an item is not a number"),
            }
        }
        if v.len() > MAX_LEVELS {
            return bad(&format!("has more than {MAX_LEVELS} levels"));
        }
        v
    };
    if levels.iter().any(|x| !(*x > 0.0 && x.is_finite())) {
        return bad("every level must be a finite intensity > 0");
    }
    if levels.windows(2).any(|w| w[1] <= w[0]) {
        return bad("levels must be strictly ascending");
    }
    Ok(levels)
}

#[cfg(test)]
mod level_tests {
    use super::parse_levels;

    #[test]
    fn a_grid_gives_the_levels_a_suite_would_run() {
        let v = parse_levels("0.05:1.0:0.05").unwrap();
        assert_eq!(v.len(), 20);
        assert_eq!(v[2], 0.15);
        assert_eq!(v[19], 1.0);
        assert_eq!(parse_levels("0.1,0.2g,0.4").unwrap(), vec![0.1, 0.2, 0.4]);
        assert_eq!(parse_levels("0.3:0.3:0.1").unwrap(), vec![0.3]);
    }

    #[test]
    fn bad_levels_are_refused_with_the_value() {
        for bad in [
            "0:1:0.1",
            "0.2,0.1",
            "0.1:1",
            "a:b:c",
            "0.1:1:0",
            "1:0.1:0.1",
            "-0.1,0.2",
            "0.1:1e9:1e-6",
        ] {
            let e = parse_levels(bad).unwrap_err();
            assert!(e.starts_with("--levels ") && e.contains(bad), "{e}");
        }
    }
}
