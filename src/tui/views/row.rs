//! Scene (d): a row of buildings (SPEC §13). A status line (row, ground,
//! time, exaggeration, playback); the row drawn at the cursor time, or two
//! drawings side by side, Kelvin against improved Kelvin; beside or under
//! it the panel: an envelope over height with and without pounding, or the
//! impact table.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::widgets::{Paragraph, Wrap};

use super::row_drawing::{self, automatic, geometry};
use super::row_panel::{self, envelope, impact_table};
use crate::tui::app::App;
use crate::tui::layout::panes_width;
use crate::tui::row_job::RowOutput;
use crate::tui::row_pane::{Panel, RowPane};

/// Smallest drawing, in cells.
pub const MIN_DRAWING: (u16, u16) = (22, 8);

/// The status line of the scene.
pub fn status(pane: &RowPane, exaggeration: f64, width: usize) -> String {
    let play = if pane.play.playing {
        format!("▶ {}×", pane.play.speed())
    } else {
        format!("‖ {}× (space)", pane.play.speed())
    };
    let parts = [
        format!("t {:.2}/{:.1} s", pane.cursor, pane.duration()),
        format!("u×{exaggeration}"),
        play,
        pane.ground_name.clone(),
    ];
    let mut out = String::new();
    for p in parts {
        if !out.is_empty() && out.chars().count() + p.chars().count() + 2 > width {
            break;
        }
        if !out.is_empty() {
            out.push_str("  ");
        }
        out.push_str(&p);
    }
    out
}

/// The exaggeration the drawings use: the user's, else from the row's own run.
pub fn exaggeration(pane: &RowPane, out: &RowOutput) -> f64 {
    pane.exaggeration
        .unwrap_or_else(|| automatic(&out.spec.row, &out.runs[0]))
}

/// Where the drawings and the panel go in the scene's body.
pub fn split(body: Rect, side_by_side: bool, laws: usize) -> (Vec<Rect>, Rect) {
    let n = if side_by_side { laws.max(1) } else { 1 };
    let (drawings, panel) = if body.width >= 64 && !side_by_side {
        let [d, p] = Layout::horizontal([Constraint::Percentage(58), Constraint::Percentage(42)])
            .areas(body);
        (d, p)
    } else {
        let panel_rows = (body.height * 2 / 5).max(4).min(body.height);
        let [d, p] =
            Layout::vertical([Constraint::Min(0), Constraint::Length(panel_rows)]).areas(body);
        (d, p)
    };
    let parts = Layout::horizontal(vec![Constraint::Ratio(1, n as u32); n]).split(drawings);
    (parts.to_vec(), panel)
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(pane) = app.row.as_ref() else {
        frame.render_widget(
            Paragraph::new("no row: p lists the building presets").wrap(Wrap { trim: true }),
            area,
        );
        return;
    };
    let [top, body] = Layout::vertical([Constraint::Length(1), Constraint::Min(0)]).areas(area);
    let Some(out) = app.jobs.shown_row() else {
        let text = app
            .jobs
            .row_refusal()
            .map_or("computing the row…".to_string(), |e| e.to_string());
        frame.render_widget(Paragraph::new(text).wrap(Wrap { trim: true }), area);
        return;
    };
    let x = exaggeration(pane, out);
    let mut line = status(pane, x, top.width as usize);
    if app.jobs.shown_row().is_some_and(|o| o.spec != pane.spec()) {
        line = format!("computing… {line}");
    }
    frame.render_widget(Paragraph::new(app.look.text(&line)), top);
    let (drawings, panel) = split(body, pane.side_by_side, out.runs.len());
    let need_w = MIN_DRAWING.0 * drawings.len() as u16;
    if drawings
        .iter()
        .any(|d| d.width < MIN_DRAWING.0 || d.height < MIN_DRAWING.1)
    {
        let (columns, rows) = app.size;
        let text = format!(
            "the row needs a terminal of at least {}x{} (this one is {columns}x{rows})",
            panes_width(columns) + need_w.max(body.width),
            rows + MIN_DRAWING.1.saturating_sub(drawings[0].height),
        );
        frame.render_widget(Paragraph::new(text).wrap(Wrap { trim: true }), body);
        return;
    }
    let row = &out.spec.row;
    let buf = frame.buffer_mut();
    for (k, d) in drawings.iter().enumerate() {
        let run = &out.runs[k.min(out.runs.len() - 1)];
        let law = out.spec.laws[k.min(out.spec.laws.len() - 1)];
        let Some(trace) = run.trace.as_ref() else {
            continue;
        };
        let g = geometry(row, run, trace, pane.cursor, x);
        // The law's short name (K, IK, …) where the whole one does not fit.
        let mut title = format!("{}: {} impacts", law.name(), run.impacts());
        if title.chars().count() >= usize::from(d.width) {
            let short = crate::tui::fit::short_law(law.name()).unwrap_or(law.name());
            title = crate::tui::fit::fit(
                &format!("{short}: {} impacts", run.impacts()),
                usize::from(d.width.saturating_sub(1)),
            );
        }
        row_drawing::render(buf, *d, app.look, &g, &title);
    }
    match pane.panel {
        Panel::Impacts => {
            let lines = row_panel::impacts(row, &out.runs[0]);
            impact_table(buf, panel, app.look, &lines, pane.cursor);
        }
        quantity => envelope(
            buf,
            panel,
            app.look,
            row,
            match &out.bare {
                Some(bare) => (&out.runs[0], bare, "no retrofit"),
                None => (&out.runs[0], &out.free, "no pounding"),
            },
            quantity,
        ),
    }
}

