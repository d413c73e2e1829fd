//! Boxes drawn over the scene: the help listing every key, the preset
//! picker (a list that scrolls to its selection), the save and path
//! prompts, and the overwrite and quit questions.

use ratatui::Frame;
use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Clear, List, ListItem, ListState, Paragraph, Wrap};

use crate::tui::app::{App, LARGE_EXPORT};
use crate::tui::export;
use crate::tui::text_field::TextField;
use crate::tui::worker::Slot;

/// Every key, as the help overlay and the README list them.
pub const KEYS: [(&str, &str); 31] = [
    ("?", "this help (any key closes it)"),
    ("↑/↓, k/j", "select a parameter"),
    ("←/→, h/l, -/+", "nudge it by one step"),
    ("Shift+←/→, H/L", "nudge by ten steps"),
    (", / .  (Ctrl+←/→)", "nudge by a tenth of a step"),
    ("Enter", "type an exact value (typing replaces it)"),
    ("Tab", "switch the active set"),
    ("m", "Kelvin ↔ improved Kelvin (row: all six)"),
    ("r", "reset the active set to its preset"),
    ("1-9", "recall preset 1-9 into the active set"),
    ("p", "preset picker"),
    ("s", "save the active set as a user preset"),
    ("e", "export a history as CSV (asks where)"),
    ("g", "write the scene as an SVG figure"),
    ("t", "scene: time histories"),
    ("f", "scene: force-drift loops"),
    (
        "v",
        "scene: contact laws (b: paper pair, all six, own vs one)",
    ),
    ("c", "scene: set 1 vs set 2 (o overlays them)"),
    ("w", "scene: spectrum against Π_ω1"),
    ("i", "scene: impact table and energy terms"),
    ("a", "scene: map (y axis, o ratio, [ ]{ })"),
    ("x", "scene: risk over a suite ([ ] design level)"),
    ("u", "physical units (presets with [physical])"),
    ("[ / ]", "move the time cursor ({ } by ten)"),
    ("n / N", "cursor to the next / previous impact"),
    ("z / Z", "zoom in around the cursor / out"),
    ("Esc", "hide the cursor (never quits)"),
    ("mouse", "click: select or cursor; wheel: nudge"),
    ("M", "mouse on/off (off: select text)"),
    ("q", "quit (asks if a set is unsaved)"),
    ("Ctrl-C", "quit at once"),
];

fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let [v] = Layout::vertical([Constraint::Length(height.min(area.height))])
        .flex(Flex::Center)
        .areas(area);
    let [h] = Layout::horizontal([Constraint::Length(width.min(area.width))])
        .flex(Flex::Center)
        .areas(v);
    h
}

fn boxed(app: &App, frame: &mut Frame, area: Rect, title: &str, lines: Vec<String>, width: u16) {
    let r = centered(area, width, lines.len() as u16 + 2);
    frame.render_widget(Clear, r);
    let lines: Vec<Line> = lines
        .into_iter()
        .map(|l| Line::from(app.look.text(&l)))
        .collect();
    frame.render_widget(
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(Block::bordered().title(app.look.text(&format!(" {title} ")))),
        r,
    );
}

pub fn help(app: &App, frame: &mut Frame, area: Rect) {
    // The keys; under `m`, the short forms a narrow pane gives the laws'
    // names, high enough to show on a 24-row screen.
    let mut lines = Vec::new();
    for (k, what) in KEYS {
        lines.push(format!("{k:>18}  {what}"));
        if k == "m" {
            lines.extend(
                crate::tui::fit::short_laws_legend()
                    .into_iter()
                    .map(|(short, name)| format!("{short:>18}  law {name}")),
            );
        }
    }
    // Taller than the screen: two columns side by side when wide enough.
    let rows = area.height.saturating_sub(2) as usize;
    if lines.len() > rows && area.width >= 124 {
        let half = lines.len().div_ceil(2);
        let joined = (0..half)
            .map(|i| {
                let right = lines.get(half + i).cloned().unwrap_or_default();
                format!("{:<60}{right}", lines[i])
            })
            .collect();
        return boxed(app, frame, area, "keys", joined, 122);
    }
    boxed(app, frame, area, "keys", lines, 62);
}

