//! The explorer driven by keys on a TestBackend: layouts at 80×24 and
//! 120×40 (insta snapshots), a scripted edit that changes the summary,
//! invalid input, resizing to 1×1, the worker's latest-wins behaviour.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pounding::model::preset::builtin;
use pounding::tui::app::{App, Look, Mode, Scene};
use pounding::tui::ui;
use pounding::tui::views::summary;
use pounding::tui::worker::{Job, Output, Pending, RunSpec, Slot, SpectrumSpec, Worker};
use ratatui::Terminal;
use ratatui::backend::TestBackend;

fn app(size: (u16, u16)) -> App {
    let presets = App::load_presets(None);
    let mut a = App::new(
        builtin("set1").unwrap(),
        builtin("set2").unwrap(),
        presets,
        None,
        Look {
            ascii: false,
            color: false,
        },
    );
    a.on_resize(size.0, size.1);
    a
}

/// Computes what the scene needs, with compute times zeroed so screens are reproducible.
fn settle(a: &mut App) {
    a.compute_blocking();
    for r in &mut a.results {
        r.elapsed_ms = 0.0;
    }
}

fn screen(a: &App) -> String {
    let mut t = Terminal::new(TestBackend::new(a.size.0, a.size.1)).unwrap();
    t.draw(|f| ui::render(a, f)).unwrap();
    let buf = t.backend().buffer();
    let mut s = String::new();
    for y in 0..buf.area.height {
        for x in 0..buf.area.width {
            s.push_str(buf[(x, y)].symbol());
        }
        s.push('\n');
    }
    s
}

fn key(a: &mut App, code: KeyCode) {
    a.on_key(KeyEvent::new(code, KeyModifiers::NONE));
}

#[test]
fn layout_80x24() {
    let mut a = app((80, 24));
    settle(&mut a);
    insta::assert_snapshot!("history_80x24", screen(&a));
}

#[test]
fn layout_120x40() {
    let mut a = app((120, 40));
    settle(&mut a);
    insta::assert_snapshot!("history_120x40", screen(&a));
    key(&mut a, KeyCode::Char('v'));
    settle(&mut a);
    insta::assert_snapshot!("kelvin_120x40", screen(&a));
}

#[test]
fn ascii_layout_has_no_other_characters() {
    let mut a = app((80, 24));
    a.look.ascii = true;
    settle(&mut a);
    let s = screen(&a);
    assert!(s.is_ascii(), "{s}");
    assert!(s.contains("P_w1"), "{s}");
}

#[test]
fn nudging_a_field_changes_the_summary() {
    let mut a = app((120, 40));
    settle(&mut a);
    let before = summary::line("set 1", a.shown(Slot::Set(0)).unwrap());
    // Set 1 with improved Kelvin: 9 impacts, Π_u1 ≈ 3.2224 (the core's check).
    assert!(before.contains("impacts 9"), "{before}");
    assert!(before.contains("Π_u 3.22/"), "{before}");
    key(&mut a, KeyCode::Char('j')); // Π_ω1
    key(&mut a, KeyCode::Char('l')); // +0.05
    assert_eq!(a.sets[0].params.omega1, 1.1);
    assert_eq!(a.sets[1].params.omega1, 1.5, "only the active set moves");
    settle(&mut a);
    let after = summary::line("set 1", a.shown(Slot::Set(0)).unwrap());
    assert_ne!(before, after);
    assert!(screen(&a).contains(&after));
    // Shift is ×10, ',' a tenth.
    a.on_key(KeyEvent::new(KeyCode::Right, KeyModifiers::SHIFT));
    assert!((a.sets[0].params.omega1 - 1.6).abs() < 1e-12);
    key(&mut a, KeyCode::Char(','));
    assert!((a.sets[0].params.omega1 - 1.595).abs() < 1e-12);
    // r resets to the preset; Tab moves to set 2; m toggles its model.
    key(&mut a, KeyCode::Char('r'));
    assert_eq!(a.sets[0].params, a.sets[0].preset.params);
    key(&mut a, KeyCode::Tab);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.active, 1);
    assert_eq!(a.sets[1].params.model.name(), "kelvin");
}

#[test]
fn typed_value_is_checked_and_old_value_stays() {
    let mut a = app((80, 24));
    for _ in 0..9 {
        key(&mut a, KeyCode::Down); // Π_d
    }
    key(&mut a, KeyCode::Enter);
    for _ in 0..5 {
        key(&mut a, KeyCode::Backspace);
    }
    key(&mut a, KeyCode::Char('-'));
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Enter);
    match &a.mode {
        Mode::Editing { error: Some(e), .. } => {
            assert_eq!(e, "`gap` = -1: must be a number in [0, 1e6], or inf")
        }
        m => panic!("expected an edit error, got {m:?}"),
    }
    assert_eq!(a.sets[0].params.gap, 0.2);
    assert!(screen(&a).contains("rejected: `gap` = -1"));
    for _ in 0..2 {
        key(&mut a, KeyCode::Backspace);
    }
    for c in "inf".chars() {
        key(&mut a, KeyCode::Char(c));
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.mode, Mode::Normal);
    assert!(a.sets[0].params.gap.is_infinite());
    settle(&mut a);
    assert_eq!(a.shown(Slot::Set(0)).unwrap().result.impacts.len(), 0);
}

