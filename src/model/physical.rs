//! Physical units in and out (SPEC §8).
//!
//! With the base quantities m2, a_p and ω_p, the energy length
//! l_e = a_p/ω_p² and the velocity scale a_p/ω_p give (SPEC §1)
//!
//! ```text
//! Π_m = m1/m2,  Π_ωi = ωi/ω_p,  Π_uyi = u_yi/l_e,  Π_d = d/l_e,
//! Π_ωcon = ω̄/ω_p,  Π_ξ = ξ,  Π_α = α,  Π_e = e,
//! Π_K = β √l_e / (m2 ω_p²)   (SPEC §10: the Hertz-type laws' f = β δ^{3/2}),
//! ```
//!
//! and results map back as X_max = Π_u l_e, Ẋ_max = Π_v a_p/ω_p.
//!
//! A preset's `[physical]` table holds these quantities in SI units:
//!
//! ```toml
//! [physical]
//! m1 = 5.0e5            # kg
//! m2 = 1.0e6            # kg
//! period1 = 0.95        # s (or omega1 in rad/s)
//! period2 = 0.42        # s (or omega2 in rad/s)
//! yield1 = 0.11         # m
//! yield2 = 0.10         # m
//! gap = 0.025           # m (inf: no pounding)
//! damping = 0.05
//! alpha = 0.1
//! contact_omega = 314.16  # rad/s
//! restitution = 0.4
//! hertz_beta = 1.0e9    # N/m^{3/2}, optional (default: Π_K derived from contact_omega)
//! ap = "0.5g"           # m/s² or "…g": the level at which the lengths above hold
//! omega_p = 6.2832      # rad/s (or period_p in s)
//! ```

use std::f64::consts::PI;

use super::params::{ParamError, Params};

/// Standard gravity, m/s², for accelerations written as `0.5g`.
pub const G: f64 = 9.80665;

/// The excitation's circular frequency ω_p in rad/s: periods from 6.3 ms to
/// 10 min hold every ground motion (dominant periods 0.05–10 s) with room to
/// spare, and keep l_e = a_p/ω_p² a normal number (ω_p = 1e300 made it 0,
/// and every Π-group NaN).
pub const OMEGA_P: std::ops::RangeInclusive<f64> = 1e-2..=1e3;
/// [`OMEGA_P`] as stated in messages.
pub const OMEGA_P_ALLOWED: &str = "must be a number in [0.01, 1000] (rad/s)";

/// Physical description of the two structures and the excitation (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Physical {
    /// Masses m1, m2 in kg.
    pub mass: [f64; 2],
    /// Natural circular frequencies ω1, ω2 in rad/s.
    pub omega: [f64; 2],
    /// Yield displacements u_y1, u_y2 in m (`inf`: elastic).
    pub yield_displacement: [f64; 2],
    /// Initial separation d in m (`inf`: no pounding).
    pub gap: f64,
    pub damping: f64,
    pub alpha: f64,
    /// Contact element frequency ω̄ in rad/s.
    pub contact_omega: f64,
    pub restitution: f64,
    /// Hertz stiffness β in N/m^{3/2} of the Hertz-type laws (SPEC §10);
    /// `None`: Π_K is derived from Π_ωcon as the settings say.
    pub hertz_beta: Option<f64>,
    /// Excitation amplitude a_p in m/s².
    pub ap: f64,
    /// Excitation circular frequency ω_p in rad/s.
    pub omega_p: f64,
}

/// A `[physical]` entry or acceleration that cannot be used: key, value, allowed range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{context}`{key}` = {value}: {allowed}")]
pub struct PhysicalError {
    pub context: &'static str,
    pub key: String,
    pub value: String,
    pub allowed: &'static str,
}

const TABLE: &str = "[physical] ";
const POSITIVE: &str = "must be a finite number > 0";

/// Parses an acceleration: `4.9` (m/s²) or `0.5g` (multiples of g = 9.80665 m/s²).
pub fn parse_acceleration(text: &str) -> Option<f64> {
    let t = text.trim();
    let v = match t.strip_suffix(['g', 'G']) {
        Some(n) => n.trim().parse::<f64>().ok()? * G,
        None => t.parse::<f64>().ok()?,
    };
    (v.is_finite() && v > 0.0).then_some(v)
}

/// Length scale l_e = a_p/ω_p² (SPEC §1).
pub fn energy_length(ap: f64, omega_p: f64) -> f64 {
    ap / (omega_p * omega_p)
}

