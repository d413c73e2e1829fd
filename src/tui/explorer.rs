//! The main loop: wait for an event, let the app take it, start the job the
//! visible scene now needs, redraw once for a burst of events.

use std::sync::mpsc;

use super::app::{App, Effect};
use super::event::{self, AppEvent};
use super::worker::Worker;
use super::{export, terminal, ui};

/// Runs the explorer until the user quits or a signal arrives; the terminal
/// is restored whatever happens.
pub fn run(mut app: App) -> std::io::Result<()> {
    let (tx, rx) = mpsc::channel();
    let worker_tx = tx.clone();
    let worker = Worker::start(move |out| {
        let _ = worker_tx.send(AppEvent::Worker(out));
    });
    event::spawn_signals(tx.clone())?;
    let mut tty = terminal::setup()?;
    let outcome = (|| -> std::io::Result<()> {
        let size = tty.size()?;
        app.on_resize(size.width, size.height);
        event::spawn_input(tx.clone());
        loop {
            if let Some(job) = app.job() {
                worker.submit(job);
            }
            terminal::draw(&mut tty, |f| ui::render(&app, f))?;
            let Ok(first) = rx.recv() else { return Ok(()) };
            // Take the whole burst before drawing again.
            for ev in std::iter::once(first).chain(rx.try_iter()) {
                match ev {
                    AppEvent::Key(k) => match app.on_key(k) {
                        Some(Effect::Quit) => return Ok(()),
                        Some(Effect::Export { params, path }) => {
                            let tx = tx.clone();
                            std::thread::spawn(move || {
                                let _ = tx.send(AppEvent::Status(export::write(&params, &path)));
                            });
                        }
                        None => {}
                    },
                    AppEvent::Mouse(m) => app.on_mouse(m),
                    AppEvent::Resize(w, h) => {
                        app.on_resize(w, h);
                        tty.autoresize()?;
                    }
                    AppEvent::Worker(out) => app.on_output(out),
                    AppEvent::Status(s) => app.status = Some(s),
                    AppEvent::Terminate => return Ok(()),
                }
            }
        }
    })();
    drop(worker);
    let restored = terminal::restore();
    outcome.and(restored)
}
