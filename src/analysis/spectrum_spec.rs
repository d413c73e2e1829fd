//! A preset's `[spectrum]` table: the grid, μ and family a spectrum uses
//! unless the command line overrides them.
//!
//! ```toml
//! [spectrum]
//! omega1 = "0.1:3.0:0.01"          # the Π_ω1 grid, START:STOP:STEP
//! mu = 1.5                         # Π_ω2 = μ Π_ω1
//! family = { gap = [0.2, 1.5, inf] }  # one curve per value (or "gap=0.2,1.5,inf")
//! ```

use super::grid::Grid;

/// The settings of a `[spectrum]` table; each is optional.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SpectrumSpec {
    pub grid: Option<Grid>,
    pub mu: Option<f64>,
    /// The family key and its values as text, checked when the curves are built.
    pub family: Option<(String, Vec<String>)>,
}

/// A `[spectrum]` entry that cannot be used: one line naming key, value and the allowed form.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("[spectrum] `{key}` = {value}: {allowed}")]
pub struct SpecError {
    pub key: String,
    pub value: String,
    pub allowed: String,
}

/// A TOML scalar as the text a command-line flag would carry (`inf` for infinity).
fn scalar_text(v: &toml::Value) -> Option<String> {
    match v {
        toml::Value::Float(f) if f.is_infinite() => {
            Some(if *f > 0.0 { "inf" } else { "-inf" }.into())
        }
        toml::Value::Float(f) => Some(f.to_string()),
        toml::Value::Integer(i) => Some(i.to_string()),
        toml::Value::String(s) => Some(s.clone()),
        _ => None,
    }
}

impl SpectrumSpec {
    /// Reads a `[spectrum]` table; unknown keys are refused.
    pub fn from_table(t: &toml::Table) -> Result<SpectrumSpec, SpecError> {
        let mut spec = SpectrumSpec::default();
        for (key, value) in t {
            let bad = |allowed: &str| SpecError {
                key: key.clone(),
                value: value.to_string(),
                allowed: allowed.to_string(),
            };
            match key.as_str() {
                "omega1" => {
                    let text = value.as_str().ok_or_else(|| bad("must be a string START:STOP:STEP"))?;
                    spec.grid = Some(text.parse().map_err(|e: super::grid::GridError| bad(e.allowed))?);
                }
                "mu" => {
                    let mu = value
                        .as_float()
                        .or_else(|| value.as_integer().map(|i| i as f64))
                        .filter(|m| m.is_finite() && *m > 0.0)
                        .ok_or_else(|| bad("must be a finite number > 0"))?;
                    spec.mu = Some(mu);
                }
                "family" => spec.family = Some(family_entry(value).ok_or_else(|| {
                    bad("must be a table with one key, e.g. { gap = [0.2, 1.5, inf] }, or \"KEY=V1,V2\"")
                })?),
                _ => return Err(bad("unknown key (known: omega1, mu, family)")),
            }
        }
        Ok(spec)
    }
}

fn family_entry(value: &toml::Value) -> Option<(String, Vec<String>)> {
    match value {
        toml::Value::String(s) => {
            let (k, v) = s.split_once('=')?;
            Some((
                k.trim().to_string(),
                v.split(',').map(|x| x.trim().to_string()).collect(),
            ))
        }
        toml::Value::Table(t) if t.len() == 1 => {
            let (k, v) = t.iter().next()?;
            let values = v
                .as_array()?
                .iter()
                .map(scalar_text)
                .collect::<Option<Vec<_>>>()?;
            Some((k.clone(), values))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(text: &str) -> Result<SpectrumSpec, SpecError> {
        SpectrumSpec::from_table(&text.parse().unwrap())
    }

    #[test]
    fn reads_every_form() {
        let s =
            spec("omega1 = \"0.5:1:0.25\"\nmu = 2\nfamily = { gap = [0.2, 1.5, inf] }").unwrap();
        assert_eq!(s.grid.unwrap().values(), vec![0.5, 0.75, 1.0]);
        assert_eq!(s.mu, Some(2.0));
        assert_eq!(
            s.family.unwrap(),
            ("gap".into(), vec!["0.2".into(), "1.5".into(), "inf".into()])
        );
        let s = spec("family = \"mu=1.5, 4\"").unwrap();
        assert_eq!(
            s.family.unwrap(),
            ("mu".into(), vec!["1.5".into(), "4".into()])
        );
    }

    #[test]
    fn refuses_bad_entries() {
        let msg = |t: &str| spec(t).unwrap_err().to_string();
        assert_eq!(
            msg("mu = -1"),
            "[spectrum] `mu` = -1: must be a finite number > 0"
        );
        assert!(msg("omega1 = \"1:0:0.1\"").contains("START <= STOP"));
        assert!(msg("grid = 1").contains("unknown key"));
        assert!(msg("family = { gap = [0.2], mu = [1] }").contains("one key"));
    }
}
