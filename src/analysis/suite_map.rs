//! Suite maps: the risk of pounding over two physical quantities of the
//! buildings (SPEC §12). Each cell of the plane (x, y) is the preset's pair
//! of buildings with two quantities of its `[physical]` table set (periods,
//! masses, yield drifts, the joint's gap, …), run under every record of a
//! suite scaled as the suite asks, with contact and without. A cell reports
//!
//! ```text
//! P(pounding)  = (records with at least one impact) / N,
//! amplification = median over records of u1 / u1,free,
//! ```
//!
//! the left building's peak drift with pounding over its peak drift
//! without (above 1: pounding amplifies it, SPEC §7's question over a
//! suite), and the median Π_d,min in m. Axes are physical because a suite
//! is: every record sets its own Π-groups for the same buildings.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::statistics::quantile;
use super::subject::Subject;
use super::suite::{MemberPlan, SuiteCase, SuiteRun, SuiteRunError, run_member, scales};
use crate::model::params::echo;
use crate::model::physical::Physical;
use crate::model::suite::SuiteMember;

/// The quantities of a `[physical]` table an axis may set, in SI: masses
/// (kg), periods (s), yield drifts and the gap (m), damping ratio, post-yield
/// ratio, contact frequency (rad/s), restitution.
pub const KEYS: [&str; 11] = [
    "m1",
    "m2",
    "period1",
    "period2",
    "yield1",
    "yield2",
    "gap",
    "damping",
    "alpha",
    "contact_omega",
    "restitution",
];

/// Most points on one axis, and most cells × records of one map.
pub const MAX_AXIS_POINTS: usize = 1000;
pub const MAX_RUNS: usize = 10_000_000;

/// One axis: a physical key over an even grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PhysicalAxis {
    pub key: &'static str,
    pub values: Vec<f64>,
}

impl PhysicalAxis {
    /// Parses `KEY=START:STOP:STEP` given to `flag`; the values must be
    /// finite and > 0 (damping and alpha may start at 0), one line naming
    /// the flag, the value and what is allowed otherwise.
    pub fn parse(flag: &str, text: &str) -> Result<PhysicalAxis, String> {
        let bad = |why: &str| {
            format!(
                "{flag} `{}`: {why}; write KEY=START:STOP:STEP with KEY one of {}",
                echo::text(text),
                KEYS.join(", ")
            )
        };
        let (key, grid) = text.split_once('=').ok_or_else(|| bad("no `=`"))?;
        let key = KEYS
            .iter()
            .copied()
            .find(|k| *k == key.trim())
            .ok_or_else(|| bad("unknown key"))?;
        let parts: Vec<Option<f64>> = grid.split(':').map(|t| t.trim().parse().ok()).collect();
        let [Some(start), Some(stop), Some(step)] = parts[..] else {
            return Err(bad("expected three numbers"));
        };
        if !(start.is_finite() && stop.is_finite() && step.is_finite())
            || step <= 0.0
            || stop < start
        {
            return Err(bad("needs finite START <= STOP and STEP > 0"));
        }
        let zero_allowed = matches!(key, "damping" | "alpha");
        if start < 0.0 || (start == 0.0 && !zero_allowed) {
            return Err(bad("values must be > 0"));
        }
        let count = ((stop - start) / step + 1e-9).floor() + 1.0;
        if count > MAX_AXIS_POINTS as f64 {
            return Err(bad(&format!("more than {MAX_AXIS_POINTS} points")));
        }
        let values = (0..count as usize)
            .map(|k| {
                let v = start + k as f64 * step;
                format!("{v:.11e}").parse().unwrap_or(v)
            })
            .collect();
        Ok(PhysicalAxis { key, values })
    }
}

/// `physical` with `key` (one of [`KEYS`]) set to `value`.
pub fn set(physical: &Physical, key: &str, value: f64) -> Physical {
    let mut p = *physical;
    match key {
        "m1" => p.mass[0] = value,
        "m2" => p.mass[1] = value,
        "period1" => p.omega[0] = std::f64::consts::TAU / value,
        "period2" => p.omega[1] = std::f64::consts::TAU / value,
        "yield1" => p.yield_displacement[0] = value,
        "yield2" => p.yield_displacement[1] = value,
        "gap" => p.gap = value,
        "damping" => p.damping = value,
        "alpha" => p.alpha = value,
        "contact_omega" => p.contact_omega = value,
        "restitution" => p.restitution = value,
        _ => {}
    }
    p
}

/// The study of each cell: the case with both quantities set.
pub fn cell_cases(
    case: &SuiteCase,
    x: &PhysicalAxis,
    y: &PhysicalAxis,
) -> Vec<(f64, f64, SuiteCase)> {
    let mut cells = Vec::with_capacity(x.values.len() * y.values.len());
    for &yv in &y.values {
        for &xv in &x.values {
            let physical = set(&set(&case.physical, x.key, xv), y.key, yv);
            cells.push((
                xv,
                yv,
                SuiteCase {
                    physical,
                    ..case.clone()
                },
            ));
        }
    }
    cells
}

