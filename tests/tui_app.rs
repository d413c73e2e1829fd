//! The explorer driven by keys on a TestBackend: every scene at 60×20,
//! 80×24 and 120×40 (insta snapshots, and no label touching another), the
//! traps of typed entry, Esc, quitting, the picker, export and the wheel;
//! the cursor, zoom, impact table, physical view and the worker.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers, MouseEvent, MouseEventKind};
use pounding::model::preset::builtin;
use pounding::tui::app::{App, Look, Mode};
use pounding::tui::effects::{self, Effect};
use pounding::tui::export::History;
use pounding::tui::scene::Scene;
use pounding::tui::ui;
use pounding::tui::views::summary;
use pounding::tui::views::units::PI_UNITS;
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
    for r in &mut a.jobs.results {
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

/// Loads the built-in preset `name` into the active set.
fn recall(a: &mut App, name: &str) {
    let index = a.presets.iter().position(|p| p.name == name).unwrap();
    a.recall(index);
}

fn key(a: &mut App, code: KeyCode) -> Option<Effect> {
    a.on_key(KeyEvent::new(code, KeyModifiers::NONE))
}

fn typed(a: &mut App, text: &str) {
    for c in text.chars() {
        key(a, KeyCode::Char(c));
    }
}

/// Runs an effect as the main loop would and hands back what came of it.
fn run(a: &mut App, e: Option<Effect>) {
    if let Some(e) = e {
        let dir = a.user_dir.clone();
        for done in effects::run(e, dir.as_deref()) {
            a.on_done(done);
        }
    }
}

/// Places where two labels touch: a digit directly against a letter of
/// another label (`x-2.93`, `0.05-1.96`, `40f_p`), or a number cut short
/// (`6.3e-`, `-7.`).
fn touching(screen: &str) -> Vec<String> {
    let mut bad = Vec::new();
    for line in screen.lines() {
        let c: Vec<char> = line.chars().collect();
        for i in 0..c.len() {
            let next = |k: usize| c.get(i + k).copied().unwrap_or(' ');
            let prev = if i > 0 { c[i - 1] } else { ' ' };
            let exponent = c[i] == 'e' && prev.is_ascii_digit();
            let glued = c[i].is_ascii_digit()
                && next(1).is_alphabetic()
                && next(1) != 'π'
                && !(next(1) == 'e' && (next(2).is_ascii_digit() || next(2) == '-'));
            let dash = (c[i].is_alphabetic() && !exponent || c[i].is_ascii_digit())
                && next(1) == '-'
                && next(2).is_ascii_digit();
            let cut = c[i].is_ascii_digit()
                && (next(1) == '.' && next(2) == ' '
                    || next(1) == 'e' && (next(2) == ' ' || next(2) == '-' && next(3) == ' '));
            if glued || dash || cut {
                let from = i.saturating_sub(8);
                let to = (i + 8).min(c.len());
                bad.push(c[from..to].iter().collect());
            }
        }
    }
    bad
}

fn scene_screens(size: (u16, u16)) -> Vec<(String, String)> {
    let mut a = app(size);
    let mut out = Vec::new();
    for (name, keys) in [
        ("time", "t"),
        ("loops", "f"),
        ("laws", "v"),
        ("laws_all", "b"),
        ("sets", "c"),
        ("overlay", "o"),
        ("spectrum", "w"),
        ("impacts", "i"),
        ("map", "a"),
        ("map_ratio", "o"),
        ("risk", "x"),
    ] {
        if name == "overlay" || name == "map_ratio" {
            key(&mut a, KeyCode::Char('o'));
        } else {
            if a.view.overlay {
                key(&mut a, KeyCode::Char('o'));
            }
            typed(&mut a, keys);
        }
        settle(&mut a);
        out.push((name.to_string(), screen(&a)));
    }
    // The cursor on the third impact, zoomed, and the physical view of two-buildings.
    key(&mut a, KeyCode::Char('t'));
    for _ in 0..3 {
        key(&mut a, KeyCode::Char('n'));
    }
    key(&mut a, KeyCode::Char('z'));
    settle(&mut a);
    out.push(("cursor".into(), screen(&a)));
    let mut b = app(size);
    recall(&mut b, "two-buildings");
    key(&mut b, KeyCode::Char('u'));
    settle(&mut b);
    out.push(("physical".into(), screen(&b)));
    out
}

#[test]
fn every_scene_at_three_sizes_has_no_touching_labels() {
    for size in [(60, 20), (80, 24), (120, 40)] {
        for (name, s) in scene_screens(size) {
            let bad = touching(&s);
            assert!(bad.is_empty(), "{name} at {size:?}: {bad:?}\n{s}");
            insta::assert_snapshot!(format!("{name}_{}x{}", size.0, size.1), s);
        }
    }
}

/// The full texts a pane or title may show: every row's meaning and
/// symbol, every name a choice row can hold, the physical rows, the panes'
/// titles and the laws scene's titles.
fn full_texts() -> Vec<String> {
    use pounding::model::params::{FIELDS, Kind};
    use pounding::tui::scene::Laws;
    let mut texts = vec![
        "parameters (Tab switches set)".to_string(),
        "physical units (u: Π-groups)".to_string(),
    ];
    for f in FIELDS {
        texts.extend([f.meaning.to_string(), f.symbol.to_string()]);
        if let Kind::Choice { names, .. } = f.kind {
            // `record:PATH` names a form, not a text the pane shows.
            texts.extend(
                names
                    .iter()
                    .filter(|n| !n.contains(':'))
                    .map(|n| n.to_string()),
            );
        }
    }
    for r in &pounding::tui::physical::ROWS {
        texts.push(format!("moves {}", r.moves));
    }
    // The risk scene's note and the fixed parts of its titles.
    use pounding::tui::views::risk;
    texts.extend([
        risk::REFERENCE_NOTE.to_string(),
        "left drift [mm] (16–84 %)".to_string(),
        "P(pounding | IM) no fit:".to_string(),
        // The title before a fit's θ and β.
        "P(pounding | IM)".to_string(),
        "at d ".to_string(),
    ]);
    // A law's words, where a label names the law its column shortens.
    for (model, _) in pounding::tui::fit::SHORT_LAWS {
        texts.push(pounding::tui::fit::law_words(model).to_string());
    }
    let own = pounding::model::ContactModel::ImprovedKelvin;
    let mut laws = Laws::Paper;
    for _ in 0..8 {
        texts.push(format!("f_p(δ) {} (b)", laws.title(own)));
        laws = laws.next(own);
    }
    texts
}

/// Places where a text of `texts` is shown cut: a prefix of it (six
/// characters at least, starting a token, trailing spaces left out)
/// followed on screen by neither the rest of it nor "…", but by a space, a
/// border or the line's end. A line that ends at one of the text's spaces
/// is the info box wrapping, not a cut; another text sharing a prefix goes
/// on with a letter or digit, or is one whole word of it.
fn cut_texts(screen: &str, texts: &[String]) -> Vec<String> {
    let mut bad = Vec::new();
    for line in screen.lines() {
        let c: Vec<char> = line.chars().collect();
        for t in texts {
            let t: Vec<char> = t.chars().collect();
            for i in 0..c.len() {
                if i > 0 && c[i - 1].is_alphanumeric() {
                    continue;
                }
                let mut m = c[i..].iter().zip(&t).take_while(|(a, b)| a == b).count();
                if m == t.len() {
                    continue;
                }
                while m > 0 && t[m - 1] == ' ' {
                    m -= 1;
                }
                if m < 6 {
                    continue;
                }
                let next = c.get(i + m).copied();
                let goes_on = next.is_some_and(|n| n == '…' || n.is_alphanumeric());
                let wraps = t[m] == ' ' && c[i + m..].iter().all(|n| *n == ' ');
                // One whole word then a space is another text's word
                // ("damping" of the energy terms), not this one cut.
                let one_word = t[m] == ' ' && !t[..m].contains(&' ');
                // A prefix that is itself a whole text ("moves Π_m" of m1,
                // beside m2's "moves Π_m and the force scale").
                let whole = texts.contains(&t[..m].iter().collect());
                // Another text shown whole there ("improved Kelvin" where
                // "improved-kelvin" shares its first word) is that text.
                let other = texts.iter().any(|o| {
                    let o: Vec<char> = o.chars().collect();
                    o.len() > m && c[i..].starts_with(&o)
                });
                if !goes_on && !wraps && !one_word && !whole && !other {
                    bad.push(c[i..(i + m + 1).min(c.len())].iter().collect());
                }
            }
        }
    }
    bad
}

#[test]
fn no_label_meaning_value_or_title_is_cut_without_an_ellipsis() {
    let texts = full_texts();
    for size in [(60, 20), (80, 24), (120, 40)] {
        let mut screens = scene_screens(size);
        // Set 1 Kelvin beside set 2's improved Kelvin, then set 2 at each
        // law with a long name.
        let mut a = app(size);
        key(&mut a, KeyCode::Char('m'));
        settle(&mut a);
        screens.push(("kelvin vs improved".into(), screen(&a)));
        key(&mut a, KeyCode::Tab);
        for model in ["hertzdamp", "hunt-crossley"] {
            a.sets[1].params.set("model", model).unwrap();
            settle(&mut a);
            screens.push((model.into(), screen(&a)));
        }
        for (name, s) in screens {
            let bad = cut_texts(&s, &texts);
            assert!(bad.is_empty(), "{name} at {size:?}: {bad:?}\n{s}");
        }
    }
    // At 80×24 a Kelvin set and an improved Kelvin set read apart.
    let mut a = app((80, 24));
    key(&mut a, KeyCode::Char('m'));
    settle(&mut a);
    let s = screen(&a);
    let row = s.lines().find(|l| l.contains("model")).unwrap();
    assert!(row.contains("kelvin") && row.contains("IK"), "{row}");
}

#[test]
fn the_cut_check_finds_what_it_should() {
    let texts = full_texts();
    for bad in [
        "│Π_K       Hertz stiffness (0: from 0         0        │",
        "│model     improved  improved │",
        "f_p [m2·a_p]                 f_p(δ) paper pair (b",
        "┌ parameters (Tab switches set┐f_p",
    ] {
        assert!(!cut_texts(bad, &texts).is_empty(), "{bad}");
    }
    for good in [
        "│Π_K       Hertz stiffness (0:… 0         0        │",
        "│model     IK        kelvin   │",
        "f_p [m2·a_p]            f_p(δ) paper pair…",
        "┌ parameters (Tab…) ┐",
        "Π_uy2 right yield displacement [0.001,  ",
    ] {
        assert!(
            cut_texts(good, &texts).is_empty(),
            "{good}: {:?}",
            cut_texts(good, &texts)
        );
    }
}

#[test]
fn a_modified_set_does_not_run_into_the_chart_beside_it() {
    // The sets' line ("set 1: set1* (Π_m)  set 2: set2") is as wide as the
    // info box at 80×24; it must not touch the g(τ) chart's title.
    for size in [(60, 20), (80, 24), (120, 40)] {
        let mut a = app(size);
        key(&mut a, KeyCode::Right);
        settle(&mut a);
        let s = screen(&a);
        assert!(s.contains("set1*"), "{s}");
        let bad = touching(&s);
        assert!(bad.is_empty(), "{size:?}: {bad:?}\n{s}");
    }
}

#[test]
fn the_label_check_finds_what_it_should() {
    for bad in ["step 0.05-1.96 ", "x-2.93 ", " 6.3e- ", " min f_p -7. "] {
        assert!(!touching(bad).is_empty(), "{bad}");
    }
    let good = "x1 x2+Π_d 1e-3 -2.5e-4 f_p 0..39.225 set 1: Π_u 3.222/0.479";
    assert!(touching(good).is_empty(), "{good}: {:?}", touching(good));
}

#[test]
fn ascii_layout_has_no_other_characters() {
    let mut a = app((80, 24));
    a.look.ascii = true;
    settle(&mut a);
    let s = screen(&a);
    assert!(s.is_ascii(), "{s}");
    assert!(s.contains("Pi_w1"), "{s}");
    assert!(s.contains("xdot [a_p/w_p]"), "{s}");
    key(&mut a, KeyCode::Down);
    a.on_resize(120, 40);
    assert!(screen(&a).contains("mu = Pi_w2/Pi_w1"), "{}", screen(&a));
    for _ in 0..4 {
        key(&mut a, KeyCode::Down);
    }
    assert!(screen(&a).contains("Pi_xi"));
}

/// The risk scene in ASCII: θ, β and 2π spelled out, bars and markers plain.
#[test]
fn the_risk_scene_in_ascii_spells_its_symbols() {
    let mut a = app((80, 24));
    a.look.ascii = true;
    typed(&mut a, "x[[[[");
    settle(&mut a);
    let s = screen(&a);
    assert!(s.is_ascii(), "{s}");
    assert!(s.contains("theta 0.1") && s.contains(" beta 0.1"), "{s}");
    assert!(s.contains("w_p 2pi"), "{s}");
    // `g` says there is no figure of this scene rather than asking for a path.
    key(&mut a, KeyCode::Char('g'));
    assert_eq!(a.mode, Mode::Normal);
    assert!(
        a.status.as_deref().unwrap().contains("no SVG"),
        "{:?}",
        a.status
    );
}

#[test]
fn overlays_use_markers_in_the_legend_without_colour() {
    let mut a = app((120, 40));
    typed(&mut a, "co");
    settle(&mut a);
    let s = screen(&a);
    assert!(s.contains("** set 1 x1  ++ set 2 x1"), "{s}");
}

#[test]
fn nudging_a_field_changes_the_summary() {
    let mut a = app((120, 40));
    settle(&mut a);
    let line = |a: &App| {
        summary::line(
            "set 1",
            a.shown(Slot::Set(0)).unwrap(),
            &PI_UNITS,
            true,
            200,
        )
    };
    let before = line(&a);
    // Set 1 with improved Kelvin: 9 impacts, Π_u1 ≈ 3.2224 (the core's check).
    assert!(before.contains("impacts 9"), "{before}");
    assert!(before.contains("Π_u 3.222/"), "{before}");
    key(&mut a, KeyCode::Char('j')); // Π_ω1
    key(&mut a, KeyCode::Char('l')); // +0.05
    assert_eq!(a.sets[0].params.omega1, 1.1);
    assert_eq!(a.sets[1].params.omega1, 1.5, "only the active set moves");
    settle(&mut a);
    let after = line(&a);
    assert_ne!(before, after);
    let shown = line(&a);
    assert!(screen(&a).contains(&shown[..60]), "{shown}");
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
    // Typing replaces the pre-filled value.
    key(&mut a, KeyCode::Char('-'));
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Enter);
    match &a.mode {
        Mode::Editing(field) => assert_eq!(
            field.error.as_deref(),
            Some("`gap` = -1: must be a number in [0, 1e6], or inf")
        ),
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
    typed(&mut a, "set2");
    key(&mut a, KeyCode::Enter);
    assert!(
        matches!(&a.mode, Mode::SaveName(f) if f.error.as_deref().is_some_and(|e| e.contains("built-in")))
    );
    a.on_key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL));
    typed(&mut a, "mine");
    let e = key(&mut a, KeyCode::Enter);
    run(&mut a, e);
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
        a.view.scene = scene;
        a.mode = Mode::Help { top: 0 };
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
    assert!(
        a.jobs.results.is_empty(),
        "a superseded run must not be shown"
    );
    assert!(a.jobs.computing);
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
            params: p.clone(),
            mu: p.mu(),
            // Seconds of work: the grid swept over 250 times.
            grid: (0..50_000).map(|i| 0.2 + 0.02 * (i % 200) as f64).collect(),
        }),
        ..Job::default()
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
            params: p.clone(),
            buckets: 100,
            window: [0.0, p.tau_end()],
        }],
        ..Job::default()
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
    // Job 1 (50 000 points, seconds of work) was stopped, not finished; of 2 and 3 at most one ran, cancelled.
    assert_eq!(done[0], (1, true), "{done:?}");
    assert!(done.len() <= 3, "{done:?}");
    assert!(done.iter().filter(|d| d.0 < 4).all(|d| d.1), "{done:?}");
}

