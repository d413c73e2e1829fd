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
use crate::model::buildings::{Ground, Row};
use crate::output::report::Report;
use crate::solver::buildings::{RowError, RowOptions, run_row};

#[derive(Debug, Clone, Serialize)]
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
    let mut free = row.clone();
    for j in &mut free.joints {
        j.gap = f64::INFINITY;
    }
    let run = run_row(&free, ground, &RowOptions::lasting(duration))?;
    let facing = free.facing_floors();
    let joints = (0..row.joints.len())
        .map(|j| {
            let (a, b) = (&row.buildings[j], &row.buildings[j + 1]);
            let (wa, wb) = (circular_frequencies(a)[0], circular_frequencies(b)[0]);
            let xi = 0.5 * (a.damping + b.damping);
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
                out.min_gap = out.min_gap.max(run.max_relative[k]);
                let ua = run.floors[j][p.left_floor - 1].displacement;
                let ub = run.floors[j + 1][p.right_floor - 1].displacement;
                let rules = CodeRules::of(ua, ub, wa, wb, xi);
                out.abs = out.abs.max(rules.absolute_sum);
                out.srss = out.srss.max(rules.srss);
                out.ddc = out.ddc.max(rules.double_difference);
            }
            out
        })
        .collect();
    Ok(RowGapReport {
        row: row.name.clone(),
        excitation: excitation.to_string(),
        duration,
        joints,
    })
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
