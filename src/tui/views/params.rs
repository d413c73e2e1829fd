//! The two parameter panes, side by side: one row per field of the
//! parameter table (symbol, meaning on wide terminals, the value in set 1
//! and set 2), or in the physical view one row per physical quantity; the
//! active set's column marked, the selected row highlighted, values that
//! differ from the preset in bold and the set marked `*`. Under them the
//! info box: presets and what differs, the selected row's range and step,
//! μ, a Δτ warning, and in the physical view the Π-groups that follow.

use ratatui::Frame;
use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Cell, Paragraph, Row, Table, Wrap};

use crate::model::params::echo;
use crate::tui::app::{App, Mode};
use crate::tui::fields::FIELDS;
use crate::tui::fit::{fit, fit_value, law_label};
use crate::tui::physical::ROWS;

const SYMBOL: u16 = 9;
const MEANING: u16 = 24;
const VALUE: u16 = 9;

fn widths(wide: bool) -> Vec<Constraint> {
    let mut w = vec![Constraint::Length(SYMBOL)];
    if wide {
        w.push(Constraint::Length(MEANING));
    }
    w.extend([Constraint::Length(VALUE), Constraint::Length(VALUE)]);
    w
}

/// The widths the table gives its columns in `area` (as ratatui's `Table`
/// lays them out: inside the border, one space between columns), so that
/// each cell is fitted to its column rather than cut by it.
fn column_widths(area: Rect, wide: bool) -> Vec<usize> {
    let inner = Block::bordered().inner(area);
    Layout::horizontal(widths(wide))
        .flex(Flex::Start)
        .spacing(1)
        .split(inner)
        .iter()
        .map(|r| usize::from(r.width))
        .collect()
}

/// The symbol and meaning of pane row `r`.
fn row_names(app: &App, r: usize) -> (String, String) {
    if app.physical_view() {
        let row = &ROWS[r];
        (
            format!("{} {}", row.label, row.unit),
            format!("moves {}", row.moves),
        )
    } else {
        let f = &FIELDS[r];
        let symbol = if app.look.ascii { f.ascii } else { f.symbol };
        (symbol.to_string(), f.meaning.to_string())
    }
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let wide = area.width >= 50;
    let columns = column_widths(area, wide);
    let value_width = columns[columns.len() - 1];
    let selected = Style::new().add_modifier(Modifier::REVERSED);
    let heading = |i: usize| {
        let mark = if app.sets[i].modified().is_empty() {
            ""
        } else {
            "*"
        };
        let text = if i == app.active {
            format!("[set {}]{mark}", i + 1)
        } else {
            format!(" set {}{mark}", i + 1)
        };
        let style = if i == app.active {
            Style::new().add_modifier(Modifier::BOLD)
        } else {
            Style::new()
        };
        Cell::from(fit(&text, value_width)).style(style)
    };
    let mut head = vec![Cell::from("")];
    if wide {
        head.push(Cell::from(fit("meaning", columns[1])));
    }
    head.extend([heading(0), heading(1)]);
    let visible = crate::tui::layout::visible_rows(area.height);
    let offset = crate::tui::layout::pane_offset(visible, app.selected);
    let rows = (offset..app.pane_rows()).take(visible).map(|r| {
        let (symbol, meaning) = row_names(app, r);
        let mut cells = vec![Cell::from(fit(&app.look.text(&symbol), columns[0]))];
        if wide {
            let values = [app.row_text(0, r), app.row_text(1, r)];
            let values = [values[0].as_str(), values[1].as_str()];
            let label = law_label(&app.look.text(&meaning), &values, value_width, columns[1]);
            cells.push(Cell::from(app.look.text(&label)));
        }
        for i in 0..2 {
            let mut text = fit_value(&app.row_text(i, r), value_width);
            let mut style = Style::new();
            if i == app.active && r == app.selected {
                if let Mode::Editing(field) = &app.mode {
                    text = field.shown(value_width);
                    if field.error.is_some() && app.look.color {
                        style = style.fg(Color::Red);
                    }
                    style = style.add_modifier(Modifier::UNDERLINED);
                } else {
                    style = selected;
                }
            } else if !app.physical_view() {
                let f = &FIELDS[r];
                if f.text(&app.sets[i].params) != f.text(&app.sets[i].preset.params) {
                    style = style.add_modifier(Modifier::BOLD);
                }
            }
            cells.push(Cell::from(text).style(style));
        }
        Row::new(cells)
    });
    let title = if app.physical_view() {
        "physical units (u: Π-groups)"
    } else {
        "parameters (Tab switches set)"
    };
    // Between the corners: padded when it fits so, else touching them, else
    // its whole words and "…".
    let room = usize::from(area.width).saturating_sub(2);
    let title = match title.chars().count() {
        n if n + 2 <= room => format!(" {title} "),
        n if n <= room => title.to_string(),
        _ => fit(title, room),
    };
    let table = Table::new(rows, widths(wide))
        .header(Row::new(head).style(Style::new().add_modifier(Modifier::UNDERLINED)))
        .block(Block::bordered().title(title));
    frame.render_widget(table, area);
}

