//! The gap that prevents pounding, per joint of a row (SPEC §13 with §11):
//! the largest u_A,i − u_B,j over the paired floors and over time in the
//! run without contact, beside the code rules ABS, SRSS and DDC applied to
//! each paired floor's separate peaks (DDC with the two buildings'
//! first-mode frequencies and their mean ξ), the largest over the joint's
//! floors.

use std::fmt::Write as _;

use serde::Serialize;

use crate::analysis::gap::CodeRules;
use crate::model::buildings::matrices::circular_frequencies;
use crate::model::buildings::{FloorPair, Ground, Row};
use crate::output::report::Report;
use crate::solver::buildings::{RowError, RowOptions, RowRun, run_row};

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

impl Report for RowGapReport {
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
