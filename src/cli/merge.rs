//! `pounding merge PART...`: the parts of a sharded sweep into the output
//! the unsharded command writes, byte for byte but for its timing field
//! (`elapsed_ms`, and the time in a table's last line), which holds the sum
//! of the parts' computing times: the sweep's cost, wherever it ran.
//!
//! The parts must be every shard of one request, once each; a merge
//! refuses anything else, naming the files and the shard numbers (exit 2).
//! It then replays the command line the parts carry, in the directory they
//! ran in where it exists, with the results taken from the parts instead of
//! computed: the same plan, the same typed results and the same writer as
//! the unsharded command. The replay recomputes the request's fingerprint,
//! so an input file changed since the shards ran is refused too.

use std::ffi::OsString;
use std::path::PathBuf;
use std::sync::Arc;

use clap::{Args, Parser};

use super::output::Format;
use super::{Cli, CliError, Command, shard, usage};
use crate::analysis::shard::{Part, merge};

#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// The parts, one per shard, in any order.
    #[arg(value_name = "PART", required = true)]
    pub parts: Vec<PathBuf>,
    /// Output format [default: the one the shards were given].
    #[arg(long, value_enum)]
    pub format: Option<Format>,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "PATH")]
    pub out: Option<PathBuf>,
}

pub fn execute(args: &MergeArgs) -> Result<(), CliError> {
    let parts: Vec<Part> = args
        .parts
        .iter()
        .map(|p| Part::read(p).map_err(usage))
        .collect::<Result<_, _>>()?;
    let parts = Arc::new(merge::check(parts).map_err(CliError::Usage)?);
    let first = &parts[0].header;
    // The output path as given here, before the replay moves to the parts' directory.
    let out = match &args.out {
        Some(p) => Some(std::path::absolute(p).map_err(|e| {
            CliError::Failed(format!(
                "cannot write {}: {}",
                crate::output::shown(p),
                crate::output::reason(&e)
            ))
        })?),
        None => None,
    };
    if let Some(out) = &out {
        crate::output::Target::open(out)?;
    }
    let argv =
        std::iter::once(OsString::from("pounding")).chain(first.args.iter().map(OsString::from));
    let cli = Cli::try_parse_from(argv).map_err(|e| {
        usage(format!(
            "merge: {}: its command line does not read here: {}",
            parts[0].name,
            e.render().to_string().lines().next().unwrap_or("")
        ))
    })?;
    let dir = PathBuf::from(&first.cwd);
    if !first.cwd.is_empty() && dir.is_dir() {
        let _ = std::env::set_current_dir(&dir);
    }
    shard::capture();
    let outcome = replay(cli.command, parts.clone(), args.format);
    let text = shard::captured();
    // A report the command printed before failing (unreliable runs, exit 1)
    // is written as the unsharded command writes it.
    if !text.is_empty() {
        match &out {
            Some(path) => crate::output::write_file(path, text.as_bytes())?,
            None => crate::output::stdout::print(&text)?,
        }
    }
    outcome
}

/// Runs the parts' command with its results from `parts`.
fn replay(
    command: Option<Command>,
    parts: Arc<Vec<Part>>,
    format: Option<Format>,
) -> Result<(), CliError> {
    let from = |s: &mut shard::ShardArgs| {
        *s = shard::ShardArgs {
            merge: Some(parts.clone()),
            ..Default::default()
        };
    };
    let set = |f: &mut Format| {
        if let Some(format) = format {
            *f = format;
        }
    };
    match command {
        Some(Command::Map(mut a)) => {
            from(&mut a.shard);
            set(&mut a.output.format);
            super::map::execute(&a)
        }
        Some(Command::Spectrum(mut a)) => {
            from(&mut a.shard);
            set(&mut a.output.format);
            super::spectrum::execute(&a)
        }
        Some(Command::Gap(mut a)) => {
            from(&mut a.shard);
            set(&mut a.output.format);
            super::gap::execute(&a)
        }
        Some(Command::Suite(mut a)) => {
            from(&mut a.shard);
            set(&mut a.output.format);
            super::suite::execute(&a)
        }
        Some(Command::Ida(mut a)) => {
            from(&mut a.suite.shard);
            set(&mut a.suite.output.format);
            super::ida::execute(&a)
        }
        _ => Err(usage(format!(
            "merge: {}: parts of `{}` cannot be merged",
            parts[0].name, parts[0].header.command
        ))),
    }
}
