//! The dimensionless inputs of one run: the ten Π-groups of SPEC §1 plus the
//! run settings (contact model, duration, time step, grazing floor).
//!
//! There is one parameter type, [`Params`], and one table of its keys,
//! [`table::FIELDS`]: [`Params::set`] parses a `KEY=VALUE` (from `--set`, a
//! preset file, a family or the explorer) through the key's row, and
//! [`Params::validate`] checks every row's range and the bounds that join
//! keys (Δτ against the periods, the step count). Both report a
//! [`ParamError`] that names the key, the value and the allowed range.

use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use std::fmt;

use super::contact::{ContactConstants, ContactModel};
use super::excitation::Excitation;
use super::method::Method;

pub mod echo;
pub mod field;
pub mod table;

pub use field::{Field, Group, Kind, Step};
pub use table::{FIELDS, field, is_pi, keys};

/// The ten Π-groups (SPEC §1) and the run settings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
    /// Π_K = β √l_e/(m2 ω_p²), stiffness of the Hertz-type laws (SPEC §10);
    /// 0: derived from Π_ωcon ([`crate::model::contact::matched_hertz_stiffness`]).
    #[serde(default)]
    pub hertz_stiffness: f64,
    /// Contact element (SPEC §4, §10).
    pub model: ContactModel,
    /// Ground motion g(τ) (SPEC §2, §9).
    #[serde(default)]
    pub excitation: Excitation,
    /// s, the factor on a recorded excitation's accelerations (SPEC §12:
    /// a record scaled to an intensity); 1 as read.
    #[serde(default = "default_record_scale")]
    pub record_scale: f64,
    /// a_p of a recorded excitation in m/s² (0: the scaled record's peak s·max|a|).
    #[serde(default)]
    pub record_amplitude: f64,
    /// ω_p of a recorded excitation in rad/s (0: its dominant frequency).
    #[serde(default)]
    pub record_omega: f64,
    /// Time integrator (Newmark-β at Δτ, or event-driven exact).
    #[serde(default)]
    pub method: Method,
    /// Size allowed to each of the last two terms of the exact method's
    /// contact series, relative to the contact scale v₀/Π_ωcon: its one
    /// knob ([`CONTACT_TOLERANCE`] by default; Newmark ignores it).
    #[serde(default = "default_contact_tolerance")]
    pub contact_tolerance: f64,
    /// Duration in excitation cycles: τ_end = 2π · cycles (SPEC §2).
    pub cycles: u32,
    /// Newmark time step Δτ (SPEC §5).
    pub dt: f64,
    /// Floor on the approach velocity v₀ of the improved Kelvin element (SPEC §4).
    pub min_impact_velocity: f64,
}

/// The exact method's default contact tolerance. Kelvin's steps are held
/// shorter by their reach of one radian of the contact's rate, and its
/// peaks agree with the reference to round-off (6e-14 and 3e-13 on the
/// presets) at any tolerance from 1e-8 down. Improved Kelvin's are set by
/// the tolerance: its peaks' error is about three times it (3e-11 and
/// 6e-11 on the presets at 1e-11, 9e-14 at 1e-14), 30 times inside the
/// method's target of 1e-9, at 0.7 of the contact segments that 1e-14 takes.
pub const CONTACT_TOLERANCE: f64 = 1e-11;

fn default_record_scale() -> f64 {
    1.0
}

fn default_contact_tolerance() -> f64 {
    CONTACT_TOLERANCE
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
    hertz_stiffness: 0.0,
    model: ContactModel::ImprovedKelvin,
    excitation: Excitation::Sine,
    record_scale: 1.0,
    record_amplitude: 0.0,
    record_omega: 0.0,
    method: Method::Newmark,
    contact_tolerance: CONTACT_TOLERANCE,
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
    /// `key` is already cut and escaped for a one-line message.
    #[error("unknown parameter `{key}` (known: {})", keys().collect::<Vec<_>>().join(", "))]
    UnknownKey { key: String },
    /// `value` is already in its shortest form, or cut and escaped.
    #[error("`{key}` = {value}: {allowed}")]
    OutOfRange {
        key: &'static str,
        value: String,
        allowed: String,
    },
}

/// Largest accepted number of Newmark steps in one run (τ_end/Δτ).
pub const MAX_STEPS: f64 = 1e9;

