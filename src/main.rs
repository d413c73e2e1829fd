//! The `pounding` command. Its one job beyond handing over to the library
//! is to see, before the standard library's start-up, whether stdout was
//! closed (`>&-`): that start-up reopens a closed fd 0, 1 or 2 on
//! `/dev/null` (read-write), after which a closed stdout and an open
//! `/dev/null` look the same ([`pounding::output::stdout`]).

use std::sync::atomic::{AtomicBool, Ordering};

/// Whether fd 1 was closed when the process began.
static STDOUT_CLOSED: AtomicBool = AtomicBool::new(false);

/// Runs from `.init_array`, before `main` and so before the standard
/// library's start-up: fcntl(1, F_GETFD) fails (EBADF) where fd 1 is closed.
#[cfg(target_os = "linux")]
extern "C" fn probe_stdout() {
    // SAFETY: F_GETFD reads the descriptor's flags and changes nothing.
    let closed = unsafe { libc::fcntl(1, libc::F_GETFD) } == -1;
    STDOUT_CLOSED.store(closed, Ordering::Relaxed);
}

#[cfg(target_os = "linux")]
#[used]
#[unsafe(link_section = ".init_array")]
static PROBE_STDOUT: extern "C" fn() = probe_stdout;

fn main() {
    pounding::output::stdout::closed_at_start(STDOUT_CLOSED.load(Ordering::Relaxed));
    std::process::exit(pounding::cli::main_with_args(std::env::args_os()));
}
