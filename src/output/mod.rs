//! Every byte the program writes goes through here: the history CSV, the
//! summaries on stdout, presets saved and histories exported by the explorer,
//! and any future figure. One set of rules, in one place:
//!
//! - `-` is stdout, streamed;
//! - a symbolic link is followed, and its target is what gets written;
//! - a device, FIFO or other special file is opened and streamed to directly
//!   (a FIFO waits for its reader, as Unix tools do);
//! - a regular file, existing or new, is written to a temporary file in the
//!   same directory and renamed over the target only once complete, so a
//!   reader sees the old file or the new one, never a torn one. An existing
//!   file must be writable by us and must carry a write permission bit (a
//!   `chmod 444` file is refused even for root); the new file keeps the old
//!   one's permissions;
//! - directories are never created: a missing parent is an error that names it.
//!
//! Every failure is an [`OutputError`] naming the path and the reason; a pipe
//! whose reader went away is [`OutputError::BrokenPipe`], which the command
//! line ends quietly on.
//!
//! Temporary files are called `.pounding-PID-XXXXXX.tmp` (short whatever the
//! target's name, so a 255-byte name still works). They are removed when
//! dropped, on SIGINT, SIGTERM and SIGHUP (see [`temp`]), and a file left by
//! a process that no longer exists (SIGKILL, power loss) is removed by the
//! next write into the same directory.
//!
//! This module sits beside `std` at the bottom of the crate: it knows nothing
//! of the model or the terminal, so every layer may write through it.

pub mod audit;
pub mod number;
pub mod report;
pub mod stdout;
pub mod target;
pub mod temp;

pub use number::Num;
pub use target::{Target, write_file};

use std::io;
use std::path::Path;

/// Why output could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The target (a path, or `stdout`) and why it could not be written.
    #[error("cannot write {target}: {reason}")]
    Failed { target: String, reason: String },
    /// The reader of a pipe closed it: not a failure of ours, stop quietly.
    #[error("broken pipe")]
    BrokenPipe,
}

impl OutputError {
    /// An error about `target` from an I/O error.
    pub fn io(target: &str, e: &io::Error) -> OutputError {
        if e.kind() == io::ErrorKind::BrokenPipe {
            OutputError::BrokenPipe
        } else {
            OutputError::failed(target, reason(e))
        }
    }

    pub fn failed(target: &str, reason: impl Into<String>) -> OutputError {
        OutputError::Failed {
            target: target.to_string(),
            reason: reason.into(),
        }
    }

    /// The reason alone, without the target.
    pub fn reason(&self) -> String {
        match self {
            OutputError::Failed { reason, .. } => reason.clone(),
            OutputError::BrokenPipe => "broken pipe".into(),
        }
    }
}

/// An I/O error as a short reason: "Permission denied", without "(os error 13)".
pub fn reason(e: &io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error") {
        Some(i) => text[..i].to_string(),
        None => text,
    }
}

/// `chars` with every control character escaped (`\n`), so a message stays on one line.
pub fn escape_controls(chars: impl Iterator<Item = char>) -> String {
    chars
        .flat_map(|c| {
            if c.is_control() {
                c.escape_default().collect::<Vec<_>>()
            } else {
                vec![c]
            }
        })
        .collect()
}

/// A path for a one-line message: control characters escaped, long paths cut in the middle.
pub fn shown(path: &Path) -> String {
    const MAX: usize = 160;
    let text = escape_controls(path.to_string_lossy().chars());
    let count = text.chars().count();
    if count <= MAX {
        return text;
    }
    let head: String = text.chars().take(MAX / 2).collect();
    let tail: String = text.chars().skip(count - MAX / 2).collect();
    format!("{head}…{tail}")
}
