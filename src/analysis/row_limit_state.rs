//! Limit states of a row of buildings for fragility (SPEC §12 with §13):
//! what one record's run must do to count as exceeding, read from each
//! building's demands ([`BuildingDemands`]).
//!
//! - pounding: at least one impact at a joint of the building;
//! - a storey drift ratio max_i |Δ_i|/h_i above a value (FEMA 356's
//!   performance levels for frames are 0.005, 0.01 and 0.02: immediate
//!   occupancy, life safety, collapse prevention);
//! - a floor absolute acceleration max_i |ü_i + ü_g| above a value (g);
//! - an impact force above a value (kN), the largest on the building;
//! - collapse (SPEC §15), for a building with P-Δ: a building that collapsed
//!   in a record exceeds every limit state of its own there.
//!
//! Each applies to one named building, or to any building (exceeded when
//! one of them is). Every comparison is strict (`>`) and a NaN demand
//! exceeds nothing, as for the pair ([`super::limit_state`]).
//!
//! # The command-line forms
//!
//! | flag | items | e.g. |
//! |---|---|---|
//! | `--drift` ([`RowLimitParser::drift`]) | `[NAME:]RATIO`, 0 < ratio < 1 | `0.005,0.01,0.02`, `frame:0.01` |
//! | `--acceleration` ([`RowLimitParser::acceleration`]) | `[NAME:]A` | `0.5g,1g`, `block:0.8g`, `4.9` |
//! | `--force` ([`RowLimitParser::force`]) | `[NAME:]KN` | `500`, `frame:250` |
//!
//! NAME is a building of the row or `any`; an item without one applies to
//! the building of `--building NAME` (by default `any`), and so does the
//! pounding limit state. An acceleration is written as for the pair: `0.5g`
//! in g, a bare number in m/s².

use std::fmt;

use serde::Serialize;

use super::ida::{LimitStateFragility, fragility_of};
use super::limit_state::{LimitStateError, acceleration_g, items, positive};
use super::row_suite::{BuildingDemands, RowSuiteRun};
use crate::model::buildings::Row;
use crate::model::params::echo;

/// Which building of the row a limit state reads; written as its name
/// (`"frame"`, `"any"`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// Any building: exceeded when one of them is.
    Any,
    /// The building at `index` (left to right), named `name`.
    Building { index: usize, name: String },
}

impl Target {
    /// `any`, or the building's name.
    pub fn name(&self) -> &str {
        match self {
            Target::Any => "any",
            Target::Building { name, .. } => name,
        }
    }

    /// Whether `exceeds` holds for a building this target reads.
    fn any(&self, demands: &[BuildingDemands], exceeds: impl Fn(&BuildingDemands) -> bool) -> bool {
        match self {
            Target::Any => demands.iter().any(exceeds),
            Target::Building { index, .. } => demands.get(*index).is_some_and(exceeds),
        }
    }
}

impl Serialize for Target {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

/// What a row's run must do to count as exceeding (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum RowLimitState {
    /// At least one impact on the building.
    Pounding { building: Target },
    /// Largest storey drift ratio above `ratio`.
    Drift { building: Target, ratio: f64 },
    /// Largest floor absolute acceleration above `g` (g).
    Acceleration { building: Target, g: f64 },
    /// Largest impact force on the building above `kn` (kN).
    Force { building: Target, kn: f64 },
    /// The building collapsed (SPEC §15).
    Collapse { building: Target },
}

impl RowLimitState {
    fn building(&self) -> &Target {
        match self {
            RowLimitState::Pounding { building }
            | RowLimitState::Collapse { building }
            | RowLimitState::Drift { building, .. }
            | RowLimitState::Acceleration { building, .. }
            | RowLimitState::Force { building, .. } => building,
        }
    }

    /// Whether a run whose buildings' demands are `demands` (left to right)
    /// exceeds this limit state. A building that collapsed exceeds every
    /// limit state of its own (SPEC §15).
    pub fn exceeded(&self, demands: &[BuildingDemands]) -> bool {
        self.building().any(demands, |d| match *self {
            _ if d.collapsed => true,
            RowLimitState::Collapse { .. } => false,
            RowLimitState::Pounding { .. } => d.impacts > 0,
            RowLimitState::Drift { ratio, .. } => d.max_drift_ratio > ratio,
            RowLimitState::Acceleration { g, .. } => d.max_absolute_acceleration_g > g,
            RowLimitState::Force { kn, .. } => d.max_force_kn > kn,
        })
    }

    /// The name in reports: `pounding (any)`, `drift>0.01 (frame)`,
    /// `acceleration>0.5g (any)`, `force>500kN (block)`.
    pub fn label(&self) -> String {
        let what = match *self {
            RowLimitState::Pounding { .. } => "pounding".to_string(),
            RowLimitState::Collapse { .. } => "collapse".to_string(),
            RowLimitState::Drift { ratio, .. } => format!("drift>{}", echo::number(ratio)),
            RowLimitState::Acceleration { g, .. } => format!("acceleration>{}g", echo::number(g)),
            RowLimitState::Force { kn, .. } => format!("force>{}kN", echo::number(kn)),
        };
        format!("{what} ({})", self.building().name())
    }

