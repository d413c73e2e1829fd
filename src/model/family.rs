//! Parameter families (SPEC §7): one spectrum curve per value of one key,
//! written `KEY=V1,V2,...` (e.g. `mass_ratio=0.1,0.5,0.9`, `gap=0.2,1.5,inf`,
//! `mu=1.5,4,10`). Any parameter key of a preset is allowed except the swept
//! `omega1`/`omega2`; `mu` = Π_ω2/Π_ω1 is the frequency-ratio family.

use std::fmt;

use super::params::{ParamError, Params, echo};

/// The family key of the frequency ratio μ = Π_ω2/Π_ω1.
pub const MU: &str = "mu";

/// Where a family was written, for messages: the flag, or a preset's file and line.
pub const FLAG: &str = "--family";

/// Why a family was refused: one line naming where it was written, the key,
/// the value and the allowed range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{origin}: {detail}")]
pub struct FamilyError {
    /// `--family`, or `FILE:LINE: [spectrum] family`.
    pub origin: String,
    pub detail: String,
}

/// One member of a family: the key's value as written.
#[derive(Debug, Clone, PartialEq)]
pub struct Member {
    pub key: String,
    /// The value as the user wrote it (`inf`, `kelvin`, `0.5`).
    pub text: String,
    /// Where the family was written (see [`FamilyError::origin`]).
    pub origin: String,
}

impl Member {
    /// The value for output: a finite number when it reads as one, else its text.
    pub fn json_value(&self) -> serde_json::Value {
        match self.text.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => serde_json::json!(v),
            _ => serde_json::Value::String(self.text.trim().to_string()),
        }
    }

    fn error(&self, detail: impl fmt::Display) -> FamilyError {
        FamilyError {
            origin: self.origin.clone(),
            detail: detail.to_string(),
        }
    }

    /// Applies the member to the base parameters and μ: returns the curve's
    /// parameters (validated as a whole) and frequency ratio.
    pub fn apply(&self, base: &Params, mu: f64) -> Result<(Params, f64), FamilyError> {
        if self.key == MU {
            let mu = parse_mu(&self.text).ok_or_else(|| self.error(mu_error(&self.text)))?;
            return Ok((base.clone(), mu));
        }
        let mut p = base.clone();
        p.set(&self.key, &self.text)
            .and_then(|()| p.validate())
            .map_err(|e: ParamError| self.error(e))?;
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

/// μ must be finite and positive (Π_ω2 = μ Π_ω1 > 0); the frequencies it
/// gives are checked against their ranges at the grid's ends.
pub fn parse_mu(text: &str) -> Option<f64> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && *v > 0.0)
}

/// The message for a μ that [`parse_mu`] refused.
pub fn mu_error(text: &str) -> String {
    format!(
        "`mu` = {}: must be a finite number > 0",
        echo::text(text.trim())
    )
}

impl Family {
    /// Builds a family from a key and the values as text, checking each one
    /// on `base` (so an out-of-range value is refused before any run).
    /// `origin` says where it was written: [`FLAG`], or a preset's file and line.
    pub fn new(
        origin: &str,
        key: &str,
        values: &[String],
        base: &Params,
    ) -> Result<Family, FamilyError> {
        let key = key.trim();
        let error = |detail: String| FamilyError {
            origin: origin.to_string(),
            detail,
        };
        let written = echo::text(&format!("{key}={}", values.join(",")));
        if key == "omega1" || key == "omega2" {
            return Err(error(format!(
                "`{written}`: omega1 and omega2 are swept by the spectrum; use `mu` for the frequency ratio"
            )));
        }
        if key.is_empty() || values.is_empty() || values.iter().any(|v| v.trim().is_empty()) {
            return Err(error(format!(
                "`{written}`: expected KEY=V1,V2,..., e.g. mass_ratio=0.1,0.5,0.9"
            )));
        }
        let members: Vec<Member> = values
            .iter()
            .map(|v| Member {
                key: key.to_string(),
                text: v.trim().to_string(),
                origin: origin.to_string(),
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

    /// Parses `KEY=V1,V2,...` as given to `--family`.
    pub fn parse(text: &str, base: &Params) -> Result<Family, FamilyError> {
        let Some((key, values)) = text.split_once('=') else {
            return Err(FamilyError {
                origin: FLAG.into(),
                detail: format!(
                    "`{}`: expected KEY=V1,V2,..., e.g. mass_ratio=0.1,0.5,0.9",
                    echo::text(text)
                ),
            });
        };
        let values: Vec<String> = values.split(',').map(str::to_string).collect();
        Family::new(FLAG, key, &values, base)
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
            "--family: `restitution` = 2: must be a number in [0.001, 1]"
        );
        // Every member is validated as a whole: Δτ = 1e-9 is below Δτ's range.
        assert!(msg("dt=0.001,1e-9").contains("`dt` = 1e-9"));
        assert!(msg("omega1=1,2").contains("swept"));
        assert!(msg("mass_ratio").contains("expected KEY=V1"));
        assert!(msg("mass_ratio=0.1,,0.2").contains("expected KEY=V1"));
        assert!(msg("mu=0,1").contains("`mu` = 0"));
        assert!(msg("bogus=1").contains("unknown parameter `bogus`"));
    }
}
