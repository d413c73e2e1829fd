//! A suite of ground motions (SPEC §12): the records one physical pair of
//! buildings is run under. A suite is named by one of
//!
//! - a directory: every record file in it, in name order. Hidden files, the
//!   suite list [`LIST_FILE`] and files that are not records (neither AT2
//!   nor K-NET by their content, and without a single line of two numbers
//!   `time, acceleration`: notes, a README) are skipped; a record file that
//!   is malformed is an error, and so is a directory without a record;
//! - a list file: one record a line, `PATH [SCALE]`, paths relative to the
//!   list file's directory (a path may carry a unit, `PATH@UNIT`, as in
//!   `record:PATH@UNIT`), lines starting with `#` and blank lines skipped;
//! - `synthetic:N` or `synthetic:N@SEED`: N simulated records
//!   ([`crate::model::simulated`], default parameters) in memory, 1 ≤ N ≤
//!   [`MAX_COUNT`], seed [`DEFAULT_SEED`] unless given. These equal bit for
//!   bit the files `pounding records synth --count N --seed SEED` writes.
//!
//! Loading reads every record (shared, [`record::load`]) or fails with one
//! line naming the file, the line and what is wrong: never a partial suite.
//! A suite holds its records while it lives: the runs made from it share
//! them, and they are freed when the suite and its runs are dropped.

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::record::{self, Format, Record, columns};
use super::simulated::{self, DEFAULT_SEED, MAX_COUNT, Simulation};

/// The suite list `records synth` writes beside its records, skipped when a
/// directory is read as a suite.
pub const LIST_FILE: &str = "suite.txt";

/// Where a suite's records come from.
#[derive(Debug, Clone, PartialEq)]
pub enum SuiteSpec {
    /// Every record file in a directory, in name order.
    Directory(PathBuf),
    /// A list file of `PATH [SCALE]` lines.
    List(PathBuf),
    /// `count` simulated records of `seed`, with the default parameters.
    Synthetic { count: usize, seed: u64 },
}

/// One record of a suite.
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteMember {
    /// The file name (a directory), the path as written (a list), or
    /// `synthetic-001` (simulated).
    pub name: String,
    pub record: Arc<Record>,
    /// The list file's scale factor on the record's accelerations; 1
    /// otherwise. The member as listed has intensity `scale` ×
    /// [`crate::model::intensity::IntensityMeasure::measure`] of `record`.
    pub scale: f64,
}

impl SuiteMember {
    /// Whether the record is zero throughout: it cannot be scaled to an
    /// intensity, and a suite runner refuses it.
    pub fn is_silent(&self) -> bool {
        self.record.is_silent()
    }
}

/// A suite that could not be read: the file or spec, the line (1-based; 0
/// for the whole file) and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct SuiteError {
    pub suite: String,
    pub line: usize,
    pub message: String,
}

impl fmt::Display for SuiteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            0 => write!(f, "suite `{}`: {}", self.suite, self.message),
            line => write!(f, "suite `{}` line {line}: {}", self.suite, self.message),
        }
    }
}

/// The largest scale factor a list file may give.
pub const MAX_SCALE: f64 = 1e3;

impl SuiteSpec {
    /// What [`SuiteSpec::parse`] takes, for messages.
    pub const FORMS: &'static str =
        "a directory of records, a list file of `PATH [SCALE]` lines, or synthetic:N[@SEED]";

    /// Parses `synthetic:N[@SEED]`, or a path to a directory or a list file
    /// (which must exist).
    pub fn parse(text: &str) -> Result<SuiteSpec, SuiteError> {
        let shown = crate::output::escape_controls(text.chars());
        let fail = |message: String| SuiteError {
            suite: shown.clone(),
            line: 0,
            message,
        };
        if let Some(rest) = text.trim().strip_prefix("synthetic:") {
            let (count, seed) = match rest.split_once('@') {
                Some((count, seed)) => (count, Some(seed)),
                None => (rest, None),
            };
            let count = count
                .trim()
                .parse::<usize>()
                .ok()
                .filter(|n| (1..=MAX_COUNT).contains(n))
                .ok_or_else(|| {
                    fail(format!(
                        "the count `{}` must be a whole number in [1, {MAX_COUNT}]",
                        count.trim()
                    ))
                })?;
            let seed = match seed {
                None => DEFAULT_SEED,
                Some(seed) => seed.trim().parse::<u64>().map_err(|_| {
                    fail(format!(
                        "the seed `{}` must be a whole number in [0, {}]",
                        seed.trim(),
                        u64::MAX
                    ))
                })?,
            };
            return Ok(SuiteSpec::Synthetic { count, seed });
        }
        let path = PathBuf::from(text);
        match std::fs::metadata(&path) {
            Ok(m) if m.is_dir() => Ok(SuiteSpec::Directory(path)),
            Ok(m) if m.is_file() => Ok(SuiteSpec::List(path)),
            Ok(_) => Err(fail(format!("not a regular file; must be {}", Self::FORMS))),
            Err(e) => Err(fail(format!(
                "{}; must be {}",
                crate::output::reason(&e),
                Self::FORMS
            ))),
        }
    }

    /// Reads every record of the suite, in order.
    pub fn load(&self) -> Result<Vec<SuiteMember>, SuiteError> {
        match self {
            SuiteSpec::Directory(dir) => load_directory(dir),
            SuiteSpec::List(list) => load_list(list),
            SuiteSpec::Synthetic { count, seed } => Ok(synthetic(*count, *seed)),
        }
    }
}

impl fmt::Display for SuiteSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SuiteSpec::Directory(p) | SuiteSpec::List(p) => {
                write!(f, "{}", crate::output::shown(p))
            }
            SuiteSpec::Synthetic { count, seed } => write!(f, "synthetic:{count}@{seed}"),
        }
    }
}

