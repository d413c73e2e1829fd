//! The dimensionless inputs of one run: the ten Π-groups of SPEC §1 plus the
//! run settings (contact model, duration, time step, grazing floor).
//!
//! There is one parameter type, [`Params`], and one place where a user's value
//! is checked: [`Params::set`] parses a `KEY=VALUE` (from `--set` or a preset
//! file) and [`Params::validate`] checks every range. Both report a
//! [`ParamError`] that names the key, the value and the allowed range.

use serde::{Deserialize, Serialize};
use std::fmt;

use super::contact::ContactModel;

/// The ten Π-groups (SPEC §1) and the run settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Params {
    /// Π_m = m1/m2, mass ratio of the left (lighter) to the right structure.
    pub mass_ratio: f64,
    /// Π_ω1 = ω1/ω_p, natural frequency of the left structure.
    pub omega1: f64,
    /// Π_ω2 = ω2/ω_p, natural frequency of the right structure.
    pub omega2: f64,
    /// Π_uy1 = u_y1 ω_p²/a_p, yield displacement of the left structure (`inf`: elastic).
    #[serde(with = "float_or_inf")]
    pub yield1: f64,
    /// Π_uy2 = u_y2 ω_p²/a_p, yield displacement of the right structure (`inf`: elastic).
    #[serde(with = "float_or_inf")]
    pub yield2: f64,
    /// Π_ξ = ξ, viscous damping ratio of both structures.
    pub damping: f64,
    /// Π_α, post-yield over elastic stiffness.
    pub alpha: f64,
    /// Π_ωcon = ω̄/ω_p, natural frequency of the contact element.
    pub contact_omega: f64,
    /// Π_e = e, coefficient of restitution, 0 < e ≤ 1.
    pub restitution: f64,
    /// Π_d = d ω_p²/a_p, initial separation (`inf`: no pounding).
    #[serde(with = "float_or_inf")]
    pub gap: f64,
    /// Contact element (SPEC §4).
    pub model: ContactModel,
    /// Duration in excitation cycles: τ_end = 2π · cycles (SPEC §2).
    pub cycles: u32,
    /// Newmark time step Δτ (SPEC §5).
    pub dt: f64,
    /// Floor on the approach velocity v₀ of the improved Kelvin element (SPEC §4).
    pub min_impact_velocity: f64,
}

/// The paper's parameter set 1 (SPEC §1): left structure in the amplification region.
pub const SET1: Params = Params {
    mass_ratio: 0.5,
    omega1: 1.05,
    omega2: 2.36,
    yield1: 0.9,
    yield2: 0.8,
    damping: 0.05,
    alpha: 0.1,
    contact_omega: 50.0,
    restitution: 0.4,
    gap: 0.2,
    model: ContactModel::ImprovedKelvin,
    cycles: 8,
    dt: 0.001,
    min_impact_velocity: 1e-3,
};

/// The paper's parameter set 2 (SPEC §1): left structure in the suppression region.
pub const SET2: Params = Params {
    omega1: 1.5,
    omega2: 3.375,
    ..SET1
};

impl Default for Params {
    fn default() -> Self {
        SET1
    }
}

/// A value outside its allowed range, or a key that does not exist.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    #[error("unknown parameter `{key}` (known: {})", KEYS.join(", "))]
    UnknownKey { key: String },
    #[error("`{key}` = {value}: {allowed}")]
    OutOfRange {
        key: &'static str,
        value: String,
        allowed: &'static str,
    },
}

/// Every key a preset or `--set` accepts, in display order.
pub const KEYS: [&str; 14] = [
    "mass_ratio",
    "omega1",
    "omega2",
    "yield1",
    "yield2",
    "damping",
    "alpha",
    "contact_omega",
    "restitution",
    "gap",
    "model",
    "cycles",
    "dt",
    "min_impact_velocity",
];

/// The ten Π keys of SPEC §1, the first ten of [`KEYS`].
pub const PI_KEYS: &[&str] = KEYS.split_at(10).0;

/// One key's allowed range, as stated in error messages and help.
struct Rule {
    key: &'static str,
    allowed: &'static str,
    ok: fn(f64) -> bool,
}

const FINITE_POSITIVE: &str = "must be a finite number > 0";
const POSITIVE_OR_INF: &str = "must be a number > 0, or inf";

