//! Output end to end, with the real binary: where files go and what happens
//! when they cannot be written (see `pounding::output`).
//!
//! - a regular file is replaced atomically, and only if it may be written;
//! - a symlink is followed, a FIFO, a device or `-` is streamed to;
//! - a missing directory is an error, never created;
//! - a closed pipe ends quietly, a full device is exit 1 with a message;
//! - the history is streamed in bounded memory, and over-large or over-long
//!   requests need a confirming flag;
//! - SIGKILL, SIGINT and SIGTERM leave the target absent or old, and no
//!   temporary file survives the next run.
//!
//! Device nodes are made in a temporary directory (`mknod`, root only: the
//! cases print a note and pass when not root); no system path is written.

use std::fs;
use std::io::{BufRead, BufReader, Read};
use std::os::unix::fs::{FileTypeExt, PermissionsExt};
use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

mod common;

use common::{
    BIN, assert_one_line, fails, history_into, history_json, json, parse_json, pounding, spawn,
    succeeds, text,
};

const HEADER: &str = "tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp,ag,vg,ug";

fn path_str(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A file `name` in `dir` holding "old\n", with permissions `mode`.
fn old_file(dir: &Path, name: &str, mode: u32) -> PathBuf {
    let path = dir.join(name);
    fs::write(&path, "old\n").unwrap();
    fs::set_permissions(&path, fs::Permissions::from_mode(mode)).unwrap();
    path
}

/// Whether `path` is still a symbolic link (a write followed it, not replaced it).
fn is_symlink(path: &Path) -> bool {
    fs::symlink_metadata(path).unwrap().file_type().is_symlink()
}

/// Our temporary files left in `dir`.
fn temporaries(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".pounding-") && n.ends_with(".tmp"))
        .collect()
}

/// A device node `major:minor` at `path`, if we may make one (root).
fn device(path: &Path, major: u32, minor: u32) -> bool {
    let made = Command::new("mknod")
        .arg(path)
        .args(["c", &major.to_string(), &minor.to_string()])
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !made {
        println!("note: cannot mknod (not root?): device case skipped");
    }
    made
}

fn fifo(path: &Path) {
    assert!(Command::new("mkfifo").arg(path).status().unwrap().success());
}

#[test]
fn read_only_file_is_refused_and_left_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let target = old_file(dir.path(), "kept.csv", 0o444);
    let o = fails(&history_into(&target), 1, &["kept.csv", "read-only"]);
    assert!(o.stdout.is_empty(), "no summary after a failed write");
    assert_eq!(fs::read_to_string(&target).unwrap(), "old\n");
    assert_eq!(
        fs::metadata(&target).unwrap().permissions().mode() & 0o777,
        0o444
    );
    assert!(temporaries(dir.path()).is_empty());
}

#[test]
fn writable_file_is_replaced_and_keeps_its_permissions() {
    let dir = tempfile::tempdir().unwrap();
    let target = old_file(dir.path(), "h.csv", 0o640);
    succeeds(&history_into(&target));
    let csv = fs::read_to_string(&target).unwrap();
    assert!(csv.starts_with(HEADER));
    assert_eq!(
        fs::metadata(&target).unwrap().permissions().mode() & 0o777,
        0o640
    );
}

#[test]
fn symlink_is_followed_to_its_target() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.csv");
    let link = dir.path().join("link.csv");
    fs::write(&real, "old\n").unwrap();
    std::os::unix::fs::symlink("real.csv", &link).unwrap();
    succeeds(&history_into(&link));
    assert!(is_symlink(&link));
    assert!(fs::read_to_string(&real).unwrap().starts_with(HEADER));
    // A dangling link: its target is created.
    let dangling = dir.path().join("dangling.csv");
    std::os::unix::fs::symlink("new.csv", &dangling).unwrap();
    succeeds(&history_into(&dangling));
    assert!(is_symlink(&dangling));
    assert!(
        fs::read_to_string(dir.path().join("new.csv"))
            .unwrap()
            .starts_with(HEADER)
    );
}

#[test]
fn fifo_is_streamed_to() {
    let dir = tempfile::tempdir().unwrap();
    let pipe = dir.path().join("pipe");
    fifo(&pipe);
    let reader = {
        let pipe = pipe.clone();
        std::thread::spawn(move || fs::read_to_string(pipe).unwrap())
    };
    let v = history_json(&pipe);
    let csv = reader.join().unwrap();
    assert!(csv.starts_with(HEADER));
    assert_eq!(
        csv.lines().count() as u64,
        v["steps"].as_u64().unwrap() + 2,
        "header, initial state, one row per step"
    );
    assert!(fs::metadata(&pipe).unwrap().file_type().is_fifo());
}