/// Simulated records 1 … `count` of `seed`.
fn synthetic(count: usize, seed: u64) -> Vec<SuiteMember> {
    use rayon::prelude::*;
    let simulation = Simulation::default();
    // Each record is its own stream of the seed, so they are made in
    // parallel (most of each is the dominant frequency's transform).
    (1..=count)
        .into_par_iter()
        .map(|j| {
            let name = simulated::member_name(j);
            let record = simulation.record(&format!("{name}@seed{seed}"), seed, j);
            SuiteMember {
                name,
                record: record::intern(record),
                scale: 1.0,
            }
        })
        .collect()
}

/// A path as a `&str` for the record reader, or an error naming it.
fn utf8(path: &Path, source: &str, line: usize) -> Result<String, SuiteError> {
    path.to_str().map(str::to_string).ok_or_else(|| SuiteError {
        suite: source.to_string(),
        line,
        message: format!("the path {} is not UTF-8", crate::output::shown(path)),
    })
}

fn load_directory(dir: &Path) -> Result<Vec<SuiteMember>, SuiteError> {
    let source = crate::output::shown(dir);
    let fail = |message: String| SuiteError {
        suite: source.clone(),
        line: 0,
        message,
    };
    let entries = std::fs::read_dir(dir).map_err(|e| fail(crate::output::reason(&e)))?;
    let mut files = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|e| fail(crate::output::reason(&e)))?;
        let name = entry.file_name();
        let Some(name) = name.to_str() else {
            return Err(fail(format!(
                "the file name {} is not UTF-8",
                crate::output::shown(Path::new(&name))
            )));
        };
        if name.starts_with('.') || name == LIST_FILE {
            continue;
        }
        let path = entry.path();
        if path.is_file() {
            files.push((name.to_string(), path));
        }
    }
    files.sort();
    let mut members = Vec::new();
    for (name, path) in files {
        let path = utf8(&path, &source, 0)?;
        let bytes = std::fs::read(&path).map_err(|e| {
            fail(format!(
                "{}: {}",
                crate::output::shown(Path::new(&path)),
                crate::output::reason(&e)
            ))
        })?;
        let text = String::from_utf8_lossy(&bytes);
        if Format::of(&path, &text) == Format::Columns && !columns::has_samples(&text) {
            continue; // notes, a README: not a record
        }
        let record = record::load(&path).map_err(|e| fail(e.to_string()))?;
        members.push(SuiteMember {
            name,
            record,
            scale: 1.0,
        });
    }
    if members.is_empty() {
        return Err(fail(format!(
            "the directory holds no record file (hidden files, {LIST_FILE} and \
             files with no line `time, acceleration` are skipped)"
        )));
    }
    Ok(members)
}

fn load_list(list: &Path) -> Result<Vec<SuiteMember>, SuiteError> {
    let source = crate::output::shown(list);
    let fail = |line: usize, message: String| SuiteError {
        suite: source.clone(),
        line,
        message,
    };
    let bytes = std::fs::read(list).map_err(|e| fail(0, crate::output::reason(&e)))?;
    let text = String::from_utf8_lossy(&bytes);
    let list_name = list.to_str().unwrap_or("");
    if matches!(Format::of(list_name, &text), Format::At2 | Format::Knet) {
        return Err(fail(
            0,
            "this is a record, not a suite; name its directory, a list file, or synthetic:N[@SEED]"
                .into(),
        ));
    }
    let base = list.parent().unwrap_or(Path::new(""));
    let mut members = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = t.split_whitespace().collect();
        let (path, scale) = match fields.as_slice() {
            [path] => (*path, 1.0),
            [path, scale] => {
                let scale = scale
                    .parse::<f64>()
                    .ok()
                    .filter(|s| *s > 0.0 && *s <= MAX_SCALE)
                    .ok_or_else(|| {
                        fail(
                            i + 1,
                            format!(
                                "scale `{}`: must be a number in (0, {MAX_SCALE}]",
                                record::cut(scale)
                            ),
                        )
                    })?;
                (*path, scale)
            }
            _ => {
                return Err(fail(
                    i + 1,
                    format!("expected `PATH [SCALE]`, found `{}`", record::cut(t)),
                ));
            }
        };
        let joined = utf8(&base.join(path), &source, i + 1)?;
        let record = record::load(&joined).map_err(|e| fail(i + 1, e.to_string()))?;
        members.push(SuiteMember {
            name: path.to_string(),
            record,
            scale,
        });
    }
    if members.is_empty() {
        return Err(fail(
            0,
            "the list names no record (one `PATH [SCALE]` a line)".into(),
        ));
    }
    Ok(members)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn synthetic_specs() {
        assert_eq!(
            SuiteSpec::parse("synthetic:3@5").unwrap(),
            SuiteSpec::Synthetic { count: 3, seed: 5 }
        );
        assert_eq!(
            SuiteSpec::parse("synthetic:2").unwrap(),
            SuiteSpec::Synthetic {
                count: 2,
                seed: DEFAULT_SEED
            }
        );
        for bad in [
            "synthetic:0",
            "synthetic:1001",
            "synthetic:x",
            "synthetic:2@-1",
        ] {
            let e = SuiteSpec::parse(bad).unwrap_err().to_string();
            assert!(e.starts_with(&format!("suite `{bad}`: the ")), "{e}");
        }
        let members = SuiteSpec::parse("synthetic:2@9").unwrap().load().unwrap();
        assert_eq!(members.len(), 2);
        assert_eq!(members[1].name, "synthetic-002");
        assert!(!members[0].is_silent());
    }
}
