//! Parameter families (SPEC §7): one spectrum curve per value of one key,
//! written `KEY=V1,V2,...` (e.g. `mass_ratio=0.1,0.5,0.9`, `gap=0.2,1.5,inf`,
//! `mu=1.5,4,10`). Any parameter key of a preset is allowed except the swept
//! `omega1`/`omega2`; `mu` = Π_ω2/Π_ω1 is the frequency-ratio family.

use std::fmt;

use crate::model::{ParamError, Params};

/// The family key of the frequency ratio μ = Π_ω2/Π_ω1.
pub const MU: &str = "mu";

/// Why a family was refused: one line naming the key, the value and the allowed range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FamilyError {
    #[error("--family `{0}`: expected KEY=V1,V2,..., e.g. mass_ratio=0.1,0.5,0.9")]
    Syntax(String),
    #[error(
        "--family `{0}`: omega1 and omega2 are swept by the spectrum; use `mu` for the frequency ratio"
    )]
    Swept(String),
    #[error("--family: {0}")]
    Value(#[from] ParamError),
    #[error("--family `mu` = {0}: must be a finite number > 0")]
    Mu(String),
}

/// One member of a family: the key's value as written and as a number.
#[derive(Debug, Clone, PartialEq)]
pub struct Member {
    pub key: String,
    /// The value as the user wrote it (`inf`, `kelvin`, `0.5`).
    pub text: String,
}

impl Member {
    /// The value for output: a finite number when it reads as one, else its text.
    pub fn json_value(&self) -> serde_json::Value {
        match self.text.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => serde_json::json!(v),
            _ => serde_json::Value::String(self.text.trim().to_string()),
        }
    }

    /// Applies the member to the base parameters and μ: returns the curve's
    /// parameters and frequency ratio.
    pub fn apply(&self, base: &Params, mu: f64) -> Result<(Params, f64), FamilyError> {
        if self.key == MU {
            return Ok((*base, parse_mu(&self.text)?));
        }
        let mut p = *base;
        p.set(&self.key, &self.text)?;
        Ok((p, mu))
    }
}

impl fmt::Display for Member {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}={}", self.key, self.text.trim())
    }
}

/// A family: one key and its values, each checked against the key's range.
#[derive(Debug, Clone, PartialEq)]
pub struct Family {
    pub key: String,
    pub members: Vec<Member>,
}

/// μ must be finite and positive (Π_ω2 = μ Π_ω1 ≥ 0).
pub fn parse_mu(text: &str) -> Result<f64, FamilyError> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(FamilyError::Mu(text.trim().to_string())),
    }
}

impl Family {
    /// Builds a family from a key and the values as text, checking each one
    /// on `base` (so an out-of-range value is refused before any run).
    pub fn new(key: &str, values: &[String], base: &Params) -> Result<Family, FamilyError> {
        let key = key.trim();
        let written = format!("{key}={}", values.join(","));
        if key == "omega1" || key == "omega2" {
            return Err(FamilyError::Swept(written));
        }
        if values.is_empty() || values.iter().any(|v| v.trim().is_empty()) {
            return Err(FamilyError::Syntax(written));
        }
        let members: Vec<Member> = values
            .iter()
            .map(|v| Member {
                key: key.to_string(),
                text: v.trim().to_string(),
            })
            .collect();
        for m in &members {
            m.apply(base, 1.0)?;
        }
        Ok(Family {
            key: key.to_string(),
            members,
        })
    }

    /// Parses `KEY=V1,V2,...`.
    pub fn parse(text: &str, base: &Params) -> Result<Family, FamilyError> {
        let (key, values) = text
            .split_once('=')
            .ok_or_else(|| FamilyError::Syntax(text.to_string()))?;
        let values: Vec<String> = values.split(',').map(str::to_string).collect();
        Family::new(key, &values, base)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn parses_and_applies() {
        let f = Family::parse("gap=0.2,1.5,inf", &SET1).unwrap();
        assert_eq!(f.members.len(), 3);
        let (p, mu) = f.members[2].apply(&SET1, 1.5).unwrap();
        assert!(p.gap.is_infinite());
        assert_eq!(mu, 1.5);
        assert_eq!(f.members[2].json_value(), serde_json::json!("inf"));
        assert_eq!(f.members[0].json_value(), serde_json::json!(0.2));
        let f = Family::parse("mu=1.5,4,10", &SET1).unwrap();
        assert_eq!(f.members[1].apply(&SET1, 1.5).unwrap().1, 4.0);
    }

    #[test]
    fn refuses_bad_families() {
        let msg = |t: &str| Family::parse(t, &SET1).unwrap_err().to_string();
        assert_eq!(
            msg("restitution=0.5,2"),
            "--family: `restitution` = 2: must be in (0, 1]"
        );
        assert!(msg("omega1=1,2").contains("swept"));
        assert!(msg("mass_ratio").contains("expected KEY=V1"));
        assert!(msg("mass_ratio=0.1,,0.2").contains("expected KEY=V1"));
        assert!(msg("mu=0,1").contains("`mu` = 0"));
        assert!(msg("bogus=1").contains("unknown parameter `bogus`"));
    }
}
