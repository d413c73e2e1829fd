//! Limit states for fragility (SPEC §12, with §13 and §15): what one
//! record's run must do to count as exceeding, read from its demands in SI
//! ([`Demands`]), the same for the physical pair and for a row.
//!
//! - pounding: at least one impact at a joint of the building;
//! - collapse (SPEC §15), for a building with P-Δ: a building that collapsed
//!   in a record exceeds every limit state of its own there;
//! - a storey drift ratio max_i |Δ_i|/h_i above a value, for a row (FEMA
//!   356's performance levels for frames are 0.005, 0.01 and 0.02:
//!   immediate occupancy, life safety, collapse prevention);
//! - a ductility μ = Π_u/Π_uy (SPEC §6) above a value, for the pair. An
//!   elastic structure (Π_uy = ∞, μ = ∞) has no ductility and never exceeds
//!   one, whatever the value;
//! - a peak floor absolute acceleration max_i |ü_i + ü_g| above a value (g);
//! - an impact force above a value (kN), the largest on the building.
//!
//! Each reads one named building, or any building (exceeded when one of
//! them is). Building i's joints are j = i − 1 and j = i (joint j between
//! buildings j and j + 1). Every comparison is strict (`>`), as the labels
//! say, and a NaN demand exceeds nothing.
//!
//! # The two spellings
//!
//! The pair and the row spell the same limit states differently
//! ([`Spelling`]); each keeps its own this once:
//!
//! | | the pair | a row |
//! |---|---|---|
//! | any building | `either` | `any` |
//! | a building | `left`, `right` | its name |
//! | pounding, force on any | `pounding`, `force>500kN` | `pounding (any)`, `force>500kN (any)` |
//! | a structure's deformation | `--ductility` | `--drift` |
//!
//! The row's spelling is the one kept for the future.
//!
//! # The command-line forms
//!
//! Each parser reads one flag's comma-separated list and gives one limit
//! state per item, or a one-line error naming the flag, the item and what is
//! allowed. Every value is a finite number > 0.
//!
//! | flag | items | e.g. |
//! |---|---|---|
//! | `--ductility` ([`LimitParser::ductility`], the pair) | `[SIDE:]μ` | `2,4`, `left:2,right:4`, `either:3` |
//! | `--drift` ([`LimitParser::drift`], a row) | `[NAME:]RATIO`, ratio < 1 | `0.005,0.01,0.02`, `frame:0.01` |
//! | `--acceleration` ([`LimitParser::acceleration`]) | `[NAME:]A` | `0.5g,1g`, `right:0.3g`, `4.9` |
//! | `--force` ([`LimitParser::force`]) | `[NAME:]KN` (a row), `KN` (the pair) | `500`, `frame:250` |
//!
//! On the pair SIDE is `left`, `right` or `either` (the default); a force
//! has no side, one force acting on both structures. On a row NAME is a
//! building or `any`; an item without one applies to the building of
//! `--building NAME` (by default `any`), and so does the pounding limit
//! state. A ductility below 1 is allowed: it is reached before yielding. An
//! acceleration is written as everywhere on the command line (`--ap`,
//! [`physical::parse_acceleration`]): `0.5g` in g, a bare number in m/s²;
//! it is kept and labelled in g.

use std::fmt;

use serde::Serialize;

use super::subject::demands::{BuildingDemand, Demands, JointDemand};
use crate::model::buildings::Row;
use crate::model::params::echo;
use crate::model::physical::{self, G};

/// How a subject spells its limit states (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spelling {
    /// `left`, `right`, `either`; pounding and force name no side.
    Pair,
    /// The buildings' names and `any`.
    Row,
}

/// Which building a limit state reads; written as its name (`"frame"`,
/// `"any"`, `"either"`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// Any building of a row: exceeded when one of them is.
    Any,
    /// Either structure of the pair: the same, spelled as the pair does.
    Either,
    /// The building at `index` (left to right), named `name`.
    Building { index: usize, name: String },
}