    /// Whether this is the pounding limit state (which the buildings apart
    /// never reach).
    pub fn is_pounding(&self) -> bool {
        matches!(self, RowLimitState::Pounding { .. })
    }
}

impl fmt::Display for RowLimitState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

/// Reads the limit-state flags of a row: building names are the row's.
#[derive(Debug, Clone)]
pub struct RowLimitParser {
    names: Vec<String>,
    /// The building of `--building` (items without a NAME: prefix).
    pub default: Target,
}

impl RowLimitParser {
    /// A parser for `row`'s buildings, items without a prefix applying to
    /// `building` (`--building`: a name of the row or `any`; `None`: any).
    pub fn new(row: &Row, building: Option<&str>) -> Result<RowLimitParser, LimitStateError> {
        let mut parser = RowLimitParser {
            names: row.buildings.iter().map(|b| b.name.clone()).collect(),
            default: Target::Any,
        };
        if let Some(name) = building {
            parser.default = parser.target(name.trim()).ok_or_else(|| {
                LimitStateError(format!(
                    "--building `{}`: {}",
                    echo::text(name),
                    parser.names_allowed()
                ))
            })?;
        }
        Ok(parser)
    }

    /// The collapse limit state of each building with P-Δ (SPEC §15), left
    /// to right: the others cannot collapse.
    pub fn collapses(&self, row: &Row) -> Vec<RowLimitState> {
        row.buildings
            .iter()
            .enumerate()
            .filter(|(_, b)| b.p_delta.is_some())
            .map(|(index, b)| RowLimitState::Collapse {
                building: Target::Building {
                    index,
                    name: b.name.clone(),
                },
            })
            .collect()
    }

    /// The pounding limit state of `--building`.
    pub fn pounding(&self) -> RowLimitState {
        RowLimitState::Pounding {
            building: self.default.clone(),
        }
    }

    /// `--drift`: `[NAME:]RATIO` items, 0 < ratio < 1.
    pub fn drift(&self, text: &str) -> Result<Vec<RowLimitState>, LimitStateError> {
        self.parse(
            "--drift",
            text,
            "a storey drift ratio in (0, 1), e.g. 0.005,0.01,0.02 or frame:0.01",
            |v| positive(v.parse().ok()).filter(|r| *r < 1.0),
            |building, ratio| RowLimitState::Drift { building, ratio },
        )
    }

    /// `--acceleration`: `[NAME:]A` items, A > 0 as `0.5g` or in m/s²; kept in g.
    pub fn acceleration(&self, text: &str) -> Result<Vec<RowLimitState>, LimitStateError> {
        self.parse(
            "--acceleration",
            text,
            "an acceleration > 0 like 0.5g, or in m/s², e.g. 0.5g,1g or frame:0.8g",
            |v| positive(acceleration_g(v)),
            |building, g| RowLimitState::Acceleration { building, g },
        )
    }

    /// `--force`: `[NAME:]KN` items, a force > 0 in kN.
    pub fn force(&self, text: &str) -> Result<Vec<RowLimitState>, LimitStateError> {
        self.parse(
            "--force",
            text,
            "a force > 0 in kN, e.g. 500 or frame:250",
            |v| positive(v.parse().ok()),
            |building, kn| RowLimitState::Force { building, kn },
        )
    }

    /// The building named `name` (`any`: every building).
    fn target(&self, name: &str) -> Option<Target> {
        if name == "any" {
            return Some(Target::Any);
        }
        self.names
            .iter()
            .position(|n| n == name)
            .map(|index| Target::Building {
                index,
                name: name.to_string(),
            })
    }

    fn names_allowed(&self) -> String {
        format!(
            "must be a building of the row ({}) or any",
            self.names.join(", ")
        )
    }

    fn parse(
        &self,
        flag: &str,
        text: &str,
        allowed: &str,
        value: impl Fn(&str) -> Option<f64>,
        make: impl Fn(Target, f64) -> RowLimitState,
    ) -> Result<Vec<RowLimitState>, LimitStateError> {
        items(flag, text, |item| {
            let (building, number) = match item.rsplit_once(':') {
                Some((name, number)) => (
                    self.target(name.trim()).ok_or_else(|| {
                        format!(
                            "NAME:VALUE with NAME {}",
                            self.names_allowed().replacen("must be ", "", 1)
                        )
                    })?,
                    number.trim(),
                ),
                None => (self.default.clone(), item),
            };
            value(number)
                .map(|v| make(building, v))
                .ok_or_else(|| allowed.to_string())
        })
    }
}

/// The fragility of every limit state over an IDA's runs of a row (`runs[l]`
/// at `levels[l]`), in the order given, with the buildings apart beside
/// each but pounding (which they never reach).
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

#[cfg(test)]
mod tests {
    use super::*;

    fn row() -> Row {
        crate::model::buildings::load("block-and-frame").unwrap()
    }

