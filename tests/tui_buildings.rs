//! The buildings scene (SPEC §13) on a TestBackend: snapshots at 80×24 and
//! 120×40, the floors drawn where the run puts them (displacement times the
//! exaggeration, to the terminal cell), playback, an edit refused with the
//! CLI's line while the previous run stays, Kelvin beside improved Kelvin,
//! and row presets recalled from the picker.

use std::sync::Arc;
use std::time::{Duration, Instant};

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pounding::model::buildings::{Ground, load_with};
use pounding::model::preset::builtin;
use pounding::model::simulated::Simulation;
use pounding::tui::app::{App, Look, Mode};
use pounding::tui::row_pane::RowPane;
use pounding::tui::scene::Scene;
use pounding::tui::ui;
use pounding::tui::views::{row, row_drawing};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::layout::Rect;

/// The explorer opened as `pounding --buildings block-and-frame` does, on
/// a 2,000-sample simulated record.
fn app(size: (u16, u16)) -> App {
    let mut a = App::new(
        builtin("set1").unwrap(),
        builtin("set2").unwrap(),
        App::load_presets(None),
        None,
        Look {
            ascii: false,
            color: false,
        },
    );
    a.on_resize(size.0, size.1);
    let record = Simulation::synthetic("synthetic:2000", 2000).unwrap();
    let ground = Arc::new(Ground::from_record(&record, 1.0));
    a.row = Some(RowPane::open("block-and-frame", ground, "synthetic:2000", None).unwrap());
    a.view.scene = Scene::Buildings;
    a
}

fn settle(a: &mut App) {
    a.compute_blocking();
    for r in &mut a.jobs.rows {
        r.elapsed_ms = 0.0;
    }
}

fn draw(a: &App) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(a.size.0, a.size.1)).unwrap();
    t.draw(|f| ui::render(a, f)).unwrap();
    t
}

