//! Boxes drawn over the scene: the help listing every key, the preset
//! picker, the save prompt and the overwrite question.

use ratatui::Frame;
use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Clear, Paragraph, Wrap};

use crate::tui::app::{App, Scene};

/// Every key, as the help overlay and the README list them.
pub const KEYS: [(&str, &str); 21] = [
    ("↑/↓, k/j", "select a parameter"),
    ("←/→, h/l, -/+", "nudge it by one step"),
    ("Shift+←/→, H/L", "nudge by ten steps"),
    (", / .  (Ctrl+←/→)", "nudge by a tenth of a step"),
    ("Enter", "type an exact value (Esc cancels)"),
    ("Tab", "switch the active set"),
    ("m", "toggle Kelvin / improved Kelvin"),
    ("r", "reset the active set to its preset"),
    ("1-9", "recall preset 1-9 into the active set"),
    ("p", "preset picker"),
    ("s", "save the active set as a user preset"),
    ("e", "export the active run as CSV"),
    ("t", "scene: time histories"),
    ("f", "scene: force-drift loops"),
    ("v", "scene: Kelvin vs improved Kelvin"),
    ("c", "scene: set 1 vs set 2"),
    ("w", "scene: spectrum against Π_ω1"),
    ("mouse", "click selects, wheel nudges"),
    ("?", "this help"),
    ("q, Esc, Ctrl-C", "quit"),
    ("", "any key closes this help"),
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

fn boxed(frame: &mut Frame, area: Rect, title: &str, lines: Vec<Line>, width: u16) {
    let r = centered(area, width, lines.len() as u16 + 2);
    frame.render_widget(Clear, r);
    frame.render_widget(
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(Block::bordered().title(format!(" {title} "))),
        r,
    );
}

pub fn help(frame: &mut Frame, area: Rect) {
    debug_assert_eq!(Scene::ALL.len(), 5);
    let lines = KEYS
        .iter()
        .map(|(k, what)| Line::from(format!("{k:>18}  {what}")))
        .collect();
    boxed(frame, area, "keys", lines, 60);
}

pub fn picker(app: &App, selected: usize, frame: &mut Frame, area: Rect) {
    let lines = app
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
            let text = format!("{number} {:<12} {kind:<8} {}", p.name, p.description);
            let style = if i == selected {
                Style::new().add_modifier(Modifier::REVERSED)
            } else {
                Style::new()
            };
            Line::styled(text, style)
        })
        .collect();
    boxed(
        frame,
        area,
        &format!(
            "preset for set {} (Enter loads, Esc closes)",
            app.active + 1
        ),
        lines,
        area.width.saturating_sub(4),
    );
}

pub fn save_name(app: &App, text: &str, error: Option<&str>, frame: &mut Frame, area: Rect) {
    let mut lines = vec![Line::from(format!("name: {text}_"))];
    if let Some(e) = error {
        lines.push(Line::styled(
            e.to_string(),
            Style::new().add_modifier(Modifier::BOLD),
        ));
    }
    lines.push(Line::from("Enter saves, Esc cancels"));
    boxed(
        frame,
        area,
        &format!("save set {} as a user preset", app.active + 1),
        lines,
        56,
    );
}

pub fn confirm(name: &str, frame: &mut Frame, area: Rect) {
    let lines = vec![Line::from(format!(
        "user preset `{name}` exists: overwrite it? (y/n)"
    ))];
    boxed(frame, area, "overwrite?", lines, 56);
}
