//! One row of the parameter table: what a key is, which values it takes,
//! and how its value is read, written, checked and shown.

use super::{ParamError, Params, echo};

/// Whether a key is one of the Π-groups of SPEC §1 (a preset's `[physical]`
/// table gives these) or a run setting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// A dimensionless group of SPEC §1.
    Pi,
    /// How the run is done: contact law, method, duration, step, floors.
    Setting,
}

/// What values a key takes, and how it is read from and written to [`Params`].
#[derive(Debug, Clone, Copy)]
pub enum Kind {
    /// A real number in `[min, max]`; with `inf`, also +∞ (meaning "never":
    /// no yield, no contact).
    Number {
        min: f64,
        max: f64,
        inf: bool,
        get: fn(&Params) -> f64,
        set: fn(&mut Params, f64),
    },
    /// A whole number in `[min, max]`.
    Integer {
        min: u32,
        max: u32,
        get: fn(&Params) -> u32,
        set: fn(&mut Params, u32),
    },
    /// One of a few names; `set` returns false for a text that is none of them.
    Choice {
        names: &'static [&'static str],
        get: fn(&Params) -> &str,
        set: fn(&mut Params, &str) -> bool,
    },
}

/// One key: its name, symbols, meaning, values and explorer nudge.
#[derive(Debug, Clone, Copy)]
pub struct Field {
    /// The key of presets, `--set`, `--family` and JSON output.
    pub key: &'static str,
    /// The paper's symbol (Unicode).
    pub symbol: &'static str,
    /// The symbol in ASCII, for terminals without Unicode.
    pub ascii: &'static str,
    /// What it means, in a few words.
    pub meaning: &'static str,
    pub group: Group,
    pub kind: Kind,
    /// One nudge in the explorer (←/→).
    pub step: Step,
}

/// How far one nudge moves a key in the explorer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// By this much; Shift moves ten times as far, the fine step a tenth.
    Add(f64),
    /// By this factor, for a key whose range spans decades; Shift by its
    /// square, the fine step by its tenth root.
    Times(f64),
}

impl std::fmt::Display for Step {
    /// As the explorer states it: `0.05`, `×10`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Step::Add(d) => write!(f, "{}", echo::g4(*d)),
            Step::Times(r) => write!(f, "×{}", echo::g4(*r)),
        }
    }
}

/// Parses a float the way a user writes it: `0.2`, `1e-3`, `inf`, `infinity`.
fn parse_float(text: &str) -> Option<f64> {
    let t = text.trim();
    match t.to_ascii_lowercase().as_str() {
        "inf" | "+inf" | "infinity" | "+infinity" => Some(f64::INFINITY),
        "-inf" | "-infinity" => Some(f64::NEG_INFINITY),
        _ => t.parse::<f64>().ok(),
    }
}

impl Field {
    /// The allowed values, as stated in every message about this key.
    pub fn allowed(&self) -> String {
        match self.kind {
            Kind::Number { min, max, inf, .. } => format!(
                "must be a number in [{}, {}]{}",
                echo::g4(min),
                echo::g4(max),
                if inf { ", or inf" } else { "" }
            ),
            Kind::Integer { min, max, .. } => format!("must be an integer in [{min}, {max}]"),
            Kind::Choice { names, .. } => format!("must be one of: {}", names.join(", ")),
        }
    }

    /// The range in short form for tables of keys: `[0.001, 1000]`, `kelvin|improved-kelvin`.
    pub fn range(&self) -> String {
        match self.kind {
            Kind::Number { min, max, inf, .. } => format!(
                "[{}, {}]{}",
                echo::g4(min),
                echo::g4(max),
                if inf { " or inf" } else { "" }
            ),
            Kind::Integer { min, max, .. } => format!("[{min}, {max}]"),
            Kind::Choice { names, .. } => names.join("|"),
        }
    }

    fn out_of_range(&self, value: String) -> ParamError {
        ParamError::OutOfRange {
            key: self.key,
            value,
            allowed: self.allowed(),
        }
    }

    /// Checks a number against this key's range (NaN fails every comparison).
    pub fn check_number(&self, v: f64) -> Result<f64, ParamError> {
        let ok = match self.kind {
            Kind::Number { min, max, inf, .. } => {
                (min..=max).contains(&v) || (inf && v == f64::INFINITY)
            }
            Kind::Integer { min, max, .. } => {
                v.fract() == 0.0 && (min as f64..=max as f64).contains(&v)
            }
            Kind::Choice { .. } => false,
        };
        if ok {
            Ok(v)
        } else {
            Err(self.out_of_range(echo::number(v)))
        }
    }

    /// The value in `p` as text, in the form `set_text` reads back.
    pub fn text(&self, p: &Params) -> String {
        match self.kind {
            Kind::Number { get, .. } => echo::number(get(p)),
            Kind::Integer { get, .. } => get(p).to_string(),
            Kind::Choice { get, .. } => get(p).to_string(),
        }
    }

    /// The value in `p` as a number: an integer as itself, a choice as its
    /// index among the names.
    pub fn number(&self, p: &Params) -> f64 {
        match self.kind {
            Kind::Number { get, .. } => get(p),
            Kind::Integer { get, .. } => get(p) as f64,
            Kind::Choice { names, get, .. } => {
                names.iter().position(|n| *n == get(p)).unwrap_or(0) as f64
            }
        }
    }

    /// Sets the key in `p` from a user's text, after checking its range.
    /// On error `p` is unchanged and the message names key, value and range.
    pub fn set_text(&self, p: &mut Params, text: &str) -> Result<(), ParamError> {
        match self.kind {
            Kind::Number { set, .. } => {
                let v = parse_float(text).ok_or_else(|| ParamError::OutOfRange {
                    key: self.key,
                    value: echo::text(text),
                    allowed: format!("is not a number; {}", self.allowed()),
                })?;
                set(p, self.check_number(v)?);
            }
            Kind::Integer { set, .. } => {
                let v = parse_float(text).ok_or_else(|| self.out_of_range(echo::text(text)))?;
                set(p, self.check_number(v)? as u32);
            }
            Kind::Choice { set, .. } => {
                let mut next = p.clone();
                if !set(&mut next, text.trim()) {
                    return Err(self.out_of_range(echo::text(text)));
                }
                *p = next;
            }
        }
        Ok(())
    }

    /// Checks the value `p` holds (for values that did not come through `set_text`).
    pub fn check(&self, p: &Params) -> Result<(), ParamError> {
        match self.kind {
            Kind::Choice { .. } => Ok(()),
            _ => self.check_number(self.number(p)).map(|_| ()),
        }
    }
}
