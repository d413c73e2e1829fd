//! Standard output for summaries: every write is checked, so a full disk is
//! an error with a message and a closed pipe a quiet stop, never a panic.

use std::io::{self, Write};

use super::OutputError;

/// Writes `text` to stdout and flushes it.
pub fn print(text: &str) -> Result<(), OutputError> {
    check_open()?;
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| OutputError::io("stdout", &e))
}

/// Fails when stdout was closed when the program started (`>&-`).
///
/// The standard library reopens a closed fd 0, 1 or 2 on `/dev/null`
/// before `main` (read-write, so that no later `open` takes the number),
/// and every write there then succeeds: a command would print nothing and
/// exit 0. That descriptor is recognised by what it is: `/dev/null` opened
/// read-write. A shell's `> /dev/null` and `Stdio::null()` open it
/// write-only, so they stay silent successes, as asked. Linux only (it reads
/// `/proc`); elsewhere this always passes.
pub fn check_open() -> Result<(), OutputError> {
    if closed_at_start() {
        return Err(OutputError::failed(
            "stdout",
            "Bad file descriptor (stdout is closed)",
        ));
    }
    Ok(())
}

fn closed_at_start() -> bool {
    let is_null = std::fs::read_link("/proc/self/fd/1").is_ok_and(|p| p.as_os_str() == "/dev/null");
    // `flags:` is octal; the access mode is its low two bits (O_RDWR = 2).
    let read_write = || {
        std::fs::read_to_string("/proc/self/fdinfo/1").is_ok_and(|info| {
            info.lines()
                .find_map(|l| l.strip_prefix("flags:"))
                .and_then(|f| u32::from_str_radix(f.trim(), 8).ok())
                .is_some_and(|flags| flags & 0o3 == 0o2)
        })
    };
    is_null && read_write()
}
