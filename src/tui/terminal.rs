//! The terminal: checks that there is one, enters raw mode and the alternate
//! screen, and restores it on quit, on panic (a hook) and on SIGTERM (via the
//! event loop). Every frame is wrapped in a synchronized update so a slow
//! link never shows a half-drawn screen.

use std::io::{self, IsTerminal, Stdout, Write};

use crossterm::event::{DisableMouseCapture, EnableMouseCapture};
use crossterm::terminal::{
    BeginSynchronizedUpdate, EndSynchronizedUpdate, EnterAlternateScreen, LeaveAlternateScreen,
    disable_raw_mode, enable_raw_mode,
};
use crossterm::{cursor, execute, queue};
use ratatui::backend::CrosstermBackend;
use ratatui::{Frame, Terminal};

pub type Tty = Terminal<CrosstermBackend<Stdout>>;

/// Why the explorer cannot start here, if it cannot.
pub fn unusable() -> Option<String> {
    let dumb = std::env::var("TERM").is_ok_and(|t| t == "dumb");
    if !io::stdout().is_terminal() || !io::stdin().is_terminal() || dumb {
        Some(
            "the explorer needs an interactive terminal (stdout is not one, or TERM=dumb); \
             use `pounding run --preset set1` (or --format json|csv) instead"
                .into(),
        )
    } else {
        None
    }
}

/// Whether the locale promises UTF-8 (the first of LC_ALL, LC_CTYPE, LANG that is set).
pub fn utf8_locale() -> bool {
    ["LC_ALL", "LC_CTYPE", "LANG"]
        .iter()
        .find_map(|k| std::env::var(k).ok().filter(|v| !v.is_empty()))
        .is_some_and(|v| {
            let v = v.to_ascii_lowercase();
            v.contains("utf-8") || v.contains("utf8")
        })
}

/// Whether colours are wanted (<https://no-color.org>: NO_COLOR set and non-empty disables them).
pub fn color_allowed() -> bool {
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// Raw mode, alternate screen, mouse; a panic hook that restores first.
pub fn setup() -> io::Result<Tty> {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let _ = restore();
        previous(info);
    }));
    enable_raw_mode()?;
    let mut out = io::stdout();
    execute!(out, EnterAlternateScreen, EnableMouseCapture, cursor::Hide)?;
    Terminal::new(CrosstermBackend::new(out))
}

/// Leaves raw mode and the alternate screen, shows the cursor.
pub fn restore() -> io::Result<()> {
    let mut out = io::stdout();
    let r = execute!(out, DisableMouseCapture, LeaveAlternateScreen, cursor::Show);
    disable_raw_mode()?;
    r
}

/// Draws one frame inside a synchronized update.
pub fn draw(tty: &mut Tty, render: impl FnOnce(&mut Frame)) -> io::Result<()> {
    queue!(tty.backend_mut(), BeginSynchronizedUpdate)?;
    tty.draw(render)?;
    execute!(tty.backend_mut(), EndSynchronizedUpdate)?;
    tty.backend_mut().flush()
}
