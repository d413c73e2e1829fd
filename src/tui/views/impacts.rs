//! Scene (i): the impacts of the active run, as `pounding run` prints them
//! (start, end, approach velocity v₀, separation velocity, achieved e, peak
//! force, penetration), the one at the cursor selected (n/N walk them, z
//! zooms the time scene onto it); under it the energy terms of SPEC §6 as
//! bars against the input, and, where a line is left, the demands of SPEC §6
//! per structure.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Cell, Paragraph, Row, Table, TableState};

use super::compact::{fit as fit_parts, num, pair};
use super::units::Units;
use crate::solver::RunResult;
use crate::tui::app::App;
use crate::tui::fit::fit;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(run) = app.shown(Slot::Set(app.active)) else {
        frame.render_widget("computing…", area);
        return;
    };
    let u = Units::active(app);
    let r = &run.result;
    // The energy's title and six bars, and a line of demands where the height allows.
    let energy_rows = 8u16.min(area.height / 2);
    let [table_area, energy_area] =
        Layout::vertical([Constraint::Min(3), Constraint::Length(energy_rows)]).areas(area);
    let t = if u.physical { "t s" } else { "τ" };
    let head = [
        "#".to_string(),
        t.to_string(),
        "end".into(),
        "v₀".into(),
        "v_sep".into(),
        "e".into(),
        "f_max".into(),
        "δ_max".into(),
    ];
    let rows = r.impacts.iter().enumerate().map(|(i, im)| {
        vec![
            Cell::from(format!("{}", i + 1)),
            Cell::from(num(im.start * u.time)),
            Cell::from(num(im.end * u.time)),
            Cell::from(num(im.approach_velocity * u.velocity)),
            Cell::from(num(im.separation_velocity * u.velocity)),
            Cell::from(num(im.restitution)),
            Cell::from(num(im.peak_force * u.force)),
            Cell::from(num(im.max_penetration * u.length)),
        ]
    });
    // Columns by priority (#, start, v₀, f_max, e, v_sep, δ_max, end),
    // as many as the width holds.
    const WIDTHS: [u16; 8] = [3, 7, 7, 6, 6, 5, 7, 6];
    const PRIORITY: [usize; 8] = [0, 1, 3, 6, 5, 4, 7, 2];
    let mut kept = [false; 8];
    let mut used = 0;
    for i in PRIORITY {
        if used + WIDTHS[i] < area.width {
            used += WIDTHS[i] + 1;
            kept[i] = true;
        }
    }
    let keep = |i: usize| kept[i];
    let widths: Vec<Constraint> = WIDTHS
        .into_iter()
        .enumerate()
        .filter(|(i, _)| keep(*i))
        .map(|(_, w)| Constraint::Length(w))
        .collect();
    let rows = rows.map(|row: Vec<Cell<'static>>| {
        Row::new(
            row.into_iter()
                .enumerate()
                .filter(|(i, _)| keep(*i))
                .map(|(_, c)| c),
        )
    });
    let title = if r.impacts.is_empty() {
        "no impacts".to_string()
    } else {
        format!(
            "{} impacts [{} {} {}]",
            r.impacts.len(),
            u.velocity_unit,
            u.force_unit,
            u.length_unit
        )
    };
    let head: Vec<String> = head
        .into_iter()
        .enumerate()
        .filter(|(i, _)| keep(*i))
        .map(|(_, h)| h)
        .collect();
    let header = Row::new(head.into_iter().map(|h| Cell::from(app.look.text(&h))))
        .style(Style::new().add_modifier(Modifier::UNDERLINED));
    let table = Table::new(rows, widths)
        .column_spacing(1)
        .header(header)
        .block(
            ratatui::widgets::Block::new()
                .title(fit(&app.look.text(&title), usize::from(table_area.width))),
        )
        .row_highlight_style(Style::new().add_modifier(Modifier::REVERSED));
    let mut state = TableState::default().with_selected(app.view.selected_impact(&r.impacts));
    frame.render_stateful_widget(table, table_area, &mut state);
    energy(app, r, &u, frame, energy_area);
}

/// The energy terms as bars scaled to the largest. The spring work E_spring
/// is split into what the springs dissipated, the hysteretic energy E_h of
/// both structures, and the elastic energy Σ f_s²/(2k) they still store at
/// the end (SPEC §6, demands); then the demands per structure (left/right).
fn energy(app: &App, r: &RunResult, u: &Units, frame: &mut Frame, area: Rect) {
    if area.height == 0 {
        return;
    }
    let e = &r.energy;
    let hysteretic = r.left.hysteretic_energy + r.right.hysteretic_energy;
    let terms = [
        ("input", e.input),
        ("kinetic", e.kinetic),
        ("damping", e.damping),
        ("hysteretic", hysteretic),
        ("elastic", e.spring - hysteretic),
        ("contact", e.contact),
    ];
    let biggest = terms.iter().fold(0f64, |m, t| m.max(t.1.abs())).max(1e-300);
    let bar_width = area.width.saturating_sub(11 + 9) as f64;
    let title = app.look.text(&format!(
        "energy [{}], residual {:.0e}",
        u.energy_unit, e.residual
    ));
    let mut lines = vec![Line::from(fit(&title, usize::from(area.width)))];
    for (name, v) in terms {
        let n = ((v.abs() / biggest) * bar_width).round() as usize;
        let bar = if app.look.ascii { "#" } else { "█" }.repeat(n);
        lines.push(Line::from(format!(
            "{name:>10} {:>8} {bar}",
            num(v * u.energy)
        )));
    }
    let (left, right) = (&r.left, &r.right);
    let pair = pair;
    let demands = [
        pair(
            "A",
            left.peak_absolute_acceleration * u.acceleration,
            right.peak_absolute_acceleration * u.acceleration,
        ),
        pair("μ", left.ductility, right.ductility),
        pair(
            "r",
            left.residual_displacement * u.length,
            right.residual_displacement * u.length,
        ),
    ];
    let demands = fit_parts(&demands, area.width as usize);
    lines.push(Line::from(app.look.text(&demands)));
    frame.render_widget(Paragraph::new(lines), area);
}
