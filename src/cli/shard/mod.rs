//! `--shard K/N`, `--part` and `--skip-done`, as every sweep command takes
//! them, and the one step each such command hands its sweep to: run it
//! whole, run one shard of it and write the part, or (under `pounding
//! merge`) take every unit's results from the parts. The partition, the
//! fingerprint and the part's format are the library's
//! ([`crate::analysis::shard`]); the commands' own glue is one small file
//! each here.

pub mod gap;
pub mod map;
pub mod spectrum;
pub mod suite;

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use clap::Args;
use serde::Serialize;
use serde::de::DeserializeOwned;

use super::{CliError, usage};
use crate::analysis::shard::partition::units_of;
use crate::analysis::shard::{Fingerprint, Part, PartHeader, Shard, merge, partition};
use crate::output::shown;

/// Where a part goes unless `--part` says otherwise.
pub const DEFAULT_PART: &str = "{command}-{K}-of-{N}.part";

#[derive(Debug, Clone, Default, Args)]
pub struct ShardArgs {
    /// Run only shard K of N of the sweep (K = 1..N), balanced by estimated
    /// work, and write a part for `pounding merge`; `slurm` takes K and N
    /// from a job array's SLURM_ARRAY_TASK_ID, _MIN and _COUNT.
    #[arg(long, value_name = "K/N|slurm")]
    pub shard: Option<String>,
    /// The part's file with --shard; {K}, {N} (either case) and {command}
    /// are replaced [default: {command}-{K}-of-{N}.part].
    #[arg(long, value_name = "PATH")]
    pub part: Option<String>,
    /// With --shard: if the part already exists, is complete and is of this
    /// request, do not run the shard again.
    #[arg(long)]
    pub skip_done: bool,
    /// Set by `pounding merge`: the parts to take the results from.
    #[arg(skip)]
    pub merge: Option<Arc<Vec<Part>>>,
}

/// A command's results and, when they come from parts, the parts' summed
/// time in ms; `None` when a shard's part was written (nothing to report).
pub type Results<T> = Result<Option<(T, Option<f64>)>, CliError>;

/// What a sweep command does with its sweep.
pub enum Sweep<T> {
    /// Run it whole, as without sharding.
    Whole,
    /// A shard's part was written (or was already there): nothing to report.
    Done,
    /// Every unit's results from the parts, and the parts' summed time in ms.
    Merged(Vec<T>, f64),
}

impl ShardArgs {
    /// Whether a shard or a merge is asked for (the caller then needs its units).
    pub fn active(&self) -> bool {
        self.shard.is_some() || self.merge.is_some()
    }

    /// Refuses `--part` and `--skip-done` without `--shard`.
    pub fn check(&self) -> Result<(), CliError> {
        if self.shard.is_none() && (self.part.is_some() || self.skip_done) {
            return Err(CliError::Usage(
                "--part and --skip-done go with --shard K/N".into(),
            ));
        }
        Ok(())
    }

    /// Runs the sweep of `command` whose units cost `unit_work`: whole, one
    /// shard (computing the units `compute` is given, writing the part), or
    /// from the merged parts.
    pub fn sweep<T: Serialize + DeserializeOwned>(
        &self,
        command: &str,
        fingerprint: Fingerprint,
        unit_work: &[f64],
        compute: impl FnOnce(&[usize]) -> Vec<T>,
    ) -> Result<Sweep<T>, CliError> {
        self.try_sweep(command, fingerprint, unit_work, |mine| Ok(compute(mine)))
    }