const RULES: [Rule; 12] = [
    Rule {
        key: "mass_ratio",
        allowed: FINITE_POSITIVE,
        ok: |v| v.is_finite() && v > 0.0,
    },
    Rule {
        key: "omega1",
        allowed: "must be a finite number >= 0",
        ok: |v| v.is_finite() && v >= 0.0,
    },
    Rule {
        key: "omega2",
        allowed: "must be a finite number >= 0",
        ok: |v| v.is_finite() && v >= 0.0,
    },
    Rule {
        key: "yield1",
        allowed: POSITIVE_OR_INF,
        ok: |v| v > 0.0,
    },
    Rule {
        key: "yield2",
        allowed: POSITIVE_OR_INF,
        ok: |v| v > 0.0,
    },
    Rule {
        key: "damping",
        allowed: "must be a finite number >= 0",
        ok: |v| v.is_finite() && v >= 0.0,
    },
    Rule {
        key: "alpha",
        allowed: "must be in [0, 1]",
        ok: |v| (0.0..=1.0).contains(&v),
    },
    Rule {
        key: "contact_omega",
        allowed: FINITE_POSITIVE,
        ok: |v| v.is_finite() && v > 0.0,
    },
    Rule {
        key: "restitution",
        allowed: "must be in (0, 1]",
        ok: |v| v > 0.0 && v <= 1.0,
    },
    Rule {
        key: "gap",
        allowed: "must be a number >= 0, or inf",
        ok: |v| v >= 0.0,
    },
    Rule {
        key: "dt",
        allowed: FINITE_POSITIVE,
        ok: |v| v.is_finite() && v > 0.0,
    },
    Rule {
        key: "min_impact_velocity",
        allowed: FINITE_POSITIVE,
        ok: |v| v.is_finite() && v > 0.0,
    },
];

/// Largest accepted `cycles`: keeps a run's step count within what fits in memory for a full history.
pub const MAX_CYCLES: u32 = 100_000;
/// Largest accepted number of Newmark steps in one run (τ_end/Δτ).
pub const MAX_STEPS: f64 = 1e9;

fn rule(key: &str) -> Option<&'static Rule> {
    RULES.iter().find(|r| r.key == key)
}

fn check(key: &'static str, value: f64) -> Result<f64, ParamError> {
    let r = rule(key).expect("every numeric key has a rule");
    // NaN fails every comparison above, so it is rejected here too.
    if (r.ok)(value) {
        Ok(value)
    } else {
        Err(ParamError::OutOfRange {
            key: r.key,
            value: fmt_value(value),
            allowed: r.allowed,
        })
    }
}

fn fmt_value(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else {
        format!("{v}")
    }
}

/// Parses a float the way a user writes it: `0.2`, `1e-3`, `inf`, `infinity`.
fn parse_float(key: &'static str, text: &str) -> Result<f64, ParamError> {
    let t = text.trim();
    let v = match t.to_ascii_lowercase().as_str() {
        "inf" | "+inf" | "infinity" => f64::INFINITY,
        _ => t.parse::<f64>().map_err(|_| ParamError::OutOfRange {
            key,
            value: text.to_string(),
            allowed: "is not a number",
        })?,
    };
    Ok(v)
}

/// The canonical `&'static str` of a known key.
fn known_key(key: &str) -> Result<&'static str, ParamError> {
    KEYS.iter()
        .copied()
        .find(|k| *k == key)
        .ok_or_else(|| ParamError::UnknownKey {
            key: key.to_string(),
        })
}

impl Params {
    /// The numeric value of a key (`model` reads as 0 for Kelvin, 1 for improved Kelvin).
    pub fn get(&self, key: &str) -> Option<f64> {
        Some(match key {
            "mass_ratio" => self.mass_ratio,
            "omega1" => self.omega1,
            "omega2" => self.omega2,
            "yield1" => self.yield1,
            "yield2" => self.yield2,
            "damping" => self.damping,
            "alpha" => self.alpha,
            "contact_omega" => self.contact_omega,
            "restitution" => self.restitution,
            "gap" => self.gap,
            "model" => match self.model {
                ContactModel::Kelvin => 0.0,
                ContactModel::ImprovedKelvin => 1.0,
            },
            "cycles" => self.cycles as f64,
            "dt" => self.dt,
            "min_impact_velocity" => self.min_impact_velocity,
            _ => return None,
        })
    }

    /// Sets one key from its text form (`--set KEY=VALUE`, a preset value, a typed field),
    /// checking the value's range. On error `self` is unchanged.
    pub fn set(&mut self, key: &str, text: &str) -> Result<(), ParamError> {
        let key = known_key(key)?;
        match key {
            "model" => {
                self.model = text.trim().parse().map_err(|_| ParamError::OutOfRange {
                    key,
                    value: text.to_string(),
                    allowed: "must be `kelvin` or `improved-kelvin`",
                })?;
            }
            "cycles" => {
                let bad = || ParamError::OutOfRange {
                    key,
                    value: text.to_string(),
                    allowed: "must be an integer in [1, 100000]",
                };
                let n: u32 = text.trim().parse().map_err(|_| bad())?;
                if !(1..=MAX_CYCLES).contains(&n) {
                    return Err(bad());
                }
                self.cycles = n;
            }
            _ => {
                let v = check(key, parse_float(key, text)?)?;
                self.set_number(key, v);
            }
        }
        Ok(())
    }

