//! The two parameter panes, side by side: one row per field (symbol,
//! meaning on wide terminals, the value in set 1 and set 2), the active
//! set's column marked, the selected row highlighted; and the info box under
//! them (presets, the selected field, an edit error).

use ratatui::Frame;
use ratatui::layout::{Constraint, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Cell, Paragraph, Row, Table, Wrap};

use crate::tui::app::{App, Mode};
use crate::tui::fields::{FIELDS, value_text};

const SYMBOL: u16 = 7;
const MEANING: u16 = 24;
const VALUE: u16 = 10;

fn widths(wide: bool) -> Vec<Constraint> {
    let mut w = vec![Constraint::Length(SYMBOL)];
    if wide {
        w.push(Constraint::Length(MEANING));
    }
    w.extend([Constraint::Length(VALUE), Constraint::Length(VALUE)]);
    w
}

/// The (set, row) of the cell at a screen position, for mouse clicks.
pub fn hit(panes: Rect, wide: bool, column: u16, row: u16) -> Option<(usize, usize)> {
    let first = panes.y + 2; // border, header
    let index = row.checked_sub(first)? as usize;
    if index >= FIELDS.len() || column <= panes.x || column >= panes.right() {
        return None;
    }
    let values_start = panes.x + 1 + SYMBOL + 1 + if wide { MEANING + 1 } else { 0 };
    let set = if column < values_start + VALUE + 1 {
        0
    } else {
        1
    };
    Some((set, index))
}

fn short_value(text: String) -> String {
    match text.as_str() {
        "improved-kelvin" => "improved".into(),
        _ => text,
    }
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let wide = area.width >= 50;
    let selected = Style::new().add_modifier(Modifier::REVERSED);
    let heading = |i: usize| {
        let text = if i == app.active {
            format!("[set {}]", i + 1)
        } else {
            format!(" set {}", i + 1)
        };
        let style = if i == app.active {
            Style::new().add_modifier(Modifier::BOLD)
        } else {
            Style::new()
        };
        Cell::from(text).style(style)
    };
    let mut head = vec![Cell::from("")];
    if wide {
        head.push(Cell::from("meaning"));
    }
    head.extend([heading(0), heading(1)]);
    let rows = FIELDS.iter().enumerate().map(|(r, f)| {
        let mut cells = vec![Cell::from(f.symbol)];
        if wide {
            cells.push(Cell::from(f.meaning));
        }
        for i in 0..2 {
            let mut text = short_value(value_text(&app.sets[i].params, f));
            let mut style = Style::new();
            if i == app.active && r == app.selected {
                if let Mode::Editing { text: typed, error } = &app.mode {
                    text = format!("{typed}_");
                    if error.is_some() && app.look.color {
                        style = style.fg(Color::Red);
                    }
                    style = style.add_modifier(Modifier::UNDERLINED);
                } else {
                    style = selected;
                }
            } else if app.sets[i].params.get(f.key) != app.sets[i].preset.params.get(f.key) {
                style = style.add_modifier(Modifier::BOLD);
            }
            cells.push(Cell::from(text).style(style));
        }
        Row::new(cells)
    });
    let table = Table::new(rows, widths(wide))
        .header(Row::new(head).style(Style::new().add_modifier(Modifier::UNDERLINED)))
        .block(Block::bordered().title(" parameters (Tab switches set) "));
    frame.render_widget(table, area);
}

/// The info box: presets of both sets, the selected field, an edit error.
pub fn render_info(app: &App, frame: &mut Frame, area: Rect) {
    let f = &FIELDS[app.selected];
    let p = app.active_params();
    let mut lines = vec![
        Line::from(format!(
            "set 1: {}   set 2: {}",
            app.sets[0].preset.name, app.sets[1].preset.name
        )),
        Line::from(format!("{} {}, step {}", f.symbol, f.meaning, f.step)),
        Line::from(format!("μ = Π_ω2/Π_ω1 = {:.4}", p.mu())),
    ];
    if let Mode::Editing { error: Some(e), .. } = &app.mode {
        let style = if app.look.color {
            Style::new().fg(Color::Red)
        } else {
            Style::new().add_modifier(Modifier::BOLD)
        };
        lines.insert(0, Line::styled(format!("rejected: {e}"), style));
    }
    frame.render_widget(Paragraph::new(lines).wrap(Wrap { trim: true }), area);
}
