//! The map scene's grid, which the app sizes and the view draws: how many
//! cells fit the scene, the ranges of its axes, and the set's own cell.

use ratatui::layout::Rect;

use crate::model::Params;
use crate::tui::look::Look;
use crate::tui::views::chart::GUTTER;
use crate::tui::worker::MapSpec;

/// The Π_ω1 range across: the spectrum's.
pub const X_RANGE: [f64; 2] = [0.1, 3.0];

/// Rows of the scene that are not map: title, x labels, legend, readout.
pub const FRAME_ROWS: u16 = 4;

/// Most cells a map of the scene has (a tall wide terminal is sampled more coarsely).
const MAX_CELLS: usize = 6000;

/// Map columns and rows for a scene area: one column per plot cell, and one
/// row per terminal row, two with colours (half blocks).
pub fn grid_size(scene: Rect, look: Look) -> (usize, usize) {
    let columns = usize::from(scene.width.saturating_sub(GUTTER)).max(2);
    let per_row = if look.color && !look.ascii { 2 } else { 1 };
    let rows = (usize::from(scene.height.saturating_sub(FRAME_ROWS)) * per_row).max(2);
    let rows = rows.min((MAX_CELLS / columns).max(2));
    (columns, rows)
}

/// The range of the y axis for `key` around the set's own value, so that
/// its point is on the map.
pub fn y_range(key: &str, p: &Params) -> [f64; 2] {
    let own = match key {
        "mu" => p.mu(),
        k => p.get(k).unwrap_or(f64::NAN),
    };
    let own = if own.is_finite() { own } else { f64::NAN };
    let [lo, hi] = match key {
        "mu" => [0.5, 5.0],
        "gap" => [0.0, 1.0],
        "mass_ratio" => [0.1, 3.0],
        _ => [0.05, 0.95],
    };
    if own.is_nan() {
        return [lo, hi];
    }
    [
        lo.min(own),
        hi.max(own * 1.25)
            .min(if key == "restitution" { 1.0 } else { f64::MAX }),
    ]
}

/// The cell of the map nearest to the set's own point (column, row from the lowest y).
pub fn own_cell(spec: &MapSpec, p: &Params) -> (usize, usize) {
    let key = spec.plan.y.key;
    let y = if key == "mu" {
        p.mu()
    } else {
        p.get(key).unwrap_or(0.0)
    };
    (
        index(&spec.plan.x.values(), p.omega1),
        index(&spec.plan.y.values(), y),
    )
}

fn index(values: &[f64], v: f64) -> usize {
    values
        .iter()
        .enumerate()
        .min_by(|a, b| (a.1 - v).abs().total_cmp(&(b.1 - v).abs()))
        .map_or(0, |(i, _)| i)
}