pub fn picker(app: &App, selected: usize, frame: &mut Frame, area: Rect) {
    let items: Vec<ListItem> = app
        .presets
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let number = if i < 9 {
                format!("{}", i + 1)
            } else {
                " ".into()
            };
            let kind = if p.path.is_some() {
                "yours"
            } else {
                "built-in"
            };
            ListItem::new(app.look.text(&format!(
                "{number} {:<14} {kind:<8} {}",
                p.name, p.description
            )))
        })
        .collect();
    let height = (items.len() as u16 + 2).min(area.height.saturating_sub(2));
    let r = centered(area, area.width.saturating_sub(4), height);
    frame.render_widget(Clear, r);
    let list = List::new(items)
        .block(Block::bordered().title(format!(
            " preset for set {} ({}/{}, Enter loads, Esc closes) ",
            app.active + 1,
            selected + 1,
            app.presets.len()
        )))
        .highlight_style(Style::new().add_modifier(Modifier::REVERSED));
    // A fresh state each frame: the list scrolls so the selection shows.
    let mut state = ListState::default().with_selected(Some(selected));
    frame.render_stateful_widget(list, r, &mut state);
}

fn prompt_lines(field: &TextField, label: &str, width: u16) -> Vec<String> {
    let room = (width as usize).saturating_sub(4 + label.len());
    let mut lines = vec![format!("{label}{}", field.shown(room))];
    if let Some(e) = &field.error {
        lines.push(e.clone());
    }
    lines
}

pub fn save_name(app: &App, field: &TextField, frame: &mut Frame, area: Rect) {
    let width = 60.min(area.width);
    let mut lines = prompt_lines(field, "name: ", width);
    lines.push("Enter saves, Esc cancels; Ctrl-U clears".into());
    boxed(
        app,
        frame,
        area,
        &format!("save set {} as a user preset", app.active + 1),
        lines,
        width,
    );
}

pub fn export(app: &App, field: &TextField, full: bool, frame: &mut Frame, area: Rect) {
    let width = 72.min(area.width);
    let p = app.active_params();
    let bytes = export::full_bytes(p);
    let shown_rows = app
        .shown(Slot::Set(app.active))
        .map_or(0, |r| r.history.filled().count());
    let mark = |on: bool| if on { "(x)" } else { "( )" };
    let mut lines = prompt_lines(field, "path: ", width);
    lines.push(format!(
        "{} full history: {} rows, about {}{}",
        mark(full),
        export::full_rows(p),
        export::size_text(bytes),
        if bytes > LARGE_EXPORT { " (large)" } else { "" }
    ));
    lines.push(format!(
        "{} on-screen history: {shown_rows} rows (min/max per bucket)",
        mark(!full)
    ));
    lines.push("Tab switches, Enter writes, Esc cancels; Ctrl-U clears".into());
    boxed(
        app,
        frame,
        area,
        "export the active run as CSV",
        lines,
        width,
    );
}

pub fn figure(app: &App, field: &TextField, frame: &mut Frame, area: Rect) {
    let width = 72.min(area.width);
    let (name, _) = app.figure_of_scene();
    let mut lines = prompt_lines(field, "path: ", width);
    lines.push(format!(
        "figure `{name}` of set {}, SVG 1200×900",
        app.active + 1
    ));
    lines.push("Enter writes, Esc cancels; Ctrl-U clears".into());
    boxed(app, frame, area, "write the scene as SVG", lines, width);
}

pub fn confirm(app: &App, name: &str, frame: &mut Frame, area: Rect) {
    let lines = vec![format!("user preset `{name}` exists: overwrite it? (y/n)")];
    boxed(app, frame, area, "overwrite?", lines, 60);
}

pub fn confirm_quit(app: &App, frame: &mut Frame, area: Rect) {
    let sets: Vec<String> = app
        .unsaved()
        .iter()
        .map(|i| format!("set {}", i + 1))
        .collect();
    let lines = vec![
        format!(
            "{} differs from its preset and is not saved.",
            sets.join(" and ")
        ),
        "Quit anyway? y quits, any other key stays (s saves)".into(),
    ];
    boxed(app, frame, area, "quit?", lines, 60);
}
