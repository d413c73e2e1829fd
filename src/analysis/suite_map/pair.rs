//! The physical pair's suite map: two quantities of its `[physical]`
//! table (periods, masses, yield drifts, the joint's gap, …), and per cell
//!
//! ```text
//! P(pounding)   = (records with at least one impact) / N,
//! amplification = median over records of u1 / u1,free,
//! ```
//!
//! the left building's peak drift with pounding over its peak drift
//! without (above 1: pounding amplifies it, SPEC §7's question over a
//! suite), and the median Π_d,min in m (SPEC §11).

use serde::{Deserialize, Serialize};

use super::{MapAxis, MapSubject};
use crate::analysis::statistics::quantile;
use crate::analysis::subject::runs::run_one;
use crate::analysis::suite::{MemberPlan, SuiteCase, SuiteRun, SuiteRunError};
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

/// The pair's axes: a key of [`KEYS`] over values > 0 (damping and alpha
/// may start at 0).
pub struct PhysicalAxis;

impl PhysicalAxis {
    /// Parses `KEY=START:STOP:STEP` given to `flag`, one line naming the
    /// flag, the value and what is allowed otherwise.
    pub fn parse(flag: &str, text: &str) -> Result<MapAxis, String> {
        let hint = format!("one of {}", KEYS.join(", "));
        let axis = MapAxis::parse(flag, text, &hint, |k| {
            if KEYS.contains(&k) {
                Ok(())
            } else {
                Err("unknown key".into())
            }
        })?;
        let zero_allowed = matches!(axis.key.as_str(), "damping" | "alpha");
        let start = axis.values[0];
        if start < 0.0 || (start == 0.0 && !zero_allowed) {
            return Err(format!(
                "{flag} `{}`: values must be > 0; write KEY=START:STOP:STEP with KEY {hint}",
                crate::model::params::echo::text(text)
            ));
        }
        Ok(axis)
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
pub fn cell_cases(case: &SuiteCase, x: &MapAxis, y: &MapAxis) -> Vec<(f64, f64, SuiteCase)> {
    let cells = super::cells_of(x, y, |xv, yv| {
        Ok::<_, std::convert::Infallible>(SuiteCase {
            physical: set(&set(&case.physical, &x.key, xv), &y.key, yv),
            ..case.clone()
        })
    });
    match cells {
        Ok(cells) => cells,
        Err(never) => match never {},
    }
}

/// One cell of the pair's suite map.
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
    /// The cell at (x, y) from its runs, one per record. The amplification
    /// is the ratio of the Π peaks, which is that of the SI peaks (both
    /// runs of a record share its length scale).
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

impl MapSubject for SuiteCase {
    type Sample = SuiteRun;
    type MapCaches = ();
    type Cell = SuiteMapCell;

    fn sample(
        &self,
        member: &SuiteMember,
        plan: &MemberPlan,
        caches: &mut (),
    ) -> Result<SuiteRun, SuiteRunError> {
        run_one(self, member, plan, caches)
    }

    fn cell(&self, x: f64, y: f64, runs: &[SuiteRun]) -> SuiteMapCell {
        SuiteMapCell::of(x, y, runs)
    }
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
