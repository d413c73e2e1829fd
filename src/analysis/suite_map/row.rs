//! A row's suite map: what a retrofit buys (SPEC §12 with §13, §14). The
//! axes are any two keys `--set` takes (`joint1.gap`, `link1.damping`,
//! `joint1.bumper.thickness`, `frame.damping`, …); each cell is the row
//! with both set, as `pounding suite --buildings ROW --set X=x --set Y=y`
//! runs it, and reports of its N records' runs with contact:
//!
//! ```text
//! P_j(pounding) = (records with an impact at joint j) / N,
//! median over records of max_i |Δ_i|/h_i        per building,
//! median over records of max_i |ü_i + ü_g| (g)  per building,
//! median over records of max_t |F_l| (kN)       per link,
//! ```
//!
//! the medians those of SPEC §12's statistics, of the demands the suite
//! reports ([`BuildingDemands`]), so that a cell is the suite's bit for bit.
//! None of them is of the run with every joint open, which the map does not
//! make: that saves a quarter to a third of a suite's work.

use serde::{Deserialize, Serialize};

use super::{MapAxis, MapSubject};
use crate::analysis::statistics::Summary;
use crate::analysis::subject::row::{
    BuildingDemands, RowSuiteCase, RowSuiteError, ground_of, run_length,
};
use crate::model::suite::SuiteMember;
use crate::solver::buildings::{MapCache, RowOptions, run_row_cached};

/// What a row's axis key may be, for the messages.
pub const ROW_KEYS: &str = "any key --set takes: NAME.KEY (frame.damping), jointN.KEY \
     (joint1.gap), jointN.bumper.KEY (joint1.bumper.thickness), linkN.KEY (link1.damping) \
     or the row's own KEY (restitution)";

/// Parses a row's axis `KEY=START:STOP:STEP` given to `flag`. Whether the
/// key exists, is a number and takes the axis's values is the row's own
/// check, made on each cell's row ([`set_text`]).
pub fn row_axis(flag: &str, text: &str) -> Result<MapAxis, String> {
    MapAxis::parse(flag, text, ROW_KEYS, |k| {
        if k.is_empty() || k.contains(char::is_whitespace) {
            Err("no key".into())
        } else {
            Ok(())
        }
    })
}

/// `KEY=V` as `--set` takes it, V written so that the preset's TOML reads
/// back exactly `value`: a whole number as an integer (so that integer keys
/// such as `link1.floor` take it), else the shortest exponent form.
pub fn set_text(key: &str, value: f64) -> String {
    if value.fract() == 0.0 && value.abs() < 9.0e15 {
        format!("{key}={}", value as i64)
    } else {
        format!("{key}={value:e}")
    }
}

/// What a cell reads of one record's run with contact.
#[derive(Debug, Clone, PartialEq)]
pub struct RowSample {
    /// Per joint: impacts over its floor pairs.
    pub impacts: Vec<usize>,
    /// Per building: max_i |Δ_i|/h_i and max_i |ü_i + ü_g| (g), ∞ for a
    /// building that collapsed (SPEC §15).
    pub drift_ratio: Vec<f64>,
    pub acceleration_g: Vec<f64>,
    /// Per link: max |F| (kN).
    pub link_forces_kn: Vec<f64>,
}

/// One cell of a row's suite map: per joint, building and link, in the
/// row's order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RowMapCell {
    pub x: f64,
    pub y: f64,
    /// Per joint: the share of records with at least one impact there.
    pub pounding_probability: Vec<f64>,
    /// Per building: the median peak storey drift ratio max_i |Δ_i|/h_i.
    pub median_drift_ratio: Vec<f64>,
    /// Per building: the median peak floor acceleration (g).
    pub median_acceleration_g: Vec<f64>,
    /// Per link: the median peak |F| (kN).
    pub median_link_force_kn: Vec<f64>,
    pub records: usize,
}