    /// [`ShardArgs::sweep`] with a computation that can fail: a shard whose
    /// units fail writes no part and returns the failure.
    pub fn try_sweep<T: Serialize + DeserializeOwned>(
        &self,
        command: &str,
        fingerprint: Fingerprint,
        unit_work: &[f64],
        compute: impl FnOnce(&[usize]) -> Result<Vec<T>, CliError>,
    ) -> Result<Sweep<T>, CliError> {
        self.check()?;
        if let Some(parts) = &self.merge {
            return from_parts(parts, command, &fingerprint, unit_work.len());
        }
        let Some(text) = &self.shard else {
            return Ok(Sweep::Whole);
        };
        let shard = Shard::parse(text, |name| std::env::var(name).ok()).map_err(CliError::Usage)?;
        let path = self.part_path(command, shard);
        if self.skip_done && done(&path, &fingerprint, shard) {
            eprintln!(
                "shard {shard}: {} is complete, skipped (--skip-done)",
                shown(&path)
            );
            return Ok(Sweep::Done);
        }
        // Checked before the work, so a bad path fails at once.
        crate::output::Target::open(&path)?;
        let mine = units_of(&partition(unit_work, shard.n), shard.k - 1);
        let t = Instant::now();
        let results = compute(&mine)?;
        let elapsed_ms = t.elapsed().as_secs_f64() * 1e3;
        let header = PartHeader {
            format: String::new(),
            version: env!("CARGO_PKG_VERSION").into(),
            command: command.into(),
            fingerprint: fingerprint.hex(),
            shard: shard.k,
            shards: shard.n,
            units: mine.len(),
            total_units: unit_work.len(),
            elapsed_ms,
            args: std::env::args_os()
                .skip(1)
                .map(|a| a.to_string_lossy().into_owned())
                .collect(),
            cwd: std::env::current_dir()
                .map(|d| d.to_string_lossy().into_owned())
                .unwrap_or_default(),
            body_bytes: 0,
            body_hash: String::new(),
        };
        Part::write(&path, header, &mine, &results).map_err(|e| match e {
            crate::analysis::shard::PartError::Write(e) => CliError::from(e),
            e => CliError::Failed(e.to_string()),
        })?;
        Ok(Sweep::Done)
    }

    /// `--part` with its fields filled in.
    fn part_path(&self, command: &str, shard: Shard) -> PathBuf {
        let template = self.part.as_deref().unwrap_or(DEFAULT_PART);
        PathBuf::from(
            template
                .replace("{k}", &shard.k.to_string())
                .replace("{K}", &shard.k.to_string())
                .replace("{n}", &shard.n.to_string())
                .replace("{N}", &shard.n.to_string())
                .replace("{command}", command),
        )
    }
}

/// Whether `path` is already a complete part of this shard of this request.
fn done(path: &Path, fingerprint: &Fingerprint, shard: Shard) -> bool {
    Part::read(path).is_ok_and(|p| {
        p.header.fingerprint == fingerprint.hex()
            && p.header.shard == shard.k
            && p.header.shards == shard.n
    })
}

/// Every unit's results from checked parts, after checking that they are
/// parts of the request the replayed command line makes here.
fn from_parts<T: DeserializeOwned>(
    parts: &[Part],
    command: &str,
    fingerprint: &Fingerprint,
    units: usize,
) -> Result<Sweep<T>, CliError> {
    let first = parts
        .first()
        .ok_or_else(|| usage("merge: no parts given"))?;
    if first.header.command != command
        || first.header.fingerprint != fingerprint.hex()
        || first.header.total_units != units
    {
        return Err(usage(format!(
            "merge: {} and the other parts are of a request (fingerprint {}) that their command \
             line no longer makes here (fingerprint {}): an input file (preset, record) changed, \
             or they were made by another version of pounding",
            first.name,
            &first.header.fingerprint,
            fingerprint.hex()
        )));
    }
    let (results, elapsed_ms) = merge::assemble(parts).map_err(usage)?;
    Ok(Sweep::Merged(results, elapsed_ms))
}

thread_local! {
    /// What the command prints, while `pounding merge` replays it.
    static CAPTURE: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Starts holding back what the commands print (see [`captured`]).
pub fn capture() {
    CAPTURE.with(|c| *c.borrow_mut() = Some(String::new()));
}

/// Holds `text` back if a merge is capturing the output; whether it did.
pub fn held(text: &str) -> bool {
    CAPTURE.with(|c| match c.borrow_mut().as_mut() {
        Some(s) => {
            s.push_str(text);
            true
        }
        None => false,
    })
}

/// What was held back since [`capture`], ending the capture.
pub fn captured() -> String {
    CAPTURE.with(|c| c.borrow_mut().take().unwrap_or_default())
}