#[test]
fn esc_never_quits_and_ctrl_letters_do_nothing() {
    let mut a = app((80, 24));
    assert_eq!(key(&mut a, KeyCode::Esc), None);
    assert_eq!(a.mode, Mode::Normal);
    for c in ['e', 'q', 's', 'w'] {
        assert_eq!(
            a.on_key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)),
            None
        );
        assert_eq!(a.mode, Mode::Normal, "Ctrl-{c}");
    }
    assert_eq!(
        a.on_key(KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL)),
        Some(Effect::Quit)
    );
    // Unchanged sets quit at once; a changed one asks, and says so in the key bar.
    assert_eq!(key(&mut a, KeyCode::Char('q')), Some(Effect::Quit));
    key(&mut a, KeyCode::Char('l'));
    assert!(screen(&a).contains("q quit (unsaved)"), "{}", screen(&a));
    assert_eq!(key(&mut a, KeyCode::Char('q')), None);
    assert_eq!(a.mode, Mode::ConfirmQuit);
    assert!(screen(&a).contains("set 1 differs from its preset"));
    assert_eq!(key(&mut a, KeyCode::Esc), None);
    assert_eq!(a.mode, Mode::Normal);
    key(&mut a, KeyCode::Char('q'));
    assert_eq!(key(&mut a, KeyCode::Char('y')), Some(Effect::Quit));
}

