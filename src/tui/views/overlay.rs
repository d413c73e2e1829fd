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
use crate::tui::keys;
use crate::tui::row_file::RowFile;
use crate::tui::text_field::TextField;
use crate::tui::worker::Slot;

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

pub fn help(app: &App, top: usize, frame: &mut Frame, area: Rect) {
    let lines = keys::help_lines();
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
    // Otherwise it scrolls (↑↓), from line `top`.
    if lines.len() > rows {
        let top = top.min(keys::help_top_max(area.height));
        let title = format!(
            "keys {}–{} of {} (↑↓ scroll)",
            top + 1,
            (top + rows).min(lines.len()),
            lines.len()
        );
        let width = keys::HELP_COLUMNS as u16 + 2;
        // The whole height, whatever the lines below `top` (a long line wraps).
        let mut shown = lines[top..].to_vec();
        shown.resize(shown.len().max(rows), String::new());
        return boxed(app, frame, area, &title, shown, width);
    }
    boxed(app, frame, area, "keys", lines, 62);
}

pub fn picker(app: &App, selected: usize, frame: &mut Frame, area: Rect) {
    let entries = app.picker_entries();
    let items: Vec<ListItem> = entries
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let number = if i < 9 {
                format!("{}", i + 1)
            } else {
                " ".into()
            };
            ListItem::new(app.look.text(&format!(
                "{number} {:<15} {:<8} {}",
                p.name, p.kind, p.description
            )))
        })
        .collect();
    let height = (items.len() as u16 + 2).min(area.height.saturating_sub(2));
    let r = centered(area, area.width.saturating_sub(4), height);
    frame.render_widget(Clear, r);
    let list = List::new(items)
        .block(Block::bordered().title(format!(
            " {} ({}/{}, Enter loads, Esc closes) ",
            if app.scene() == crate::tui::scene::Scene::Buildings {
                "row preset".to_string()
            } else {
                format!("preset for set {}", app.active + 1)
            },
            selected + 1,
            entries.len()
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

/// Where `e` and `g` of the buildings scene write the row's file.
pub fn row_file(app: &App, field: &TextField, file: RowFile, frame: &mut Frame, area: Rect) {
    let width = 72.min(area.width);
    let mut lines = prompt_lines(field, "path: ", width);
    lines.push(
        match file {
            RowFile::Csv => "peaks per floor, as pounding run --buildings --format csv",
            RowFile::Figure => "figure `buildings`, as pounding figure buildings (SVG)",
        }
        .to_string(),
    );
    lines.push("Enter writes, Esc cancels; Ctrl-U clears".into());
    let title = match file {
        RowFile::Csv => "write the row's peaks as CSV",
        RowFile::Figure => "write the row's figure as SVG",
    };
    boxed(app, frame, area, title, lines, width);
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