    /// Sets a numeric key that is known to be valid.
    fn set_number(&mut self, key: &str, v: f64) {
        match key {
            "mass_ratio" => self.mass_ratio = v,
            "omega1" => self.omega1 = v,
            "omega2" => self.omega2 = v,
            "yield1" => self.yield1 = v,
            "yield2" => self.yield2 = v,
            "damping" => self.damping = v,
            "alpha" => self.alpha = v,
            "contact_omega" => self.contact_omega = v,
            "restitution" => self.restitution = v,
            "gap" => self.gap = v,
            "dt" => self.dt = v,
            "min_impact_velocity" => self.min_impact_velocity = v,
            _ => unreachable!("set_number called with non-numeric key {key}"),
        }
    }

    /// Checks every range of SPEC §1 and the run settings. Every constructor
    /// path that takes outside input ends here.
    pub fn validate(&self) -> Result<(), ParamError> {
        for r in &RULES {
            check(r.key, self.get(r.key).unwrap_or(f64::NAN))?;
        }
        if !(1..=MAX_CYCLES).contains(&self.cycles) {
            return Err(ParamError::OutOfRange {
                key: "cycles",
                value: self.cycles.to_string(),
                allowed: "must be an integer in [1, 100000]",
            });
        }
        if self.tau_end() / self.dt > MAX_STEPS {
            return Err(ParamError::OutOfRange {
                key: "dt",
                value: fmt_value(self.dt),
                allowed: "gives more than 1e9 steps for this many cycles",
            });
        }
        Ok(())
    }

    /// End of the run, τ_end = 2π · cycles (SPEC §2).
    pub fn tau_end(&self) -> f64 {
        2.0 * std::f64::consts::PI * self.cycles as f64
    }

    /// Frequency ratio μ = Π_ω2/Π_ω1 (SPEC §1).
    pub fn mu(&self) -> f64 {
        self.omega2 / self.omega1
    }

    /// True when contact can happen at all (`gap` finite).
    pub fn pounding(&self) -> bool {
        self.gap.is_finite()
    }

    /// Steps per contact period 2π/Π_ωcon; fewer than 20 resolves a contact poorly.
    pub fn steps_per_contact_period(&self) -> f64 {
        2.0 * std::f64::consts::PI / (self.contact_omega * self.dt)
    }

    /// A warning when Δτ is too coarse to resolve a contact, else `None`.
    pub fn coarse_dt_warning(&self) -> Option<String> {
        let n = self.steps_per_contact_period();
        (self.pounding() && n < 20.0).then(|| {
            format!(
                "warning: dt = {} gives only {:.1} steps per contact period 2π/contact_omega \
                 (contact_omega = {}); at least 20 are advised",
                self.dt, n, self.contact_omega
            )
        })
    }
}

/// Serde for floats that may be infinite: TOML has `inf`, JSON does not, so
/// infinity is written as the string `"inf"` in JSON and read back from either.
mod float_or_inf {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        if v.is_infinite() && s.is_human_readable() {
            s.serialize_str(if *v > 0.0 { "inf" } else { "-inf" })
        } else {
            s.serialize_f64(*v)
        }
    }

    #[derive(Deserialize)]
    #[serde(untagged)]
    enum NumOrText {
        Num(f64),
        Text(String),
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        match NumOrText::deserialize(d)? {
            NumOrText::Num(v) => Ok(v),
            NumOrText::Text(t) => match t.as_str() {
                "inf" => Ok(f64::INFINITY),
                "-inf" => Ok(f64::NEG_INFINITY),
                _ => Err(serde::de::Error::custom(format!(
                    "expected a number or \"inf\", got {t:?}"
                ))),
            },
        }
    }
}

impl fmt::Display for Params {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "Π_m={} Π_ω1={} Π_ω2={} Π_uy1={} Π_uy2={} Π_ξ={} Π_α={} Π_ωcon={} Π_e={} Π_d={} model={} cycles={} Δτ={}",
            self.mass_ratio,
            self.omega1,
            self.omega2,
            self.yield1,
            self.yield2,
            self.damping,
            self.alpha,
            self.contact_omega,
            self.restitution,
            self.gap,
            self.model,
            self.cycles,
            self.dt
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid() {
        SET1.validate().unwrap();
        SET2.validate().unwrap();
        assert!((SET2.mu() - 2.25).abs() < 1e-12);
    }

    #[test]
    fn set_rejects_bad_values_and_keeps_old() {
        let mut p = SET1;
        let e = p.set("restitution", "0").unwrap_err();
        assert_eq!(e.to_string(), "`restitution` = 0: must be in (0, 1]");
        assert!(p.set("gap", "NaN").is_err());
        assert!(p.set("gap", "-1").is_err());
        assert!(p.set("bogus", "1").is_err());
        assert!(p.set("cycles", "0").is_err());
        assert!(p.set("model", "hertz").is_err());
        assert_eq!(p, SET1);
        p.set("gap", "inf").unwrap();
        assert!(!p.pounding());
        p.set("model", "kelvin").unwrap();
        assert_eq!(p.model, ContactModel::Kelvin);
    }
}
