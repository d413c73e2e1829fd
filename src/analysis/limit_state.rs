//! Limit states for fragility (SPEC §12): what a run must do to count as
//! exceeding, read from the demands of one run ([`Observed`]).
//!
//! - pounding: at least one impact;
//! - a ductility μ_i = Π_u,i/Π_uy,i (SPEC §6) above a value, for the left
//!   structure, the right one, or either. An elastic structure (Π_uy = ∞)
//!   has no ductility and never exceeds one, whatever the value;
//! - a peak absolute acceleration A_i (SPEC §6, in g) above a value, by side;
//! - a peak impact force above a value in kN (one force acts on both
//!   structures, so it has no side).
//!
//! Every comparison is strict (`>`), as the labels say, and a NaN demand
//! exceeds nothing.
//!
//! # The command-line forms
//!
//! Each parser reads one flag's comma-separated list and gives one limit
//! state per item, or a one-line error naming the flag, the item and what is
//! allowed. Every value is a finite number > 0.
//!
//! | flag | items | e.g. |
//! |---|---|---|
//! | `--ductility` ([`parse_ductility`]) | `[SIDE:]μ` | `2,4`, `left:2,right:4`, `either:3` |
//! | `--acceleration` ([`parse_acceleration`]) | `[SIDE:]A` | `0.5g,1g`, `right:0.3g`, `4.9` |
//! | `--force` ([`parse_force`]) | kN | `500`, `250,500` |
//!
//! SIDE is `left`, `right` or `either` (the default). A ductility below 1 is
//! allowed: it is reached before yielding, a fraction of the yield
//! displacement. An acceleration is written as everywhere on the command line
//! (`--ap`, [`physical::parse_acceleration`]): `0.5g` in g, a bare number in
//! m/s²; it is kept and labelled in g.

use std::fmt;

use serde::Serialize;

use crate::model::params::echo;
use crate::model::physical::{self, G};

/// Which structure a limit state reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// Structure 1.
    Left,
    /// Structure 2.
    Right,
    /// Either structure: exceeded when one of them is.
    Either,
}

impl Side {
    /// `left`, `right`, `either`.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
            Side::Either => "either",
        }
    }

    /// Whether `exceeds` holds for the structures this side reads (index 0
    /// left, 1 right).
    fn any(self, exceeds: impl Fn(usize) -> bool) -> bool {
        match self {
            Side::Left => exceeds(0),
            Side::Right => exceeds(1),
            Side::Either => exceeds(0) || exceeds(1),
        }
    }
}

/// What a run must do to count as exceeding (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LimitState {
    /// At least one impact.
    Pounding,
    /// Ductility μ above `value`.
    Ductility { side: Side, value: f64 },
    /// Peak absolute acceleration above `g` (in g).
    Acceleration { side: Side, g: f64 },
    /// Peak impact force above `kn` (in kN).
    Force { kn: f64 },
}

/// The demands of one run that the limit states read; index 0 is the left
/// structure, 1 the right.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observed {
    /// At least one impact.
    pub pounded: bool,
    /// μ_i of a structure that can yield, `None` for an elastic one (build it
    /// with [`ductility`], which knows the convention).
    pub ductility: [Option<f64>; 2],
    /// Peak absolute accelerations A_i, in g.
    pub acceleration_g: [f64; 2],
    /// The largest pounding force of the run, in kN (0 without impacts).
    pub max_force_kn: f64,
}

/// A structure's ductility for [`Observed`]: Π_u/Π_uy, or `None` for an
/// elastic structure (Π_uy = ∞, whose μ the run reports as ∞ by SPEC §6's
/// convention). Any pair of lengths in one unit will do.
pub fn ductility(peak_displacement: f64, yield_displacement: f64) -> Option<f64> {
    yield_displacement
        .is_finite()
        .then(|| peak_displacement / yield_displacement)
}

impl LimitState {
    /// Whether the run `o` exceeds this limit state. A ductility is exceeded
    /// only by a finite μ: an elastic structure never exceeds one, even if its
    /// μ was passed as the run's ∞.
    pub fn exceeded(&self, o: &Observed) -> bool {
        match *self {
            LimitState::Pounding => o.pounded,
            LimitState::Ductility { side, value } => {
                side.any(|i| o.ductility[i].is_some_and(|mu| mu.is_finite() && mu > value))
            }
            LimitState::Acceleration { side, g } => side.any(|i| o.acceleration_g[i] > g),
            LimitState::Force { kn } => o.max_force_kn > kn,
        }
    }

