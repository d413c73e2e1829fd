//! Everything the main loop reacts to arrives on one channel: terminal input
//! (a thread blocked in `crossterm::event::read`), worker results, what came
//! of file effects, and termination signals. The loop blocks on the channel,
//! so an idle explorer uses no CPU and redraws nothing.

use std::sync::mpsc::Sender;

use crossterm::event::{Event, KeyEvent, MouseEvent};

use super::effects::Done;
use super::worker::Output;

/// An input of the main loop.
#[derive(Debug)]
pub enum AppEvent {
    Key(KeyEvent),
    Mouse(MouseEvent),
    Resize(u16, u16),
    /// A result of the solver thread.
    Worker(Output),
    /// What came of a file effect.
    Done(Done),
    /// SIGTERM, SIGHUP or SIGINT (its number): restore the terminal and leave.
    Terminate(i32),
}

/// Turns a crossterm event into the app's own, if it matters.
pub fn translate(e: Event) -> Option<AppEvent> {
    match e {
        Event::Key(k) => Some(AppEvent::Key(k)),
        Event::Mouse(m) => Some(AppEvent::Mouse(m)),
        Event::Resize(w, h) => Some(AppEvent::Resize(w, h)),
        _ => None,
    }
}

/// Reads terminal input on its own thread until the channel closes.
pub fn spawn_input(tx: Sender<AppEvent>) {
    let _ = std::thread::Builder::new()
        .name("pounding-input".into())
        .spawn(move || {
            while let Ok(e) = crossterm::event::read() {
                if let Some(ev) = translate(e)
                    && tx.send(ev).is_err()
                {
                    return;
                }
            }
        });
}

/// Forwards SIGTERM, SIGHUP and SIGINT as [`AppEvent::Terminate`].
pub fn spawn_signals(tx: Sender<AppEvent>) -> std::io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGTERM, SIGHUP, SIGINT])?;
    std::thread::Builder::new()
        .name("pounding-signals".into())
        .spawn(move || {
            for signal in signals.forever() {
                if tx.send(AppEvent::Terminate(signal)).is_err() {
                    return;
                }
            }
        })?;
    Ok(())
}
