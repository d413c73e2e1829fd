//! Presets: a named [`Params`] stored as flat TOML keys (the keys of SPEC §1
//! and the run settings), with a `name`, a one-line `description`, and
//! optional `[spectrum]` and `[physical]` tables read by the commands that use
//! them. Built-in presets (`presets/*.toml`) are compiled into the binary.

use std::fmt;
use std::path::{Path, PathBuf};

use super::params::{ParamError, Params};

include!(concat!(env!("OUT_DIR"), "/builtin_presets.rs"));

/// A parameter set with its name and what it is for.
#[derive(Debug, Clone, PartialEq)]
pub struct Preset {
    pub name: String,
    pub description: String,
    pub params: Params,
    /// The `[spectrum]` table (grid, mu, family), if any: read by `pounding spectrum`.
    pub spectrum: Option<toml::Table>,
    /// The `[physical]` table (physical units, SPEC §8), if any; when present,
    /// `params` holds its Π-groups.
    pub physical: Option<toml::Table>,
    /// Where it came from: `None` for a built-in.
    pub path: Option<PathBuf>,
}

/// Why a preset could not be found, read or parsed.
#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    #[error("no preset named `{name}` (built-in: {}{})", builtin_names().join(", "), user_hint(.user))]
    NotFound { name: String, user: Vec<String> },
    #[error("{file}: {source}")]
    Io {
        file: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        file: String,
        line: usize,
        column: usize,
        message: String,
    },
    #[error("{file}: {message}")]
    Physical { file: String, message: String },
    #[error("{file}: {source}")]
    Value {
        file: String,
        #[source]
        source: ParamError,
    },
}

fn user_hint(user: &[String]) -> String {
    if user.is_empty() {
        String::new()
    } else {
        format!("; yours: {}", user.join(", "))
    }
}

/// Names of the built-in presets.
pub fn builtin_names() -> Vec<&'static str> {
    BUILTIN.iter().map(|(name, _, _)| *name).collect()
}

/// Is `name` one of the built-in presets?
pub fn is_builtin(name: &str) -> bool {
    BUILTIN.iter().any(|(n, _, _)| *n == name)
}

/// A built-in preset by name.
pub fn builtin(name: &str) -> Option<Preset> {
    let (_, file, text) = BUILTIN.iter().find(|(n, _, _)| *n == name)?;
    // Built-ins are checked by the test suite, so this parse cannot fail in a shipped binary.
    Preset::parse(text, file).ok().map(|mut p| {
        p.name = name.to_string();
        p
    })
}

/// Every built-in preset: the paper's sets first, then the rest by name.
pub fn builtins() -> Vec<Preset> {
    builtin_names().into_iter().filter_map(builtin).collect()
}

/// Line and column (1-based) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The text form of a TOML value as `Params::set` reads it.
fn value_text(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(f) if f.is_infinite() => if *f > 0.0 { "inf" } else { "-inf" }.into(),
        toml::Value::Float(f) if f.is_nan() => "NaN".into(),
        other => other.to_string(),
    }
}