#[test]
fn the_key_bar_always_ends_with_help_and_quit() {
    for w in [60, 80, 120] {
        let a = app((w, 24));
        let bar = ui::key_bar(&a, (w - 12) as usize);
        assert!(bar.ends_with("? help  q quit"), "{w}: {bar}");
        assert!(bar.chars().count() <= (w - 12) as usize);
    }
}

#[test]
fn typed_entry_edits_in_place() {
    let mut a = app((80, 24));
    key(&mut a, KeyCode::Enter); // Π_m = 0.5, selected
    typed(&mut a, "0.3");
    key(&mut a, KeyCode::Home);
    key(&mut a, KeyCode::Delete);
    typed(&mut a, "1");
    key(&mut a, KeyCode::End);
    a.on_key(KeyEvent::new(KeyCode::Char('w'), KeyModifiers::CONTROL));
    typed(&mut a, "0.25");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.sets[0].params.mass_ratio, 0.25);
}

#[test]
fn a_coarse_time_step_is_refused_or_warned_as_the_cli_does() {
    let mut a = app((80, 24));
    let dt = pounding::model::params::FIELDS
        .iter()
        .position(|f| f.key == "dt")
        .unwrap();
    a.selected = dt;
    for (text, ok) in [("3000", false), ("0.5", false), ("0.02", true)] {
        key(&mut a, KeyCode::Enter);
        typed(&mut a, text);
        key(&mut a, KeyCode::Enter);
        assert_eq!(a.mode == Mode::Normal, ok, "{text}: {:?}", a.mode);
        if !ok {
            key(&mut a, KeyCode::Esc);
        }
    }
    assert_eq!(a.sets[0].params.dt, 0.02);
    assert!(
        a.status
            .as_deref()
            .unwrap()
            .contains("steps per contact period")
    );
    assert!(screen(&a).contains("steps per contact period"));
}

