//! The main loop: wait for an event, let the app take it, run the effect it
//! returns, start the job the visible scene now needs, redraw once for a
//! burst of events, when [`Pace`] says so (a quick job's result in the same
//! frame as the key that asked for it). All I/O of the explorer happens
//! here or on threads started here.

use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Instant;

use super::app::{App, Exit};
use super::effects::{self, Effect};
use super::event::{self, AppEvent};
use super::pace::{Pace, Step};
use super::worker::Worker;
use super::{terminal, ui};

/// Runs the explorer until the user quits or a signal arrives; the terminal
/// is restored whatever happens. Temporary files left in the preset and
/// export folders by an earlier process that was killed are removed first.
pub fn run(mut app: App) -> std::io::Result<Exit> {
    for dir in app.user_dir.iter().chain(std::iter::once(&app.export_dir)) {
        crate::output::temp::remove_stale(dir);
    }
    let (tx, rx) = mpsc::channel();
    let worker_tx = tx.clone();
    let worker = Worker::start(move |out| {
        let _ = worker_tx.send(AppEvent::Worker(out));
    });
    event::spawn_signals(tx.clone())?;
    let mut tty = terminal::setup()?;
    let outcome = (|| -> std::io::Result<Exit> {
        let size = tty.size()?;
        app.on_resize(size.width, size.height);
        event::spawn_input(tx.clone());
        let mut pace = Pace::default();
        loop {
            let was_computing = app.jobs.computing;
            if let Some(job) = app.job() {
                worker.submit(job);
                if !was_computing {
                    pace.started(Instant::now());
                }
            }
            // Playback wakes the loop for its next frame, whatever else waits.
            if app.frame_due().is_some_and(|f| f <= Instant::now()) && app.on_tick(Instant::now()) {
                pace.input();
            }
            let frame = app.frame_due();
            let wait =
                |until: Instant| rx.recv_timeout(until.saturating_duration_since(Instant::now()));
            let first = match (pace.next(Instant::now(), app.jobs.computing), frame) {
                (Step::Draw, _) => {
                    terminal::draw(&mut tty, |f| ui::render(&app, f))?;
                    continue;
                }
                (Step::Sleep, None) => rx.recv().map_err(|_| RecvTimeoutError::Disconnected),
                (Step::Sleep, Some(f)) => wait(f),
                (Step::WaitUntil(t), f) => wait(f.map_or(t, |f| f.min(t))),
            };
            let first = match first {
                Ok(ev) => ev,
                Err(RecvTimeoutError::Timeout) => continue,
                Err(RecvTimeoutError::Disconnected) => return Ok(Exit::Quit),
            };
            // Take the whole burst before drawing again.
            for ev in std::iter::once(first).chain(rx.try_iter()) {
                if matches!(ev, AppEvent::Worker(_)) {
                    pace.progress();
                } else {
                    pace.input();
                }
                let effect = match ev {
                    AppEvent::Key(k) => app.on_key(k),
                    AppEvent::Mouse(m) => {
                        app.on_mouse(m);
                        None
                    }
                    AppEvent::Resize(w, h) => {
                        app.on_resize(w, h);
                        tty.autoresize()?;
                        None
                    }
                    AppEvent::Worker(out) => {
                        app.on_output(out);
                        None
                    }
                    AppEvent::Done(done) => {
                        app.on_done(done);
                        None
                    }
                    AppEvent::Terminate(signal) => return Ok(Exit::Signal(signal)),
                };
                match effect {
                    None => {}
                    Some(Effect::Quit) => return Ok(Exit::Quit),
                    Some(Effect::Mouse(on)) => terminal::set_mouse(on)?,
                    Some(e) => {
                        let tx = tx.clone();
                        let dir = app.user_dir.clone();
                        std::thread::spawn(move || {
                            for done in effects::run(e, dir.as_deref()) {
                                let _ = tx.send(AppEvent::Done(done));
                            }
                        });
                    }
                }
            }
        }
    })();
    drop(worker);
    let restored = terminal::restore();
    crate::output::temp::remove_live();
    let exit = outcome?;
    restored.map(|()| exit)
}
