//! Standard output for summaries: every write is checked, so a full disk is
//! an error with a message and a closed pipe a quiet stop, never a panic.

use std::io::{self, Write};

use super::OutputError;

/// Writes `text` to stdout and flushes it.
pub fn print(text: &str) -> Result<(), OutputError> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| OutputError::io("stdout", &e))
}
