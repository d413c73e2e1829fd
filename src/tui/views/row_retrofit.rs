//! A row's retrofits drawn at one instant (SPEC §14): each bumper a thick
//! face on the left building, t·X wide, at each floor it covers; each link
//! a line from its left floor's right edge to its right floor's left edge,
//! coloured by the magnitude of its force F = k_l Δu + c_l|Δv|^α sgn Δv at
//! that instant against the link's peak |F| over the run: grey below a
//! tenth of it, yellow below half, red above. Δu is the trace's at t and
//! Δv the slope of the trace's segment around t. Pure: a function of the
//! row, its run's trace and link peaks, the time and the drawing of the
//! frames.

use ratatui::style::Color;

use crate::model::buildings::Row;
use crate::solver::buildings::RowTrace;

/// What a mark is, for its colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    Bumper,
    /// A link carrying at least half its peak |F|, at least a tenth, or less.
    Heavy,
    Loaded,
    Unloaded,
}

impl Mark {
    pub fn color(self) -> Color {
        match self {
            Mark::Bumper => Color::LightMagenta,
            Mark::Heavy => Color::LightRed,
            Mark::Loaded => Color::Yellow,
            Mark::Unloaded => Color::Gray,
        }
    }

    /// All marks, in the order of their raster series after the frames'.
    pub const ALL: [Mark; 4] = [Mark::Bumper, Mark::Heavy, Mark::Loaded, Mark::Unloaded];

    /// A link's mark at |F| = `force` (N), against its peak `peak` (N).
    pub fn of_link(force: f64, peak: f64) -> Mark {
        let share = if peak > 0.0 { force.abs() / peak } else { 0.0 };
        if share >= 0.5 {
            Mark::Heavy
        } else if share >= 0.1 {
            Mark::Loaded
        } else {
            Mark::Unloaded
        }
    }
}

/// A segment in drawing coordinates, and what it is.
pub type Segment = ((f64, f64), (f64, f64), Mark);

/// u̇ of every floor at t: the slope of the trace's segment around t.
pub fn velocities(trace: &RowTrace, t: f64) -> Vec<f64> {
    let k = trace
        .times
        .partition_point(|&s| s <= t)
        .clamp(1, trace.times.len().max(2) - 1);
    if trace.times.len() < 2 {
        return vec![0.0; trace.dofs];
    }
    let dt = trace.times[k] - trace.times[k - 1];
    trace
        .point(k - 1)
        .iter()
        .zip(trace.point(k))
        .map(|(a, b)| if dt > 0.0 { (b - a) / dt } else { 0.0 })
        .collect()
}

/// Where the frames are drawn: each floor's left edge and elevation
/// (building, floor), the buildings' width, the exaggeration X and the
/// picture's height.
pub struct Frames<'a> {
    pub floor: &'a dyn Fn(usize, usize) -> (f64, f64),
    pub width: f64,
    pub exaggeration: f64,
    pub height: f64,
}

/// The bumpers' and links' segments of `row` at time t over the frames;
/// `peaks` is each link's peak |F| over the run (N).
pub fn segments(
    row: &Row,
    trace: &RowTrace,
    peaks: &[f64],
    t: f64,
    drawing: &Frames,
) -> Vec<Segment> {
    let mut out = Vec::new();
    let x = drawing.exaggeration;
    let thick = 0.01 * drawing.height;
    for e in row.bumper_elements() {
        let p = e.pair;
        let (edge, y) = (drawing.floor)(p.left, p.left_floor);
        let edge = edge + drawing.width;
        let t_drawn = e.thickness.unwrap_or(0.0) * x;
        for dy in [-thick, 0.0, thick] {
            out.push(((edge, y + dy), (edge + t_drawn, y + dy), Mark::Bumper));
        }
    }
    let links = row.link_elements();
    if links.is_empty() {
        return out;
    }
    let u = trace.at(t);
    let v = velocities(trace, t);
    for (k, l) in links.iter().enumerate() {
        let p = l.pair;
        let (a, b) = (p.left_dof, p.right_dof);
        let force = l.force(u[a] - u[b], v[a] - v[b]);
        let mark = Mark::of_link(force, peaks.get(k).copied().unwrap_or(0.0));
        let (xa, ya) = (drawing.floor)(p.left, p.left_floor);
        let (xb, yb) = (drawing.floor)(p.right, p.right_floor);
        out.push(((xa + drawing.width, ya), (xb, yb), mark));
    }
    out
}