#[test]
fn device_is_streamed_to_and_stays_a_device() {
    let dir = tempfile::tempdir().unwrap();
    let null = dir.path().join("null");
    let full = dir.path().join("full");
    if !device(&null, 1, 3) || !device(&full, 1, 7) {
        return;
    }
    succeeds(&history_into(&null));
    fails(
        &history_into(&full),
        1,
        &["full", "No space left on device"],
    );
    for node in [&null, &full] {
        assert!(fs::metadata(node).unwrap().file_type().is_char_device());
    }
    assert!(temporaries(dir.path()).is_empty());
}

#[test]
fn dash_is_stdout_and_the_summary_goes_to_stderr() {
    let o = succeeds(&["run", "--cycles", "1", "--format", "json", "--history", "-"]);
    let out = text(&o.stdout);
    assert_eq!(out.lines().next(), Some(HEADER));
    let v = parse_json(&o.stderr);
    assert_eq!(out.lines().count() as u64, v["steps"].as_u64().unwrap() + 2);
}

#[test]
fn missing_directory_is_an_error_and_is_not_created() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("no/such/h.csv");
    fails(
        &history_into(&target),
        1,
        &["no/such/h.csv", "does not exist"],
    );
    assert!(!dir.path().join("no").exists());
    // A directory as the target.
    fails(&history_into(dir.path()), 1, &["is a directory"]);
}

#[test]
fn longest_legal_name_works() {
    let dir = tempfile::tempdir().unwrap();
    let name = format!("{}.csv", "a".repeat(250));
    assert_eq!(name.len(), 254);
    let target = dir.path().join(&name);
    succeeds(&history_into(&target));
    assert!(fs::read_to_string(&target).unwrap().starts_with(HEADER));
}

#[test]
fn closed_pipe_ends_quietly() {
    for args in [
        &["run", "--cycles", "2000"][..],
        &["spectrum", "--omega1", "0.5:1.5:0.1"][..],
        &["run", "--cycles", "20", "--history", "-"][..],
    ] {
        // The reader has gone before the first write (`| head` done early).
        let mut child = spawn(args);
        drop(child.stdout.take());
        let o = child.wait_with_output().unwrap();
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        assert!(o.stderr.is_empty() || args.contains(&"-"), "{args:?}");
        // The reader takes one line, then goes (`| head -1`).
        let mut child = spawn(args);
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        assert!(!line.is_empty());
        let o = child.wait_with_output().unwrap();
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        assert!(!text(&o.stderr).contains("panicked"));
    }
}

#[test]
fn full_stdout_is_exit_1_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let full = dir.path().join("full");
    if !device(&full, 1, 7) {
        return;
    }
    for args in [&["run"][..], &["spectrum", "--omega1", "0.5:1.5:0.5"][..]] {
        let o = Command::new(BIN)
            .args(args)
            .stdout(fs::OpenOptions::new().write(true).open(&full).unwrap())
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(1), "{args:?}");
        assert_one_line(&o, &["stdout", "No space left on device"]);
    }
}