impl Preset {
    /// Parses preset text; `file` names it in error messages. Unspecified
    /// keys keep the defaults of set 1, so a preset may list only what differs.
    pub fn parse(text: &str, file: &str) -> Result<Preset, PresetError> {
        let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
            let (line, column) = e.span().map_or((1, 1), |s| line_column(text, s.start));
            PresetError::Syntax {
                file: file.into(),
                line,
                column,
                message: e.message().trim().to_string(),
            }
        })?;
        let value_err = |source| PresetError::Value {
            file: file.into(),
            source,
        };
        let mut preset = Preset {
            name: Path::new(file)
                .file_stem()
                .map_or_else(String::new, |s| s.to_string_lossy().into()),
            description: String::new(),
            params: Params::default(),
            spectrum: None,
            physical: None,
            path: None,
        };
        for (key, value) in table {
            match (key.as_str(), value) {
                ("name", toml::Value::String(s)) => preset.name = s,
                ("description", toml::Value::String(s)) => preset.description = s,
                ("spectrum", toml::Value::Table(t)) => preset.spectrum = Some(t),
                ("physical", toml::Value::Table(t)) => preset.physical = Some(t),
                (_, v @ toml::Value::Table(_)) | (_, v @ toml::Value::Array(_)) => {
                    return Err(value_err(ParamError::OutOfRange {
                        key: "preset",
                        value: format!("{key} = {v}"),
                        allowed: "is not a known table or parameter",
                    }));
                }
                (k, v) => preset.params.set(k, &value_text(&v)).map_err(value_err)?,
            }
        }
        // A [physical] table (SPEC §8) gives the Π-groups in physical units;
        // the flat keys then only set the run settings (model, cycles, dt, ...).
        if let Some(table) = &preset.physical {
            let physical = super::physical::Physical::from_table(table).map_err(|e| {
                PresetError::Physical {
                    file: file.into(),
                    message: e.to_string(),
                }
            })?;
            preset.params = physical.to_params(&preset.params).map_err(value_err)?;
        }
        preset.params.validate().map_err(value_err)?;
        Ok(preset)
    }

    /// Reads a preset file.
    pub fn load(path: &Path) -> Result<Preset, PresetError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|source| PresetError::Io {
            file: file.clone(),
            source,
        })?;
        let mut p = Preset::parse(&text, &file)?;
        p.path = Some(path.to_path_buf());
        Ok(p)
    }

    /// Finds a preset by path or by name: an existing file path is loaded;
    /// otherwise the name is looked up among the user's `dirs` (as
    /// `DIR/NAME.toml`) and then the built-ins.
    pub fn find(name_or_path: &str, dirs: &[PathBuf]) -> Result<Preset, PresetError> {
        let as_path = Path::new(name_or_path);
        if as_path.is_file() {
            return Preset::load(as_path);
        }
        for dir in dirs {
            let candidate = dir.join(format!("{name_or_path}.toml"));
            if candidate.is_file() {
                return Preset::load(&candidate);
            }
        }
        builtin(name_or_path).ok_or_else(|| PresetError::NotFound {
            name: name_or_path.to_string(),
            user: dirs.iter().flat_map(|d| user_preset_names(d)).collect(),
        })
    }

    /// The preset as TOML, flat keys as in `presets/` (tables kept).
    pub fn to_toml(&self) -> String {
        let p = &self.params;
        let num = |v: f64| {
            if v.is_infinite() {
                "inf".to_string()
            } else {
                format!("{v:?}")
            }
        };
        let mut s = format!(
            "name = {:?}\ndescription = {:?}\nmass_ratio = {}\nomega1 = {}\nomega2 = {}\nyield1 = {}\nyield2 = {}\n\
             damping = {}\nalpha = {}\ncontact_omega = {}\nrestitution = {}\ngap = {}\nmodel = \"{}\"\n\
             cycles = {}\ndt = {}\nmin_impact_velocity = {}\n",
            self.name,
            self.description,
            num(p.mass_ratio),
            num(p.omega1),
            num(p.omega2),
            num(p.yield1),
            num(p.yield2),
            num(p.damping),
            num(p.alpha),
            num(p.contact_omega),
            num(p.restitution),
            num(p.gap),
            p.model,
            p.cycles,
            num(p.dt),
            num(p.min_impact_velocity),
        );
        for (name, table) in [("spectrum", &self.spectrum), ("physical", &self.physical)] {
            if let Some(t) = table {
                s += &format!("\n[{name}]\n{t}");
            }
        }
        s
    }

    /// Writes the preset to `path` by the rules of [`crate::output`] (a
    /// regular file is replaced atomically, a read-only one refused). The
    /// folder is created if missing: presets are saved into the program's
    /// own preset folder.
    pub fn save(&self, path: &Path) -> std::io::Result<()> {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)?;
        }
        crate::output::write_file(path, self.to_toml().as_bytes())
            .map_err(|e| std::io::Error::other(e.reason()))
    }
}

impl fmt::Display for Preset {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.name, self.description)
    }
}

/// Names of the `*.toml` presets in a user directory, sorted.
pub fn user_preset_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .filter_map(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{SET1, SET2};

    #[test]
    fn builtins_match_the_paper() {
        assert_eq!(builtin("set1").unwrap().params, SET1);
        assert_eq!(builtin("set2").unwrap().params, SET2);
        for p in builtins() {
            assert!(!p.description.is_empty(), "{} has no description", p.name);
        }
    }

    #[test]
    fn syntax_error_names_line_and_column() {
        let e = Preset::parse("mass_ratio = 0.5\ngap = = 1\n", "x.toml").unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with("x.toml:2:"), "{msg}");
    }

    #[test]
    fn value_error_names_file_and_key() {
        let e = Preset::parse("restitution = 1.5\n", "x.toml").unwrap_err();
        assert_eq!(
            e.to_string(),
            "x.toml: `restitution` = 1.5: must be in (0, 1]"
        );
        let e = Preset::parse("bogus = 1\n", "x.toml").unwrap_err();
        assert!(e.to_string().contains("unknown parameter `bogus`"));
    }

    #[test]
    fn round_trips_through_toml() {
        let mut p = builtin("set1").unwrap();
        p.params.gap = f64::INFINITY;
        p.params.yield1 = f64::INFINITY;
        let back = Preset::parse(&p.to_toml(), "y.toml").unwrap();
        assert_eq!(back.params, p.params);
        assert_eq!(back.description, p.description);
    }
}