    fn demands(drift: [f64; 2], impacts: usize) -> Vec<BuildingDemands> {
        ["block", "frame"]
            .iter()
            .zip(drift)
            .map(|(name, d)| BuildingDemands {
                name: name.to_string(),
                max_drift_ratio: d,
                max_absolute_acceleration_g: 10.0 * d,
                max_residual_drift_m: 0.0,
                max_drift_m: 3.0 * d,
                max_ductility: d / 0.01,
                impacts,
                max_force_kn: 100.0 * impacts as f64,
                collapsed: false,
                cut_short: false,
            })
            .collect()
    }

    #[test]
    fn reads_names_and_the_default_building() {
        let p = RowLimitParser::new(&row(), Some("frame")).unwrap();
        let frame = Target::Building {
            index: 1,
            name: "frame".into(),
        };
        let block = Target::Building {
            index: 0,
            name: "block".into(),
        };
        assert_eq!(
            p.drift("0.005, block:0.01 ,any:0.02").unwrap(),
            [
                RowLimitState::Drift {
                    building: frame.clone(),
                    ratio: 0.005
                },
                RowLimitState::Drift {
                    building: block,
                    ratio: 0.01
                },
                RowLimitState::Drift {
                    building: Target::Any,
                    ratio: 0.02
                },
            ]
        );
        assert_eq!(p.pounding().label(), "pounding (frame)");
        assert_eq!(
            p.acceleration("1g").unwrap()[0].label(),
            "acceleration>1g (frame)"
        );
        assert_eq!(
            RowLimitParser::new(&row(), None)
                .unwrap()
                .force("500")
                .unwrap()[0]
                .label(),
            "force>500kN (any)"
        );
    }

    #[test]
    fn refuses_with_the_flag_the_item_and_what_is_allowed() {
        let p = RowLimitParser::new(&row(), None).unwrap();
        let err = |r: Result<Vec<RowLimitState>, LimitStateError>| r.unwrap_err().to_string();
        assert_eq!(
            err(p.drift("0.01,0")),
            "--drift `0`: must be a storey drift ratio in (0, 1), e.g. 0.005,0.01,0.02 or frame:0.01"
        );
        assert_eq!(
            err(p.drift("tower:0.01")),
            "--drift `tower:0.01`: must be NAME:VALUE with NAME a building of the row (block, frame) or any"
        );
        for bad in ["", "1", "-0.01", "nan", "inf", "0.01,", "block:"] {
            assert!(p.drift(bad).is_err(), "{bad:?}");
        }
        assert!(p.acceleration("0g").is_err() && p.force("frame:-5").is_err());
        assert_eq!(
            RowLimitParser::new(&row(), Some("tower"))
                .unwrap_err()
                .to_string(),
            "--building `tower`: must be a building of the row (block, frame) or any"
        );
    }

    #[test]
    fn exceeded_by_the_building_named_or_any() {
        let p = RowLimitParser::new(&row(), None).unwrap();
        let d = demands([0.004, 0.012], 0);
        let drift = |t: &str| p.drift(t).unwrap()[0].exceeded(&d);
        assert!(drift("0.01") && drift("frame:0.01") && !drift("block:0.01"));
        assert!(!drift("0.012"), "strictly above");
        assert!(!p.pounding().exceeded(&d));
        assert!(p.pounding().exceeded(&demands([0.0; 2], 1)));
        assert!(p.force("50").unwrap()[0].exceeded(&demands([0.0; 2], 1)));
        assert!(!p.force("100").unwrap()[0].exceeded(&demands([0.0; 2], 1)));
        let nan = demands([f64::NAN; 2], 0);
        assert!(!p.drift("0.001").unwrap()[0].exceeded(&nan));
    }

    /// A building that collapsed exceeds every limit state of its own, and
    /// none of its neighbour's (SPEC §15).
    #[test]
    fn a_collapsed_building_exceeds_every_limit_state_of_its_own() {
        let mut row = row();
        row.buildings[1].p_delta = Some(crate::model::buildings::PDelta {
            gravity_mass: vec![1.0; 8],
            collapse_drift_ratio: 0.1,
        });
        let p = RowLimitParser::new(&row, None).unwrap();
        let collapses = p.collapses(&row);
        assert_eq!(collapses.len(), 1);
        assert_eq!(collapses[0].label(), "collapse (frame)");
        let mut d = demands([0.001, 0.001], 0);
        d[1].collapsed = true;
        d[0].cut_short = true;
        assert!(collapses[0].exceeded(&d));
        for state in [
            p.drift("frame:0.5").unwrap()[0].clone(),
            p.acceleration("frame:100g").unwrap()[0].clone(),
            p.force("frame:1e9").unwrap()[0].clone(),
            RowLimitParser::new(&row, Some("frame")).unwrap().pounding(),
        ] {
            assert!(state.exceeded(&d), "{state}");
        }
        for state in [
            p.drift("block:0.5").unwrap()[0].clone(),
            RowLimitParser::new(&row, Some("block")).unwrap().pounding(),
        ] {
            assert!(!state.exceeded(&d), "{state}");
        }
        assert!(!collapses[0].exceeded(&demands([0.5, 0.5], 3)));
    }
}
