//! The gap that prevents pounding, and the rules building codes use for it
//! (SPEC §11).
//!
//! Contact begins when δ = x1 − x2 − Π_d turns positive (SPEC §4). In a run
//! without contact (Π_d = ∞) the two structures move independently, and the
//! smallest gap for which they never touch is
//!
//! ```text
//! Π_d,min = max(0, max over τ of (x1(τ) − x2(τ)))
//! ```
//!
//! exact for the run's excitation and duration. The exact method tracks the
//! maximum on its own series ([`RunResult::max_relative_displacement`]), so
//! Π_d,min costs one no-pounding run.
//!
//! Codes instead combine the two separate peaks Π_u1, Π_u2 of that run:
//! - absolute sum (ABS): Π_u1 + Π_u2, never below Π_d,min (x1 − x2 ≤ |x1| + |x2|);
//! - square root of the sum of squares (SRSS): √(Π_u1² + Π_u2²);
//! - double difference (DDC): √(Π_u1² + Π_u2² − 2ρ Π_u1 Π_u2), with the
//!   equal-damping correlation coefficient ρ of [`correlation`].
//!
//! **A row's joints** (SPEC §13 with §11): per joint, the largest
//! u_A,i − u_B,j over the paired floors and over time in the run without
//! contact ([`joint_gaps`]), beside the code rules applied to each paired
//! floor's separate peaks (DDC with the two buildings' first-mode
//! frequencies and their mean ξ, [`joint_modes`]), the largest over the
//! joint's floors. The pair is the row of two one-storey buildings, its one
//! joint its roofs.

use std::fmt::Write as _;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::model::buildings::matrices::circular_frequencies;
use crate::model::buildings::{FloorPair, Ground, Row};
use crate::model::{Method, Params};
use crate::solver::buildings::{RowError, RowOptions, RowRun, run_row};
use crate::solver::exact::ContactExtremes;
use crate::solver::{RunResult, StructurePeaks, run_for_sweep, solve};

/// The correlation coefficient of the double-difference rule for two
/// oscillators with the same damping ratio ξ (SPEC §11):
///
/// ```text
/// ρ = 8ξ²(1 + r) r^{3/2} / ((1 − r²)² + 4ξ² r (1 + r)²),   r = ω_low/ω_high ≤ 1.
/// ```
///
/// ρ = 1 for equal frequencies (both structures move in phase) and falls
/// towards 0 as they part; ρ = 0 without damping unless r = 1.
pub fn correlation(omega1: f64, omega2: f64, damping: f64) -> f64 {
    let (low, high) = if omega1 <= omega2 {
        (omega1, omega2)
    } else {
        (omega2, omega1)
    };
    if low == high {
        return 1.0;
    }
    let r = low / high;
    let xi2 = damping * damping;
    8.0 * xi2 * (1.0 + r) * r.powf(1.5)
        / ((1.0 - r * r).powi(2) + 4.0 * xi2 * r * (1.0 + r).powi(2))
}

/// The three code estimates of the gap from the separate peaks (SPEC §11).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CodeRules {
    /// ABS: Π_u1 + Π_u2.
    pub absolute_sum: f64,
    /// SRSS: √(Π_u1² + Π_u2²).
    pub srss: f64,
    /// DDC: √(Π_u1² + Π_u2² − 2ρ Π_u1 Π_u2).
    pub double_difference: f64,
    /// ρ of the double-difference rule ([`correlation`]).
    pub correlation: f64,
}

impl CodeRules {
    /// The rules for peaks `u1`, `u2` of structures with frequencies
    /// Π_ω1, Π_ω2 and damping ratio Π_ξ.
    pub fn of(u1: f64, u2: f64, omega1: f64, omega2: f64, damping: f64) -> CodeRules {
        CodeRules::with_correlation(u1, u2, correlation(omega1, omega2, damping))
    }

    /// The rules for peaks `u1`, `u2` with the double-difference rule's ρ
    /// given (a suite's median peaks take the records' ρ).
    pub fn with_correlation(u1: f64, u2: f64, rho: f64) -> CodeRules {
        CodeRules {
            absolute_sum: u1 + u2,
            srss: u1.hypot(u2),
            // ρ ≤ 1 keeps the radicand ≥ (u1 − u2)² ≥ 0 but for round-off.
            double_difference: (u1 * u1 + u2 * u2 - 2.0 * rho * u1 * u2).max(0.0).sqrt(),
            correlation: rho,
        }
    }

