//! Where output goes: stdout, a stream (device, FIFO) or a regular file
//! replaced atomically. See the module rules in [`crate::output`].

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use super::temp::{self, TempFile};
use super::{OutputError, reason, shown};

/// An open output: write to it, then [`Target::commit`]. Dropped without a
/// commit, a regular file's target is left as it was.
pub struct Target {
    /// The path as the user gave it, for messages.
    shown: String,
    out: BufWriter<Sink>,
    /// The file a temporary file is renamed to on commit.
    dest: Option<PathBuf>,
}

enum Sink {
    Stdout(io::Stdout),
    Stream(File),
    Temp(TempFile),
}

impl Write for Sink {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match self {
            Sink::Stdout(s) => s.write(buf),
            Sink::Stream(f) => f.write(buf),
            Sink::Temp(t) => t.as_file_mut().write(buf),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match self {
            Sink::Stdout(s) => s.flush(),
            Sink::Stream(f) => f.flush(),
            Sink::Temp(t) => t.as_file_mut().flush(),
        }
    }
}

/// Buffer of the writer in front of every target.
const BUFFER: usize = 1 << 16;

impl Target {
    /// Opens `path` for writing by the rules of [`crate::output`]: checks
    /// everything that can be checked before any work is done.
    pub fn open(path: &Path) -> Result<Target, OutputError> {
        if path.as_os_str() == "-" {
            super::stdout::check_open()?;
            return Ok(Target::stdout());
        }
        let name = shown(path);
        let fail = |why: String| OutputError::failed(&name, why);
        let dest = follow_links(path).map_err(|e| fail(reason(&e)))?;
        let sink = match fs::metadata(&dest) {
            Ok(m) if m.is_dir() => return Err(fail("it is a directory".into())),
            Ok(m) if m.is_file() => {
                if m.permissions().readonly() {
                    return Err(fail("the file is read-only".into()));
                }
                // Opening for writing (without truncating) asks the system
                // whether we may; the file itself is replaced by a rename.
                OpenOptions::new()
                    .write(true)
                    .open(&dest)
                    .map_err(|e| fail(reason(&e)))?;
                Sink::Temp(temp_beside(&dest, Some(m.permissions()), &fail)?)
            }
            Ok(_) => Sink::Stream(
                OpenOptions::new()
                    .write(true)
                    .open(&dest)
                    .map_err(|e| fail(reason(&e)))?,
            ),
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                let dir = parent(&dest);
                match fs::metadata(dir) {
                    Ok(m) if m.is_dir() => {}
                    Ok(_) => return Err(fail(format!("{} is not a directory", shown(dir)))),
                    Err(e) if e.kind() == io::ErrorKind::NotFound => {
                        return Err(fail(format!("directory {} does not exist", shown(dir))));
                    }
                    Err(e) => return Err(fail(format!("{}: {}", shown(dir), reason(&e)))),
                }
                Sink::Temp(temp_beside(&dest, None, &fail)?)
            }
            Err(e) => return Err(fail(reason(&e))),
        };
        let atomic = matches!(sink, Sink::Temp(_));
        Ok(Target {
            shown: name,
            out: BufWriter::with_capacity(BUFFER, sink),
            dest: atomic.then_some(dest),
        })
    }

    /// Standard output.
    pub fn stdout() -> Target {
        Target {
            shown: "stdout".into(),
            out: BufWriter::with_capacity(BUFFER, Sink::Stdout(io::stdout())),
            dest: None,
        }
    }

    /// Whether this is standard output.
    pub fn is_stdout(&self) -> bool {
        matches!(self.out.get_ref(), Sink::Stdout(_))
    }

    /// The target as named in messages.
    pub fn name(&self) -> &str {
        &self.shown
    }

    /// An I/O error met while writing here, as an [`OutputError`].
    pub fn error(&self, e: &io::Error) -> OutputError {
        OutputError::io(&self.shown, e)
    }

    /// Flushes everything; a regular file is synced and renamed over its target.
    pub fn commit(self) -> Result<(), OutputError> {
        let Target { shown, out, dest } = self;
        let sink = out
            .into_inner()
            .map_err(|e| OutputError::io(&shown, e.error()))?;
        match (sink, dest) {
            (Sink::Temp(temp), Some(dest)) => {
                temp.persist(&dest).map_err(|e| OutputError::io(&shown, &e))
            }
            (mut sink, _) => sink.flush().map_err(|e| OutputError::io(&shown, &e)),
        }
    }
}

impl Write for Target {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.out.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.out.flush()
    }
}

/// Writes `bytes` to `path` by the rules of [`crate::output`].
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let mut target = Target::open(path)?;
    target.write_all(bytes).map_err(|e| target.error(&e))?;
    target.commit()
}

/// `path` with every symbolic link along its last component followed, also
/// a dangling one (its target is the file to create).
fn follow_links(path: &Path) -> io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = fs::read_link(&p)?;
                p = if to.is_absolute() {
                    to
                } else {
                    parent(&p).join(to)
                };
            }
            _ => return Ok(p),
        }
    }
    Err(io::Error::other("too many levels of symbolic links"))
}

/// The directory a path lives in (`.` for a bare name).
fn parent(path: &Path) -> &Path {
    path.parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// A temporary file in the directory of `dest`.
fn temp_beside(
    dest: &Path,
    permissions: Option<fs::Permissions>,
    fail: &dyn Fn(String) -> OutputError,
) -> Result<TempFile, OutputError> {
    let dir = parent(dest);
    temp::create_in(dir, permissions).map_err(|e| {
        fail(format!(
            "cannot create a temporary file in {}: {}",
            shown(dir),
            reason(&e)
        ))
    })
}
