//! Chart building blocks shared by the scenes: decimated histories as
//! min/max spans (so peaks stay visible), bounds, labelled axes, a legend,
//! Braille markers (or plain ones with `--ascii`).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, LegendPosition};

use crate::solver::Decimated;
use crate::tui::app::Look;

/// Columns reserved for the y-axis labels.
pub const Y_LABEL_WIDTH: u16 = 7;

/// Channel indices of `Sample::channels`.
pub const X1: usize = 0;
pub const V1: usize = 1;
pub const X2: usize = 3;
pub const V2: usize = 4;
pub const FS1: usize = 6;
pub const FS2: usize = 7;
pub const FP: usize = 8;

/// One line of a chart.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            name: name.into(),
            points,
        }
    }
}

/// A channel over time as a vertical span per bucket: (τ, min), (τ, max).
pub fn spans(h: &Decimated, channel: usize, offset: f64) -> Vec<(f64, f64)> {
    h.filled()
        .flat_map(|b| {
            [
                (b.tau, b.min[channel] + offset),
                (b.tau, b.max[channel] + offset),
            ]
        })
        .filter(|(_, y)| y.is_finite())
        .collect()
}

/// Two channels against each other through each bucket's midpoint (the
/// force–drift loop needs pairs; buckets are fine enough to trace it).
pub fn pairs(h: &Decimated, cx: usize, cy: usize) -> Vec<(f64, f64)> {
    let mid = |b: &crate::solver::observer::Bucket, c: usize| 0.5 * (b.min[c] + b.max[c]);
    h.filled()
        .map(|b| (mid(b, cx), mid(b, cy)))
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect()
}

/// Bounds of every point, widened a little; [0, 1] when there are none.
pub fn bounds(series: &[Series], pick: impl Fn(&(f64, f64)) -> f64) -> [f64; 2] {
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.points.iter().map(&pick))
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return [0.0, 1.0];
    }
    let pad = ((hi - lo) * 0.05).max(1e-9);
    [lo - pad, hi + pad]
}

/// A short number for an axis label.
pub fn short(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && !(1e-2..1e4).contains(&a) {
        format!("{v:.1e}")
    } else if a >= 100.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.2}")
    }
}

fn labels(b: [f64; 2]) -> Vec<Span<'static>> {
    vec![
        Span::raw(short(b[0])),
        Span::raw(short(0.5 * (b[0] + b[1]))),
        Span::raw(short(b[1])),
    ]
}

const COLORS: [Color; 5] = [
    Color::Cyan,
    Color::Yellow,
    Color::Magenta,
    Color::Green,
    Color::Red,
];
const ASCII_MARKERS: [char; 5] = ['*', '+', 'o', '#', 'x'];

/// What a chart shows besides its lines.
pub struct ChartSpec<'a> {
    pub title: &'a str,
    pub x_title: &'a str,
    /// x bounds; `None` fits the data.
    pub x_bounds: Option<[f64; 2]>,
    /// Whether to draw the x labels (off for stacked charts but the last).
    pub x_labels: bool,
}

/// Draws `series` as a line chart with axes, labels and a legend.
pub fn draw(frame: &mut Frame, area: Rect, look: Look, spec: &ChartSpec, series: &[Series]) {
    let xb = spec.x_bounds.unwrap_or_else(|| bounds(series, |p| p.0));
    let yb = bounds(series, |p| p.1);
    let datasets: Vec<Dataset> = series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let marker = if look.ascii {
                Marker::Custom(ASCII_MARKERS[i % ASCII_MARKERS.len()])
            } else {
                Marker::Braille
            };
            let style = if look.color {
                Style::new().fg(COLORS[i % COLORS.len()])
            } else {
                Style::new()
            };
            Dataset::default()
                .name(s.name.clone())
                .marker(marker)
                .graph_type(GraphType::Line)
                .style(style)
                .data(&s.points)
        })
        .collect();
    let mut x_axis = Axis::default().bounds(xb);
    if spec.x_labels {
        x_axis = x_axis.labels(labels(xb)).title(spec.x_title.to_string());
    }
    // A legend box needs room; in a short chart the names go in the title instead.
    let roomy = area.height >= 12;
    let title = if roomy {
        spec.title.to_string()
    } else {
        let names: Vec<&str> = series.iter().map(|s| s.name.as_str()).collect();
        format!("{} [{}]", spec.title, names.join(", "))
    };
    let chart = Chart::new(datasets)
        .block(Block::new().title(title))
        .x_axis(x_axis)
        .y_axis(Axis::default().bounds(yb).labels(labels(yb)))
        .legend_position(roomy.then_some(LegendPosition::TopRight))
        .hidden_legend_constraints((
            ratatui::layout::Constraint::Percentage(60),
            ratatui::layout::Constraint::Percentage(90),
        ));
    frame.render_widget(chart, area);
}