    /// The name in reports: `pounding`, `ductility>2 (either)`,
    /// `acceleration>0.5g (left)`, `force>500kN`.
    pub fn label(&self) -> String {
        match *self {
            LimitState::Pounding => "pounding".into(),
            LimitState::Ductility { side, value } => {
                format!("ductility>{} ({})", echo::number(value), side.name())
            }
            LimitState::Acceleration { side, g } => {
                format!("acceleration>{}g ({})", echo::number(g), side.name())
            }
            LimitState::Force { kn } => format!("force>{}kN", echo::number(kn)),
        }
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

/// Reads `--ductility`: `[SIDE:]μ` items, μ finite and > 0 (module docs).
pub fn parse_ductility(text: &str) -> Result<Vec<LimitState>, LimitStateError> {
    parse_sided(
        "--ductility",
        text,
        "a ductility > 0, e.g. 2,4 or left:2,right:4",
        |v| v.parse::<f64>().ok(),
        |side, value| LimitState::Ductility { side, value },
    )
}

/// Reads `--acceleration`: `[SIDE:]A` items, A > 0 as `0.5g` or in m/s²
/// (module docs); kept in g.
pub fn parse_acceleration(text: &str) -> Result<Vec<LimitState>, LimitStateError> {
    parse_sided(
        "--acceleration",
        text,
        "an acceleration > 0 like 0.5g, or in m/s², e.g. 0.5g,1g or right:0.3g",
        acceleration_g,
        |side, g| LimitState::Acceleration { side, g },
    )
}

/// Reads `--force`: values in kN, finite and > 0, e.g. `500` or `250,500`.
pub fn parse_force(text: &str) -> Result<Vec<LimitState>, LimitStateError> {
    items("--force", text, |item| {
        positive(item.parse::<f64>().ok())
            .map(|kn| LimitState::Force { kn })
            .ok_or("a force > 0 in kN, e.g. 500 or 250,500")
    })
}

/// Each comma-separated item of `text` read by `read`, or the first
/// failure as `FLAG `item`: must be ALLOWED` (a pair's limit states or a
/// row's, [`super::row_limit_state`]).
pub(crate) fn items<T, E: fmt::Display>(
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

/// Items `[SIDE:]VALUE`, the value read by `value` and required finite and
/// > 0 (SIDE `left`, `right` or `either`, by default `either`).
fn parse_sided(
    flag: &str,
    text: &str,
    allowed: &'static str,
    value: impl Fn(&str) -> Option<f64>,
    make: impl Fn(Side, f64) -> LimitState,
) -> Result<Vec<LimitState>, LimitStateError> {
    items(flag, text, |item| {
        let (side, number) = match item.split_once(':') {
            Some((side, number)) => (
                match side.trim() {
                    "left" => Side::Left,
                    "right" => Side::Right,
                    "either" => Side::Either,
                    _ => return Err("left:, right: or either: (or no side), then a value > 0"),
                },
                number.trim(),
            ),
            None => (Side::Either, item),
        };
        positive(value(number))
            .map(|v| make(side, v))
            .ok_or(allowed)
    })
}

/// An acceleration in g: `0.5g` as written (0.3g stays 0.3, not 0.3·g/g),
/// a bare number in m/s² as [`physical::parse_acceleration`] reads it, over g.
pub(crate) fn acceleration_g(text: &str) -> Option<f64> {
    match text.strip_suffix(['g', 'G']) {
        Some(number) => number.trim().parse().ok(),
        None => physical::parse_acceleration(text).map(|a| a / G),
    }
}

/// `v` if it is a finite number > 0.
pub(crate) fn positive(v: Option<f64>) -> Option<f64> {
    v.filter(|v| v.is_finite() && *v > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn observed() -> Observed {
        Observed {
            pounded: false,
            ductility: [Some(1.5), Some(3.0)],
            acceleration_g: [0.4, 0.7],
            max_force_kn: 0.0,
        }
    }

    #[test]
    fn parses_the_documented_forms() {
        let either = |value| LimitState::Ductility {
            side: Side::Either,
            value,
        };
        assert_eq!(parse_ductility("2,4").unwrap(), [either(2.0), either(4.0)]);
        assert_eq!(
            parse_ductility(" left:2 , right: 4,either:3").unwrap(),
            [
                LimitState::Ductility {
                    side: Side::Left,
                    value: 2.0
                },
                LimitState::Ductility {
                    side: Side::Right,
                    value: 4.0
                },
                either(3.0)
            ]
        );
        assert_eq!(parse_ductility("0.5").unwrap(), [either(0.5)]);
        let acc = parse_acceleration("0.3g,right:1g,9.80665").unwrap();
        assert_eq!(
            acc,
            [
                LimitState::Acceleration {
                    side: Side::Either,
                    g: 0.3
                },
                LimitState::Acceleration {
                    side: Side::Right,
                    g: 1.0
                },
                LimitState::Acceleration {
                    side: Side::Either,
                    g: 1.0
                },
            ]
        );
        assert_eq!(
            parse_force("500, 250").unwrap(),
            [
                LimitState::Force { kn: 500.0 },
                LimitState::Force { kn: 250.0 }
            ]
        );
    }

    #[test]
    fn refuses_with_the_flag_item_and_what_is_allowed() {
        let err = |r: Result<Vec<LimitState>, LimitStateError>| r.unwrap_err().to_string();
        assert_eq!(
            err(parse_ductility("2,0")),
            "--ductility `0`: must be a ductility > 0, e.g. 2,4 or left:2,right:4"
        );
        assert_eq!(
            err(parse_ductility("middle:2")),
            "--ductility `middle:2`: must be left:, right: or either: (or no side), then a value > 0"
        );
        for bad in ["", "inf", "NaN", "-1", "2,", "two", "left:"] {
            assert!(parse_ductility(bad).is_err(), "{bad:?}");
        }
        assert_eq!(
            err(parse_acceleration("0g")),
            "--acceleration `0g`: must be an acceleration > 0 like 0.5g, or in m/s², e.g. 0.5g,1g or right:0.3g"
        );
        assert!(parse_acceleration("left:-0.5g").is_err());
        assert_eq!(
            err(parse_force("left:500")),
            "--force `left:500`: must be a force > 0 in kN, e.g. 500 or 250,500"
        );
        assert!(parse_force("1e999").is_err());
    }

    #[test]
    fn exceedance_by_side() {
        let o = observed();
        let duct = |side, value| LimitState::Ductility { side, value }.exceeded(&o);
        assert!(!duct(Side::Left, 2.0) && duct(Side::Right, 2.0) && duct(Side::Either, 2.0));
        assert!(!duct(Side::Either, 3.0), "strictly above");
        let acc = |side, g| LimitState::Acceleration { side, g }.exceeded(&o);
        assert!(acc(Side::Left, 0.3) && !acc(Side::Left, 0.5) && acc(Side::Either, 0.5));
        assert!(!LimitState::Pounding.exceeded(&o));
        assert!(!LimitState::Force { kn: 1.0 }.exceeded(&o));
        let hit = Observed {
            pounded: true,
            max_force_kn: 600.0,
            ..o
        };
        assert!(LimitState::Pounding.exceeded(&hit));
        assert!(LimitState::Force { kn: 500.0 }.exceeded(&hit));
        assert!(!LimitState::Force { kn: 600.0 }.exceeded(&hit));
    }

    /// An elastic structure never exceeds a ductility: not through
    /// [`ductility`] (None), nor through the run's μ = ∞ passed as it is,
    /// nor through a NaN.
    #[test]
    fn an_elastic_structure_never_exceeds_a_ductility() {
        assert_eq!(ductility(0.3, f64::INFINITY), None);
        assert_eq!(ductility(1.8, 0.9), Some(2.0));
        for elastic in [None, Some(f64::INFINITY), Some(f64::NAN)] {
            let o = Observed {
                ductility: [elastic, elastic],
                ..observed()
            };
            for side in [Side::Left, Side::Right, Side::Either] {
                assert!(!LimitState::Ductility { side, value: 0.1 }.exceeded(&o));
            }
        }
        let nan = Observed {
            acceleration_g: [f64::NAN; 2],
            max_force_kn: f64::NAN,
            ..observed()
        };
        assert!(
            !LimitState::Acceleration {
                side: Side::Either,
                g: 0.1
            }
            .exceeded(&nan)
        );
        assert!(!LimitState::Force { kn: 1.0 }.exceeded(&nan));
    }

    #[test]
    fn labels() {
        assert_eq!(LimitState::Pounding.label(), "pounding");
        assert_eq!(
            parse_ductility("2").unwrap()[0].label(),
            "ductility>2 (either)"
        );
        assert_eq!(
            parse_acceleration("left:0.5g").unwrap()[0].label(),
            "acceleration>0.5g (left)"
        );
        assert_eq!(parse_force("500").unwrap()[0].to_string(), "force>500kN");
    }
}