    /// The rules in report order, with their short names.
    pub fn named(&self) -> [(&'static str, f64); 3] {
        [
            ("ABS", self.absolute_sum),
            ("SRSS", self.srss),
            ("DDC", self.double_difference),
        ]
    }
}

/// Π_d,min from the largest x1 − x2 of a run without contact.
pub fn from_max_relative(max_relative_displacement: f64) -> f64 {
    max_relative_displacement.max(0.0)
}

/// The exact minimum gap of one parameter set beside the code rules.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MinimumGap {
    pub omega1: f64,
    pub omega2: f64,
    /// Peaks of the no-pounding run.
    pub free_left: StructurePeaks,
    pub free_right: StructurePeaks,
    /// Π_d,min = max(0, max over τ of x1 − x2).
    pub exact: f64,
    pub rules: CodeRules,
    /// False when the no-pounding run stopped before τ_end: `exact` then
    /// covers only the part that was run.
    pub completed: bool,
}

impl MinimumGap {
    /// From the no-pounding run `r` of `p`; `None` if the run did not track
    /// x1 − x2 (a Newmark run).
    pub fn from_free_run(p: &Params, r: &RunResult) -> Option<MinimumGap> {
        let top = r.max_relative_displacement?;
        let (u1, u2) = (r.left.peak_displacement, r.right.peak_displacement);
        Some(MinimumGap {
            omega1: p.omega1,
            omega2: p.omega2,
            free_left: r.left,
            free_right: r.right,
            exact: from_max_relative(top),
            rules: CodeRules::of(u1, u2, p.omega1, p.omega2, p.damping),
            completed: r.completed,
        })
    }

    /// Each rule over the exact minimum gap (above 1: conservative; below 1:
    /// the structures would pound); `None` where Π_d,min = 0.
    pub fn ratios(&self) -> [Option<f64>; 3] {
        self.rules
            .named()
            .map(|(_, v)| (self.exact > 0.0).then(|| v / self.exact))
    }
}

/// The no-pounding twin of `p`, run by the exact method.
pub fn free_params(p: &Params) -> Params {
    Params {
        gap: f64::INFINITY,
        method: Method::Exact,
        ..p.clone()
    }
}

/// The no-pounding twin of `p` run in full by the exact method (energy and
/// every demand of SPEC §6): the run whose largest x1 − x2 is Π_d,min for
/// `run`, `gap`, the explorer and every suite, so that they agree to the bit.
pub fn free_run(p: &Params) -> RunResult {
    solve(&free_params(p), &mut ())
}

/// The minimum gap of `p` (validated): one full exact no-pounding run.
pub fn minimum_gap(p: &Params) -> MinimumGap {
    MinimumGap::from_free_run(&free_params(p), &free_run(p))
        .expect("the exact method tracks x1 − x2")
}

/// The minimum gap of every parameter set of a sweep, in parallel. The
/// sweep's runs skip the energy and the absolute acceleration, as all
/// sweeps do; under a record their quiet samples may then take other
/// paths than a full run's, and Π_d,min differ from [`minimum_gap`]'s in
/// the last bits.
pub fn minimum_gaps(points: &[Params]) -> Vec<MinimumGap> {
    points
        .par_iter()
        .map(|p| {
            let q = free_params(p);
            MinimumGap::from_free_run(&q, &run_for_sweep(&q, ContactExtremes::None))
                .expect("the exact method tracks x1 − x2")
        })
        .collect()
}

/// One joint of a row: its gap that prevents pounding and the code rules
/// (m), the largest over its paired floors.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointGap {
    pub left: String,
    pub right: String,
    /// Paired floors (left, right), 1-based.
    pub floors: Vec<(usize, usize)>,
    /// m: the smallest gap for which the joint never closes.
    pub min_gap: f64,
    pub abs: f64,
    pub srss: f64,
    pub ddc: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct RowGapReport {
    pub row: String,
    pub excitation: String,
    pub duration: f64,
    pub joints: Vec<JointGap>,
}

/// Runs `row` without contact and measures every joint.
pub fn row_gap(
    row: &Row,
    ground: &Ground,
    duration: f64,
    excitation: &str,
) -> Result<RowGapReport, RowError> {
    let run = run_row(&row.apart(), ground, &RowOptions::lasting(duration))?;
    Ok(RowGapReport {
        row: row.name.clone(),
        excitation: excitation.to_string(),
        duration,
        joints: joint_gaps(row, &run),
    })
}