impl RowMapCell {
    /// The cell at (x, y) from each record's sample, in suite order.
    pub fn of(x: f64, y: f64, samples: &[RowSample]) -> RowMapCell {
        let n = samples.len();
        let first = samples.first();
        let count = |f: fn(&RowSample) -> usize| first.map_or(0, f);
        let median = |get: &dyn Fn(&RowSample) -> f64| {
            Summary::of(&samples.iter().map(get).collect::<Vec<_>>()).median
        };
        let buildings = count(|s| s.drift_ratio.len());
        RowMapCell {
            x,
            y,
            pounding_probability: (0..count(|s| s.impacts.len()))
                .map(|j| {
                    samples.iter().filter(|s| s.impacts[j] > 0).count() as f64 / n.max(1) as f64
                })
                .collect(),
            median_drift_ratio: (0..buildings)
                .map(|b| median(&|s| s.drift_ratio[b]))
                .collect(),
            median_acceleration_g: (0..buildings)
                .map(|b| median(&|s| s.acceleration_g[b]))
                .collect(),
            median_link_force_kn: (0..count(|s| s.link_forces_kn.len()))
                .map(|l| median(&|s| s.link_forces_kn[l]))
                .collect(),
            records: n,
        }
    }
}

impl MapSubject for RowSuiteCase {
    type Sample = RowSample;
    type MapCaches = MapCache;
    type Cell = RowMapCell;

    /// The record's run with contact, as the suite makes it: the same
    /// ground, length and options.
    fn sample(
        &self,
        member: &SuiteMember,
        &(scale, _): &(f64, f64),
        cache: &mut MapCache,
    ) -> Result<RowSample, RowSuiteError> {
        let row = &self.row;
        let ground = ground_of(member, scale);
        let options = RowOptions::lasting(run_length(row, &ground));
        let run =
            run_row_cached(row, &ground, &options, cache).map_err(|error| RowSuiteError::Run {
                record: member.name.clone(),
                error,
            })?;
        let buildings = BuildingDemands::of(row, &run);
        let pairs = row.pairs();
        Ok(RowSample {
            impacts: (0..row.joints.len())
                .map(|j| {
                    let at_joint = pairs.iter().zip(&run.pairs).filter(|(p, _)| p.joint == j);
                    at_joint.map(|(_, r)| r.impacts.len()).sum()
                })
                .collect(),
            drift_ratio: buildings.iter().map(|b| b.max_drift_ratio).collect(),
            acceleration_g: buildings
                .iter()
                .map(|b| b.max_absolute_acceleration_g)
                .collect(),
            link_forces_kn: run.links.iter().map(|l| l.max_force / 1e3).collect(),
        })
    }

    fn cell(&self, x: f64, y: f64, samples: &[RowSample]) -> RowMapCell {
        RowMapCell::of(x, y, samples)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(drift: f64, impacts: usize, link: f64) -> RowSample {
        RowSample {
            impacts: vec![impacts],
            drift_ratio: vec![drift, 2.0 * drift],
            acceleration_g: vec![10.0 * drift, 1.0],
            link_forces_kn: vec![link],
        }
    }

    #[test]
    fn a_cell_counts_and_takes_medians() {
        let d = [
            sample(0.010, 3, 10.0),
            sample(0.005, 0, 30.0),
            sample(0.020, 1, 20.0),
            sample(0.015, 0, 40.0),
        ];
        let c = RowMapCell::of(1.0, 2.0, &d);
        assert_eq!(c.pounding_probability, vec![0.5]);
        // The median of four is halfway between the middle two.
        assert!((c.median_drift_ratio[0] - 0.0125).abs() < 1e-17);
        assert!((c.median_drift_ratio[1] - 0.025).abs() < 1e-17);
        assert_eq!(c.median_acceleration_g[1], 1.0);
        assert_eq!(c.median_link_force_kn, vec![25.0]);
        assert_eq!(c.records, 4);
        // A collapsed building's ∞ counts as the largest value.
        let mut e = d.to_vec();
        e[0].drift_ratio[0] = f64::INFINITY;
        e.push(sample(0.001, 0, 0.0));
        assert_eq!(RowMapCell::of(1.0, 2.0, &e).median_drift_ratio[0], 0.015);
    }

    #[test]
    fn values_are_written_back_exactly() {
        for v in [0.004, 4.0e6, 1.0 / 3.0, 2.0e-300, 0.0, -2.5, 3.0] {
            let text = set_text("k", v);
            let toml: toml::Table = format!("k = {}", &text["k=".len()..]).parse().unwrap();
            let back = crate::model::buildings::keys::as_f64(&toml["k"]);
            assert_eq!(back, Some(v), "{text}");
        }
        assert_eq!(set_text("link1.floor", 3.0), "link1.floor=3");
        assert!(row_axis("--x", "link1.damping=1e6:4e6:1e6").is_ok());
        assert!(row_axis("--x", "=1:2:1").unwrap_err().contains("no key"));
    }
}
