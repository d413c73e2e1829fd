//! Keypress to redrawn time-history scene: a nudge of Π_ω1 (alternately up
//! and down, with the result cache emptied so every iteration is a new run), the job it triggers computed
//! as the worker would, and the frame rendered on a TestBackend. Terminal
//! I/O and the thread hand-off are not included (microseconds).
//!
//! The same for the spectrum scene (key to the complete spectrum, every
//! batch applied, then one frame) and for the map scene (key to its first
//! coarse picture: the job cancelled after its first rows, then one frame).
//!
//! `cargo bench --bench tui`

use criterion::{Criterion, criterion_group, criterion_main};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pounding::model::preset::builtin;
use pounding::tui::app::{App, Look};
use pounding::tui::ui;
use pounding::tui::worker::{Output, run_job};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use std::cell::{Cell, RefCell};

/// Set 1 against set 2 at `w`×`h`, scene `scene` shown and computed once,
/// Π_ω1 selected.
fn app_at(w: u16, h: u16, scene: char) -> App {
    let mut app = App::new(
        builtin("set1").unwrap(),
        builtin("set2").unwrap(),
        App::load_presets(None),
        None,
        Look {
            ascii: false,
            color: true,
        },
    );
    app.on_resize(w, h);
    app.on_key(KeyEvent::new(KeyCode::Char(scene), KeyModifiers::NONE));
    app.on_key(KeyEvent::new(KeyCode::Down, KeyModifiers::NONE)); // Π_ω1
    app.compute_blocking();
    app
}

fn key(up: &mut bool) -> KeyEvent {
    let code = if *up { KeyCode::Right } else { KeyCode::Left };
    *up = !*up;
    KeyEvent::new(code, KeyModifiers::NONE)
}

/// A nudge of Π_ω1 in the spectrum scene to the complete spectrum drawn.
fn spectrum_complete(c: &mut Criterion) {
    for (w, h) in [(80u16, 24u16), (120, 40)] {
        let mut app = app_at(w, h, 'w');
        let mut term = Terminal::new(TestBackend::new(w, h)).unwrap();
        let mut up = true;
        c.bench_function(&format!("keypress_to_spectrum_complete_{w}x{h}"), |b| {
            b.iter(|| {
                app.jobs.results.clear();
                app.on_key(key(&mut up));
                app.compute_blocking();
                let st = app.jobs.spectrum.as_ref().unwrap();
                assert_eq!(st.done(), st.points.len());
                term.draw(|f| ui::render(&app, f)).unwrap();
            })
        });
    }
}

/// A nudge of Π_ω1 in the map scene to its first coarse rows drawn.
fn map_first_picture(c: &mut Criterion) {
    for (w, h) in [(80u16, 24u16), (120, 40)] {
        let mut app = app_at(w, h, 'a');
        let mut term = Terminal::new(TestBackend::new(w, h)).unwrap();
        let mut up = true;
        c.bench_function(&format!("keypress_to_map_first_picture_{w}x{h}"), |b| {
            b.iter(|| {
                app.jobs.results.clear();
                app.on_key(key(&mut up));
                let job = app.job().unwrap();
                let outputs = RefCell::new(Vec::new());
                let rows_seen = Cell::new(false);
                let send = |o: Output| {
                    rows_seen.set(rows_seen.get() || matches!(o, Output::MapRows { .. }));
                    outputs.borrow_mut().push(o);
                };
                run_job(&job, &|| !rows_seen.get(), &send);
                assert!(rows_seen.get());
                for o in outputs.into_inner() {
                    app.on_output(o);
                }
                term.draw(|f| ui::render(&app, f)).unwrap();
            })
        });
    }
}

fn keypress_to_redraw(c: &mut Criterion) {
    for (w, h) in [(80u16, 24u16), (120, 40)] {
        let mut app = app_at(w, h, 't');
        let mut term = Terminal::new(TestBackend::new(w, h)).unwrap();
        let mut up = true;
        c.bench_function(&format!("keypress_to_redraw_history_{w}x{h}"), |b| {
            b.iter(|| {
                app.jobs.results.clear();
                app.on_key(key(&mut up));
                app.compute_blocking();
                term.draw(|f| ui::render(&app, f)).unwrap();
            })
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30);
    targets = keypress_to_redraw, spectrum_complete, map_first_picture
}
criterion_main!(benches);
