//! Presets: a named [`Params`] stored as flat TOML keys (the keys of the
//! parameter table: SPEC §1 and the run settings), with a `name`, a one-line
//! `description`, and optional `[spectrum]` and `[physical]` tables. Every
//! part is checked when the preset is read, whichever command reads it; each
//! message names the file and, where it can, the line. Built-in presets
//! (`presets/*.toml`) are compiled into the binary.
//!
//! Read and written with serde: the file is deserialized into spanned TOML
//! values (for line numbers), each parameter value then goes through its
//! row of the table; [`Preset::to_toml`] serializes [`Params`] itself.

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use toml::Spanned;

use super::params::{ParamError, Params, echo, is_pi};
use super::spectrum_spec::{SpectrumSpec, check_sweep};

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
    /// `FILE:LINE` of each entry (`gap`, `spectrum.family`, ...), for messages
    /// about it after the preset was read.
    pub lines: BTreeMap<String, String>,
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
    /// Any other entry that cannot be used; `place` is `FILE` or `FILE:LINE`.
    #[error("{place}: {message}")]
    Entry { place: String, message: String },
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
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The text form of a TOML value as `Params::set` reads it.
fn value_text(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(f) => echo::number(*f),
        other => other.to_string(),
    }
}

/// A TOML value as a message shows it: one line, cut.
fn shown(v: &toml::Value) -> String {
    echo::text(&v.to_string())
}

/// The `[spectrum]` table with the span of each entry (read on its own, as
/// serde gives spans only to values it deserializes directly).
#[derive(Deserialize)]
struct SpectrumDoc {
    spectrum: Option<BTreeMap<String, Spanned<toml::Value>>>,
}

/// A preset as written back: name and description, every parameter key of
/// the table (serialized by [`Params`] itself), then the tables.
#[derive(Serialize)]
struct PresetOut<'a> {
    name: &'a str,
    description: &'a str,
    #[serde(flatten)]
    params: toml::Table,
    #[serde(skip_serializing_if = "Option::is_none")]
    spectrum: Option<&'a toml::Table>,
    #[serde(skip_serializing_if = "Option::is_none")]
    physical: Option<&'a toml::Table>,
}

