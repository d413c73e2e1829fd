//! The options every simulating command shares: which preset, which
//! overrides. Resolved once into a validated [`Params`].

use std::path::PathBuf;

use clap::Args;

use super::CliError;
use crate::model::excitation::ExcitationError;
use crate::model::physical::Physical;
use crate::model::{Excitation, Params, Preset};

#[derive(Debug, Clone, Default, Args)]
pub struct ParamArgs {
    /// Built-in preset name (set1, set2, ...) or a path to a preset file [default: set1].
    #[arg(long, value_name = "NAME|PATH")]
    pub preset: Option<String>,
    /// Override one parameter, e.g. --set gap=0.5 (repeatable; keys as in presets).
    #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
    pub overrides: Vec<String>,
    /// Contact law (SPEC §4, §10).
    #[arg(long, value_parser = ["kelvin", "improved-kelvin", "hertz", "hertzdamp", "jankowski", "hunt-crossley"])]
    pub model: Option<String>,
    /// Ground motion (SPEC §9): sine, pulse-a, pulse-b, pulse-c1, pulse-c2, or
    /// record:PATH for a recorded accelerogram: a PEER NGA .AT2 file (in g), or
    /// plain columns of time (s) and acceleration, record:PATH@UNIT with UNIT
    /// g, m/s2 or cm/s2 [default unit: g].
    #[arg(long, value_name = "NAME|record:PATH")]
    pub excitation: Option<String>,
    /// Integrator: newmark (Newmark-β, the paper's; default of `run`) or exact
    /// (event-driven; default of the commands that run many cases).
    #[arg(long, value_parser = ["newmark", "exact"])]
    pub method: Option<String>,
    /// Newmark time step Δτ.
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub dt: Option<String>,
    /// Duration in excitation cycles.
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub cycles: Option<String>,
    /// No contact at all (gap = inf): the no-pounding baseline.
    #[arg(long)]
    pub no_pounding: bool,
    /// Directory of the user's own presets [default: $XDG_CONFIG_HOME/pounding/presets].
    #[arg(long, value_name = "DIR")]
    pub presets: Option<PathBuf>,
}

/// The user's preset directory: `--presets DIR`, else
/// `$XDG_CONFIG_HOME/pounding/presets`, else `~/.config/pounding/presets`.
pub fn user_preset_dir(explicit: Option<&PathBuf>) -> Option<PathBuf> {
    if let Some(d) = explicit {
        return Some(d.clone());
    }
    let base = std::env::var_os("XDG_CONFIG_HOME")
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".config")))?;
    Some(base.join("pounding").join("presets"))
}

/// Sets the excitation, with a record's own message (file and line) when
/// `record:PATH` cannot be read.
fn set_excitation(p: &mut Params, text: &str) -> Result<(), CliError> {
    match Excitation::parse(text) {
        Ok(e) => {
            p.excitation = e;
            Ok(())
        }
        Err(ExcitationError::Record(e)) => Err(CliError::Usage(e.to_string())),
        Err(ExcitationError::Unknown) => Ok(p.set("excitation", text)?),
    }
}

impl ParamArgs {
    /// The preset's buildings in SI (its `[physical]` table, SPEC §8), or
    /// `None` without one. Their Π-groups then come from that table and
    /// the excitation's a_p and ω_p, so a `--set` of a Π key is refused.
    pub fn physical(&self, preset: &Preset) -> Result<Option<Physical>, CliError> {
        let Some(table) = &preset.physical else {
            return Ok(None);
        };
        if let Some(kv) = self
            .overrides
            .iter()
            .find(|kv| crate::model::params::is_pi(kv.split('=').next().unwrap_or("").trim()))
        {
            return Err(CliError::Usage(format!(
                "--set `{}`: preset `{}` gives this in physical units; edit its [physical] table",
                crate::model::params::echo::text(kv),
                preset.name
            )));
        }
        Physical::from_table(table)
            .map(Some)
            .map_err(|e| CliError::Usage(format!("{}: {e}", preset.name)))
    }

    /// The preset, with every override applied and validated. A `dt` too
    /// coarse for the contact is a warning on stderr, not an error.
    /// As [`ParamArgs::resolve`], for a command that runs many cases
    /// (spectra, similarity): unless `--method` or `--set method=` names
    /// one, they use the exact method, whatever the preset names.
    pub fn resolve_for_many(&self) -> Result<(Preset, Params), CliError> {
        let (preset, mut p) = self.resolve()?;
        let named = self.method.is_some()
            || self.overrides.iter().any(|kv| {
                kv.split_once('=')
                    .is_some_and(|(k, _)| k.trim() == "method")
            });
        if !named {
            p.method = crate::model::Method::Exact;
        }
        Ok((preset, p))
    }

    pub fn resolve(&self) -> Result<(Preset, Params), CliError> {
        let dirs: Vec<PathBuf> = user_preset_dir(self.presets.as_ref()).into_iter().collect();
        let preset = Preset::find(self.preset.as_deref().unwrap_or("set1"), &dirs)?;
        let mut p = preset.params.clone();
        for kv in &self.overrides {
            let (key, value) = kv.split_once('=').ok_or_else(|| {
                CliError::Usage(format!(
                    "--set `{}`: expected KEY=VALUE, e.g. --set gap=0.5",
                    crate::model::params::echo::text(kv)
                ))
            })?;
            if key.trim() == "excitation" {
                set_excitation(&mut p, value)?;
            } else {
                p.set(key.trim(), value)?;
            }
        }
        if let Some(e) = &self.excitation {
            set_excitation(&mut p, e)?;
        }
        if let Some(m) = &self.model {
            p.set("model", m)?;
        }
        if let Some(m) = &self.method {
            p.set("method", m)?;
        }
        if let Some(dt) = &self.dt {
            p.set("dt", dt)?;
        }
        if let Some(c) = &self.cycles {
            p.set("cycles", c)?;
        }
        // A physical preset under a record: the record's own a_p and ω_p
        // set the Π-groups of the same buildings (SPEC §12), as in a suite.
        if let Excitation::Record(motion) = p.ground()
            && let Some(physical) = self.physical(&preset)?.filter(|_| motion.record.peak > 0.0)
        {
            p = physical.under_record(&p, motion)?;
        }
        if self.no_pounding {
            p.gap = f64::INFINITY;
        }
        p.validate()?;
        if let Some(w) = p
            .coarse_dt_warning()
            .filter(|_| p.method == crate::model::Method::Newmark)
        {
            eprintln!("{w}");
        }
        Ok((preset, p))
    }
}