/// One cell of a suite map.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SuiteMapCell {
    pub x: f64,
    pub y: f64,
    /// The share of records whose run had at least one impact.
    pub pounding_probability: f64,
    /// The median over records of the left building's peak drift with
    /// pounding over its peak drift without.
    pub median_amplification: f64,
    /// The median Π_d,min (m) of SPEC §11.
    pub median_min_gap_m: f64,
    pub records: usize,
}

impl SuiteMapCell {
    /// The cell at (x, y) from its runs, one per record.
    pub fn of(x: f64, y: f64, runs: &[SuiteRun]) -> SuiteMapCell {
        let sorted = |mut v: Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v
        };
        let ratios = sorted(
            runs.iter()
                .map(|r| r.result.left.peak_displacement / r.free.left.peak_displacement)
                .filter(|v| !v.is_nan())
                .collect(),
        );
        let gaps = sorted(runs.iter().map(SuiteRun::min_gap_m).collect());
        SuiteMapCell {
            x,
            y,
            pounding_probability: runs.iter().filter(|r| r.pounded()).count() as f64
                / runs.len().max(1) as f64,
            median_amplification: quantile(&ratios, 0.5),
            median_min_gap_m: quantile(&gaps, 0.5),
            records: runs.len(),
        }
    }
}

/// Plans every record in every cell before any run, so that a building
/// out of range (a Δτ too coarse for a short period, …) fails at once and
/// names the record and cell.
pub fn plan_cells(
    cells: &[(f64, f64, SuiteCase)],
    members: &[SuiteMember],
) -> Result<Vec<Vec<MemberPlan>>, (f64, f64, SuiteRunError)> {
    let Some((x0, y0, first)) = cells.first() else {
        return Ok(Vec::new());
    };
    // The scaling depends on the records alone: measured once for all cells.
    let scales = scales(members, &first.scaling).map_err(|e| (*x0, *y0, e))?;
    cells
        .iter()
        .map(|(x, y, case)| {
            members
                .iter()
                .zip(&scales)
                .map(|(m, &(scale, intensity))| case.plan_at(m, scale, intensity))
                .collect::<Result<_, _>>()
                .map_err(|e| (*x, *y, e))
        })
        .collect()
}

/// Computes the cells `range` of a planned map (every record of each cell,
/// in parallel over (cell, record) pairs), in order; `done` is told of each
/// finished run.
pub fn compute_cells(
    cells: &[(f64, f64, SuiteCase)],
    plans: &[Vec<MemberPlan>],
    members: &[SuiteMember],
    range: std::ops::Range<usize>,
    done: &(dyn Fn(&SuiteRun) + Sync),
) -> Vec<SuiteMapCell> {
    compute_listed(cells, plans, members, &range.collect::<Vec<_>>(), done)
}

/// [`compute_cells`] for the cells `list` (indices, any set, such as a
/// shard's), in that order.
pub fn compute_listed(
    cells: &[(f64, f64, SuiteCase)],
    plans: &[Vec<MemberPlan>],
    members: &[SuiteMember],
    list: &[usize],
    done: &(dyn Fn(&SuiteRun) + Sync),
) -> Vec<SuiteMapCell> {
    let pairs: Vec<(usize, usize)> = list
        .iter()
        .flat_map(|&c| (0..members.len()).map(move |j| (c, j)))
        .collect();
    let runs: Vec<SuiteRun> = pairs
        .par_iter()
        .map(|&(c, j)| {
            let run = run_member(&cells[c].2, &members[j], &plans[c][j]);
            done(&run);
            run
        })
        .collect();
    list.iter()
        .zip(runs.chunks(members.len().max(1)))
        .map(|(&c, at)| SuiteMapCell::of(cells[c].0, cells[c].1, at))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_parse_with_their_values() {
        let a = PhysicalAxis::parse("--x", "period1=0.5:1.0:0.1").unwrap();
        assert_eq!(a.key, "period1");
        assert_eq!(a.values, vec![0.5, 0.6, 0.7, 0.8, 0.9, 1.0]);
        let g = PhysicalAxis::parse("--y", "gap=0.01:0.05:0.01").unwrap();
        assert_eq!(g.values[2], 0.03);
        for bad in [
            "period1",
            "height=1:2:1",
            "gap=0:0.1:0.01",
            "gap=0.1:0.01:0.01",
            "gap=a:b:c",
        ] {
            let e = PhysicalAxis::parse("--x", bad).unwrap_err();
            assert!(e.starts_with("--x `"), "{e}");
        }
        assert!(PhysicalAxis::parse("--x", "damping=0:0.1:0.05").is_ok());
    }

    #[test]
    fn a_period_sets_the_frequency() {
        let p = crate::model::physical::Physical::from_params(
            &crate::model::SET1,
            4.9,
            std::f64::consts::TAU,
            1.0e6,
        );
        let q = set(&p, "period2", 0.5);
        assert!((q.omega[1] - 4.0 * std::f64::consts::PI).abs() < 1e-12);
        assert_eq!(q.omega[0], p.omega[0]);
        assert_eq!(set(&p, "gap", 0.03).gap, 0.03);
    }
}