impl Preset {
    /// Parses preset text; `file` names it in error messages. Unspecified
    /// keys keep the defaults of set 1, so a preset may list only what differs.
    pub fn parse(text: &str, file: &str) -> Result<Preset, PresetError> {
        let syntax = |e: toml::de::Error| {
            let (line, column) = e.span().map_or((1, 1), |s| line_column(text, s.start));
            PresetError::Syntax {
                file: file.into(),
                line,
                column,
                message: echo::text(e.message().trim()),
            }
        };
        let doc: BTreeMap<String, Spanned<toml::Value>> = toml::from_str(text).map_err(syntax)?;
        let at =
            |span: std::ops::Range<usize>| format!("{file}:{}", line_column(text, span.start).0);
        let entry = |place: String, message: String| PresetError::Entry { place, message };
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
            lines: BTreeMap::new(),
        };
        let mut physical_at = None;
        for (key, spanned) in &doc {
            let place = at(spanned.span());
            preset.lines.insert(key.clone(), place.clone());
            match (key.as_str(), spanned.get_ref()) {
                ("name", toml::Value::String(s)) => preset.name = s.clone(),
                ("description", toml::Value::String(s)) => preset.description = s.clone(),
                ("name" | "description", v) => {
                    return Err(entry(
                        place,
                        format!("`{key}` = {}: must be a string in quotes", shown(v)),
                    ));
                }
                ("spectrum", toml::Value::Table(t)) => preset.spectrum = Some(t.clone()),
                ("physical", toml::Value::Table(t)) => {
                    preset.physical = Some(t.clone());
                    physical_at = Some(place);
                }
                (_, v @ (toml::Value::Table(_) | toml::Value::Array(_))) => {
                    return Err(entry(
                        place,
                        format!(
                            "`{}` = {}: is not a known table (spectrum, physical) or parameter",
                            echo::text(key),
                            shown(v)
                        ),
                    ));
                }
                (k, v) => preset
                    .params
                    .set(k, &value_text(v))
                    .map_err(|e| entry(place, e.to_string()))?,
            }
        }
        // A [physical] table (SPEC §8) gives the Π-groups in physical units;
        // the flat keys then only set the run settings (model, cycles, dt, ...).
        if let (Some(table), Some(physical_at)) = (&preset.physical, physical_at) {
            if let Some(key) = doc.keys().find(|k| is_pi(k)) {
                return Err(entry(
                    preset.lines[key].clone(),
                    format!(
                        "`{key}` and the [physical] table ({physical_at}) both give {key}: \
                         a preset with [physical] takes its Π-groups from it; remove one"
                    ),
                ));
            }
            let physical = super::physical::Physical::from_table(table).map_err(|e| {
                PresetError::Physical {
                    file: physical_at.clone(),
                    message: e.to_string(),
                }
            })?;
            preset.params =
                physical
                    .to_params(&preset.params)
                    .map_err(|e| PresetError::Physical {
                        file: physical_at.clone(),
                        message: format!("[physical] gives {e}"),
                    })?;
        }
        preset.params.validate().map_err(value_err)?;
        if preset.spectrum.is_some() {
            preset.check_spectrum(text, file)?;
        }
        Ok(preset)
    }

    /// Checks the `[spectrum]` table as `pounding spectrum` would use it:
    /// each entry, its family on this preset's parameters, and the whole
    /// sweep at the grid's ends.
    fn check_spectrum(&mut self, text: &str, file: &str) -> Result<(), PresetError> {
        let doc: SpectrumDoc = toml::from_str(text).map_err(|e| PresetError::Entry {
            place: file.into(),
            message: format!("[spectrum]: {}", echo::text(e.message().trim())),
        })?;
        let entries: BTreeMap<String, (toml::Value, String)> = doc
            .spectrum
            .unwrap_or_default()
            .into_iter()
            .map(|(k, v)| {
                let place = format!("{file}:{}", line_column(text, v.span().start).0);
                self.lines.insert(format!("spectrum.{k}"), place.clone());
                (k, (v.into_inner(), format!("{place}: ")))
            })
            .collect();
        let spec = SpectrumSpec::from_entries(&entries).map_err(|e| PresetError::Entry {
            place: e.origin.trim_end_matches([':', ' ']).to_string(),
            message: format!("[spectrum] `{}` = {}: {}", e.key, e.value, e.allowed),
        })?;
        let family = match &spec.family {
            Some((key, values)) => Some(
                super::family::Family::new(
                    &self.origin("spectrum.family"),
                    key,
                    values,
                    &self.params,
                )
                .map_err(|e| PresetError::Entry {
                    place: e.origin,
                    message: e.detail,
                })?,
            ),
            None => None,
        };
        let mu = spec.mu.unwrap_or_else(|| self.params.mu());
        check_sweep(
            &self.params,
            &spec.grid.unwrap_or_default(),
            mu,
            family.as_ref(),
        )
        .map_err(|message| PresetError::Entry {
            place: file.into(),
            message: format!("[spectrum]: {message}"),
        })
    }

    /// `FILE:LINE: [spectrum] family`-style origin of an entry, for messages
    /// about it after the preset was read (the preset's name when unknown).
    pub fn origin(&self, key: &str) -> String {
        let label = match key.split_once('.') {
            Some((table, k)) => format!("[{table}] {k}"),
            None => key.to_string(),
        };
        match self.lines.get(key) {
            Some(place) => format!("{place}: {label}"),
            None => format!("{}: {label}", self.name),
        }
    }

    /// Reads a preset file. Only a regular file is opened (a FIFO or a
    /// device would block or never end).
    pub fn load(path: &Path) -> Result<Preset, PresetError> {
        let file = path.display().to_string();
        let io = |source| PresetError::Io {
            file: file.clone(),
            source,
        };
        let meta = std::fs::metadata(path).map_err(io)?;
        if !meta.is_file() {
            return Err(PresetError::Entry {
                place: file.clone(),
                message: "is not a regular file".into(),
            });
        }
        let text = std::fs::read_to_string(path).map_err(io)?;
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
            name: echo::text(name_or_path),
            user: dirs.iter().flat_map(|d| user_preset_names(d)).collect(),
        })
    }

    /// The preset as TOML, flat keys as in `presets/` (tables kept).
    pub fn to_toml(&self) -> String {
        // With a [physical] table the Π-groups come from it: write only the settings.
        let mut params = toml::Table::try_from(&self.params).unwrap_or_default();
        if self.physical.is_some() {
            params.retain(|k, _| !is_pi(k));
        }
        let out = PresetOut {
            name: &self.name,
            description: &self.description,
            params,
            spectrum: self.spectrum.as_ref(),
            physical: self.physical.as_ref(),
        };
        // Every field of `PresetOut` is a string, a number or a table of them.
        toml::to_string(&out).unwrap_or_else(|e| format!("# cannot write this preset: {e}\n"))
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
                // Only regular files (following links): reading a FIFO would block.
                .filter(|p| p.is_file())
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
            "x.toml:1: `restitution` = 1.5: must be a number in [0.001, 1]"
        );
        let e = Preset::parse("gap = 1\nbogus = 1\n", "x.toml").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("x.toml:2: unknown parameter `bogus`")
        );
        let e = Preset::parse("name = 5\n", "x.toml").unwrap_err();
        assert_eq!(
            e.to_string(),
            "x.toml:1: `name` = 5: must be a string in quotes"
        );
    }

    #[test]
    fn flat_pi_keys_beside_physical_are_refused() {
        let text = builtin_text("two-buildings").replace("dt = 0.001", "dt = 0.001\ngap = 5.0");
        let e = Preset::parse(&text, "x.toml").unwrap_err().to_string();
        assert!(e.contains("`gap` and the [physical] table (x.toml:"), "{e}");
    }

    #[test]
    fn spectrum_table_is_checked_with_its_line() {
        let text = "gap = 0.2\n[spectrum]\nmu = 1.5\nfamily = { dt = [1e-12] }\n";
        let e = Preset::parse(text, "x.toml").unwrap_err().to_string();
        assert!(
            e.starts_with("x.toml:4: [spectrum] family: `dt` = 1e-12"),
            "{e}"
        );
        let e = Preset::parse("[spectrum]\nmu = -1\n", "x.toml")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("x.toml:2: [spectrum] `mu` = -1"), "{e}");
        let e = Preset::parse("[spectrum]\nomega1 = \"1e300:1e300:1\"\n", "x.toml")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("x.toml:2: [spectrum] `omega1`"), "{e}");
    }

    fn builtin_text(name: &str) -> &'static str {
        BUILTIN.iter().find(|(n, _, _)| *n == name).unwrap().2
    }

    #[test]
    fn round_trips_through_toml() {
        for mut p in builtins() {
            p.params.yield1 = f64::INFINITY;
            p.params.method = crate::model::Method::Exact;
            if p.physical.is_none() {
                p.params.gap = f64::INFINITY;
            }
            let back = Preset::parse(&p.to_toml(), "y.toml").unwrap();
            if p.physical.is_none() {
                assert_eq!(back.params, p.params, "{}", p.name);
            }
            assert_eq!(back.description, p.description);
            assert_eq!(back.spectrum, p.spectrum);
        }
    }
}