/// A stdout closed before the start (`>&-`) is a failed write, exit 1 with
/// one line, for every command that prints; `Stdio::null()` would not do
/// (it is an open `/dev/null`), so a shell closes fd 1 and execs the binary.
#[test]
fn closed_stdout_is_exit_1_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("h.svg");
    let cases: [&[&str]; 9] = [
        &["run", "--format", "json"],
        &["run", "--history", "-"],
        &["spectrum", "--omega1", "0.5:1.5:0.5"],
        &["map", "--x", "omega1=0.5:1:0.5", "--y", "mu=1:2:1"],
        &["gap", "--x", "omega1=0.5:1:0.5"],
        &[
            "similarity",
            "--omega1",
            "0.5:1:0.5",
            "--ap",
            "0.2g",
            "--omega-p",
            "6",
        ],
        &["stress", "--cases", "0"],
        &[
            "bench", "--preset", "set1", "--model", "kelvin", "--method", "exact",
        ],
        &["figure", "history", "--out", path_str(&svg)],
    ];
    for args in cases {
        let o = Command::new("sh")
            .arg("-c")
            .arg(r#"exec "$0" "$@" >&-"#)
            .arg(BIN)
            .args(args)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", text(&o.stderr));
        assert_one_line(&o, &["stdout", "Bad file descriptor"]);
    }
    // An open /dev/null is a reader that wants nothing: success, whether
    // opened write-only (a shell's `>`, Stdio::null()) or read-write (as
    // Python's subprocess.DEVNULL and daemon(3) open it).
    let o = Command::new(BIN)
        .args(["run", "--format", "json"])
        .stdout(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let o = Command::new("sh")
        .arg("-c")
        .arg(r#"exec "$0" "$@" 1<>/dev/null"#)
        .arg(BIN)
        .args(["run", "--format", "json"])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "read-write: {}", text(&o.stderr));
}

/// Peak resident memory of a live process, in kB (Linux).
fn peak_rss_kb(pid: u32) -> Option<u64> {
    let status = fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

#[test]
fn long_history_is_streamed_in_bounded_memory() {
    // 40 cycles: 251 000 rows, about 45 MB of CSV. Held in memory, as
    // before, the samples and the text took about 70 MB.
    let mut child = spawn(&[
        "run",
        "--cycles",
        "40",
        "--format",
        "json",
        "--history",
        "-",
    ]);
    let mut out = child.stdout.take().unwrap();
    let mut buf = vec![0u8; 1 << 16];
    let (mut bytes, mut newlines) = (0usize, 0usize);
    let mut peak = None;
    loop {
        let n = out.read(&mut buf).unwrap();
        if n == 0 {
            break;
        }
        bytes += n;
        newlines += buf[..n].iter().filter(|&&b| b == b'\n').count();
        // Most of the history is out: the writer is alive, waiting for us.
        if peak.is_none() && bytes > 35_000_000 {
            peak = peak_rss_kb(child.id());
        }
    }
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success(), "{}", text(&o.stderr));
    let v = parse_json(&o.stderr);
    assert_eq!(newlines as u64, v["steps"].as_u64().unwrap() + 2);
    assert!(bytes > 40_000_000, "{bytes} bytes");
    match peak {
        Some(kb) => {
            println!("peak RSS {kb} kB while streaming {bytes} bytes");
            assert!(kb < 20_000, "peak RSS {kb} kB");
        }
        None => println!("note: no /proc: peak memory not measured"),
    }
}

#[test]
fn large_and_long_requests_need_their_flags() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("x.csv");
    fails(
        &["run", "--cycles", "20000", "--history", path_str(&target)],
        2,
        &["--history", "25 GB", "limit 1 GB", "--allow-large"],
    );
    assert!(!target.exists());
    fails(
        &[
            "run",
            "--cycles",
            "100000",
            "--set",
            "dt=6.2832e-4",
            "--repeat",
            "100000",
        ],
        2,
        &["1.0e14 steps", "--allow-long"],
    );
    fails(
        &["spectrum", "--cycles", "100000", "--omega1", "0.1:3:0.001"],
        2,
        &["spectrum", "--allow-long"],
    );
    fails(
        &["similarity", "--omega-p", "10", "--cycles", "100000"],
        2,
        &["similarity", "--allow-long"],
    );
}

#[test]
fn no_progress_bar_without_a_terminal() {
    // Estimated at over a second (set1, 700 repeats of 50 000 steps).
    let o = succeeds(&["run", "--repeat", "700", "--format", "json"]);
    assert!(o.stderr.is_empty(), "{}", text(&o.stderr));
}

#[test]
fn reliable_runs_say_so_with_their_method() {
    let v = json(&["run", "--format", "json"]);
    assert_eq!(v["reliable"], true);
    assert_eq!(v["method"], "newmark");
    assert!(v.get("unreliable_reason").is_none());
    let csv = common::stdout(&succeeds(&["run", "--format", "csv"]));
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    let column = |name: &str| rows[0].iter().position(|c| *c == name).unwrap();
    assert_eq!(rows[1][column("reliable")], "true");
    assert_eq!(rows[1][column("method")], "newmark");
}

/// Starts a long history run into `target`, waits until its temporary file
/// exists, and returns the child.
fn start_history_run(target: &Path) -> Child {
    let dir = target.parent().unwrap();
    let child = Command::new(BIN)
        .args(["run", "--cycles", "400", "--history", path_str(target)])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while temporaries(dir).is_empty() {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "no temporary file"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    child
}

fn kill(child: &Child, signal: &str) {
    let pid = child.id().to_string();
    assert!(
        Command::new("kill")
            .args(["-s", signal, &pid])
            .status()
            .unwrap()
            .success()
    );
}

#[test]
fn killed_runs_leave_the_target_old_and_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("big.csv");
    fs::write(&target, "old\n").unwrap();
    for (signal, number) in [("INT", 2), ("TERM", 15), ("KILL", 9)] {
        let mut child = start_history_run(&target);
        kill(&child, signal);
        let status = child.wait().unwrap();
        assert_eq!(status.signal(), Some(number), "{signal}: {status:?}");
        assert_eq!(fs::read_to_string(&target).unwrap(), "old\n", "{signal}");
        // SIGINT and SIGTERM are caught and clean up; SIGKILL cannot be.
        assert_eq!(temporaries(dir.path()).is_empty(), number != 9, "{signal}");
        // The next run into the directory leaves no temporary file, SIGKILL's included.
        let other = dir.path().join("other.csv");
        succeeds(&history_into(&other));
        assert!(temporaries(dir.path()).is_empty(), "{signal}");
    }
    // Absent before, absent after.
    let fresh: PathBuf = dir.path().join("fresh.csv");
    let mut child = start_history_run(&fresh);
    kill(&child, "TERM");
    child.wait().unwrap();
    assert!(!fresh.exists());
    assert!(temporaries(dir.path()).is_empty());
}

