//! Drawing: a pure function from the explorer's state to a frame. Nothing
//! here changes the state. The layout functions are shared with the app,
//! which sizes the decimated histories from [`chart_columns`].

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use super::app::{App, Mode, Scene};
use super::views;

/// Smallest terminal the explorer draws in; below it, a notice.
pub const MIN_SIZE: (u16, u16) = (60, 20);
/// Width from which the panes also show each parameter's meaning.
pub const WIDE: u16 = 110;

/// The regions of the screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Areas {
    pub header: Rect,
    pub panes: Rect,
    pub info: Rect,
    pub scene: Rect,
    pub summary: Rect,
    pub footer: Rect,
}

/// Width of the parameter panes for a terminal this wide.
pub fn panes_width(columns: u16) -> u16 {
    if columns >= WIDE { 56 } else { 31 }
}

/// Splits the screen: header, panes and info on the left, the scene on the
/// right, two summary lines and a footer.
pub fn areas(area: Rect) -> Areas {
    let [header, main, summary, footer] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Min(0),
        Constraint::Length(2),
        Constraint::Length(1),
    ])
    .areas(area);
    let [left, scene] = Layout::horizontal([
        Constraint::Length(panes_width(area.width)),
        Constraint::Min(0),
    ])
    .areas(main);
    // One row per parameter, a header and two borders.
    let rows = crate::tui::fields::FIELDS.len() as u16 + 3;
    let [panes, info] =
        Layout::vertical([Constraint::Length(rows), Constraint::Min(0)]).areas(left);
    Areas {
        header,
        panes,
        info,
        scene,
        summary,
        footer,
    }
}

/// Plotting width, in columns, of a full-width chart of the scene.
pub fn chart_columns(size: (u16, u16)) -> u16 {
    let a = areas(Rect::new(0, 0, size.0, size.1));
    a.scene
        .width
        .saturating_sub(views::chart::Y_LABEL_WIDTH + 1)
        .max(1)
}

/// The pane cell under a mouse click: (set, field row).
pub fn pane_hit(size: (u16, u16), column: u16, row: u16) -> Option<(usize, usize)> {
    let a = areas(Rect::new(0, 0, size.0, size.1));
    views::params::hit(a.panes, size.0 >= WIDE, column, row)
}

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
        let a = areas(area);
        header(app, frame, a.header);
        views::params::render(app, frame, a.panes);
        views::params::render_info(app, frame, a.info);
        match app.scene {
            Scene::History => views::history::render(app, frame, a.scene),
            Scene::Loops => views::loops::render(app, frame, a.scene),
            Scene::Kelvin => views::kelvin::render(app, frame, a.scene),
            Scene::Sets => views::sets::render(app, frame, a.scene),
            Scene::Spectrum => views::spectrum::render(app, frame, a.scene),
        }
        views::summary::render(app, frame, a.summary);
        footer(app, frame, a.footer);
        match &app.mode {
            Mode::Help => views::overlay::help(frame, area),
            Mode::Picker { selected } => views::overlay::picker(app, *selected, frame, area),
            Mode::SaveName { text, error } => {
                views::overlay::save_name(app, text, error.as_deref(), frame, area)
            }
            Mode::ConfirmOverwrite { name } => views::overlay::confirm(name, frame, area),
            Mode::Normal | Mode::Editing { .. } => {}
        }
    }
    if app.look.ascii {
        asciify(frame.buffer_mut());
    }
}

fn header(app: &App, frame: &mut Frame, area: Rect) {
    let mut spans = vec![Span::styled(
        "pounding ",
        Style::new().add_modifier(Modifier::BOLD),
    )];
    for s in Scene::ALL {
        let text = format!(" {}:{} ", s.key(), s.title());
        let style = if s == app.scene {
            Style::new().add_modifier(Modifier::REVERSED)
        } else {
            Style::new()
        };
        spans.push(Span::styled(text, style));
    }
    frame.render_widget(Line::from(spans), area);
}

fn footer(app: &App, frame: &mut Frame, area: Rect) {
    let state = if app.computing { "computing… " } else { "" };
    let [left, right] = Layout::horizontal([
        Constraint::Min(0),
        Constraint::Length(state.chars().count() as u16),
    ])
    .areas(area);
    let text = match (&app.status, &app.mode) {
        (_, Mode::Editing { .. }) => "type a value · Enter sets it · Esc cancels".to_string(),
        (Some(s), _) => s.clone(),
        (None, _) => {
            "↑↓ select  ←→ nudge (⇧ ×10, ,. fine)  Enter type  Tab set  m model  r reset  \
                      1-9 p preset  s save  e csv  ? help  q quit"
                .to_string()
        }
    };
    frame.render_widget(Paragraph::new(text), left);
    frame.render_widget(
        Paragraph::new(state).style(Style::new().add_modifier(Modifier::BOLD)),
        right,
    );
}

/// Replaces every non-ASCII character of the frame with a plain one, for
/// terminals without UTF-8: box lines, Braille, Greek letters.
pub fn asciify(buf: &mut Buffer) {
    for cell in buf.content.iter_mut() {
        let s = cell.symbol();
        if s.is_ascii() {
            continue;
        }
        let mut out = String::new();
        for c in s.chars() {
            out.push(ascii_char(c));
        }
        cell.set_symbol(&out);
    }
}

fn ascii_char(c: char) -> char {
    match c {
        c if c.is_ascii() => c,
        '\u{2800}' => ' ',
        '\u{2801}'..='\u{28FF}' | '•' | '█' | '▀' | '▄' => '*',
        '─' | '━' | '═' | '−' | '–' | '—' => '-',
        '│' | '┃' | '║' | '▏' => '|',
        '┌' | '┐' | '└' | '┘' | '├' | '┤' | '┬' | '┴' | '┼' | '╭' | '╮' | '╰' | '╯' => {
            '+'
        }
        'Π' => 'P',
        'ω' => 'w',
        'ξ' => 'x',
        'α' => 'a',
        'τ' => 't',
        'Δ' => 'D',
        'μ' => 'u',
        'δ' => 'd',
        '²' => '2',
        '×' => 'x',
        '·' | '…' => '.',
        '←' => '<',
        '→' => '>',
        '↑' => '^',
        '↓' => 'v',
        '⇧' => 'S',
        '̄' => ' ',
        _ => '?',
    }
}