fn screen(a: &App) -> String {
    let t = draw(a);
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

fn typed(a: &mut App, text: &str) {
    for c in text.chars() {
        key(a, KeyCode::Char(c));
    }
}

/// The cursor at a time when the block's roof is against the frame.
fn at_an_impact(a: &mut App) -> f64 {
    let out = a.jobs.shown_row().unwrap();
    let i = out.runs[0].pairs[2].impacts[5];
    let t = 0.5 * (i.start + i.end);
    a.row.as_mut().unwrap().cursor = t;
    t
}

#[test]
fn the_scene_at_two_sizes() {
    for size in [(80, 24), (120, 40)] {
        let mut a = app(size);
        settle(&mut a);
        at_an_impact(&mut a);
        let s = screen(&a);
        assert!(s.contains("improved-kelvin: 46 impacts"), "{s}");
        assert!(s.contains("contact block 3|frame 3"), "{s}");
        insta::assert_snapshot!(format!("buildings_{}x{}", size.0, size.1), s);
        key(&mut a, KeyCode::Char('o'));
        key(&mut a, KeyCode::Char('o'));
        key(&mut a, KeyCode::Char('o'));
        let s = screen(&a);
        assert!(s.contains("46 impacts  floors"), "{s}");
        insta::assert_snapshot!(format!("buildings_impacts_{}x{}", size.0, size.1), s);
    }
}

#[test]
fn floors_are_drawn_where_the_run_puts_them_to_the_cell() {
    let mut a = app((120, 40));
    settle(&mut a);
    let t = at_an_impact(&mut a);
    let out = a.jobs.shown_row().unwrap().clone();
    let pane = a.row.as_ref().unwrap();
    let run = &out.runs[0];
    let trace = run.trace.as_ref().unwrap();
    let x = row::exaggeration(pane, &out);
    let g = row_drawing::geometry(&out.spec.row, run, trace, t, x);
    let u = trace.at(t);
    let offsets = out.spec.row.offsets();
    let terminal = draw(&a);
    let buf = terminal.backend().buffer();
    // The scene's drawing area, as the view splits it.
    let scene = pounding::tui::layout::scene(a.size);
    let body = Rect {
        y: scene.y + 1,
        height: scene.height - 1,
        ..scene
    };
    let (drawings, _) = row::split(body, false, 1);
    let plot = row_drawing::plot_area(drawings[0]);
    let raster = row_drawing::raster(&g, plot, true);
    let mut checked = 0;
    for (b, building) in out.spec.row.buildings.iter().enumerate() {
        for floor in 1..=building.storeys() {
            let (left, elevation) = g.floor(b, floor);
            // Displacement times the exaggeration, from the left edge at rest.
            let expected = u[offsets[b] + floor - 1] * x;
            assert!(
                (left - g.frames[b].rest_left - expected).abs() <= 1e-12 * x,
                "{} floor {floor}",
                building.name
            );
            assert_eq!(elevation, building.elevation(floor));
            // The floor's left end is a drawn cell of the screen.
            let (c, r) = (raster.col(left), raster.row(elevation));
            let cell = buf[(plot.x + c as u16, plot.y + r as u16)].symbol();
            let dots = cell.chars().next().unwrap() as u32;
            // A Braille cell, or the contact mark drawn without colour.
            assert!(
                (0x2801..=0x28ff).contains(&dots) || cell == "X",
                "{} floor {floor}: `{cell}` at column {c}, row {r}",
                building.name
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 11);
    // The block's roof and the frame's third floor touch: drawn in contact.
    assert!(g.frames[0].contact[3] && g.frames[1].contact[3]);
    let gap = out.spec.row.joints[0].gap * x;
    let block_right = g.floor(0, 3).0 + g.width;
    assert!(block_right >= g.floor(1, 3).0 - 1e-12 && gap > 0.0);
}

#[test]
fn playback_moves_the_cursor_with_the_clock() {
    let mut a = app((80, 24));
    settle(&mut a);
    key(&mut a, KeyCode::Char(' '));
    let due = a.frame_due().expect("playing");
    let t0 = a.row.as_ref().unwrap().cursor;
    assert!(a.on_tick(due + Duration::from_millis(960)));
    let moved = a.row.as_ref().unwrap().cursor - t0;
    let speed = a.row.as_ref().unwrap().play.speed();
    assert!((moved - speed).abs() < 0.1 * speed, "{moved}");
    assert!(screen(&a).contains("▶"));
    key(&mut a, KeyCode::Char(' '));
    assert_eq!(a.frame_due(), None);
    assert!(!a.on_tick(Instant::now() + Duration::from_secs(1)));
}

#[test]
fn a_refused_edit_keeps_the_run_on_screen() {
    let mut a = app((80, 24));
    settle(&mut a);
    let before = screen(&a);
    // The block's storeys: the third row.
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Backspace);
    typed(&mut a, "0");
    key(&mut a, KeyCode::Enter);
    let cli = load_with("block-and-frame", &["block.storeys=0".into()])
        .unwrap_err()
        .to_string();
    match &a.mode {
        Mode::Editing(field) => assert_eq!(field.error.as_deref(), Some(cli.as_str())),
        m => panic!("{m:?}"),
    }
    key(&mut a, KeyCode::Esc);
    settle(&mut a);
    // The scene beside the panes is as it was.
    let scene =
        |s: &str| -> Vec<String> { s.lines().map(|l| l.chars().skip(31).collect()).collect() };
    assert_eq!(scene(&screen(&a)), scene(&before));
    // A storey more: the row reruns with four.
    key(&mut a, KeyCode::Right);
    settle(&mut a);
    let s = screen(&a);
    assert!(s.contains("block storeys     4"), "{s}");
    assert_eq!(
        a.jobs.shown_row().unwrap().spec.row.buildings[0].storeys(),
        4
    );
}

#[test]
fn kelvin_beside_improved_kelvin_and_presets_recalled() {
    let mut a = app((120, 40));
    settle(&mut a);
    key(&mut a, KeyCode::Char('|'));
    settle(&mut a);
    let s = screen(&a);
    assert!(s.contains("improved-kelvin: 46 impacts"), "{s}");
    let out = a.jobs.shown_row().unwrap();
    assert_eq!(out.runs.len(), 2);
    let kelvin = out.runs[1].impacts();
    assert!(s.contains(&format!("kelvin: {kelvin} impacts")), "{s}");
    // The picker lists the rows; the third is three-in-series.
    key(&mut a, KeyCode::Char('p'));
    assert!(screen(&a).contains("three-in-series"));
    key(&mut a, KeyCode::Char('3'));
    settle(&mut a);
    assert_eq!(a.row.as_ref().unwrap().source, "three-in-series");
    assert_eq!(a.jobs.shown_row().unwrap().spec.row.buildings.len(), 3);
    assert!(screen(&a).contains("row three-in-series"));
}

#[test]
fn a_terminal_too_small_for_the_drawing_says_how_large() {
    let mut a = app((60, 20));
    key(&mut a, KeyCode::Char('|'));
    settle(&mut a);
    let s = screen(&a);
    assert!(s.contains("the row needs a terminal of"), "{s}");
    assert!(s.contains("at least 75x20"), "{s}");
}

/// The risk scene studies a joint of the row: `y` turns from the pair to
/// the row's joint, and the picture follows the joint's taller building.
#[test]
fn the_risk_scene_studies_the_rows_joint() {
    let mut a = app((100, 30));
    let ground = a.row.as_ref().unwrap().ground.clone();
    a.row = Some(RowPane::open("two-buildings", ground, "synthetic:2000", None).unwrap());
    key(&mut a, KeyCode::Char('x'));
    assert!(a.risk_spec().row.is_none());
    key(&mut a, KeyCode::Char('y'));
    let spec = a.risk_spec();
    let case = spec.row.as_ref().expect("the row's joint");
    assert_eq!((case.joint, case.building), (0, 0));
    a.compute_blocking();
    let state = a.jobs.risk.as_ref().unwrap();
    assert!(state.full && state.error.is_none(), "{:?}", state.error);
    let p = state.picture.as_ref().unwrap();
    assert_eq!(p.records, 20);
    assert_eq!(p.gap_m, a.row.as_ref().unwrap().row.joints[0].gap);
    let s = screen(&a);
    assert!(s.contains("joint 1 frame|block (y)"), "{s}");
    assert!(s.contains("frame drift [mm]"), "{s}");
    // Back to the pair.
    key(&mut a, KeyCode::Char('y'));
    assert!(a.risk_spec().row.is_none());
}

/// A row with P-Δ that collapses (SPEC §15): the summary says which
/// building, which storey and when, as `run --buildings` reports it.
#[test]
fn a_collapse_is_named_in_the_summary() {
    let mut a = app((160, 40));
    let record = Simulation::synthetic("synthetic:2000", 2000).unwrap();
    let ground = Arc::new(Ground::from_record(&record, 6.0));
    a.row = Some(RowPane::open("block-and-frame-pdelta", ground, "synthetic:2000", None).unwrap());
    settle(&mut a);
    let lines = row::summary(&a, 400);
    assert!(
        lines[0].contains("frame collapses (storey 4, 2.33 s)"),
        "{lines:?}"
    );
}

/// `e` and `g` in the buildings scene write the row's CSV and its figure
/// (they pointed to the CLI before), the same bytes `pounding run
/// --buildings --format csv` and `pounding figure buildings` write for
/// this row and ground, each atomically: the file appears whole under its
/// name (a file there before is replaced by a rename, not written into)
/// and nothing else is left in the folder.
#[test]
fn e_and_g_write_the_rows_csv_and_figure() {
    use pounding::tui::effects::{self, Done};
    use std::os::unix::fs::MetadataExt;
    let dir = tempfile::tempdir().unwrap();
    let write = |a: &mut App, k: char, name: &str| -> (std::path::PathBuf, String) {
        a.on_key(KeyEvent::new(KeyCode::Char(k), KeyModifiers::NONE));
        assert!(matches!(a.mode, Mode::RowFile { .. }), "{:?}", a.mode);
        let shown = screen(a);
        a.on_key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL));
        let path = dir.path().join(name);
        typed(a, path.to_str().unwrap());
        let effect = a
            .on_key(KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE))
            .expect("Enter writes");
        let status: Vec<String> = effects::run(effect, None)
            .into_iter()
            .map(|d| match d {
                Done::Status(s) => s,
                other => panic!("{other:?}"),
            })
            .collect();
        assert_eq!(status.len(), 1);
        assert!(status[0].contains("written to"), "{}", status[0]);
        (path, shown)
    };
    let mut a = app((120, 40));
    settle(&mut a);
    // A file already at the CSV's path is replaced whole.
    std::fs::write(dir.path().join("row.csv"), "old\n").unwrap();
    let before = std::fs::metadata(dir.path().join("row.csv")).unwrap().ino();
    let (csv, prompt) = write(&mut a, 'e', "row.csv");
    assert!(prompt.contains("write the row's peaks as CSV"), "{prompt}");
    assert!(
        prompt.contains("pounding-block-and-frame-buildings.csv"),
        "{prompt}"
    );
    assert_ne!(std::fs::metadata(&csv).unwrap().ino(), before);
    let (svg, prompt) = write(&mut a, 'g', "row.svg");
    assert!(prompt.contains("write the row's figure as SVG"), "{prompt}");
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["row.csv", "row.svg"]);
    // The CLI's own output for this row and ground.
    let cli = std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args([
            "run",
            "--buildings",
            "block-and-frame",
            "--excitation",
            "synthetic:2000",
            "--format",
            "csv",
        ])
        .output()
        .unwrap();
    assert!(cli.status.success());
    let written = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(written, String::from_utf8(cli.stdout).unwrap());
    assert_eq!(written.lines().count(), 1 + 3 + 8, "{written}");
    let figure = dir.path().join("cli.svg");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args([
            "figure",
            "buildings",
            "--buildings",
            "block-and-frame",
            "--excitation",
            "synthetic:2000",
            "--out",
            figure.to_str().unwrap(),
        ])
        .status()
        .unwrap();
    assert!(status.success());
    assert_eq!(
        std::fs::read(&svg).unwrap(),
        std::fs::read(&figure).unwrap()
    );
}

