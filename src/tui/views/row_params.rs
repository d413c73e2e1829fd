//! The parameter pane in the buildings scene: one row per editable value of
//! the row (the law and e, per building storeys, floor mass, storey
//! stiffness, yield drift, α and ξ, per joint the gap and k̄), values edited
//! since the preset in bold; under it the info box: the preset, the
//! selected row's `--set` key and how its steps go.

use ratatui::Frame;
use ratatui::layout::{Constraint, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Cell, Row, Table};

use crate::tui::app::{App, Mode};
use crate::tui::fit::{fit, fit_value, law_label};
use crate::tui::row_fields::{Kind, RowField};
use crate::tui::row_pane::RowPane;

const VALUE: u16 = 11;

pub fn render(app: &App, pane: &RowPane, frame: &mut Frame, area: Rect) {
    let fields = pane.fields();
    let label_width = usize::from(area.width.saturating_sub(2 + 1 + VALUE));
    let visible = crate::tui::layout::visible_rows(area.height);
    let offset = crate::tui::layout::pane_offset(visible, pane.selected);
    let edited: Vec<&str> = pane.edits.iter().map(|(k, _)| k.as_str()).collect();
    let rows = fields
        .iter()
        .enumerate()
        .skip(offset)
        .take(visible)
        .map(|(r, f)| {
            let mut text = fit_value(&f.value, usize::from(VALUE));
            let mut style = Style::new();
            if r == pane.selected {
                if let Mode::Editing(field) = &app.mode {
                    text = field.shown(usize::from(VALUE));
                    if field.error.is_some() && app.look.color {
                        style = style.fg(Color::Red);
                    }
                    style = style.add_modifier(Modifier::UNDERLINED);
                } else {
                    style = style.add_modifier(Modifier::REVERSED);
                }
            } else if edited.contains(&f.key.as_str()) {
                style = style.add_modifier(Modifier::BOLD);
            }
            Row::new(vec![
                Cell::from(app.look.text(&law_label(
                    &app.look.text(&f.label),
                    &[f.value.as_str()],
                    usize::from(VALUE),
                    label_width,
                ))),
                Cell::from(text).style(style),
            ])
        });
    let mark = if pane.modified() { "*" } else { "" };
    let title = fit(
        &format!(" row {}{mark} ", pane.name()),
        usize::from(area.width).saturating_sub(2),
    );
    let table = Table::new(
        rows,
        [
            Constraint::Length(label_width as u16),
            Constraint::Length(VALUE),
        ],
    )
    .header(
        Row::new(vec![Cell::from("building value"), Cell::from("")])
            .style(Style::new().add_modifier(Modifier::UNDERLINED)),
    )
    .block(Block::bordered().title(title));
    frame.render_widget(table, area);
}

/// How the selected row steps.
fn steps(f: &RowField) -> &'static str {
    match f.kind {
        Kind::Law => "←→ next law, m Kelvin pair",
        Kind::Restitution => "step 0.05",
        Kind::Storeys(_) => "step 1; lists grow by the top value",
        Kind::Alpha(_) => "step 0.01",
        Kind::Damping(_) => "step 0.005 (Rayleigh, modes 1-2)",
        Kind::BumperRestitution(_) => "step 0.05",
        Kind::LinkStiffness(_) | Kind::LinkDamping(_) => "×1.1 a step; at 0 type a value",
        _ => "×1.1 a step (H/L ×2, ,/. ×1.02)",
    }
}

pub fn render_info(app: &App, pane: &RowPane, frame: &mut Frame, area: Rect) {
    let mut lines = Vec::new();
    lines.extend(super::params::rejected(app));
    let fields = pane.fields();
    let f = &fields[pane.selected.min(fields.len() - 1)];
    let edited = if pane.modified() {
        format!("{}* ({} edits, r resets)", pane.source, pane.edits.len())
    } else {
        pane.source.clone()
    };
    lines.push(Line::from(edited));
    lines.push(Line::from(format!("--set {}: {}", f.key, steps(f))));
    let pairs = pane.row.pairs().len();
    lines.push(Line::from(format!(
        "{} floors, {pairs} floor pairs",
        pane.row.dofs()
    )));
    super::params::draw_info(app, lines, frame, area);
}
