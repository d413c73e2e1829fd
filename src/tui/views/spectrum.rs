//! Scene (w): the spectrum of the active set (SPEC §7): Π_u (or Π_v, key o)
//! of both structures against Π_ω1 with and without pounding, Π_ω2 = μ Π_ω1,
//! the impact count, the current Π_ω1 as a cursor with its values read out,
//! and a strip marking each point's region (+ amplification, − suppression,
//! · none) with its legend. Filled in as batches of points arrive.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;

use super::chart::{self, ChartSpec, GUTTER, Series};
use crate::analysis::spectrum::{Region, SpectrumPoint};
use crate::solver::StructurePeaks;
use crate::tui::app::App;
use crate::tui::look::palette;

fn curve(
    points: &[Option<SpectrumPoint>],
    pick: impl Fn(&SpectrumPoint) -> f64,
) -> Vec<(f64, f64)> {
    points
        .iter()
        .flatten()
        .map(|p| (p.omega1, pick(p)))
        .collect()
}

/// The region mark of a point.
pub fn mark(region: Region) -> char {
    match region {
        Region::Amplification => '+',
        Region::Suppression => '-',
        Region::None => '·',
    }
}

/// The region strip, one character per column: the nearest grid point's mark.
pub fn strip(
    points: &[Option<SpectrumPoint>],
    grid: &[f64],
    bounds: [f64; 2],
    width: usize,
) -> String {
    (0..width)
        .map(|c| {
            let w = bounds[0] + (bounds[1] - bounds[0]) * (c as f64 + 0.5) / width.max(1) as f64;
            grid.iter()
                .enumerate()
                .min_by(|a, b| (a.1 - w).abs().total_cmp(&(b.1 - w).abs()))
                .and_then(|(i, _)| points.get(i).copied().flatten())
                .map_or(' ', |p| mark(p.region))
        })
        .collect()
}

/// The grid point nearest to `omega1`, once computed.
fn nearest(points: &[Option<SpectrumPoint>], omega1: f64) -> Option<SpectrumPoint> {
    points
        .iter()
        .flatten()
        .min_by(|a, b| {
            (a.omega1 - omega1)
                .abs()
                .total_cmp(&(b.omega1 - omega1).abs())
        })
        .copied()
}

/// The readout at the cursor (the set's own Π_ω1): both structures with
/// pounding, then both without.
pub fn readout(p: &SpectrumPoint, velocity: bool) -> String {
    let (q, pick): (&str, fn(&StructurePeaks) -> f64) = if velocity {
        ("v", |s| s.peak_velocity)
    } else {
        ("u", |s| s.peak_displacement)
    };
    format!(
        "Π_ω1 {:.2}  Π_{q}1 {:.2}  Π_{q}2 {:.2}  free {:.2} {:.2}",
        p.omega1,
        pick(&p.left),
        pick(&p.right),
        pick(&p.free_left),
        pick(&p.free_right),
    )
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(s) = &app.jobs.spectrum else {
        frame.render_widget(app.look.text("spectrum: μ undefined (Π_ω1 = 0)"), area);
        return;
    };
    let grid = &s.spec.grid;
    let xb = [grid[0], grid[grid.len() - 1]];
    let omega1 = app.active_params().omega1;
    let velocity = app.view.velocity;
    let [
        l_area,
        r_area,
        n_area,
        strip_area,
        legend_area,
        readout_area,
    ] = Layout::vertical([
        Constraint::Fill(3),
        Constraint::Fill(3),
        Constraint::Fill(2),
        Constraint::Length(1),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let (q, pick): (&str, fn(&StructurePeaks) -> f64) = if velocity {
        ("v", |p| p.peak_velocity)
    } else {
        ("u", |p| p.peak_displacement)
    };
    let pair = |own: fn(&SpectrumPoint) -> &StructurePeaks,
                free: fn(&SpectrumPoint) -> &StructurePeaks,
                color| {
        vec![
            Series::line("pounding", color, curve(&s.points, |p| pick(own(p)))),
            Series::line("free", palette::FREE, curve(&s.points, |p| pick(free(p)))),
        ]
    };
    let progress = if s.done() < s.points.len() {
        format!(" {}/{}", s.done(), s.points.len())
    } else {
        String::new()
    };
    let buf = frame.buffer_mut();
    let charts = [
        (
            l_area,
            format!("Π_{q}1 μ={:.2}{progress}", s.spec.mu),
            pair(|p| &p.left, |p| &p.free_left, palette::LEFT),
        ),
        (
            r_area,
            format!("Π_{q}2 (o: Π_u/Π_v)"),
            pair(|p| &p.right, |p| &p.free_right, palette::RIGHT),
        ),
        (
            n_area,
            "impacts".to_string(),
            vec![Series::line(
                "count",
                palette::FORCE,
                curve(&s.points, |p| p.impacts as f64),
            )],
        ),
    ];
    for (k, (area, title, series)) in charts.into_iter().enumerate() {
        let spec = ChartSpec {
            title,
            x_title: "Π_ω1".into(),
            x_bounds: Some(xb),
            x_labels: k == 2,
            cursor: Some(omega1),
            no_legend: false,
            // Counts start at zero.
            y_range: (k == 2).then(|| {
                let most = s.points.iter().flatten().map(|p| p.impacts).max();
                [0.0, most.unwrap_or(1).max(1) as f64]
            }),
        };
        chart::draw(buf, area, app.look, &spec, &series);
    }
    let pad = GUTTER as usize;
    let width = (strip_area.width as usize).saturating_sub(pad);
    let text = format!(
        "{:>pad$}{}",
        "left ",
        strip(&s.points, grid, xb, width),
        pad = pad
    );
    frame.render_widget(Line::from(app.look.text(&text)), strip_area);
    let here = nearest(&s.points, omega1);
    let legend = format!(
        "+ amplified  − suppressed  · none{}",
        here.map_or_else(String::new, |p| format!("   {} impacts", p.impacts))
    );
    frame.render_widget(Line::from(app.look.text(&legend)), legend_area);
    // Whole items only: the readout is cut at a double space, never inside a number.
    let full = here.map_or_else(String::new, |p| app.look.text(&readout(&p, velocity)));
    let mut line = String::new();
    for item in full.split("  ") {
        let sep = if line.is_empty() { 0 } else { 2 };
        if line.chars().count() + sep + item.chars().count() > readout_area.width as usize {
            break;
        }
        if sep > 0 {
            line.push_str("  ");
        }
        line.push_str(item);
    }
    frame.render_widget(Line::from(line), readout_area);
}