impl Physical {
    /// Reads a `[physical]` table (keys as in the module docs; unknown keys refused).
    pub fn from_table(t: &toml::Table) -> Result<Physical, PhysicalError> {
        const KNOWN: [&str; 17] = [
            "m1",
            "m2",
            "omega1",
            "omega2",
            "period1",
            "period2",
            "yield1",
            "yield2",
            "gap",
            "damping",
            "alpha",
            "contact_omega",
            "restitution",
            "hertz_beta",
            "ap",
            "omega_p",
            "period_p",
        ];
        if let Some(k) = t.keys().find(|k| !KNOWN.contains(&k.as_str())) {
            return Err(PhysicalError {
                context: TABLE,
                key: super::params::echo::text(k),
                value: super::params::echo::text(&t[k].to_string()),
                allowed: "unknown key (known: m1, m2, omega1|period1, omega2|period2, yield1, yield2, \
                          gap, damping, alpha, contact_omega, restitution, hertz_beta, ap, omega_p|period_p)",
            });
        }
        let err = |key: &str, allowed| PhysicalError {
            context: TABLE,
            key: key.to_string(),
            value: t.get(key).map_or_else(
                || "(missing)".into(),
                |v| super::params::echo::text(&v.to_string()),
            ),
            allowed,
        };
        let number = |key: &str| -> Option<f64> {
            match t.get(key)? {
                toml::Value::Float(f) => Some(*f),
                toml::Value::Integer(i) => Some(*i as f64),
                toml::Value::String(s) if s.trim() == "inf" => Some(f64::INFINITY),
                _ => Some(f64::NAN),
            }
        };
        let positive = |key: &str| {
            number(key)
                .filter(|v| v.is_finite() && *v > 0.0)
                .ok_or_else(|| err(key, POSITIVE))
        };
        let positive_or_inf = |key: &str| {
            number(key)
                .filter(|v| *v > 0.0)
                .ok_or_else(|| err(key, "must be a number > 0, or inf"))
        };
        // A circular frequency given directly, or as a period T (ω = 2π/T).
        let frequency =
            |omega: &str, period: &str| match (t.contains_key(omega), t.contains_key(period)) {
                (true, false) => positive(omega),
                (false, true) => positive(period).map(|p| 2.0 * PI / p),
                (true, true) => Err(err(
                    omega,
                    "give either the frequency or the period, not both",
                )),
                (false, false) => Err(err(omega, "missing: give it in rad/s, or the period in s")),
            };
        let ap = match t.get("ap") {
            Some(toml::Value::String(s)) => parse_acceleration(s),
            Some(_) => number("ap").filter(|v| v.is_finite() && *v > 0.0),
            None => None,
        }
        .ok_or_else(|| {
            err(
                "ap",
                "must be an acceleration > 0 in m/s², or like \"0.5g\"",
            )
        })?;
        let omega_p = frequency("omega_p", "period_p")?;
        if !OMEGA_P.contains(&omega_p) {
            return Err(PhysicalError {
                context: TABLE,
                key: "omega_p".into(),
                value: super::params::echo::number(omega_p),
                allowed: OMEGA_P_ALLOWED,
            });
        }
        Ok(Physical {
            mass: [positive("m1")?, positive("m2")?],
            omega: [
                frequency("omega1", "period1")?,
                frequency("omega2", "period2")?,
            ],
            yield_displacement: [positive_or_inf("yield1")?, positive_or_inf("yield2")?],
            gap: number("gap")
                .filter(|v| *v >= 0.0)
                .ok_or_else(|| err("gap", "must be a number >= 0 in m, or inf"))?,
            damping: number("damping")
                .filter(|v| v.is_finite() && *v >= 0.0)
                .ok_or_else(|| err("damping", "must be a finite number >= 0"))?,
            alpha: number("alpha")
                .filter(|v| (0.0..=1.0).contains(v))
                .ok_or_else(|| err("alpha", "must be in [0, 1]"))?,
            contact_omega: positive("contact_omega")?,
            restitution: number("restitution")
                .filter(|v| *v > 0.0 && *v <= 1.0)
                .ok_or_else(|| err("restitution", "must be in (0, 1]"))?,
            hertz_beta: match t.contains_key("hertz_beta") {
                true => {
                    Some(positive("hertz_beta").map_err(|_| {
                        err("hertz_beta", "must be a finite number > 0 (N/m^{3/2})")
                    })?)
                }
                false => None,
            },
            ap,
            omega_p,
        })
    }

    /// The physical system whose Π-groups are those of `p`, at excitation
    /// a_p, ω_p and right-hand mass m2 (the inverse of [`Physical::to_params`]);
    /// β = Π_K m2 ω_p² / √l_e when `p` sets its own Π_K.
    pub fn from_params(p: &Params, ap: f64, omega_p: f64, m2: f64) -> Physical {
        let le = energy_length(ap, omega_p);
        let hertz_beta = (p.hertz_stiffness > 0.0)
            .then(|| p.hertz_stiffness * m2 * omega_p * omega_p / le.sqrt());
        Physical {
            mass: [p.mass_ratio * m2, m2],
            omega: [p.omega1 * omega_p, p.omega2 * omega_p],
            yield_displacement: [p.yield1 * le, p.yield2 * le],
            gap: p.gap * le,
            damping: p.damping,
            alpha: p.alpha,
            contact_omega: p.contact_omega * omega_p,
            restitution: p.restitution,
            hertz_beta,
            ap,
            omega_p,
        }
    }