/// The info box.
pub fn render_info(app: &App, frame: &mut Frame, area: Rect) {
    let p = app.active_params();
    let mut lines = Vec::new();
    lines.extend(rejected(app));
    let mut presets = Vec::new();
    for (i, s) in app.sets.iter().enumerate() {
        let modified = s.modified();
        let text = if modified.is_empty() {
            format!("set {}: {}", i + 1, s.preset.name)
        } else {
            let symbols: Vec<&str> = modified
                .iter()
                .filter_map(|k| crate::model::params::field(k))
                .map(|f| if app.look.ascii { f.ascii } else { f.symbol })
                .collect();
            format!("set {}: {}* ({})", i + 1, s.preset.name, symbols.join(", "))
        };
        presets.push(text);
    }
    // Two spaces between the sets, or one where only that makes the line
    // fit the box (it wraps otherwise).
    let fits = |line: &String| line.chars().count() < usize::from(area.width);
    let (wide, narrow) = (presets.join("  "), presets.join(" "));
    let line = if !fits(&wide) && fits(&narrow) {
        narrow
    } else {
        wide
    };
    lines.push(Line::from(line));
    if app.physical_view() {
        let groups: Vec<String> = FIELDS
            .iter()
            .filter(|f| crate::model::params::is_pi(f.key))
            .map(|f| format!("{} {}", f.symbol, echo::g4(f.number(p))))
            .collect();
        lines.push(Line::from(format!("→ {}", groups.join("  "))));
    } else {
        let f = &FIELDS[app.selected];
        // A choice's names, `a|b|c`, spaced so that the box wraps between
        // them rather than inside one.
        lines.push(Line::from(format!(
            "{} {} {}, step {}",
            f.symbol,
            f.meaning,
            f.range().replace('|', " | "),
            f.step
        )));
        lines.push(Line::from(format!("μ = Π_ω2/Π_ω1 = {:.4}", p.mu())));
    }
    if let Some(w) = p.coarse_dt_warning() {
        let style = Style::new().add_modifier(Modifier::BOLD);
        lines.push(Line::styled(w.replace("warning: ", "⚠ "), style));
    }
    draw_info(app, lines, frame, area);
}

/// The typed value's refusal, while the field is open with one.
pub fn rejected(app: &App) -> Option<Line<'static>> {
    let Mode::Editing(field) = &app.mode else {
        return None;
    };
    let e = field.error.as_ref()?;
    let style = if app.look.color {
        Style::new().fg(Color::Red)
    } else {
        Style::new().add_modifier(Modifier::BOLD)
    };
    Some(Line::styled(format!("rejected: {e}"), style))
}

/// Draws the info box's lines, spelled as the terminal can show them and
/// wrapped at word boundaries.
pub fn draw_info(app: &App, lines: Vec<Line>, frame: &mut Frame, area: Rect) {
    let lines: Vec<Line> = lines
        .into_iter()
        .map(|l| {
            let style = l.style;
            let text: String = l.spans.iter().map(|s| s.content.as_ref()).collect();
            Line::styled(app.look.text(&text), style)
        })
        .collect();
    // One blank column on the right, so that a full line never runs into
    // the chart titles beside the box.
    let area = Rect {
        width: area.width.saturating_sub(1),
        ..area
    };
    frame.render_widget(Paragraph::new(lines).wrap(Wrap { trim: true }), area);
}