/// Where a column is too narrow for a law's name it shows the short form,
/// and the row's label names the law in words: the first screen says
/// "improved Kelvin" at 120×40 (it read `IK  IK`), and the row pane too.
#[test]
fn the_label_names_the_law_a_narrow_column_shortens() {
    let mut a = app((120, 40));
    a.view.scene = Scene::History;
    let s = screen(&a);
    let line = s.lines().find(|l| l.contains("IK")).expect("the model row");
    assert!(line.contains("contact: improved Kelvin"), "{line}");
    a.view.scene = Scene::Buildings;
    settle(&mut a);
    let s = screen(&a);
    let line = s.lines().find(|l| l.contains("IK")).expect("the law row");
    assert!(line.contains("improved Kelvin"), "{line}");
}

/// `b` on a retrofitted row: the bare row is run only then, its envelope
/// drawn in grey where the row without pounding was, and its impacts in
/// the summary; a row without retrofits says so.
#[test]
fn b_sets_the_retrofit_against_the_bare_row() {
    let mut a = app((80, 24));
    let ground = a.row.as_ref().unwrap().ground.clone();
    a.row =
        Some(RowPane::open("block-and-frame-retrofit", ground, "synthetic:2000", None).unwrap());
    settle(&mut a);
    assert!(a.jobs.shown_row().unwrap().bare.is_none(), "not asked for");
    assert!(screen(&a).contains("grey: no pounding"));
    key(&mut a, KeyCode::Char('b'));
    settle(&mut a);
    let out = a.jobs.shown_row().unwrap();
    let bare = out.bare.as_ref().expect("run once b asks for it");
    // The bare row is block-and-frame: its 46 impacts under this record.
    assert_eq!(bare.impacts(), 46);
    assert_eq!(out.runs[0].impacts(), 14);
    let s = screen(&a);
    assert!(s.contains("grey: no retrofit"), "{s}");
    assert!(s.contains("no retrofit: 46 impacts"), "{s}");
    insta::assert_snapshot!("buildings_bare_80x24", s);
    key(&mut a, KeyCode::Char('b'));
    settle(&mut a);
    assert!(a.jobs.shown_row().unwrap().bare.is_none());
    // The pane lists the retrofit's keys, each a --set key.
    let keys: Vec<String> = a
        .row
        .as_ref()
        .unwrap()
        .fields()
        .iter()
        .map(|f| f.key.clone())
        .collect();
    for k in ["joint1.bumper.thickness", "link1.damping"] {
        assert!(keys.iter().any(|x| x == k), "{k}");
    }
    let mut plain = app((80, 24));
    settle(&mut plain);
    key(&mut plain, KeyCode::Char('b'));
    assert!(
        plain
            .status
            .as_deref()
            .is_some_and(|s| s.contains("no bumper or link")),
        "{:?}",
        plain.status
    );
}