/// The row of a known key, or the error naming an unknown one.
fn known(key: &str) -> Result<&'static Field, ParamError> {
    field(key.trim()).ok_or_else(|| ParamError::UnknownKey {
        key: echo::text(key),
    })
}

impl Params {
    /// The numeric value of a key (a choice reads as its index: `model` is
    /// 0 for Kelvin, 1 for improved Kelvin).
    pub fn get(&self, key: &str) -> Option<f64> {
        field(key).map(|f| f.number(self))
    }

    /// Sets one key from its text form (`--set KEY=VALUE`, a preset value, a
    /// family member, a typed field), checking the key's own range. On error
    /// `self` is unchanged. The bounds that join keys are [`Params::validate`]'s.
    pub fn set(&mut self, key: &str, text: &str) -> Result<(), ParamError> {
        known(key)?.set_text(self, text)
    }

    /// Checks every row's range, then the bounds that join keys:
    /// - Δτ ≤ 2π/(20 · max(1, Π_ω1, Π_ω2)): 20 steps per period of the
    ///   excitation and of both structures ([`table::STEPS_PER_PERIOD`]);
    /// - τ_end/Δτ ≤ [`MAX_STEPS`].
    ///
    /// Every path that takes outside input ends here.
    pub fn validate(&self) -> Result<(), ParamError> {
        for f in FIELDS {
            f.check(self)?;
        }
        // A record of zeros has no a_p to scale by (SPEC §9: a_p defaults to
        // its peak |a|), and shakes nothing: refuse it rather than run it at
        // an invented amplitude.
        if let Excitation::Record(m) = &self.excitation
            && m.record.peak <= 0.0
        {
            return Err(ParamError::OutOfRange {
                key: "excitation",
                value: m.record.spec.clone(),
                allowed: "every sample of the record is zero: a record needs a nonzero \
                          acceleration to set a_p and to shake anything"
                    .into(),
            });
        }
        let dt_max = self.dt_max();
        if self.dt > dt_max {
            return Err(ParamError::OutOfRange {
                key: "dt",
                value: echo::number(self.dt),
                allowed: format!(
                    "must be <= {} here: 2π/(20 · max(1, omega1, omega2)), 20 steps per \
                     period of the excitation and of each structure (omega1 = {}, omega2 = {})",
                    echo::g4(dt_max),
                    echo::number(self.omega1),
                    echo::number(self.omega2)
                ),
            });
        }
        if self.tau_end() / self.dt > MAX_STEPS {
            return Err(ParamError::OutOfRange {
                key: "dt",
                value: echo::number(self.dt),
                allowed: format!(
                    "gives {} steps for {} cycles; at most 1e9 are allowed",
                    echo::g4(self.tau_end() / self.dt),
                    self.cycles
                ),
            });
        }
        Ok(())
    }

    /// Largest Δτ for these frequencies: 2π/(20 · max(1, Π_ω1, Π_ω2)).
    pub fn dt_max(&self) -> f64 {
        TAU / (table::STEPS_PER_PERIOD * self.omega1.max(self.omega2).max(1.0))
    }

    /// End of the run: τ_end = 2π · cycles (SPEC §2); under a record, the
    /// record's length ω_p·(N−1)·DT plus a free-vibration tail of `cycles`
    /// periods 2π (SPEC §9).
    pub fn tau_end(&self) -> f64 {
        let cycles = 2.0 * std::f64::consts::PI * self.cycles as f64;
        match self.ground() {
            Excitation::Record(m) => m.end() + cycles,
            _ => cycles,
        }
    }

    /// The excitation as the solvers take it: a record scaled by the set's
    /// s, with its a_p (s·max|a| unless given) and ω_p (SPEC §9, §12),
    /// otherwise as named.
    pub fn ground(&self) -> Excitation {
        match &self.excitation {
            Excitation::Record(m) => {
                let mut m = m.clone();
                m.scale = self.record_scale;
                m.amplitude = if self.record_amplitude > 0.0 {
                    self.record_amplitude
                } else {
                    self.record_scale * m.amplitude
                };
                if self.record_omega > 0.0 {
                    m.omega = self.record_omega;
                }
                Excitation::Record(m)
            }
            e => e.clone(),
        }
    }