#[test]
fn explorer_export_and_preset_save_follow_the_same_rules() {
    let dir = tempfile::tempdir().unwrap();
    let target = old_file(dir.path(), "export.csv", 0o444);
    let p = pounding::model::SET1;
    let msg = pounding::tui::export::write(&p, &target);
    assert!(msg.contains("read-only"), "{msg}");
    assert_eq!(fs::read_to_string(&target).unwrap(), "old\n");
    let fresh = dir.path().join("fresh.csv");
    let msg = pounding::tui::export::write(&p, &fresh);
    assert!(msg.starts_with("exported"), "{msg}");
    assert!(
        fs::read_to_string(&fresh)
            .unwrap()
            .starts_with("tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp")
    );

    let preset = pounding::model::Preset::find("set1", &[]).unwrap();
    let saved = dir.path().join("mine.toml");
    fs::write(dir.path().join("real.toml"), "").unwrap();
    std::os::unix::fs::symlink("real.toml", &saved).unwrap();
    preset.save(&saved).unwrap();
    assert!(is_symlink(&saved));
    let back = fs::read_to_string(dir.path().join("real.toml")).unwrap();
    assert!(back.contains("mass_ratio"), "{back}");
    fs::set_permissions(
        dir.path().join("real.toml"),
        fs::Permissions::from_mode(0o444),
    )
    .unwrap();
    let e = preset.save(&saved).unwrap_err();
    assert!(e.to_string().contains("read-only"), "{e}");
    assert!(temporaries(dir.path()).is_empty());
}

#[test]
fn unreliable_run_is_flagged_and_exits_1_unless_allowed() {
    // A restitution this small makes the contact damping explode: the
    // energy balance fails by orders of magnitude.
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("h.csv");
    fs::write(&target, "old\n").unwrap();
    let bad = ["run", "--set", "restitution=1e-20", "--format", "json"];
    let o = pounding(&[&bad[..], &["--history", path_str(&target)]].concat());
    if o.status.code() == Some(2) {
        // The parameter table rules this value out: bad input, not a run.
        assert_one_line(&o, &["restitution"]);
        println!("note: restitution = 1e-20 is out of range; unreliable case not reached");
        return;
    }
    assert_eq!(o.status.code(), Some(1));
    assert_one_line(
        &o,
        &[
            "unreliable result",
            "energy residual",
            "--allow-unreliable",
            "h.csv was not written",
        ],
    );
    let v = parse_json(&o.stdout);
    assert_eq!(v["reliable"], false);
    assert!(
        v["unreliable_reason"]
            .as_str()
            .unwrap()
            .contains("energy residual")
    );
    assert_eq!(fs::read_to_string(&target).unwrap(), "old\n");
    assert!(temporaries(dir.path()).is_empty());
    let o = pounding(
        &[
            &bad[..],
            &["--allow-unreliable", "--history", path_str(&target)],
        ]
        .concat(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v = parse_json(&o.stdout);
    assert_eq!(v["reliable"], false);
    assert!(fs::read_to_string(&target).unwrap().starts_with(HEADER));
}

#[test]
fn progress_bar_with_time_left_on_a_terminal() {
    use portable_pty::{CommandBuilder, PtySize, native_pty_system};
    let pty = native_pty_system()
        .openpty(PtySize {
            rows: 24,
            cols: 80,
            pixel_width: 0,
            pixel_height: 0,
        })
        .unwrap();
    // Estimated at just over a second: 1 000 runs of set1's 50 266 steps.
    let mut cmd = CommandBuilder::new(BIN);
    cmd.args(["run", "--repeat", "1000", "--format", "json"]);
    cmd.env("TERM", "xterm-256color");
    let mut child = pty.slave.spawn_command(cmd).unwrap();
    drop(pty.slave);
    let mut reader = pty.master.try_clone_reader().unwrap();
    let collected = std::thread::spawn(move || {
        let mut all = Vec::new();
        let _ = reader.read_to_end(&mut all);
        all
    });
    let status = child.wait().unwrap();
    drop(pty.master);
    let screen = text(&collected.join().unwrap());
    assert!(status.success(), "{screen}");
    assert!(
        screen.contains("about ") && screen.contains("%"),
        "no bar with a time estimate:\n{screen}"
    );
    assert!(screen.contains("\"reliable\":true"), "{screen}");
}