    /// Π_K = β √l_e / (m2 ω_p²) (SPEC §10): f = β δ^{3/2} in newtons over
    /// m2 a_p, with δ = l_e δ̂, is Π_K δ̂^{3/2}.
    pub fn hertz_stiffness(&self, beta: f64) -> f64 {
        beta * self.length_scale().sqrt() / (self.mass[1] * self.omega_p * self.omega_p)
    }

    /// l_e = a_p/ω_p², metres per unit of Π_u.
    pub fn length_scale(&self) -> f64 {
        energy_length(self.ap, self.omega_p)
    }

    /// a_p/ω_p, metres per second per unit of Π_v.
    pub fn velocity_scale(&self) -> f64 {
        self.ap / self.omega_p
    }

    /// The Π-groups (SPEC §1); model, duration, Δτ and the grazing floor
    /// come from `settings`. The result is validated.
    pub fn to_params(&self, settings: &Params) -> Result<Params, ParamError> {
        let le = self.length_scale();
        if !(le.is_normal() && le > 0.0) {
            return Err(ParamError::OutOfRange {
                key: "ap",
                value: format!(
                    "{} m/s² at omega_p = {} rad/s",
                    super::params::echo::number(self.ap),
                    super::params::echo::number(self.omega_p)
                ),
                allowed: format!(
                    "the length scale a_p/ω_p² = {} m is not a usable number",
                    super::params::echo::number(le)
                ),
            });
        }
        let p = Params {
            mass_ratio: self.mass[0] / self.mass[1],
            omega1: self.omega[0] / self.omega_p,
            omega2: self.omega[1] / self.omega_p,
            yield1: self.yield_displacement[0] / le,
            yield2: self.yield_displacement[1] / le,
            damping: self.damping,
            alpha: self.alpha,
            contact_omega: self.contact_omega / self.omega_p,
            restitution: self.restitution,
            gap: self.gap / le,
            hertz_stiffness: self
                .hertz_beta
                .map_or(settings.hertz_stiffness, |b| self.hertz_stiffness(b)),
            ..settings.clone()
        };
        p.validate()?;
        Ok(p)
    }

    /// The Π-groups of these structures under a record (SPEC §12: suites are
    /// physical). The record's own a_p and ω_p (`motion`) are the base
    /// quantities, so l_e = a_p/ω_p² and every Π-group follow the record,
    /// while the masses, frequencies, yield displacements and gap stay those
    /// of the same buildings; the set names the record with that a_p and ω_p
    /// explicitly. Model, duration, Δτ and the grazing floor come from
    /// `settings`. The result is validated.
    pub fn under_record(
        &self,
        settings: &Params,
        motion: super::excitation::RecordMotion,
    ) -> Result<Params, ParamError> {
        let at_record = Physical {
            ap: motion.amplitude,
            omega_p: motion.omega,
            ..*self
        };
        at_record.to_params(&Params {
            record_scale: motion.scale,
            record_amplitude: motion.amplitude,
            record_omega: motion.omega,
            excitation: super::excitation::Excitation::Record(motion),
            ..settings.clone()
        })
    }

