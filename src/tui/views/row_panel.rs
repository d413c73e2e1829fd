//! Beside the row's drawing: an envelope over height (peak floor
//! displacement, peak storey drift ratio or peak floor absolute
//! acceleration, SPEC §13), with pounding in each building's colour and
//! without in grey; or the row's impacts (pair, floors, time, force), the
//! one at the cursor marked.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget};

use super::chart::{self, ChartSpec, Series};
use super::row_drawing::COLORS;
use crate::model::buildings::{FloorPair, Row};
use crate::model::record::STANDARD_GRAVITY;
use crate::solver::buildings::{FloorPeaks, RowRun};
use crate::tui::look::{Look, palette};
use crate::tui::row_pane::Panel;

/// The quantity of an envelope panel, its title and its unit factor.
fn quantity(panel: Panel) -> (&'static str, fn(&FloorPeaks) -> f64) {
    match panel {
        Panel::Displacement => ("peak u mm", |f| f.displacement * 1e3),
        Panel::DriftRatio => ("peak drift %", |f| f.drift_ratio * 1e2),
        Panel::Acceleration => ("peak ü+üg g", |f| {
            f.absolute_acceleration / STANDARD_GRAVITY
        }),
        Panel::Impacts => ("", |_| 0.0),
    }
}

/// The envelope of one quantity over floor elevation: per building, the
/// run with pounding and (grey) the run it is set against, named `grey`:
/// without pounding, or without the retrofits.
pub fn envelope(
    buf: &mut Buffer,
    area: Rect,
    look: Look,
    row: &Row,
    (with, without, grey): (&RowRun, &RowRun, &str),
    panel: Panel,
) {
    let (title, value) = quantity(panel);
    let mut series = Vec::new();
    for (k, b) in row.buildings.iter().enumerate() {
        let line = |run: &RowRun| -> Vec<(f64, f64)> {
            run.floors[k]
                .iter()
                .enumerate()
                .map(|(i, f)| (value(f), b.elevation(i + 1)))
                .collect()
        };
        series.push(Series::line(b.name.clone(), COLORS[k % COLORS.len()], line(with)).unlisted());
        series.push(Series::line(grey, palette::FREE, line(without)).unlisted());
    }
    // The grey runs drawn first, under the runs with pounding.
    series.sort_by_key(|s| s.name != grey);
    let top = row
        .buildings
        .iter()
        .map(|b| b.elevation(b.storeys()))
        .fold(0.0, f64::max);
    let spec = ChartSpec {
        title: format!("{title} (grey: {grey})"),
        x_title: String::new(),
        x_bounds: None,
        y_range: Some([0.0, top]),
        x_labels: true,
        cursor: None,
        no_legend: true,
    };
    let max = series
        .iter()
        .filter_map(|s| chart::data_range(std::slice::from_ref(s), |p| p.0))
        .map(|r| r[1])
        .fold(0.0, f64::max);
    let spec = ChartSpec {
        x_bounds: Some([0.0, if max > 0.0 { max * 1.05 } else { 1.0 }]),
        ..spec
    };
    chart::draw(buf, area, look, &spec, &series);
}

/// One impact of the row, for the table.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactLine {
    pub pair: usize,
    /// `block 3|frame 3`.
    pub floors: String,
    pub start: f64,
    /// kN.
    pub force: f64,
}

/// A floor pair as the scene names it: `block 3|frame 3`.
pub fn floors(row: &Row, p: &FloorPair) -> String {
    format!(
        "{} {}|{} {}",
        row.buildings[p.left].name, p.left_floor, row.buildings[p.right].name, p.right_floor
    )
}

/// Every impact of the run, by time.
pub fn impacts(row: &Row, run: &RowRun) -> Vec<ImpactLine> {
    let pairs = row.pairs();
    let mut out: Vec<ImpactLine> = run
        .pairs
        .iter()
        .zip(&pairs)
        .enumerate()
        .flat_map(|(k, (result, p))| {
            let floors = floors(row, p);
            result.impacts.iter().map(move |i| ImpactLine {
                pair: k,
                floors: floors.clone(),
                start: i.start,
                force: i.max_force / 1e3,
            })
        })
        .collect();
    out.sort_by(|a, b| a.start.total_cmp(&b.start));
    out
}

/// The impact table, scrolled so that the last impact at or before the
/// cursor shows, marked.
pub fn impact_table(buf: &mut Buffer, area: Rect, look: Look, lines: &[ImpactLine], cursor: f64) {
    if area.height == 0 {
        return;
    }
    let at = lines.iter().rposition(|l| l.start <= cursor);
    let visible = area.height.saturating_sub(1) as usize;
    let first = at.map_or(0, |k| (k + 1).saturating_sub(visible));
    let mut text = vec![Line::styled(
        format!("{} impacts  floors   t s   kN", lines.len()),
        Style::new().add_modifier(Modifier::BOLD),
    )];
    for (k, l) in lines.iter().enumerate().skip(first).take(visible) {
        let s = format!("{:>3} {} {:.3} {:.0}", k + 1, l.floors, l.start, l.force);
        let style = if Some(k) == at {
            Style::new().add_modifier(Modifier::REVERSED)
        } else {
            Style::new()
        };
        text.push(Line::styled(look.text(&s), style));
    }
    if lines.is_empty() {
        text.push(Line::from("no impact: the joints stay open"));
    }
    Paragraph::new(text).render(area, buf);
}
