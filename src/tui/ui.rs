//! Drawing: a pure function from the explorer's state to a frame. Nothing
//! here changes the state; the geometry comes from [`super::layout`].

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use super::app::{App, Mode};
use super::layout::{self, MIN_SIZE};
use super::look::asciify;
use super::scene::Scene;
use super::views;

/// Draws the whole explorer.
pub fn render(app: &App, frame: &mut Frame) {
    let area = frame.area();
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        let text = format!(
            "terminal too small: {}x{}, need {}x{} (q quits)",
            area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
        );
        frame.render_widget(
            Paragraph::new(text).wrap(ratatui::widgets::Wrap { trim: true }),
            area,
        );
    } else {
        let a = layout::areas(area, app.pane_rows());
        header(app, frame, a.header);
        match app
            .row
            .as_ref()
            .filter(|_| app.view.scene == Scene::Buildings)
        {
            Some(pane) => {
                views::row_params::render(app, pane, frame, a.panes);
                views::row_params::render_info(app, pane, frame, a.info);
            }
            None => {
                views::params::render(app, frame, a.panes);
                views::params::render_info(app, frame, a.info);
            }
        }
        match app.view.scene {
            Scene::History => views::history::render(app, frame, a.scene),
            Scene::Loops => views::loops::render(app, frame, a.scene),
            Scene::Laws => views::laws::render(app, frame, a.scene),
            Scene::Sets => views::sets::render(app, frame, a.scene),
            Scene::Spectrum => views::spectrum::render(app, frame, a.scene),
            Scene::Impacts => views::impacts::render(app, frame, a.scene),
            Scene::Map => views::map::render(app, frame, a.scene),
            Scene::Risk => views::risk::render(app.jobs.risk.as_ref(), app.look, frame, a.scene),
            Scene::Buildings => views::row::render(app, frame, a.scene),
        }
        views::summary::render(app, frame, a.summary);
        footer(app, frame, a.footer);
        use views::overlay;
        match &app.mode {
            Mode::Help { top } => overlay::help(app, *top, frame, area),
            Mode::Picker { selected } => overlay::picker(app, *selected, frame, area),
            Mode::SaveName(field) => overlay::save_name(app, field, frame, area),
            Mode::ConfirmOverwrite { name } => overlay::confirm(app, name, frame, area),
            Mode::ConfirmQuit => overlay::confirm_quit(app, frame, area),
            Mode::Export { path, full, .. } => overlay::export(app, path, *full, frame, area),
            Mode::Figure { path } => overlay::figure(app, path, frame, area),
            Mode::RowFile { path, file } => overlay::row_file(app, path, *file, frame, area),
            Mode::Normal | Mode::Editing(_) => {}
        }
    }
    if app.look.ascii {
        asciify(frame.buffer_mut());
    }
}

/// The scene tabs: `t:time  f:force-drift …`, or the keys alone with the
/// current scene's name when that does not fit.
fn header(app: &App, frame: &mut Frame, area: Rect) {
    let bold = Style::new().add_modifier(Modifier::BOLD);
    let full: usize = 9 + Scene::ALL
        .iter()
        .map(|s| s.title().chars().count() + 4)
        .sum::<usize>();
    let mut spans = vec![Span::styled("pounding ", bold)];
    for s in Scene::ALL {
        let text = if full <= area.width as usize || s == app.view.scene {
            format!(" {}:{} ", s.key(), s.title())
        } else {
            format!(" {} ", s.key())
        };
        let style = if s == app.view.scene {
            Style::new().add_modifier(Modifier::REVERSED)
        } else {
            Style::new()
        };
        spans.push(Span::styled(text, style));
    }
    frame.render_widget(Line::from(spans), area);
}

/// The key bar: as many hints as fit, always ending with help and quit
/// (and whether quitting would lose changes); or the dialog's keys.
pub fn key_bar(app: &App, width: usize) -> String {
    let unsaved = !app.unsaved().is_empty();
    let end = if unsaved {
        "? help  q quit (unsaved)"
    } else {
        "? help  q quit"
    };
    let hints: &[&str] = match &app.mode {
        Mode::Editing(_) => &[
            "type a value",
            "Enter sets it",
            "Esc cancels",
            "Ctrl-U clears",
        ],
        _ if app.view.scene == Scene::Buildings => &[
            "↑↓ select",
            "←→ nudge",
            "space play",
            "[ ] time",
            "< > scale",
            "o panel",
            "| both laws",
            "p rows",
            "Enter type",
            "e csv",
            "g svg",
        ],
        _ => &[
            "↑↓ select",
            "←→ nudge",
            "Enter type",
            "Tab set",
            "t f v c w i a x scenes",
            "[ ] cursor",
            "z zoom",
            "p preset",
            "s save",
            "e csv",
            "g svg",
            "u units",
        ],
    };
    if matches!(app.mode, Mode::Editing(_)) {
        return hints.join("  ");
    }
    let mut out = String::new();
    for h in hints {
        if out.chars().count() + h.chars().count() + 2 + end.chars().count() > width {
            break;
        }
        out.push_str(h);
        out.push_str("  ");
    }
    out.push_str(end);
    out
}

fn footer(app: &App, frame: &mut Frame, area: Rect) {
    let state = if app.jobs.computing {
        " computing…"
    } else {
        ""
    };
    let [left, right] = Layout::horizontal([
        Constraint::Min(0),
        Constraint::Length(state.chars().count() as u16),
    ])
    .areas(area);
    let text = match (&app.status, &app.mode) {
        (Some(s), Mode::Normal) => s.clone(),
        _ => key_bar(app, left.width as usize),
    };
    frame.render_widget(Paragraph::new(app.look.text(&text)), left);
    frame.render_widget(
        Paragraph::new(app.look.text(state)).style(Style::new().add_modifier(Modifier::BOLD)),
        right,
    );
}