    /// Π_K of the Hertz-type laws: the set's own, or derived from Π_ωcon (SPEC §10).
    pub fn hertz_stiffness(&self) -> f64 {
        if self.hertz_stiffness > 0.0 {
            self.hertz_stiffness
        } else {
            super::contact::matched_hertz_stiffness(self.mass_ratio, self.contact_omega)
        }
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
                echo::number(self.dt),
                n,
                echo::number(self.contact_omega)
            )
        })
    }
}

/// Serde for floats that may be infinite: TOML has `inf`, JSON does not, so
/// infinity is written as the string `"inf"` in JSON (by the one writer of
/// such floats, [`crate::output::report::float_or_inf`]) and read back from either.
mod float_or_inf {
    use serde::{Deserialize, Deserializer};

    pub use crate::output::report::float_or_inf as serialize;

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
    /// Every key of the table as `symbol=value`, in table order.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, field) in FIELDS.iter().enumerate() {
            let sep = if i == 0 { "" } else { " " };
            write!(f, "{sep}{}={}", field.symbol, field.text(self))?;
        }
        Ok(())
    }
}

/// The contact law's constants of a parameter set. It lives here, beside
/// the parameters, so that the contact laws need not know the parameter set.
impl ContactConstants {
    pub fn of(p: &Params) -> Self {
        ContactConstants {
            model: p.model,
            mass_ratio: p.mass_ratio,
            contact_omega: p.contact_omega,
            restitution: p.restitution,
            hertz_stiffness: p.hertz_stiffness(),
            min_impact_velocity: p.min_impact_velocity,
        }
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
        assert_eq!(
            e.to_string(),
            "`restitution` = 0: must be a number in [0.001, 1]"
        );
        assert!(p.set("gap", "NaN").is_err());
        assert!(p.set("gap", "-1").is_err());
        assert!(p.set("bogus", "1").is_err());
        assert!(p.set("cycles", "0").is_err());
        assert!(p.set("model", "hertz-mindlin").is_err());
        assert!(p.set("excitation", "pulse-d").is_err());
        assert_eq!(p, SET1);
        p.set("gap", "inf").unwrap();
        assert!(!p.pounding());
        p.set("model", "kelvin").unwrap();
        assert_eq!(p.model, ContactModel::Kelvin);
    }

    #[test]
    fn every_row_reads_back_what_it_writes() {
        let mut p = SET1;
        p.method = Method::Exact;
        for f in FIELDS {
            let mut q = SET2;
            q.set(f.key, &f.text(&p)).unwrap();
            assert_eq!(f.text(&q), f.text(&p), "{}", f.key);
        }
        p.set("method", "newmark").unwrap();
        assert_eq!(p.method, Method::Newmark);
        let e = p.set("method", "rk4").unwrap_err().to_string();
        assert_eq!(e, "`method` = rk4: must be one of: newmark, exact");
    }

    #[test]
    fn values_that_hung_the_solver_are_refused() {
        for (key, value) in [
            ("contact_omega", "1e300"),
            ("mass_ratio", "1e300"),
            ("restitution", "1e-100"),
            ("mass_ratio", "1e-320"),
            ("omega1", "1e100"),
            ("dt", "1e300"),
            ("dt", "60"),
        ] {
            let e = SET1.clone().set(key, value).unwrap_err().to_string();
            assert!(e.starts_with(&format!("`{key}` = {value}: must be")), "{e}");
        }
        // Δτ against the structural period: 2π/(20 · 30) = 0.01047.
        let p = Params {
            omega2: 30.0,
            dt: 0.02,
            ..SET1
        };
        let e = p.validate().unwrap_err().to_string();
        assert!(e.starts_with("`dt` = 0.02: must be <= 0.01047 here"), "{e}");
        let p = Params {
            cycles: 100_000,
            dt: 1e-6,
            ..SET1
        };
        assert!(
            p.validate()
                .unwrap_err()
                .to_string()
                .contains("at most 1e9")
        );
    }

    #[test]
    fn display_shows_every_key() {
        let text = SET1.to_string();
        assert!(text.starts_with("Π_m=0.5 Π_ω1=1.05 "), "{text}");
        assert!(text.contains(
            " model=improved-kelvin g(τ)=sine s=1 a_p=0 ω_p=0 method=newmark tol=1e-11 cycles=8 Δτ=0.001"
        ));
        assert_eq!(text.split(' ').count(), FIELDS.len());
    }
}
