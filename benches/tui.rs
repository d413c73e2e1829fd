//! Keypress to redrawn time-history scene: a nudge of Π_ω1 (alternately up
//! and down, with the result cache emptied so every iteration is a new run), the job it triggers computed
//! as the worker would, and the frame rendered on a TestBackend. Terminal
//! I/O and the thread hand-off are not included (microseconds).
//!
//! `cargo bench --bench tui`

use criterion::{Criterion, criterion_group, criterion_main};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pounding::model::preset::builtin;
use pounding::tui::app::{App, Look};
use pounding::tui::ui;
use ratatui::Terminal;
use ratatui::backend::TestBackend;

fn keypress_to_redraw(c: &mut Criterion) {
    for (w, h) in [(80u16, 24u16), (120, 40)] {
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
        app.on_key(KeyEvent::new(KeyCode::Down, KeyModifiers::NONE)); // Π_ω1
        app.compute_blocking();
        let mut term = Terminal::new(TestBackend::new(w, h)).unwrap();
        let mut up = true;
        c.bench_function(&format!("keypress_to_redraw_history_{w}x{h}"), |b| {
            b.iter(|| {
                let code = if up { KeyCode::Right } else { KeyCode::Left };
                up = !up;
                app.jobs.results.clear();
                app.on_key(KeyEvent::new(code, KeyModifiers::NONE));
                app.compute_blocking();
                term.draw(|f| ui::render(&app, f)).unwrap();
            })
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30);
    targets = keypress_to_redraw
}
criterion_main!(benches);