#[test]
fn presets_recall_and_save_never_overwrites_a_builtin() {
    let dir = std::env::temp_dir().join(format!("pounding-tui-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut a = app((80, 24));
    a.user_dir = Some(dir.clone());
    key(&mut a, KeyCode::Tab);
    let set1 = a.presets.iter().position(|p| p.name == "set1").unwrap();
    assert!(set1 < 9);
    key(&mut a, KeyCode::Char(char::from(b'1' + set1 as u8))); // set1 into set 2
    assert_eq!(a.sets[1].preset.name, "set1");
    key(&mut a, KeyCode::Char('s'));
    for c in "set2".chars() {
        key(&mut a, KeyCode::Char(c));
    }
    key(&mut a, KeyCode::Enter);
    assert!(matches!(&a.mode, Mode::SaveName { error: Some(e), .. } if e.contains("built-in")));
    for _ in 0..4 {
        key(&mut a, KeyCode::Backspace);
    }
    for c in "mine".chars() {
        key(&mut a, KeyCode::Char(c));
    }
    key(&mut a, KeyCode::Enter);
    let saved = dir.join("mine.toml");
    assert!(saved.is_file(), "{:?}", a.status);
    assert!(a.presets.iter().any(|p| p.name == "mine"));
    // Saving again asks first; n keeps the file.
    key(&mut a, KeyCode::Char('l'));
    key(&mut a, KeyCode::Char('s'));
    for c in "mine".chars() {
        key(&mut a, KeyCode::Char(c));
    }
    key(&mut a, KeyCode::Enter);
    assert!(matches!(a.mode, Mode::ConfirmOverwrite { .. }));
    key(&mut a, KeyCode::Char('n'));
    let kept = pounding::model::Preset::load(&saved).unwrap();
    assert_eq!(kept.params.mass_ratio, 0.5);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn resizing_to_1x1_and_back_does_not_panic() {
    let mut a = app((120, 40));
    settle(&mut a);
    let mut t = Terminal::new(TestBackend::new(120, 40)).unwrap();
    for scene in Scene::ALL {
        a.scene = scene;
        a.mode = Mode::Help;
        for (w, h) in [
            (1, 1),
            (2, 1),
            (59, 19),
            (60, 20),
            (80, 24),
            (1, 40),
            (300, 3),
            (120, 40),
        ] {
            t.backend_mut().resize(w, h);
            a.on_resize(w, h);
            t.draw(|f| ui::render(&a, f)).unwrap();
        }
        a.mode = Mode::Normal;
    }
    t.backend_mut().resize(30, 10);
    a.on_resize(30, 10);
    let s = screen(&a);
    assert!(s.contains("terminal too small"), "{s}");
}

#[test]
fn stale_results_are_dropped() {
    let mut a = app((80, 24));
    let first = a.job().unwrap();
    key(&mut a, KeyCode::Char('l'));
    let second = a.job().unwrap();
    assert!(second.generation > first.generation);
    let old = pounding::tui::worker::compute_run(&first.runs[0], &|| true);
    a.on_output(Output::Run {
        generation: first.generation,
        output: Box::new(old),
    });
    assert!(a.results.is_empty(), "a superseded run must not be shown");
    assert!(a.computing);
}

#[test]
fn pending_keeps_only_the_newest_request() {
    let mut p = Pending::default();
    let job = |g| Job {
        generation: g,
        ..Job::default()
    };
    assert_eq!(p.put(job(1)), None);
    assert_eq!(p.put(job(2)).unwrap().generation, 1);
    assert_eq!(p.put(job(3)).unwrap().generation, 2);
}

#[test]
fn worker_latest_wins_and_cancels_the_running_job() {
    let (tx, rx) = std::sync::mpsc::channel();
    let w = Worker::start(move |o| {
        let _ = tx.send(o);
    });
    let p = pounding::model::SET1;
    let spectrum = |g| Job {
        generation: g,
        runs: vec![],
        spectrum: Some(SpectrumSpec {
            params: p,
            mu: p.mu(),
            grid: (0..200).map(|i| 0.2 + 0.02 * i as f64).collect(),
        }),
    };
    w.submit(spectrum(1));
    // Wait until job 1 runs, then ask for 2, 3, 4 at once.
    let first = rx.recv().unwrap();
    assert_eq!(first.generation(), 1);
    for g in 2..=3 {
        w.submit(spectrum(g));
    }
    let last = Job {
        generation: 4,
        runs: vec![RunSpec {
            slot: Slot::Set(0),
            params: p,
            buckets: 100,
        }],
        spectrum: None,
    };
    w.submit(last);
    let mut done = Vec::new();
    let mut runs_of_4 = 0;
    while let Ok(o) = rx.recv_timeout(std::time::Duration::from_secs(60)) {
        match o {
            Output::Done {
                generation,
                cancelled,
            } => {
                done.push((generation, cancelled));
                if generation == 4 {
                    break;
                }
            }
            Output::Run {
                generation: 4,
                output,
            } => {
                runs_of_4 += 1;
                assert_eq!(output.result.impacts.len(), 9);
            }
            _ => {}
        }
    }
    assert_eq!(done.last(), Some(&(4, false)), "{done:?}");
    assert_eq!(runs_of_4, 1);
    // Job 1 (200 points, seconds of work) was stopped, not finished; of 2 and 3 at most one ran, cancelled.
    assert_eq!(done[0], (1, true), "{done:?}");
    assert!(done.len() <= 3, "{done:?}");
    assert!(done.iter().filter(|d| d.0 < 4).all(|d| d.1), "{done:?}");
}
