//! The buildings scene (SPEC §13): block-and-frame (3 + 8 storeys) under a
//! simulated 2,000-sample record, on a TestBackend at 80×24 and 200×60.
//!
//! - `row_preset_to_frame`: choosing the row preset from the picker (its
//!   digit) to the first complete frame: the row's runs with pounding (with
//!   its trace) and without, computed as the worker would, then one frame;
//! - `row_nudge_to_frame`: a nudge of the block's storey stiffness, up and
//!   down in turn, to the redrawn frame;
//! - `row_playback_frame`: one frame of playback (the cursor moved on and
//!   the scene drawn again), which bounds the frame rate.
//!
//! Terminal I/O is not included. `cargo bench --bench row_scene`

use std::sync::Arc;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pounding::model::buildings::Ground;
use pounding::model::preset::builtin;
use pounding::model::simulated::Simulation;
use pounding::tui::app::{App, Look};
use pounding::tui::row_pane::RowPane;
use pounding::tui::scene::Scene;
use pounding::tui::ui;
use ratatui::Terminal;
use ratatui::backend::TestBackend;

fn app_at(w: u16, h: u16) -> App {
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
    let record = Simulation::synthetic("synthetic:2000", 2000).unwrap();
    let ground = Arc::new(Ground::from_record(&record, 1.0));
    app.row = Some(RowPane::open("block-and-frame", ground, "synthetic:2000", None).unwrap());
    app.view.scene = Scene::Buildings;
    app.compute_blocking();
    app
}

fn press(app: &mut App, code: KeyCode) {
    app.on_key(KeyEvent::new(code, KeyModifiers::NONE));
}

fn scene(c: &mut Criterion) {
    for (w, h) in [(80u16, 24u16), (200, 60)] {
        let mut app = app_at(w, h);
        let mut term = Terminal::new(TestBackend::new(w, h)).unwrap();
        c.bench_function(&format!("row_preset_to_frame_{w}x{h}"), |b| {
            b.iter_custom(|iters| {
                let mut total = Duration::ZERO;
                for _ in 0..iters {
                    // Away to two-buildings (not timed), then back.
                    press(&mut app, KeyCode::Char('1'));
                    app.compute_blocking();
                    app.jobs.rows.clear();
                    let start = Instant::now();
                    press(&mut app, KeyCode::Char('2')); // block-and-frame
                    app.compute_blocking();
                    term.draw(|f| ui::render(&app, f)).unwrap();
                    total += start.elapsed();
                }
                total
            })
        });
        // The block's storey stiffness: the fifth row.
        app.row.as_mut().unwrap().selected = 4;
        let mut up = true;
        c.bench_function(&format!("row_nudge_to_frame_{w}x{h}"), |b| {
            b.iter(|| {
                press(&mut app, if up { KeyCode::Right } else { KeyCode::Left });
                up = !up;
                app.jobs.rows.clear();
                app.compute_blocking();
                term.draw(|f| ui::render(&app, f)).unwrap();
            })
        });
        press(&mut app, KeyCode::Char(' '));
        let mut now = Instant::now();
        c.bench_function(&format!("row_playback_frame_{w}x{h}"), |b| {
            b.iter(|| {
                now += Duration::from_millis(40);
                if !app.on_tick(now) {
                    // Played to the end: from the start again.
                    app.row.as_mut().unwrap().cursor = 0.0;
                    press(&mut app, KeyCode::Char(' '));
                }
                term.draw(|f| ui::render(&app, f)).unwrap();
            })
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = scene
}
criterion_main!(benches);
