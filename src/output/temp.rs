//! Temporary files of atomic writes, and their removal however the process ends.
//!
//! - Normal end or error: [`tempfile::NamedTempFile`] deletes its file when dropped.
//! - SIGINT, SIGTERM, SIGHUP: every temporary file still open is registered
//!   here; [`cleanup_then_die_on_signals`] removes them, then lets the signal
//!   end the process as it would have (status 128 + signal in a shell). The
//!   explorer has its own signal handling and calls [`remove_live`] on its way out.
//! - SIGKILL or power loss cannot be caught: the file stays, and the next
//!   write into the same directory removes it ([`remove_stale`]), because its
//!   name carries the id of a process that no longer exists.

use std::ffi::OsStr;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Paths of the temporary files this process has open.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    LIVE.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Our temporary names: `.pounding-PID-XXXXXX.tmp`.
const PREFIX: &str = ".pounding-";
const SUFFIX: &str = ".tmp";

/// A new temporary file in `dir`, registered for removal on signals.
pub fn create_in(dir: &Path, permissions: Option<fs::Permissions>) -> io::Result<TempFile> {
    remove_stale(dir);
    let prefix = format!("{PREFIX}{}-", std::process::id());
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(SUFFIX).rand_bytes(6);
    #[cfg(unix)]
    let new_file_mode = {
        use std::os::unix::fs::PermissionsExt;
        // Like any new file: 0666 less the umask (the open applies it).
        fs::Permissions::from_mode(0o666)
    };
    #[cfg(unix)]
    builder.permissions(new_file_mode);
    let file = builder.tempfile_in(dir)?;
    if let Some(p) = permissions {
        file.as_file().set_permissions(p)?;
    }
    live().push(file.path().to_path_buf());
    Ok(TempFile { file: Some(file) })
}

/// A registered temporary file: deleted on drop unless persisted.
#[derive(Debug)]
pub struct TempFile {
    file: Option<tempfile::NamedTempFile>,
}

impl TempFile {
    pub fn as_file(&self) -> &fs::File {
        self.file
            .as_ref()
            .expect("present until persisted")
            .as_file()
    }

    pub fn as_file_mut(&mut self) -> &mut fs::File {
        self.file
            .as_mut()
            .expect("present until persisted")
            .as_file_mut()
    }

    /// Flushes the file to disk and renames it to `dest`.
    pub fn persist(mut self, dest: &Path) -> io::Result<()> {
        let file = self.file.take().expect("present until persisted");
        let path = file.path().to_path_buf();
        let outcome = file
            .as_file()
            .sync_all()
            .and_then(|()| file.persist(dest).map(drop).map_err(|e| e.error));
        unregister(&path);
        outcome
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if let Some(file) = self.file.take() {
            let path = file.path().to_path_buf();
            drop(file);
            unregister(&path);
        }
    }
}

fn unregister(path: &Path) {
    live().retain(|p| p != path);
}

/// Removes every temporary file this process still has open.
pub fn remove_live() {
    for path in live().drain(..) {
        let _ = fs::remove_file(path);
    }
}

/// Installs the handler of SIGINT, SIGTERM and SIGHUP for the command line:
/// remove the temporary files, then end the process by the same signal.
pub fn cleanup_then_die_on_signals() -> io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])?;
    std::thread::Builder::new()
        .name("pounding-cleanup".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                remove_live();
                let _ = signal_hook::low_level::emulate_default_handler(signal);
                std::process::exit(128 + signal);
            }
        })?;
    Ok(())
}

/// Removes our temporary files in `dir` whose process no longer exists.
/// Files of live processes (another run writing into the same directory)
/// are left alone; where liveness cannot be told, nothing is removed.
pub fn remove_stale(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        if let Some(pid) = owner(&name)
            && pid != std::process::id()
            && process_is_gone(pid)
            && entry.file_type().is_ok_and(|t| t.is_file())
        {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// The process id in one of our temporary names.
fn owner(name: &OsStr) -> Option<u32> {
    let rest = name.to_str()?.strip_prefix(PREFIX)?.strip_suffix(SUFFIX)?;
    let (pid, random) = rest.split_once('-')?;
    (random.len() == 6).then_some(())?;
    pid.parse().ok()
}

/// Whether process `pid` certainly no longer exists (Linux: no `/proc/PID`).
fn process_is_gone(pid: u32) -> bool {
    let proc = Path::new("/proc");
    proc.join("self").exists() && !proc.join(pid.to_string()).exists()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn owner_reads_only_our_names() {
        assert_eq!(owner(OsStr::new(".pounding-1234-a1B2c3.tmp")), Some(1234));
        assert_eq!(owner(OsStr::new(".pounding-1234-a1B2c.tmp")), None);
        assert_eq!(owner(OsStr::new(".h.csv.1234.tmp")), None);
        assert_eq!(owner(OsStr::new("pounding-1234-a1B2c3.tmp")), None);
    }

    #[test]
    fn stale_files_of_dead_processes_go_live_ones_stay() {
        let dir = tempfile::tempdir().unwrap();
        // Pid 0 is never a user process and has no /proc entry; ours is alive.
        let dead = dir.path().join(".pounding-0-abcdef.tmp");
        let alive = dir
            .path()
            .join(format!(".pounding-{}-abcdef.tmp", std::process::id()));
        let other = dir.path().join("keep.tmp");
        for p in [&dead, &alive, &other] {
            fs::write(p, "x").unwrap();
        }
        remove_stale(dir.path());
        assert!(!dead.exists());
        assert!(alive.exists());
        assert!(other.exists());
    }
}