impl Target {
    /// `any`, `either`, or the building's name.
    pub fn name(&self) -> &str {
        match self {
            Target::Any => "any",
            Target::Either => "either",
            Target::Building { name, .. } => name,
        }
    }

    /// Whether `exceeds` holds for a building this target reads.
    fn any(&self, count: usize, exceeds: impl Fn(usize) -> bool) -> bool {
        match self {
            Target::Any | Target::Either => (0..count).any(exceeds),
            Target::Building { index, .. } => *index < count && exceeds(*index),
        }
    }
}

impl Serialize for Target {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

/// What a run must do to count as exceeding (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LimitState {
    /// At least one impact on the building.
    Pounding { building: Target },
    /// Largest storey drift ratio above `ratio` (a row).
    Drift { building: Target, ratio: f64 },
    /// Ductility μ above `value` (the pair).
    Ductility { building: Target, value: f64 },
    /// Largest floor absolute acceleration above `g` (g).
    Acceleration { building: Target, g: f64 },
    /// Largest impact force on the building above `kn` (kN).
    Force { building: Target, kn: f64 },
    /// The building collapsed (SPEC §15).
    Collapse { building: Target },
}

impl LimitState {
    /// The building it reads.
    pub fn building(&self) -> &Target {
        match self {
            LimitState::Pounding { building }
            | LimitState::Collapse { building }
            | LimitState::Drift { building, .. }
            | LimitState::Ductility { building, .. }
            | LimitState::Acceleration { building, .. }
            | LimitState::Force { building, .. } => building,
        }
    }

    /// Whether a run whose buildings' demands are `buildings` and joints'
    /// `joints` (left to right; none for the run with every joint open)
    /// exceeds this limit state. A building that collapsed exceeds every
    /// limit state of its own (SPEC §15); a ductility is exceeded only by a
    /// finite μ.
    pub fn exceeded(&self, buildings: &[BuildingDemand], joints: &[JointDemand]) -> bool {
        // Building i's joints: i − 1 and i.
        let touching = |i: usize| joints.iter().skip(i.saturating_sub(1)).take(1 + i.min(1));
        self.building().any(buildings.len(), |i| {
            let d = &buildings[i];
            match *self {
                _ if d.collapsed => true,
                LimitState::Collapse { .. } => false,
                LimitState::Pounding { .. } => touching(i).map(|j| j.impacts).sum::<usize>() > 0,
                LimitState::Drift { ratio, .. } => d.drift_ratio.is_some_and(|r| r > ratio),
                LimitState::Ductility { value, .. } => {
                    d.ductility.is_finite() && d.ductility > value
                }
                LimitState::Acceleration { g, .. } => d.acceleration_g > g,
                LimitState::Force { kn, .. } => {
                    touching(i).map(|j| j.max_force_kn).fold(0.0, f64::max) > kn
                }
            }
        })
    }

    /// Whether the run `d` exceeds it, with contact.
    pub fn exceeded_by(&self, d: &Demands) -> bool {
        self.exceeded(&d.buildings, &d.joints)
    }

    /// Whether the run `d` exceeds it with every joint open.
    pub fn exceeded_apart(&self, d: &Demands) -> bool {
        self.exceeded(&d.no_pounding, &[])
    }

    /// The name in reports: `pounding (any)`, `drift>0.01 (frame)`,
    /// `acceleration>0.5g (left)`, `ductility>2 (either)`; the pair's
    /// pounding and force, on its one joint, name no side: `pounding`,
    /// `force>500kN`.
    pub fn label(&self) -> String {
        let what = match *self {
            LimitState::Pounding { .. } => "pounding".to_string(),
            LimitState::Collapse { .. } => "collapse".to_string(),
            LimitState::Drift { ratio, .. } => format!("drift>{}", echo::number(ratio)),
            LimitState::Ductility { value, .. } => format!("ductility>{}", echo::number(value)),
            LimitState::Acceleration { g, .. } => format!("acceleration>{}g", echo::number(g)),
            LimitState::Force { kn, .. } => format!("force>{}kN", echo::number(kn)),
        };
        match (self, self.building()) {
            (LimitState::Pounding { .. } | LimitState::Force { .. }, Target::Either) => what,
            (_, building) => format!("{what} ({})", building.name()),
        }
    }

