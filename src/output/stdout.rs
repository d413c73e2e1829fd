//! Standard output for summaries: every write is checked, so a full disk is
//! an error with a message and a closed pipe a quiet stop, never a panic.

use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};

use super::OutputError;

/// Writes `text` to stdout and flushes it.
pub fn print(text: &str) -> Result<(), OutputError> {
    check_open()?;
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| OutputError::io("stdout", &e))
}

/// Whether stdout was closed when the program started, as the binary saw
/// it before the standard library's start-up.
static CLOSED_AT_START: AtomicBool = AtomicBool::new(false);

/// Records that stdout was closed when the program started (`>&-`). The
/// standard library reopens a closed fd 0, 1 or 2 on `/dev/null` before
/// `main`, and every write there then succeeds: a command would print
/// nothing and exit 0. Only a probe that runs before that start-up can
/// tell a closed stdout from an open `/dev/null` (which a shell's
/// `> /dev/null`, Python's `subprocess.DEVNULL` or a daemon's stdio may
/// open read-write, as the start-up does); the binary's is in `main.rs`.
pub fn closed_at_start(closed: bool) {
    CLOSED_AT_START.store(closed, Ordering::Relaxed);
}

/// Fails when stdout was closed when the program started ([`closed_at_start`]).
pub fn check_open() -> Result<(), OutputError> {
    if CLOSED_AT_START.load(Ordering::Relaxed) {
        return Err(OutputError::failed(
            "stdout",
            "Bad file descriptor (stdout is closed)",
        ));
    }
    Ok(())
}
