//! Scene (w): the spectrum of the active set (SPEC §7): Π_u and Π_v of the
//! left structure against Π_ω1 with and without pounding, Π_ω2 = μ Π_ω1, the
//! current Π_ω1 as a cursor, and a strip marking each point's region
//! (+ amplification, − suppression, · none). Filled in as points arrive.

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

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(s) = &app.jobs.spectrum else {
        frame.render_widget(app.look.text("spectrum: μ undefined (Π_ω1 = 0)"), area);
        return;
    };
    let grid = &s.spec.grid;
    let xb = [grid[0], grid[grid.len() - 1]];
    let omega1 = app.active_params().omega1;
    let [u_area, v_area, strip_area] = Layout::vertical([
        Constraint::Ratio(1, 2),
        Constraint::Ratio(1, 2),
        Constraint::Length(1),
    ])
    .areas(area);
    let peaks = |pick: fn(&StructurePeaks) -> f64| -> [Series; 2] {
        [
            Series::line(
                "pounding",
                palette::LEFT,
                curve(&s.points, |p| pick(&p.left)),
            ),
            Series::line(
                "free",
                palette::FREE,
                curve(&s.points, |p| pick(&p.free_left)),
            ),
        ]
    };
    let progress = if s.done() < s.points.len() {
        format!(" {}/{}", s.done(), s.points.len())
    } else {
        String::new()
    };
    let buf = frame.buffer_mut();
    for (area, title, series, x_labels) in [
        (
            u_area,
            format!("Π_u1 μ={:.2}{progress}", s.spec.mu),
            peaks(|p| p.peak_displacement),
            false,
        ),
        (v_area, "Π_v1".to_string(), peaks(|p| p.peak_velocity), true),
    ] {
        let spec = ChartSpec {
            title,
            x_title: "Π_ω1".into(),
            x_bounds: Some(xb),
            x_labels,
            cursor: Some(omega1),
            ..Default::default()
        };
        chart::draw(buf, area, app.look, &spec, &series);
    }
    let pad = GUTTER as usize;
    let width = (strip_area.width as usize).saturating_sub(pad);
    let label = if pad >= 6 { "+-·  " } else { "" };
    let text = format!(
        "{:>pad$}{}",
        label,
        strip(&s.points, grid, xb, width),
        pad = pad
    );
    frame.render_widget(Line::from(app.look.text(&text)), strip_area);
}
