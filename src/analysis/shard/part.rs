//! A shard's partial result on disk.
//!
//! A part is one line of JSON, its header, then its results:
//!
//! ```text
//! {"format":"pounding-part 1","version":"0.1.0","command":"map","fingerprint":"…",
//!  "shard":2,"shards":4,"units":3322,"total_units":13286,"elapsed_ms":812.5,
//!  "args":["map","--x","omega1=0.1:3.0:0.02",…],"cwd":"/scratch/me",
//!  "body_bytes":1234567,"body_hash":"…"}
//! <body_bytes bytes of CBOR: the shard's unit numbers and its typed results>
//! ```
//!
//! The header says what the part is without any other file: the request's
//! fingerprint, which shard of how many, the command line that made it (a
//! merge replays it to build the report) and the directory it ran in. The
//! results are CBOR because it carries every `f64` bit for bit, infinities
//! and NaN included, which JSON cannot. The header's byte count and hash of
//! the body tell a complete part from one cut short by a killed task (parts
//! are written atomically, so a short one can only come from elsewhere).

use std::path::Path;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use super::fingerprint::Fingerprint;
use crate::output::{OutputError, shown, write_file};

/// The first field of every part, and its format's version.
pub const FORMAT: &str = "pounding-part 1";

/// What a part says about itself.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PartHeader {
    pub format: String,
    pub version: String,
    pub command: String,
    pub fingerprint: String,
    pub shard: usize,
    pub shards: usize,
    /// Units in this part, and in the whole sweep.
    pub units: usize,
    pub total_units: usize,
    /// Wall time of the shard's computation.
    pub elapsed_ms: f64,
    /// The command line after the program's name.
    pub args: Vec<String>,
    /// The working directory it ran in.
    pub cwd: String,
    pub body_bytes: u64,
    pub body_hash: String,
}

#[derive(Deserialize)]
struct Body<R> {
    units: Vec<usize>,
    results: R,
}

/// [`Body`] as written.
#[derive(Serialize)]
struct BodyRef<'a, R> {
    units: &'a [usize],
    results: &'a R,
}

/// A part read back: its header and its still encoded results.
#[derive(Debug, Clone)]
pub struct Part {
    pub header: PartHeader,
    body: Vec<u8>,
    /// The file, as shown in messages.
    pub name: String,
}

/// Why a part could not be read or written, naming the file.
#[derive(Debug, thiserror::Error)]
pub enum PartError {
    #[error("part {0}: {1}")]
    Bad(String, String),
    #[error(transparent)]
    Write(#[from] OutputError),
}

fn hash(bytes: &[u8]) -> String {
    let mut f = Fingerprint::new("body");
    f.add_bytes(bytes);
    f.hex()
}

impl Part {
    /// Writes `header` (its body fields filled in here) and the shard's
    /// `units` and `results` to `path`, atomically.
    pub fn write<R: Serialize>(
        path: &Path,
        mut header: PartHeader,
        units: &[usize],
        results: &R,
    ) -> Result<(), PartError> {
        let mut body = Vec::new();
        ciborium::into_writer(&BodyRef { units, results }, &mut body)
            .map_err(|e| PartError::Bad(shown(path), format!("cannot encode results: {e}")))?;
        header.format = FORMAT.into();
        header.body_bytes = body.len() as u64;
        header.body_hash = hash(&body);
        let mut bytes = serde_json::to_vec(&header)
            .map_err(|e| PartError::Bad(shown(path), format!("cannot encode header: {e}")))?;
        bytes.push(b'\n');
        bytes.extend(body);
        Ok(write_file(path, &bytes)?)
    }

    /// Reads `path` and checks that it is a whole part.
    pub fn read(path: &Path) -> Result<Part, PartError> {
        let name = shown(path);
        let bad = |why: String| PartError::Bad(name.clone(), why);
        let bytes = std::fs::read(path).map_err(|e| bad(crate::output::reason(&e)))?;
        let Some(end) = bytes.iter().position(|&b| b == b'\n') else {
            let magic: &[u8] = b"{\"format\":\"pounding-part";
            return Err(bad(
                if bytes.starts_with(magic) || magic.starts_with(&bytes) {
                    "incomplete: its header line is cut short (a task stopped while writing it?)"
                        .into()
                } else {
                    "not a part written by `--shard` (no header line)".into()
                },
            ));
        };
        let header: PartHeader = serde_json::from_slice(&bytes[..end]).map_err(|e| {
            bad(format!(
                "not a part written by `--shard` (its header does not read: {e})"
            ))
        })?;
        if header.format != FORMAT {
            return Err(bad(format!(
                "format `{}`, this program reads `{FORMAT}`",
                crate::output::escape_controls(header.format.chars())
            )));
        }
        let body = bytes[end + 1..].to_vec();
        if (body.len() as u64) < header.body_bytes {
            return Err(bad(format!(
                "incomplete: {} of its {} bytes of results (a task stopped while writing it?)",
                body.len(),
                header.body_bytes
            )));
        }
        if body.len() as u64 > header.body_bytes || hash(&body) != header.body_hash {
            return Err(bad(
                "damaged: its results do not match the header's byte count and hash".into(),
            ));
        }
        Ok(Part { header, body, name })
    }

    /// The part's units and typed results.
    pub fn results<R: DeserializeOwned>(&self) -> Result<(Vec<usize>, R), PartError> {
        let body: Body<R> = ciborium::from_reader(self.body.as_slice()).map_err(|e| {
            PartError::Bad(
                self.name.clone(),
                format!("its results do not read as {}'s: {e}", self.header.command),
            )
        })?;
        Ok((body.units, body.results))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header() -> PartHeader {
        PartHeader {
            format: String::new(),
            version: "0".into(),
            command: "map".into(),
            fingerprint: "f".into(),
            shard: 1,
            shards: 2,
            units: 2,
            total_units: 4,
            elapsed_ms: 1.5,
            args: vec!["map".into()],
            cwd: "/".into(),
            body_bytes: 0,
            body_hash: String::new(),
        }
    }

    #[test]
    fn round_trip_bit_for_bit_and_truncation_named() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.part");
        let values = vec![f64::NAN, f64::INFINITY, 0.1 + 0.2, -0.0];
        Part::write(&path, header(), &[0, 3], &values).unwrap();
        let part = Part::read(&path).unwrap();
        assert_eq!(part.header.shard, 1);
        let (units, back): (Vec<usize>, Vec<f64>) = part.results().unwrap();
        assert_eq!(units, [0, 3]);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back), bits(&values));
        let bytes = std::fs::read(&path).unwrap();
        for cut in [bytes.len() - 1, 20] {
            std::fs::write(&path, &bytes[..cut]).unwrap();
            let e = Part::read(&path).unwrap_err().to_string();
            assert!(e.contains("a.part") && e.contains("incomplete"), "{e}");
        }
    }
}
