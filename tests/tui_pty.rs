//! End to end: the real binary in a pseudo-terminal (read back through a
//! vt100 screen), and its refusal to start without a terminal.

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
    let pty = native_pty_system()
        .openpty(PtySize {
            rows: 30,
            cols: 100,
            pixel_width: 0,
            pixel_height: 0,
        })
        .unwrap();
    let mut cmd = CommandBuilder::new(BIN);
    cmd.env("TERM", "xterm-256color");
    cmd.env("LANG", "C.UTF-8");
    cmd.env(
        "XDG_CONFIG_HOME",
        std::env::temp_dir().join("pounding-pty-test"),
    );
    let mut child = pty.slave.spawn_command(cmd).unwrap();
    drop(pty.slave);
    let mut reader = pty.master.try_clone_reader().unwrap();
    let mut writer = pty.master.take_writer().unwrap();
    let screen = Arc::new(Mutex::new(vt100::Parser::new(
        30.try_into().unwrap(),
        100.try_into().unwrap(),
        0,
    )));
    let sink = Arc::clone(&screen);
    std::thread::spawn(move || {
        let mut buf = [0u8; 4096];
        while let Ok(n) = reader.read(&mut buf) {
            if n == 0 {
                break;
            }
            sink.lock().unwrap().process(&buf[..n]);
        }
    });
    wait_for(&screen, "impacts 9");
    writer.write_all(b"jl").unwrap(); // select Π_ω1, nudge it to 1.1
    writer.flush().unwrap();
    let text = wait_for(&screen, "1.1 ");
    assert!(text.contains("[set 1]"), "{text}");
    writer.write_all(b"?").unwrap();
    wait_for(&screen, "this help");
    writer.write_all(b"xq").unwrap();
    writer.flush().unwrap();
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        assert!(start.elapsed() < Duration::from_secs(10), "did not quit");
        std::thread::sleep(Duration::from_millis(20));
    };
    assert!(status.success(), "{status:?}");
    // The alternate screen was left: the explorer's frame is gone.
    std::thread::sleep(Duration::from_millis(100));
    let text = screen.lock().unwrap().screen().contents();
    assert!(!text.contains("[set 1]"), "{text}");
    assert!(!screen.lock().unwrap().screen().alternate_screen());
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