/// Every joint's gap that prevents pounding and code rules from `free`, a
/// run of `row` in which no floors touched (its run without contact, or a
/// run with contact that had no impact: the same motion). Per joint,
///
/// ```text
/// d_min = max(0, max over paired floors (i, j) and over t of u_A,i(t) − u_B,j(t))   (SPEC §13, §11)
/// ```
///
/// and each code rule the largest over the paired floors of the rule on
/// their separate peaks.
pub fn joint_gaps(row: &Row, free: &RowRun) -> Vec<JointGap> {
    let facing = row.facing_floors();
    (0..row.joints.len())
        .map(|j| {
            let (a, b) = (&row.buildings[j], &row.buildings[j + 1]);
            let (wa, wb, xi) = joint_modes(row, j);
            let mut out = JointGap {
                left: a.name.clone(),
                right: b.name.clone(),
                floors: Vec::new(),
                min_gap: 0.0,
                abs: 0.0,
                srss: 0.0,
                ddc: 0.0,
            };
            for (k, p) in facing.iter().enumerate().filter(|(_, p)| p.joint == j) {
                out.floors.push((p.left_floor, p.right_floor));
                out.min_gap = out.min_gap.max(free.max_relative[k]);
                let (ua, ub) = floor_peaks(free, p);
                let rules = CodeRules::of(ua, ub, wa, wb, xi);
                out.abs = out.abs.max(rules.absolute_sum);
                out.srss = out.srss.max(rules.srss);
                out.ddc = out.ddc.max(rules.double_difference);
            }
            out
        })
        .collect()
}

/// What the double-difference rule takes at joint `j` (SPEC §11): the
/// first-mode circular frequencies (rad/s) of its left and right buildings
/// and their mean damping ratio ξ.
pub fn joint_modes(row: &Row, j: usize) -> (f64, f64, f64) {
    let (a, b) = (&row.buildings[j], &row.buildings[j + 1]);
    (
        circular_frequencies(a)[0],
        circular_frequencies(b)[0],
        0.5 * (a.damping + b.damping),
    )
}

/// The peaks max|u_A,i| and max|u_B,j| (m) of a paired floor's two floors in `run`.
pub fn floor_peaks(run: &RowRun, pair: &FloorPair) -> (f64, f64) {
    (
        run.floors[pair.left][pair.left_floor - 1].displacement,
        run.floors[pair.right][pair.right_floor - 1].displacement,
    )
}

impl crate::output::report::Report for RowGapReport {
    fn table(&self) -> String {
        let mut s = format!(
            "{}: {} excitation, {:.3} s, run without contact (SPEC §13, §11)\njoint                    floors   min gap mm    ABS mm   SRSS mm    DDC mm\n",
            self.row, self.excitation, self.duration
        );
        for (i, j) in self.joints.iter().enumerate() {
            let name = format!("joint{} {}–{}", i + 1, j.left, j.right);
            let _ = writeln!(
                s,
                "{name:24} {:6} {:12.2} {:9.2} {:9.2} {:9.2}",
                j.floors.len(),
                j.min_gap * 1e3,
                j.abs * 1e3,
                j.srss * 1e3,
                j.ddc * 1e3
            );
        }
        s
    }

    fn csv_header(&self) -> Vec<&'static str> {
        vec![
            "joint", "left", "right", "floors", "min_gap", "abs", "srss", "ddc",
        ]
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        use crate::output::Num;
        self.joints
            .iter()
            .enumerate()
            .map(|(i, j)| {
                vec![
                    format!("joint{}", i + 1),
                    j.left.clone(),
                    j.right.clone(),
                    j.floors.len().to_string(),
                    Num(j.min_gap).to_string(),
                    Num(j.abs).to_string(),
                    Num(j.srss).to_string(),
                    Num(j.ddc).to_string(),
                ]
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn correlation_limits() {
        assert_eq!(correlation(1.0, 1.0, 0.05), 1.0);
        assert_eq!(correlation(1.0, 2.0, 0.05), correlation(2.0, 1.0, 0.05));
        assert_eq!(correlation(1.0, 2.0, 0.0), 0.0);
        // Far apart: ρ → 0.
        assert!(correlation(0.01, 100.0, 0.05) < 1e-5);
    }

    #[test]
    fn rules_order() {
        let r = CodeRules::of(2.0, 1.0, 1.0, 2.0, 0.05);
        assert_eq!(r.absolute_sum, 3.0);
        assert!((r.srss - 5f64.sqrt()).abs() < 1e-15);
        assert!(r.double_difference < r.srss && r.double_difference >= 1.0);
    }
}
