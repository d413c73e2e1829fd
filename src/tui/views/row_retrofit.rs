//! A row's retrofits drawn at one instant (SPEC §14): each bumper a thick
//! face on the left building, t·X wide, at each floor it covers; each link
//! a line from its left floor's right edge to its right floor's left edge,
//! coloured by the sign of its force F = k_l Δu + c_l|Δv|^α sgn Δv at that
//! instant (compression F > 0, tension F < 0). Δu is the trace's at t and
//! Δv the slope of the trace's segment around t. Pure: a function of the
//! row, its run's trace, the time and the drawing of the frames.

use ratatui::style::Color;

use super::row_drawing::Drawing;
use crate::model::buildings::Row;
use crate::solver::buildings::RowTrace;

/// What a mark is, for its colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    Bumper,
    /// A link in compression (F > 0), in tension (F < 0), or unloaded.
    Compression,
    Tension,
    Unloaded,
}

impl Mark {
    pub fn color(self) -> Color {
        match self {
            Mark::Bumper => Color::LightMagenta,
            Mark::Compression => Color::LightRed,
            Mark::Tension => Color::LightBlue,
            Mark::Unloaded => Color::Gray,
        }
    }

    /// All marks, in the order of their raster series after the frames'.
    pub const ALL: [Mark; 4] = [
        Mark::Bumper,
        Mark::Compression,
        Mark::Tension,
        Mark::Unloaded,
    ];
}

/// A segment in drawing coordinates, and what it is.
pub type Segment = ((f64, f64), (f64, f64), Mark);

/// u̇ of every floor at t: the slope of the trace's segment around t.
fn velocities(trace: &RowTrace, t: f64) -> Vec<f64> {
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

/// The bumpers' and links' segments of `row` at time t over `drawing`.
pub fn segments(row: &Row, trace: &RowTrace, t: f64, drawing: &Drawing) -> Vec<Segment> {
    let mut out = Vec::new();
    let x = drawing.exaggeration;
    let thick = 0.01 * (drawing.y[1] - drawing.y[0]);
    for e in row.bumper_elements() {
        let p = e.pair;
        let (edge, y) = drawing.floor(p.left, p.left_floor);
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
    for l in links {
        let p = l.pair;
        let (a, b) = (p.left_dof, p.right_dof);
        let force = l.force(u[a] - u[b], v[a] - v[b]);
        let mark = if force > 0.0 {
            Mark::Compression
        } else if force < 0.0 {
            Mark::Tension
        } else {
            Mark::Unloaded
        };
        let (xa, ya) = drawing.floor(p.left, p.left_floor);
        let (xb, yb) = drawing.floor(p.right, p.right_floor);
        out.push(((xa + drawing.width, ya), (xb, yb), mark));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::buildings::{Ground, load};
    use crate::solver::buildings::{RowOptions, run_row};
    use crate::tui::views::row_drawing::geometry;

    /// Three lines a bumper floor, one a link, the link's colour the sign
    /// of k_l Δu + c_l Δv from the trace; a bare row draws none.
    #[test]
    fn draws_each_bumper_face_and_each_link_by_its_force() {
        let row = load("block-and-frame-retrofit").unwrap();
        let ground = Ground::sine(3.0, 6.0, 2.0);
        let options = RowOptions {
            trace: true,
            ..RowOptions::lasting(2.0)
        };
        let run = run_row(&row, &ground, &options).unwrap();
        let trace = run.trace.as_ref().unwrap();
        let mut signs = Vec::new();
        for t in [0.3, 0.6, 0.9, 1.2, 1.5] {
            let d = geometry(&row, &run, trace, t, 50.0);
            let bumpers = d.retrofits.iter().filter(|s| s.2 == Mark::Bumper).count();
            assert_eq!(bumpers, 9);
            let link = d.retrofits.last().unwrap();
            assert_ne!(link.2, Mark::Bumper);
            // The link runs from the block's roof edge to the frame's third floor.
            let (xa, ya) = d.floor(0, 3);
            assert_eq!(link.0, (xa + d.width, ya));
            assert_eq!(link.1, d.floor(1, 3));
            let v = velocities(trace, t);
            let f = 4.0e6 * (v[2] - v[5]);
            let want = if f > 0.0 {
                Mark::Compression
            } else {
                Mark::Tension
            };
            assert_eq!(link.2, want, "t = {t}");
            signs.push(link.2);
        }
        assert!(signs.contains(&Mark::Compression) && signs.contains(&Mark::Tension));
        let bare = load("block-and-frame").unwrap();
        let d = geometry(&bare, &run, trace, 1.0, 50.0);
        assert!(d.retrofits.is_empty());
    }
}
