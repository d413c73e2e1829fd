//! End to end: the real binary in a pseudo-terminal (read back through a
//! vt100 screen): keys, Esc and a split escape sequence that must not quit,
//! the picker scrolling, typed entry, the export prompt, exit statuses on
//! signals, no temporary file left after SIGKILL during saves, and the
//! bytes sent per nudge and per scene switch, the risk scene's first and
//! full pictures after a key, timed; and its refusal to start without a
//! terminal.

use std::io::{Read, Write};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use portable_pty::{CommandBuilder, PtySize, native_pty_system};

const BIN: &str = env!("CARGO_BIN_EXE_pounding");

fn wait_for(screen: &Arc<Mutex<vt100::Parser>>, what: &str) -> String {
    let start = Instant::now();
    loop {
        let text = screen.lock().unwrap().screen().contents();
        if text.contains(what) {
            return text;
        }
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "`{what}` never appeared:\n{text}"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn explorer_in_a_pty_takes_keys_and_quits_cleanly() {
    let dir = scratch("keys");
    let mut s = Session::start(100, 30, &dir, &dir);
    s.wait_for("impacts 9");
    s.send(b"jl"); // select Π_ω1, nudge it to 1.1
    let text = s.wait_for("1.1 ");
    assert!(text.contains("[set 1]"), "{text}");
    s.send(b"?");
    s.wait_for("this help");
    // Set 1 was changed: q asks first, y quits.
    s.send(b"xq");
    s.wait_for("Quit anyway");
    s.send(b"y");
    let status = s.exit_status();
    assert!(status.success(), "{status:?}");
    // The alternate screen was left: the explorer's frame is gone.
    std::thread::sleep(Duration::from_millis(100));
    let text = s.screen.lock().unwrap().screen().contents();
    assert!(!text.contains("[set 1]"), "{text}");
    assert!(!s.screen.lock().unwrap().screen().alternate_screen());
}

#[test]
fn without_a_terminal_it_points_to_pounding_run() {
    for args in [vec![], vec!["tui"]] {
        let out = std::process::Command::new(BIN)
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("pounding run"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    let out = std::process::Command::new(BIN)
        .args(["tui", "--left", "nosuch"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

/// The explorer in a pty of `cols`×`rows`, its screen, its writer and a byte counter.
struct Session {
    child: Box<dyn portable_pty::Child + Send + Sync>,
    screen: Arc<Mutex<vt100::Parser>>,
    bytes: Arc<Mutex<usize>>,
    writer: Box<dyn Write + Send>,
    _master: Box<dyn portable_pty::MasterPty + Send>,
}

impl Session {
    fn start(cols: u16, rows: u16, config: &std::path::Path, cwd: &std::path::Path) -> Session {
        Session::start_with(cols, rows, config, cwd, false, &[])
    }

    /// As [`Session::start`], with NO_COLOR set when `no_color`, and `args`.
    fn start_with(
        cols: u16,
        rows: u16,
        config: &std::path::Path,
        cwd: &std::path::Path,
        no_color: bool,
        args: &[&str],
    ) -> Session {
        let pty = native_pty_system()
            .openpty(PtySize {
                rows,
                cols,
                pixel_width: 0,
                pixel_height: 0,
            })
            .unwrap();
        let mut cmd = CommandBuilder::new(BIN);
        cmd.args(args);
        cmd.env("TERM", "xterm-256color");
        cmd.env("LANG", "C.UTF-8");
        cmd.env("XDG_CONFIG_HOME", config);
        if no_color {
            cmd.env("NO_COLOR", "1");
        } else if let Ok(v) = std::env::var("POUNDING_PTY_NO_COLOR") {
            cmd.env("NO_COLOR", v);
        }
        cmd.cwd(cwd);
        let child = pty.slave.spawn_command(cmd).unwrap();
        drop(pty.slave);
        let mut reader = pty.master.try_clone_reader().unwrap();
        let writer = pty.master.take_writer().unwrap();
        let screen = Arc::new(Mutex::new(vt100::Parser::new(
            rows.try_into().unwrap(),
            cols.try_into().unwrap(),
            0,
        )));
        let bytes = Arc::new(Mutex::new(0));
        let (sink, count) = (Arc::clone(&screen), Arc::clone(&bytes));
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n) = reader.read(&mut buf) {
                if n == 0 {
                    break;
                }
                *count.lock().unwrap() += n;
                sink.lock().unwrap().process(&buf[..n]);
            }
        });
        Session {
            child,
            screen,
            bytes,
            writer,
            _master: pty.master,
        }
    }

    fn send(&mut self, keys: &[u8]) {
        self.writer.write_all(keys).unwrap();
        self.writer.flush().unwrap();
    }

    fn wait_for(&self, what: &str) -> String {
        wait_for(&self.screen, what)
    }

    fn alive(&mut self) -> bool {
        self.child.try_wait().unwrap().is_none()
    }

    /// Waits until nothing has arrived for `quiet`, returns the bytes since `from`.
    fn settle(&self, from: usize, quiet: Duration) -> usize {
        let mut last = *self.bytes.lock().unwrap();
        let mut since = Instant::now();
        loop {
            std::thread::sleep(Duration::from_millis(20));
            let now = *self.bytes.lock().unwrap();
            if now != last {
                last = now;
                since = Instant::now();
            } else if since.elapsed() > quiet {
                return now - from;
            }
        }
    }

    fn exit_status(&mut self) -> portable_pty::ExitStatus {
        let start = Instant::now();
        loop {
            if let Some(s) = self.child.try_wait().unwrap() {
                return s;
            }
            assert!(start.elapsed() < Duration::from_secs(10), "did not quit");
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("pounding-pty-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn esc_and_a_split_escape_sequence_do_not_quit() {
    let dir = scratch("esc");
    let mut s = Session::start(80, 24, &dir, &dir);
    s.wait_for("impacts 9");
    s.send(b"\x1b");
    std::thread::sleep(Duration::from_millis(300));
    assert!(s.alive(), "Esc quit the explorer");
    // ↓ as ESC, then `[B` in a later read.
    s.send(b"\x1b");
    std::thread::sleep(Duration::from_millis(60));
    s.send(b"[B");
    std::thread::sleep(Duration::from_millis(300));
    assert!(s.alive(), "a split escape sequence quit the explorer");
    s.send(b"q");
    assert!(s.exit_status().success());
}

#[test]
fn picker_scrolls_typed_entry_replaces_and_export_asks_where() {
    let config = scratch("keys");
    let presets = config.join("pounding/presets");
    std::fs::create_dir_all(&presets).unwrap();
    let mut p = pounding::model::preset::builtin("set1").unwrap();
    for name in ["aa", "bb", "cc", "dd", "zz-last"] {
        p.name = name.into();
        p.save(&presets.join(format!("{name}.toml"))).unwrap();
    }
    let mut s = Session::start(80, 24, &config, &config);
    s.wait_for("impacts 9");
    // The picker: End goes to the last entry (the last row of buildings),
    // which is on screen; one up per built-in row is the last of the
    // user's presets.
    s.send(b"p");
    s.wait_for("preset for set 1");
    s.send(b"\x1b[F");
    s.wait_for("block-and-frame-pdelta");
    s.wait_for("zz-last");
    let rows = pounding::model::buildings::builtin::names().len();
    s.send(&[&b"\x1b[A"[..]].repeat(rows).concat());
    s.send(b"\r");
    s.wait_for("set 1: zz-last");
    // Typed entry: Enter on Π_m selects 0.5; typing 0.3 replaces it.
    s.send(b"\r0.3\r");
    let text = s.wait_for("0.3 ");
    assert!(!text.contains("0.50.3"), "{text}");
    // Export: the prompt proposes a path in the working folder; typing replaces it.
    s.send(b"e");
    let text = s.wait_for("export the active run");
    assert!(text.contains("pounding-zz-last-time.csv"), "{text}");
    let out = config.join("mine.csv");
    s.send(b"\t");
    s.send(out.to_str().unwrap().as_bytes());
    s.send(b"\r");
    s.wait_for("exported");
    assert!(out.is_file());
    s.send(b"q");
    s.wait_for("Quit anyway");
    s.send(b"y");
    assert!(s.exit_status().success());
}

#[test]
fn signals_end_with_128_plus_their_number() {
    let dir = scratch("signals");
    for (signal, code) in [(libc_sig::TERM, 143), (libc_sig::HUP, 129)] {
        let mut s = Session::start(80, 24, &dir, &dir);
        s.wait_for("impacts 9");
        let pid = s.child.process_id().unwrap();
        std::process::Command::new("kill")
            .args([format!("-{signal}"), pid.to_string()])
            .status()
            .unwrap();
        let status = s.exit_status();
        assert_eq!(status.exit_code(), code, "{signal}");
    }
}

mod libc_sig {
    pub const TERM: &str = "TERM";
    pub const HUP: &str = "HUP";
}

fn temporary_files(dir: &std::path::Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.ends_with(".tmp"))
                .collect()
        })
        .unwrap_or_default()
}

#[test]
fn saves_killed_with_sigkill_leave_no_temporary_file_after_the_next_start() {
    let config = scratch("kill");
    let presets = config.join("pounding/presets");
    std::fs::create_dir_all(&presets).unwrap();
    // One left as a killed save leaves it: a process id that no longer runs.
    let dead = {
        let mut c = std::process::Command::new("true").spawn().unwrap();
        let id = c.id();
        c.wait().unwrap();
        id
    };
    std::fs::write(presets.join(format!(".pounding-{dead}-abcdef.tmp")), "x").unwrap();
    for round in 0..8u64 {
        let mut s = Session::start(80, 24, &config, &config);
        s.wait_for("impacts 9");
        s.send(format!("l s{}\r", "k".repeat(1 + round as usize)).as_bytes());
        std::thread::sleep(Duration::from_millis(round * 3));
        let pid = s.child.process_id().unwrap();
        std::process::Command::new("kill")
            .args(["-KILL", &pid.to_string()])
            .status()
            .unwrap();
        s.exit_status();
    }
    let mut s = Session::start(80, 24, &config, &config);
    s.wait_for("impacts 9");
    assert_eq!(temporary_files(&presets), Vec::<String>::new());
    assert_eq!(temporary_files(&config), Vec::<String>::new());
    s.send(b"\x03");
    s.exit_status();
}

/// Bytes sent at 80×24 with or without colours: per nudge to a value not
/// computed before (one frame: the result comes within the grace, so no
/// "computing…" frame), per nudge back and forth (all but the first
/// between two computed values), and per scene switch (f v c w i a t).
fn bytes_at_80x24(no_color: bool) -> (Vec<usize>, Vec<usize>, Vec<usize>) {
    let dir = scratch(if no_color { "bytes-nc" } else { "bytes" });
    let mut s = Session::start_with(80, 24, &dir, &dir, no_color, &[]);
    s.wait_for("impacts 9");
    s.send(b"j");
    s.settle(0, Duration::from_millis(400));
    let mut measure = |keys: &[&[u8]], quiet: u64| -> Vec<usize> {
        keys.iter()
            .map(|k| {
                let from = *s.bytes.lock().unwrap();
                s.send(k);
                s.settle(from, Duration::from_millis(quiet))
            })
            .collect()
    };
    // Π_ω1 1.05 → 1.1 → 1.05 …, then down from 1.05 to values not seen yet.
    let back_and_forth = measure(&[b"l", b"h", b"l", b"h", b"l", b"h"], 400);
    let new = measure(&[b"h".as_slice(); 6], 400);
    let switches = measure(&[b"f", b"v", b"c", b"w", b"i", b"a", b"t"], 600);
    s.send(b"\x03");
    s.exit_status();
    (new, back_and_forth, switches)
}

/// Bytes the explorer sends at 80×24 for one nudge and for one scene
/// switch, printed for the record (`cargo test --release --test tui_pty
/// bytes -- --nocapture`), and bounded a little above what they are, so
/// that a regression shows. The map switch (a) draws the map's progress
/// while it computes, so its count depends a little on the machine.
#[test]
fn bytes_per_nudge_and_per_scene_switch_at_80x24() {
    let mean = |v: &[usize]| v.iter().sum::<usize>() / v.len();
    // (no_color, mean nudge, back and forth, switch, map switch)
    for (no_color, nudge, back, switch, map) in [
        (false, 1300, 1450, 2700, 3800),
        (true, 560, 700, 1700, 1900),
    ] {
        let (new, back_and_forth, switches) = bytes_at_80x24(no_color);
        let look = if no_color { "NO_COLOR" } else { "colour" };
        eprintln!(
            "{look}: bytes per nudge to a new value: {new:?}, mean {}",
            mean(&new)
        );
        eprintln!(
            "{look}: bytes per nudge back and forth: {back_and_forth:?}, mean {}",
            mean(&back_and_forth)
        );
        eprintln!("{look}: bytes per scene switch (f v c w i a t): {switches:?}");
        assert!(mean(&new) < nudge, "{look}: {new:?}");
        assert!(mean(&back_and_forth) < back, "{look}: {back_and_forth:?}");
        for (key, bytes) in "fvcwiat".chars().zip(&switches) {
            let limit = if key == 'a' { map } else { switch };
            assert!(*bytes < limit, "{look}: switch to {key}: {switches:?}");
        }
    }
}

/// Milliseconds from `keys` until the screen shows the risk scene's first
/// picture of the new spec (`new(screen)` holds and the design line does
/// not say "computing…"), and until the whole suite is drawn (nothing
/// computing, no "first pass").
fn risk_times(s: &mut Session, keys: &[u8], new: impl Fn(&str) -> bool) -> (f64, f64) {
    let start = Instant::now();
    s.send(keys);
    let mut first = None;
    loop {
        let text = s.screen.lock().unwrap().screen().contents();
        let design = text.lines().find(|l| l.contains("design ")).unwrap_or("");
        let ms = start.elapsed().as_secs_f64() * 1e3;
        let drawn = text.contains("P(pounding)") && new(&text);
        if first.is_none() && drawn && !design.contains("computing…") {
            first = Some(ms);
        }
        if drawn && !text.contains("computing…") && !text.contains("first pass") {
            return (first.unwrap_or(ms), ms);
        }
        assert!(ms < 30_000.0, "the risk picture never completed:\n{text}");
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// The risk scene at 80×24 in a pty, two-buildings: the first picture and
/// the whole suite after the key that opens it (the suite is generated
/// then), after `]` (design level 0.35 g) and after a nudge of the gap,
/// printed for the record (`cargo test --release --test tui_pty risk --
/// --nocapture`). The first picture is drawn once the job has run for the
/// pace's grace (100 ms) unless it ends before.
#[test]
fn the_risk_scene_draws_a_first_pass_then_the_whole_suite() {
    let dir = scratch("risk");
    let mut s = Session::start_with(80, 24, &dir, &dir, false, &["--left", "two-buildings"]);
    s.wait_for("impacts");
    let opened = risk_times(&mut s, b"x", |t| t.contains("design 0.3 g"));
    let level = risk_times(&mut s, b"]", |t| t.contains("design 0.35 g"));
    // Π_d is the tenth row: nine down, then a nudge of ten steps, which
    // changes the gap in the probability's title.
    s.send(b"jjjjjjjjj");
    std::thread::sleep(Duration::from_millis(300));
    let title = |t: &str| {
        t.lines()
            .find_map(|l| {
                l.split_once("P(pounding) ")
                    .map(|(_, r)| r.trim().to_string())
            })
            .unwrap_or_default()
    };
    let before = title(&s.screen.lock().unwrap().screen().contents());
    let gap = risk_times(&mut s, b"L", |t| title(t) != before);
    for (what, (first, full)) in [
        ("x opens the scene", opened),
        ("] design level", level),
        ("L gap nudge", gap),
    ] {
        eprintln!("risk scene, {what}: first picture {first:.0} ms, whole suite {full:.0} ms");
        assert!(first <= full && full < 20_000.0, "{what}: {first} {full}");
    }
    s.send(b"\x03");
    s.exit_status();
}

/// The buildings scene in a real terminal at 80×24: it opens on the row,
/// plays and pauses, takes a storey count typed in its pane, recalls a
/// row preset and quits cleanly.
#[test]
fn the_buildings_scene_plays_edits_and_recalls_in_a_pty() {
    let dir = scratch("buildings");
    let mut s = Session::start_with(
        80,
        24,
        &dir,
        &dir,
        false,
        &["--buildings", "block-and-frame"],
    );
    s.wait_for("improved-kelvin: 46 impacts");
    s.send(b" ");
    s.wait_for("▶ 0.5×");
    std::thread::sleep(Duration::from_millis(400));
    s.send(b" ");
    let text = s.wait_for("‖ 0.5×");
    assert!(
        !text.contains("t 0.00/14.6 s"),
        "the cursor did not move:\n{text}"
    );
    // The block's storeys, typed: 4.
    s.send(b"jj\r4\r");
    s.wait_for("block storeys     4");
    s.wait_for("improved-kelvin: ");
    // The third row preset from the picker.
    s.send(b"p");
    s.wait_for("row preset");
    s.send(b"3");
    s.wait_for("row three-in-series");
    s.wait_for("mid storeys");
    s.send(b"q");
    let status = s.exit_status();
    assert!(status.success(), "{status:?}");
    assert!(!s.screen.lock().unwrap().screen().alternate_screen());
}
