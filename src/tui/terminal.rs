//! The terminal: checks that there is one, sets it up with ratatui's own
//! `init` (raw mode, alternate screen, a panic hook that restores first),
//! captures mouse buttons only (no motion reports, so moving the mouse costs
//! nothing), and restores it all on the way out. Every frame is wrapped in a
//! synchronized update so a slow link never shows a half-drawn screen, and
//! drawn through [`GapFill`] and [`ShortCodes`] so that it costs fewer bytes.

use std::io::{self, IsTerminal, Write};

use crossterm::terminal::{BeginSynchronizedUpdate, EndSynchronizedUpdate};
use crossterm::{execute, queue};
use ratatui::backend::{Backend, ClearType, CrosstermBackend};
use ratatui::{Frame, Terminal};

use super::gapfill::GapFill;
use super::short_codes::ShortCodes;

pub type Tty = Terminal<GapFill<CrosstermBackend<ShortCodes<io::Stdout>>>>;

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

/// Raw mode and the alternate screen (ratatui's `init`), mouse buttons on.
pub fn setup() -> io::Result<Tty> {
    // ratatui's set-up (raw mode, alternate screen, panic hook); its own
    // terminal is replaced by one drawing through the gap filler.
    drop(ratatui::try_init()?);
    let mut tty = Terminal::new(GapFill::new(CrosstermBackend::new(ShortCodes::new(
        io::stdout(),
    ))))?;
    // A clear screen is one the gap filler knows: blanks it may resend.
    // (The backend's own clear: the terminal's would ask for the cursor.)
    tty.backend_mut().clear_region(ClearType::All)?;
    set_mouse(true)?;
    Ok(tty)
}

/// Mouse reporting of button presses and the wheel only (xterm mode 1000,
/// SGR coordinates 1006): no motion events. Off leaves the mouse to the
/// terminal, so text can be selected.
pub fn set_mouse(on: bool) -> io::Result<()> {
    let mut out = io::stdout();
    let text: &[u8] = if on {
        b"\x1b[?1000h\x1b[?1006h"
    } else {
        b"\x1b[?1006l\x1b[?1000l"
    };
    out.write_all(text)?;
    out.flush()
}

/// Mouse off, then ratatui's `restore` (raw mode off, main screen, cursor shown).
pub fn restore() -> io::Result<()> {
    let mouse = set_mouse(false);
    ratatui::try_restore()?;
    mouse
}

/// Draws one frame inside a synchronized update.
pub fn draw(tty: &mut Tty, render: impl FnOnce(&mut Frame)) -> io::Result<()> {
    queue!(tty.backend_mut().inner_mut(), BeginSynchronizedUpdate)?;
    tty.draw(render)?;
    execute!(tty.backend_mut().inner_mut(), EndSynchronizedUpdate)?;
    Write::flush(tty.backend_mut().inner_mut())
}