/// The two summary lines of the scene: per law shown, impacts, the largest
/// force, drift ratio and floor acceleration, and the compute time; then
/// at the cursor, the floor pairs in contact and each roof's displacement.
pub fn summary(app: &App, width: usize) -> Vec<String> {
    let (Some(pane), Some(out)) = (app.row.as_ref(), app.jobs.shown_row()) else {
        return vec![];
    };
    let row = &out.spec.row;
    let mut first = Vec::new();
    for (law, run) in out.spec.laws.iter().zip(&out.runs) {
        let peak = |f: fn(&crate::solver::buildings::FloorPeaks) -> f64| {
            run.floors.iter().flatten().map(f).fold(0.0, f64::max)
        };
        let force = run.pairs.iter().map(|p| p.max_force()).fold(0.0, f64::max);
        // A collapse (SPEC §15) ends the run: say where and when.
        let collapse = run.collapse.map_or(String::new(), |c| {
            format!(
                ", {} collapses (storey {}, {:.2} s)",
                row.buildings[c.building].name, c.storey, c.time
            )
        });
        first.push(format!(
            "{}: {} impacts, {:.0} kN, drift {:.2}%, {:.2} g{collapse}",
            law.name(),
            run.impacts(),
            force / 1e3,
            peak(|f| f.drift_ratio) * 1e2,
            peak(|f| f.absolute_acceleration) / crate::model::record::STANDARD_GRAVITY
        ));
    }
    first.push(format!("{:.0} ms", out.elapsed_ms));
    let run = &out.runs[0];
    let pairs = row.pairs();
    let touching: Vec<String> = row_drawing::contacts_at(run, pane.cursor)
        .iter()
        .zip(&pairs)
        .filter(|(on, _)| **on)
        .map(|(_, p)| row_panel::floors(row, p))
        .collect();
    // The row without its retrofits, when shown (`b`), leads the second line.
    let mut second: Vec<String> = out
        .bare
        .iter()
        .map(|bare| {
            let force = bare.pairs.iter().map(|p| p.max_force()).fold(0.0, f64::max);
            format!(
                "no retrofit: {} impacts, {:.0} kN",
                bare.impacts(),
                force / 1e3
            )
        })
        .collect();
    second.push(format!(
        "t {:.3} s: {}",
        pane.cursor,
        if touching.is_empty() {
            "no contact".to_string()
        } else {
            format!("contact {}", touching.join(", "))
        }
    ));
    if let Some(trace) = run.trace.as_ref() {
        let u = trace.at(pane.cursor);
        let offsets = row.offsets();
        for (b, o) in row.buildings.iter().zip(offsets) {
            second.push(format!(
                "{} roof {:.1} mm",
                b.name,
                u[o + b.storeys() - 1] * 1e3
            ));
        }
    }
    vec![
        super::compact::fit(&first, width),
        super::compact::fit(&second, width),
    ]
}
