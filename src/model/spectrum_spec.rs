//! A preset's `[spectrum]` table: the grid, μ and family a spectrum uses
//! unless the command line overrides them.
//!
//! ```toml
//! [spectrum]
//! omega1 = "0.1:3.0:0.01"          # the Π_ω1 grid, START:STOP:STEP
//! mu = 1.5                         # Π_ω2 = μ Π_ω1
//! family = { gap = [0.2, 1.5, inf] }  # one curve per value (or "gap=0.2,1.5,inf")
//! ```

use std::collections::BTreeMap;

use super::family::{Family, mu_error, parse_mu};
use super::grid::Grid;
use super::params::{Params, echo};

/// The settings of a `[spectrum]` table; each is optional.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SpectrumSpec {
    pub grid: Option<Grid>,
    pub mu: Option<f64>,
    /// The family key and its values as text, checked when the curves are built.
    pub family: Option<(String, Vec<String>)>,
}

/// A `[spectrum]` entry that cannot be used: one line naming where, the key,
/// the value and the allowed form.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{origin}[spectrum] `{key}` = {value}: {allowed}")]
pub struct SpecError {
    /// `FILE:LINE: ` when known, else empty.
    pub origin: String,
    pub key: String,
    pub value: String,
    pub allowed: String,
}

/// A TOML scalar as the text a command-line flag would carry (`inf` for infinity).
fn scalar_text(v: &toml::Value) -> Option<String> {
    match v {
        toml::Value::Float(f) => Some(echo::number(*f)),
        toml::Value::Integer(i) => Some(i.to_string()),
        toml::Value::String(s) => Some(s.clone()),
        _ => None,
    }
}

/// A preset's own spectrum, resolved: its μ (else Π_ω2/Π_ω1), family (if
/// any) and grid (else the default), as its `[spectrum]` table gives them.
#[derive(Debug, Clone, PartialEq)]
pub struct PresetSpectrum {
    pub mu: f64,
    pub family: Option<Family>,
    pub grid: Grid,
}

impl PresetSpectrum {
    /// The spectrum a preset's `[spectrum]` table (if any) gives at its
    /// parameters `p` (as they are); the message of the table's or the
    /// family's error otherwise.
    pub fn of(table: Option<&toml::Table>, p: Params) -> Result<PresetSpectrum, String> {
        let spec = match table {
            Some(t) => SpectrumSpec::from_table(t).map_err(|e| e.to_string())?,
            None => SpectrumSpec::default(),
        };
        let family = match &spec.family {
            Some((key, values)) => {
                Some(Family::new(super::family::FLAG, key, values, &p).map_err(|e| e.to_string())?)
            }
            None => None,
        };
        Ok(PresetSpectrum {
            mu: spec.mu.unwrap_or_else(|| p.mu()),
            family,
            grid: spec.grid.unwrap_or_default(),
        })
    }
}

impl SpectrumSpec {
    /// Reads a `[spectrum]` table; unknown keys are refused.
    pub fn from_table(t: &toml::Table) -> Result<SpectrumSpec, SpecError> {
        let entries: BTreeMap<String, (toml::Value, String)> = t
            .iter()
            .map(|(k, v)| (k.clone(), (v.clone(), String::new())))
            .collect();
        SpectrumSpec::from_entries(&entries)
    }

    /// Reads `[spectrum]` entries, each with the origin (`FILE:LINE: `) its
    /// messages start with; unknown keys are refused.
    pub fn from_entries(
        entries: &BTreeMap<String, (toml::Value, String)>,
    ) -> Result<SpectrumSpec, SpecError> {
        let mut spec = SpectrumSpec::default();
        for (key, (value, origin)) in entries {
            let bad = |allowed: &str| SpecError {
                origin: origin.clone(),
                key: echo::text(key),
                value: echo::text(&value.to_string()),
                allowed: allowed.to_string(),
            };
            match key.as_str() {
                "omega1" => {
                    let text = value.as_str().ok_or_else(|| bad("must be a string START:STOP:STEP"))?;
                    spec.grid = Some(text.parse().map_err(|e: super::grid::GridError| bad(&e.allowed))?);
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

/// Checks a whole sweep before any run: every curve (each family member, or
/// `base` alone) at both ends of the grid, with Π_ω2 = μ Π_ω1, must pass
/// [`Params::validate`] — so Π_ω2 stays in its range and Δτ resolves the
/// shortest structural period at the grid's top. Returns the message.
pub fn check_sweep(
    base: &Params,
    grid: &Grid,
    mu: f64,
    family: Option<&Family>,
) -> Result<(), String> {
    let curves: Vec<(Params, f64, String)> = match family {
        None => vec![(base.clone(), mu, String::new())],
        Some(f) => f
            .members
            .iter()
            .map(|m| {
                m.apply(base, mu)
                    .map(|(p, mu)| (p, mu, format!(" (family {m})")))
            })
            .collect::<Result<_, _>>()
            .map_err(|e| e.to_string())?,
    };
    for (p, mu, which) in curves {
        for w in [grid.start, grid.stop] {
            let q = Params {
                omega1: w,
                omega2: mu * w,
                ..p.clone()
            };
            q.validate().map_err(|e| {
                format!(
                    "at omega1 = {}, omega2 = mu·omega1 = {}{which} of the grid {grid}: {e}",
                    echo::number(w),
                    echo::number(mu * w)
                )
            })?;
        }
    }
    Ok(())
}

/// μ from its text, or the one-line message naming it.
pub fn mu_from_text(text: &str) -> Result<f64, String> {
    parse_mu(text).ok_or_else(|| mu_error(text))
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
    fn checks_the_sweep_at_the_grid_ends() {
        use crate::model::SET1;
        let grid: Grid = "0.1:3:0.01".parse().unwrap();
        check_sweep(&SET1, &grid, 2.25, None).unwrap();
        // μ = 1000 puts Π_ω2 = 3000 above its range at the top of the grid.
        let e = check_sweep(&SET1, &grid, 1000.0, None).unwrap_err();
        assert!(
            e.contains("at omega1 = 3, omega2 = mu·omega1 = 3000"),
            "{e}"
        );
        assert!(e.contains("`omega2` = 3000"), "{e}");
        let family = Family::parse("dt=0.001,0.05", &SET1).unwrap();
        let e = check_sweep(&SET1, &grid, 2.25, Some(&family)).unwrap_err();
        assert!(
            e.contains("(family dt=0.05)") && e.contains("`dt` = 0.05"),
            "{e}"
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