    /// The same structures under excitation amplitude `ap`. With `similar`
    /// the yield displacements and the gap scale with a_p, so every Π-group
    /// is unchanged (the paper's Figure 7), β scaling as 1/√(scale) to keep
    /// Π_K = β √l_e/(m2 ω_p²); without it they stay put, and Π_uy, Π_d fall
    /// and Π_K grows as a_p grows.
    pub fn at_level(&self, ap: f64, similar: bool) -> Physical {
        let scale = if similar { ap / self.ap } else { 1.0 };
        Physical {
            yield_displacement: self.yield_displacement.map(|u| u * scale),
            gap: self.gap * scale,
            hertz_beta: self.hertz_beta.map(|b| b / scale.sqrt()),
            ap,
            ..*self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn round_trips_through_params() {
        let phys = Physical::from_params(&SET1, 0.5 * G, 2.0 * PI, 1.0e6);
        let back = phys.to_params(&SET1).unwrap();
        for key in [
            "mass_ratio",
            "omega1",
            "omega2",
            "yield1",
            "yield2",
            "gap",
            "contact_omega",
        ] {
            let (a, b) = (back.get(key).unwrap(), SET1.get(key).unwrap());
            assert!((a - b).abs() <= 1e-14 * b.abs(), "{key}: {a} vs {b}");
        }
        // l_e = 0.5 g / (2π)² = 0.124203... m
        assert!((phys.length_scale() - 0.5 * 9.80665 / (4.0 * PI * PI)).abs() < 1e-15);
    }

    #[test]
    fn reads_a_table_and_names_bad_entries() {
        let text = "m1 = 5e5\nm2 = 1e6\nperiod1 = 1.0\nomega2 = 12.566370614359172\nyield1 = 0.1\nyield2 = inf\n\
                    gap = 0.02\ndamping = 0.05\nalpha = 0.1\ncontact_omega = 314.0\nrestitution = 0.4\n\
                    ap = \"0.5g\"\nomega_p = 6.283185307179586\n";
        let p = Physical::from_table(&text.parse().unwrap()).unwrap();
        assert!((p.omega[0] - 2.0 * PI).abs() < 1e-12);
        assert!((p.ap - 4.903325).abs() < 1e-12);
        assert!(p.yield_displacement[1].is_infinite());
        let q = p.to_params(&SET1).unwrap();
        assert!((q.omega1 - 1.0).abs() < 1e-12 && (q.omega2 - 2.0).abs() < 1e-12);
        let bad = text.replace("restitution = 0.4", "restitution = 1.4");
        let e = Physical::from_table(&bad.parse().unwrap()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "[physical] `restitution` = 1.4: must be in (0, 1]"
        );
        let bad = text.replace("period1 = 1.0", "");
        let e = Physical::from_table(&bad.parse().unwrap()).unwrap_err();
        assert!(e.to_string().contains("`omega1` = (missing)"), "{e}");
    }

    /// β = 1e9 N/m^{3/2}, m2 = 1e6 kg, a_p = 0.5 g, ω_p = 2π rad/s:
    /// l_e = 4.903325/(4π²) = 0.1242027... m, so Π_K = 1e9 · 0.3524241.../(1e6 · 39.4784176...)
    /// = 8.92704... (worked by hand from the definitions).
    #[test]
    fn hertz_beta_maps_to_pi_k_and_stays_self_similar() {
        let text = "m1 = 5e5\nm2 = 1e6\nomega1 = 6.6\nomega2 = 14.8\nyield1 = 0.1\nyield2 = 0.1\n\
                    gap = 0.02\ndamping = 0.05\nalpha = 0.1\ncontact_omega = 314.0\nrestitution = 0.4\n\
                    hertz_beta = 1e9\nap = \"0.5g\"\nomega_p = 6.283185307179586\n";
        let phys = Physical::from_table(&text.parse().unwrap()).unwrap();
        let le: f64 = 0.5 * G / (4.0 * PI * PI);
        assert!((le - 0.124_202_7).abs() < 1e-7);
        let by_hand = 1e9 * le.sqrt() / (1e6 * 4.0 * PI * PI);
        assert!((by_hand - 8.927_04).abs() < 1e-4, "{by_hand}");
        let p = phys.to_params(&SET1).unwrap();
        assert!((p.hertz_stiffness - by_hand).abs() < 1e-12 * by_hand);
        // Back through from_params: the same β.
        let again = Physical::from_params(&p, phys.ap, phys.omega_p, 1e6);
        assert!((again.hertz_beta.unwrap() - 1e9).abs() < 1e-3);
        // Self-similar levels keep Π_K; fixed structures see Π_K grow as √a_p.
        for level in [0.2, 0.8] {
            let similar = phys.at_level(level * G, true).to_params(&SET1).unwrap();
            assert!((similar.hertz_stiffness - by_hand).abs() < 1e-12 * by_hand);
            let fixed = phys.at_level(level * G, false).to_params(&SET1).unwrap();
            let grown = by_hand * (level / 0.5_f64).sqrt();
            assert!((fixed.hertz_stiffness - grown).abs() < 1e-12 * grown);
        }
        // Without the key the settings' Π_K (0: derived from Π_ωcon) stands.
        let none = text.replace("hertz_beta = 1e9\n", "");
        let q = Physical::from_table(&none.parse().unwrap()).unwrap();
        assert_eq!(q.hertz_beta, None);
        assert_eq!(
            q.to_params(&SET1).unwrap().hertz_stiffness,
            SET1.hertz_stiffness
        );
        let bad = text.replace("hertz_beta = 1e9", "hertz_beta = -1");
        let e = Physical::from_table(&bad.parse().unwrap()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "[physical] `hertz_beta` = -1: must be a finite number > 0 (N/m^{3/2})"
        );
    }

    #[test]
    fn accelerations() {
        assert_eq!(parse_acceleration("0.2g"), Some(0.2 * G));
        assert_eq!(parse_acceleration(" 1.5 "), Some(1.5));
        for bad in ["", "g", "-1g", "0", "inf", "x"] {
            assert_eq!(parse_acceleration(bad), None, "{bad}");
        }
    }
}