#[test]
fn the_picker_scrolls_to_its_last_entry() {
    let dir = std::env::temp_dir().join(format!("pounding-picker-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut p = builtin("set1").unwrap();
    for name in ["alpha", "beta", "gamma", "delta", "zeta"] {
        p.name = name.into();
        p.save(&dir.join(format!("{name}.toml"))).unwrap();
    }
    let mut a = app((80, 24));
    a.user_dir = Some(dir.clone());
    let e = key(&mut a, KeyCode::Char('p'));
    run(&mut a, e);
    let n = a.presets.len();
    assert!(n >= 12, "{n}");
    for _ in 0..n - 1 {
        key(&mut a, KeyCode::Down);
    }
    let s = screen(&a);
    let last = a.presets[n - 1].name.clone();
    assert!(s.contains(&format!("{last} ")), "{s}");
    // The rows of buildings follow the pair's presets.
    let entries = a.picker_entries().len();
    assert_eq!(
        entries,
        n + pounding::model::buildings::builtin::names().len()
    );
    assert!(s.contains(&format!("({n}/{entries}")), "{s}");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.sets[0].preset.name, last);
    // A preset saved by another process joins at the end; the others keep their digits.
    let before: Vec<String> = a.presets.iter().map(|p| p.name.clone()).collect();
    p.name = "aaa".into();
    p.save(&dir.join("aaa.toml")).unwrap();
    let e = key(&mut a, KeyCode::Char('p'));
    run(&mut a, e);
    let after: Vec<String> = a.presets.iter().map(|p| p.name.clone()).collect();
    assert_eq!(after[..before.len()], before[..]);
    assert_eq!(after.last().unwrap(), "aaa");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn export_asks_for_a_path_and_offers_the_on_screen_history() {
    let dir = std::env::temp_dir().join(format!("pounding-export-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut a = app((80, 24));
    a.export_dir = dir.clone();
    settle(&mut a);
    assert_eq!(key(&mut a, KeyCode::Char('e')), None);
    let s = screen(&a);
    assert!(s.contains("pounding-set1-time.csv"), "{s}");
    assert!(s.contains("full history: 50266 rows"), "{s}");
    key(&mut a, KeyCode::Tab);
    a.on_key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL));
    let path = dir.join("screen.csv");
    typed(&mut a, path.to_str().unwrap());
    let e = key(&mut a, KeyCode::Enter);
    assert!(
        matches!(
            &e,
            Some(Effect::Export {
                history: History::Shown(_),
                ..
            })
        ),
        "{e:?}"
    );
    run(&mut a, e);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with("tau,x1_min,x1_max,"), "{text}");
    assert!(text.lines().count() > 50);
    // A run of 100 cycles is large: Enter once shows its size, twice writes.
    a.sets[0].params.cycles = 100;
    key(&mut a, KeyCode::Char('e'));
    assert_eq!(key(&mut a, KeyCode::Enter), None);
    assert!(screen(&a).contains("MB"), "{}", screen(&a));
    assert!(matches!(
        key(&mut a, KeyCode::Enter),
        Some(Effect::Export {
            history: History::Full,
            ..
        })
    ));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_wheel_nudges_only_over_the_panes() {
    let mut a = app((80, 24));
    let wheel = |column, row| MouseEvent {
        kind: MouseEventKind::ScrollUp,
        column,
        row,
        modifiers: KeyModifiers::NONE,
    };
    a.on_mouse(wheel(60, 10));
    assert_eq!(a.sets[0].params, a.sets[0].preset.params);
    a.on_mouse(wheel(12, 3)); // Π_m of set 1
    assert_eq!(a.sets[0].params.mass_ratio, 0.55);
}

#[test]
fn cursor_reads_out_and_zoom_shows_detail() {
    let mut a = app((80, 24));
    settle(&mut a);
    let impacts = a.shown(Slot::Set(0)).unwrap().result.impacts.clone();
    key(&mut a, KeyCode::Char('n'));
    key(&mut a, KeyCode::Char('n'));
    assert_eq!(a.view.cursor, Some(impacts[1].start));
    let s = screen(&a);
    assert!(s.contains("cursor τ"), "{s}");
    // Zoomed onto the impact, the buckets cover the window only.
    key(&mut a, KeyCode::Char('i'));
    key(&mut a, KeyCode::Char('z'));
    assert_eq!(a.view.scene, Scene::History);
    settle(&mut a);
    let run = a.shown(Slot::Set(0)).unwrap();
    let [t0, t1] = run.history.window;
    assert!(t0 < impacts[1].start && t1 > impacts[1].end && t1 - t0 < 1.0);
    let filled = run.history.filled().count();
    assert!(
        filled > 80 && (t1 - t0) / (filled as f64) < 0.01,
        "{filled}"
    );
    // The readout at the impact's start is the sample there, at its τ.
    let (tau, v) = run.history.at(impacts[1].start).unwrap();
    let bucket = (t1 - t0) / run.history.slices.len() as f64;
    assert!(
        tau >= impacts[1].start - 1e-3 && tau <= impacts[1].start + bucket,
        "{tau}"
    );
    assert!(v[0].is_finite());
    key(&mut a, KeyCode::Char('Z'));
    key(&mut a, KeyCode::Char('Z'));
    key(&mut a, KeyCode::Char('Z'));
    assert_eq!(a.view.zoom, None);
}

#[test]
fn physical_view_edits_metres_and_the_groups_follow() {
    let mut a = app((120, 40));
    let two = a
        .presets
        .iter()
        .position(|p| p.name == "two-buildings")
        .unwrap();
    a.recall(two);
    key(&mut a, KeyCode::Char('u'));
    assert!(a.physical_view());
    let gap = pounding::tui::physical::ROWS
        .iter()
        .position(|r| r.label == "d")
        .unwrap();
    a.selected = gap;
    let before = a.sets[0].params.gap;
    key(&mut a, KeyCode::Enter);
    typed(&mut a, "50");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.mode, Mode::Normal);
    assert!((a.sets[0].params.gap / before - 2.0).abs() < 1e-9);
    let s = screen(&a);
    assert!(s.contains("d mm"), "{s}");
    assert!(s.contains("[set 1]*"), "{s}");
    assert!(s.contains("two-buildings* (Π_d)"), "{s}");
    settle(&mut a);
    assert!(screen(&a).contains("t [s]"));
}

#[test]
fn the_laws_scene_computes_only_the_laws_it_shows() {
    let mut a = app((80, 24));
    typed(&mut a, "v");
    assert_eq!(a.needed().runs.len(), 2);
    // All six: the set's own run and five others, each law in its own model.
    key(&mut a, KeyCode::Char('b'));
    let runs = a.needed().runs;
    assert_eq!(runs.len(), 6);
    let mut models: Vec<_> = runs.iter().map(|r| r.params.model.name()).collect();
    models.sort();
    models.dedup();
    assert_eq!(models.len(), 6);
    // The set's law against one other.
    key(&mut a, KeyCode::Char('b'));
    let runs = a.needed().runs;
    assert_eq!(runs.len(), 2);
    assert!(runs.iter().any(|r| r.slot == Slot::Set(0)));
}

#[test]
fn the_map_scene_matches_the_library_map_cell_for_cell() {
    let mut a = app((80, 24));
    typed(&mut a, "a");
    settle(&mut a);
    let m = a.jobs.map.as_ref().expect("map state");
    assert_eq!(m.done(), m.cells.len());
    let plan = &m.spec.plan;
    let (cells, _) = pounding::analysis::map::compute(plan);
    assert_eq!(cells.len(), m.cells.len());
    for (got, want) in m.cells.iter().zip(&cells) {
        let got = got.as_ref().unwrap();
        assert_eq!(got.region, want.region);
        assert_eq!(
            got.left_amplification.to_bits(),
            want.left_amplification.to_bits()
        );
    }
    // The set's own point is on the map, and y cycles through the keys.
    let s = screen(&a);
    assert!(s.contains('◆'), "{s}");
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(a.map_spec().unwrap().plan.y.key, "gap");
    key(&mut a, KeyCode::Char(']'));
    assert!(a.view.map_cursor.is_some());
}

#[test]
fn the_map_rows_come_coarse_first_and_each_once() {
    let order = pounding::tui::worker::row_order(30);
    assert_eq!(&order[..4], &[0, 8, 16, 24]);
    let mut sorted = order.clone();
    sorted.sort();
    assert_eq!(sorted, (0..30).collect::<Vec<_>>());
}

/// The two-buildings set in the risk scene at design level `level` (g).
fn risk_app(size: (u16, u16), level_steps_down: usize) -> App {
    let mut a = app(size);
    recall(&mut a, "two-buildings");
    key(&mut a, KeyCode::Char('x'));
    for _ in 0..level_steps_down {
        key(&mut a, KeyCode::Char('['));
    }
    settle(&mut a);
    a
}

/// P(pounding) over `synthetic:20` at `level` of Sa(0.95 s) of the
/// buildings `physical`, computed here from the library's suite runs: the
/// fraction of records whose Π_d,min exceeds the gap, and that count.
fn direct_probability(
    physical: pounding::model::physical::Physical,
    settings: pounding::model::Params,
    level: f64,
) -> (f64, usize, Vec<f64>) {
    use pounding::model::intensity::IntensityMeasure;
    direct_probability_at(
        physical,
        settings,
        level,
        IntensityMeasure::Sa { period: 0.95 },
    )
}

/// [`direct_probability`] with the records scaled to `measure`.
fn direct_probability_at(
    physical: pounding::model::physical::Physical,
    settings: pounding::model::Params,
    level: f64,
    measure: pounding::model::intensity::IntensityMeasure,
) -> (f64, usize, Vec<f64>) {
    use pounding::analysis::separation::probability_of_pounding;
    use pounding::analysis::subject::runs::{plan, run_suite};
    use pounding::analysis::suite::{Scaling, SuiteCase};
    use pounding::model::suite::SuiteSpec;
    let members = SuiteSpec::parse("synthetic:20").unwrap().load().unwrap();
    let case = SuiteCase {
        physical,
        settings: pounding::model::Params {
            method: pounding::model::Method::Exact,
            ..settings
        },
        scaling: Scaling {
            measure,
            level: Some(level),
            collective: false,
        },
    };
    let plans = plan(&case, &members).unwrap();
    let runs = run_suite(&case, &members, &plans, &|_| ()).unwrap();
    let gaps: Vec<f64> = runs.iter().map(|r| r.min_gap_m()).collect();
    let p = probability_of_pounding(&gaps, physical.gap);
    let k = gaps.iter().filter(|&&d| d > physical.gap).count();
    (p, k, gaps)
}

/// The probability the risk scene prints at the set's gap is the
/// library's `probability_of_pounding` of the suite's Π_d,min computed
/// here, for the preset's own buildings (its `[physical]` table, Sa at
/// T1 = 0.95 s, 0.1 g) and after a nudge of the gap Π_d, which moves the
/// buildings' gap and nothing else.
#[test]
fn the_risk_scene_prints_the_librarys_probability_at_the_sets_gap() {
    use pounding::model::physical::Physical;
    let mut a = risk_app((80, 24), 4);
    assert_eq!(a.view.risk_level, 0.1);
    let preset = a.sets[0].preset.clone();
    let physical = Physical::from_table(preset.physical.as_ref().unwrap()).unwrap();
    let (p, k, gaps) = direct_probability(physical, preset.params.clone(), 0.1);
    assert!(0 < k && k < 20, "a mixed level: {k}");
    let s = screen(&a);
    let shown = format!("P(pounding) {p:.2} ({k}/20) at d 25 mm");
    assert!(s.contains(&shown), "{shown}\n{s}");
    assert!(
        s.contains("IM Sa(0.95 s)") && s.contains("design 0.1 g"),
        "{s}"
    );
    let picture = a.jobs.risk.as_ref().unwrap().picture.as_ref().unwrap();
    assert_eq!(picture.probability_at_gap(), p);
    for (shown, direct) in picture.min_gaps_m.iter().zip(&gaps) {
        assert!((shown - direct).abs() <= 1e-9 * direct, "{shown} {direct}");
    }
    // A wider gap Π_d: the buildings' gap follows at the preset's base
    // (a_p = 0.5 g, ω_p = 2π rad/s), and fewer records pound.
    for _ in 0..9 {
        key(&mut a, KeyCode::Char('j'));
    }
    assert_eq!(pounding::model::params::FIELDS[a.selected].key, "gap");
    key(&mut a, KeyCode::Char('L'));
    settle(&mut a);
    let gap_m = a.sets[0].params.gap * 0.5 * 9.80665 / (std::f64::consts::TAU).powi(2);
    let wider = Physical {
        gap: gap_m,
        ..physical
    };
    let (p2, k2, _) = direct_probability(wider, preset.params.clone(), 0.1);
    assert!(k2 < k, "{k2} {k}");
    let s = screen(&a);
    let shown = format!("P(pounding) {p2:.2} ({k2}/20)");
    assert!(s.contains(&shown), "{shown}\n{s}");
}

/// `o` in the risk scene scales the records to their PGA instead of
/// Sa(T1): the probability printed is then the library's at that PGA.
#[test]
fn o_scales_the_risk_scenes_records_to_their_pga() {
    use pounding::model::intensity::IntensityMeasure;
    use pounding::model::physical::Physical;
    let mut a = risk_app((80, 24), 4);
    key(&mut a, KeyCode::Char('o'));
    assert_eq!(a.risk_spec().measure, IntensityMeasure::Pga);
    settle(&mut a);
    let preset = a.sets[0].preset.clone();
    let physical = Physical::from_table(preset.physical.as_ref().unwrap()).unwrap();
    let (p, k, _) = direct_probability_at(physical, preset.params, 0.1, IntensityMeasure::Pga);
    let s = screen(&a);
    let shown = format!("P(pounding) {p:.2} ({k}/20) at d 25 mm");
    assert!(s.contains(&shown) && s.contains("IM PGA"), "{shown}\n{s}");
    assert!(s.contains("PGA [g]"), "{s}");
    // And back to Sa(T1).
    key(&mut a, KeyCode::Char('o'));
    assert_eq!(a.risk_spec().measure, IntensityMeasure::Sa { period: 0.95 });
}

/// The risk scene computes suites only when shown, and a change of the
/// design level starts a new picture that keeps the old one on screen
/// (stale) until its first pass arrives.
#[test]
fn only_the_risk_scene_runs_a_suite() {
    let mut a = app((80, 24));
    for scene in ["t", "f", "v", "c", "w", "i", "a"] {
        typed(&mut a, scene);
        assert!(a.needed().risk.is_none(), "{scene}");
    }
    typed(&mut a, "x");
    let spec = a.needed().risk.unwrap();
    assert!(spec.reference);
    assert_eq!(spec.levels.len(), 10);
    assert_eq!(spec.levels[4], spec.design_level);
    settle(&mut a);
    let st = a.jobs.risk.as_ref().unwrap();
    assert!(st.full && !st.stale && st.picture.as_ref().unwrap().records == 20);
    key(&mut a, KeyCode::Char(']'));
    let job = a.job().unwrap();
    assert_eq!(job.risk.unwrap().design_level, 0.35);
    let st = a.jobs.risk.as_ref().unwrap();
    assert!(st.stale && !st.full);
    assert!(screen(&a).contains("computing…"));
}

/// The worker sends the coarse picture first, then the whole suite; a
/// newer job cancels the full pass, and nothing of the old job's full pass
/// arrives. The pass times are printed for the record (`cargo test
/// --release --test tui_app risk -- --nocapture`).
#[test]
fn a_risk_picture_comes_coarse_first_and_a_newer_job_cancels_it() {
    use pounding::tui::risk_job::{RiskOutput, spec_of};
    use std::time::{Duration, Instant};
    let (tx, rx) = std::sync::mpsc::channel();
    let w = Worker::start(move |o| {
        let _ = tx.send((Instant::now(), o));
    });
    let risk = |g, level| Job {
        generation: g,
        risk: Some(spec_of(&pounding::model::SET1, None, level, false)),
        ..Job::default()
    };
    // Job 1 runs to the end (the suite is generated on its first use).
    let start = Instant::now();
    w.submit(risk(1, 0.3));
    let mut passes = Vec::new();
    loop {
        let (at, o) = rx.recv_timeout(Duration::from_secs(60)).unwrap();
        match o {
            Output::Risk {
                output: RiskOutput::Picture { picture, full },
                ..
            } => passes.push((
                at - start,
                picture.records,
                picture.drift.len(),
                full,
                picture.fragility,
            )),
            Output::Done { cancelled, .. } => {
                assert!(!cancelled);
                break;
            }
            other => panic!("{other:?}"),
        }
    }
    // Set 1's buildings pound at every level from 0.12 g and at none below:
    // the ten levels leave the fit without a β, and the full pass runs once
    // more with six levels inside that bracket, where it finds one.
    assert_eq!(passes.len(), 3, "{passes:?}");
    assert_eq!((passes[0].1, passes[0].2, passes[0].3), (6, 4, false));
    assert_eq!((passes[1].1, passes[1].2, passes[1].3), (20, 10, true));
    assert_eq!((passes[2].1, passes[2].2, passes[2].3), (20, 16, true));
    use pounding::analysis::fragility::Fragility;
    assert!(
        matches!(passes[1].4, Fragility::Separated { .. }),
        "{passes:?}"
    );
    match passes[2].4 {
        // Between the last level without pounding and the first with it everywhere.
        Fragility::Fitted { theta, beta, .. } => {
            assert!(theta > 0.06 && theta < 0.12 && beta > 0.0, "{passes:?}")
        }
        _ => panic!("no fit after the bridging levels: {passes:?}"),
    }
    // Job 2 at another level: its coarse pass, then job 3 at once.
    let start = Instant::now();
    w.submit(risk(2, 0.25));
    let (coarse_at, o) = rx.recv_timeout(Duration::from_secs(60)).unwrap();
    assert!(
        matches!(
            o,
            Output::Risk {
                generation: 2,
                output: RiskOutput::Picture { full: false, .. }
            }
        ),
        "{o:?}"
    );
    w.submit(Job {
        generation: 3,
        ..Job::default()
    });
    let mut ended = false;
    while let Ok((at, o)) = rx.recv_timeout(Duration::from_secs(60)) {
        match o {
            Output::Risk {
                generation: 2,
                output: RiskOutput::Picture { full: true, .. },
            } => {
                panic!("the cancelled job's full pass arrived")
            }
            Output::Done {
                generation: 2,
                cancelled,
            } => {
                assert!(cancelled);
                eprintln!(
                    "risk job 2: coarse pass {:.0} ms, cancelled {:.0} ms after job 3 came",
                    (coarse_at - start).as_secs_f64() * 1e3,
                    (at - coarse_at).as_secs_f64() * 1e3
                );
                ended = true;
            }
            Output::Done { generation: 3, .. } => break,
            _ => {}
        }
    }
    assert!(ended);
    eprintln!(
        "risk job 1 (suite generated first): coarse pass {:.0} ms, whole suite {:.0} ms",
        passes[0].0.as_secs_f64() * 1e3,
        passes[1].0.as_secs_f64() * 1e3
    );
}

/// At 80×24 the help is taller than the screen: ↑↓ and Space scroll it to
/// its last keys (the risk scene's among them), any other key closes it.
#[test]
fn the_help_scrolls_to_its_last_keys() {
    let mut a = app((80, 24));
    settle(&mut a);
    key(&mut a, KeyCode::Char('?'));
    let s = screen(&a);
    assert!(s.contains("keys 1–") && s.contains("this help"), "{s}");
    assert!(!s.contains("Ctrl-C"), "{s}");
    for _ in 0..3 {
        key(&mut a, KeyCode::Char(' '));
    }
    let s = screen(&a);
    assert!(s.contains("x  scene: risk over a suite"), "{s}");
    assert!(
        s.contains("Ctrl-C  quit at once") && s.contains("of 37 (↑↓ scroll)"),
        "{s}"
    );
    key(&mut a, KeyCode::Up);
    assert!(matches!(a.mode, Mode::Help { .. }));
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.mode, Mode::Normal);
    assert_eq!(
        a.view.scene,
        Scene::History,
        "a key that closes the help does nothing else"
    );
}