    /// Whether this is the pounding limit state (which the buildings apart
    /// never reach).
    pub fn is_pounding(&self) -> bool {
        matches!(self, LimitState::Pounding { .. })
    }
}

impl fmt::Display for LimitState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

/// A limit-state flag that cannot be read, as one line naming the flag, the
/// item and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct LimitStateError(pub String);

/// Reads the limit-state flags of a subject, in its spelling.
#[derive(Debug, Clone)]
pub struct LimitParser {
    spelling: Spelling,
    names: Vec<String>,
    /// The building of items without a prefix: `--building` on a row,
    /// `either` on the pair.
    pub default: Target,
}

impl LimitParser {
    /// The pair's parser: `left`, `right`, `either`.
    pub fn pair() -> LimitParser {
        LimitParser {
            spelling: Spelling::Pair,
            names: vec!["left".into(), "right".into()],
            default: Target::Either,
        }
    }

    /// A parser for `row`'s buildings, items without a prefix applying to
    /// any of them.
    pub fn row(row: &Row) -> LimitParser {
        LimitParser {
            spelling: Spelling::Row,
            names: row.buildings.iter().map(|b| b.name.clone()).collect(),
            default: Target::Any,
        }
    }

    /// This parser with items without a prefix applying to `building`
    /// (`--building`: a name of the row or `any`; `None`: as it was).
    pub fn with_building(mut self, building: Option<&str>) -> Result<LimitParser, LimitStateError> {
        if let Some(name) = building {
            self.default = self.target(name.trim()).ok_or_else(|| {
                LimitStateError(format!(
                    "--building `{}`: {}",
                    echo::text(name),
                    self.names_allowed()
                ))
            })?;
        }
        Ok(self)
    }

    /// The collapse limit state of each building with P-Δ (SPEC §15), left
    /// to right: the others cannot collapse.
    pub fn collapses(&self, row: &Row) -> Vec<LimitState> {
        row.buildings
            .iter()
            .enumerate()
            .filter(|(_, b)| b.p_delta.is_some())
            .map(|(index, b)| LimitState::Collapse {
                building: Target::Building {
                    index,
                    name: b.name.clone(),
                },
            })
            .collect()
    }

    /// The pounding limit state of the default building.
    pub fn pounding(&self) -> LimitState {
        LimitState::Pounding {
            building: self.default.clone(),
        }
    }

    /// `--ductility`: `[SIDE:]μ` items, μ > 0; the pair's structures only.
    pub fn ductility(&self, text: &str) -> Result<Vec<LimitState>, LimitStateError> {
        if self.spelling == Spelling::Row {
            return Err(LimitStateError(format!(
                "--ductility {}: a row's storeys take --drift (storey drift ratio, e.g. 0.01); drop --ductility",
                echo::text(text)
            )));
        }
        self.parse(
            "--ductility",
            text,
            "a ductility > 0, e.g. 2,4 or left:2,right:4",
            |v| positive(v.parse().ok()),
            |building, value| LimitState::Ductility { building, value },
        )
    }

    /// `--drift`: `[NAME:]RATIO` items, 0 < ratio < 1; a row's storeys only.
    pub fn drift(&self, text: &str) -> Result<Vec<LimitState>, LimitStateError> {
        if self.spelling == Spelling::Pair {
            return Err(LimitStateError(ROW_ONLY.replace("{flag}", "--drift")));
        }
        self.parse(
            "--drift",
            text,
            "a storey drift ratio in (0, 1), e.g. 0.005,0.01,0.02 or frame:0.01",
            |v| positive(v.parse().ok()).filter(|r| *r < 1.0),
            |building, ratio| LimitState::Drift { building, ratio },
        )
    }

    /// `--acceleration`: `[NAME:]A` items, A > 0 as `0.5g` or in m/s²; kept in g.
    pub fn acceleration(&self, text: &str) -> Result<Vec<LimitState>, LimitStateError> {
        let allowed = match self.spelling {
            Spelling::Pair => {
                "an acceleration > 0 like 0.5g, or in m/s², e.g. 0.5g,1g or right:0.3g"
            }
            Spelling::Row => {
                "an acceleration > 0 like 0.5g, or in m/s², e.g. 0.5g,1g or frame:0.8g"
            }
        };
        self.parse(
            "--acceleration",
            text,
            allowed,
            |v| positive(acceleration_g(v)),
            |building, g| LimitState::Acceleration { building, g },
        )
    }

    /// `--force`: `[NAME:]KN` items (the pair's: `KN`, no side), a force > 0 in kN.
    pub fn force(&self, text: &str) -> Result<Vec<LimitState>, LimitStateError> {
        let force = |v: &str| positive(v.parse().ok());
        let make = |building, kn| LimitState::Force { building, kn };
        match self.spelling {
            Spelling::Row => self.parse(
                "--force",
                text,
                "a force > 0 in kN, e.g. 500 or frame:250",
                force,
                make,
            ),
            Spelling::Pair => items("--force", text, |item| {
                force(item)
                    .map(|kn| make(Target::Either, kn))
                    .ok_or("a force > 0 in kN, e.g. 500 or 250,500")
            }),
        }
    }

    /// The building named `name` (`any` or `either`: every building).
    fn target(&self, name: &str) -> Option<Target> {
        match (self.spelling, name) {
            (Spelling::Row, "any") => return Some(Target::Any),
            (Spelling::Pair, "either") => return Some(Target::Either),
            _ => {}
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

    /// Items `[NAME:]VALUE`, the value read by `value` (which checks it).
    fn parse(
        &self,
        flag: &str,
        text: &str,
        allowed: &str,
        value: impl Fn(&str) -> Option<f64>,
        make: impl Fn(Target, f64) -> LimitState,
    ) -> Result<Vec<LimitState>, LimitStateError> {
        items(flag, text, |item| {
            let named = match self.spelling {
                Spelling::Pair => item.split_once(':'),
                Spelling::Row => item.rsplit_once(':'),
            };
            let (building, number) = match named {
                Some((name, number)) => (
                    self.target(name.trim())
                        .ok_or_else(|| match self.spelling {
                            Spelling::Pair => {
                                "left:, right: or either: (or no side), then a value > 0"
                                    .to_string()
                            }
                            Spelling::Row => format!(
                                "NAME:VALUE with NAME {}",
                                self.names_allowed().replacen("must be ", "", 1)
                            ),
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

/// The refusal of a row's limit-state flag on the pair.
pub const ROW_ONLY: &str = "{flag}: applies to a row of buildings; give --buildings PRESET \
                            (a pair's limit states are --ductility, --acceleration, --force)";

/// Each comma-separated item of `text` read by `read`, or the first
/// failure as `FLAG `item`: must be ALLOWED`.
fn items<T, E: fmt::Display>(
    flag: &str,
    text: &str,
    read: impl Fn(&str) -> Result<T, E>,
) -> Result<Vec<T>, LimitStateError> {
    text.split(',')
        .map(|item| {
            read(item.trim()).map_err(|allowed| {
                LimitStateError(format!(
                    "{flag} `{}`: must be {allowed}",
                    echo::text(item.trim())
                ))
            })
        })
        .collect()
}

/// An acceleration in g: `0.5g` as written (0.3g stays 0.3, not 0.3·g/g),
/// a bare number in m/s² as [`physical::parse_acceleration`] reads it, over g.
fn acceleration_g(text: &str) -> Option<f64> {
    match text.strip_suffix(['g', 'G']) {
        Some(number) => number.trim().parse().ok(),
        None => physical::parse_acceleration(text).map(|a| a / G),
    }
}

/// `v` if it is a finite number > 0.
fn positive(v: Option<f64>) -> Option<f64> {
    v.filter(|v| v.is_finite() && *v > 0.0)
}

#[cfg(test)]
mod tests;
