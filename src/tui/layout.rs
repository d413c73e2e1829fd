//! Where each part of the screen goes, as pure geometry of the terminal
//! size: shared by the app (history width, mouse hits) and the drawing.

use ratatui::layout::{Constraint, Layout, Rect};

use super::views::chart::GUTTER;

/// Smallest terminal the explorer draws in; below it, a notice.
pub const MIN_SIZE: (u16, u16) = (60, 20);
/// Width from which the panes also show each parameter's meaning.
pub const WIDE: u16 = 110;

/// The regions of the screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Areas {
    pub header: Rect,
    pub panes: Rect,
    pub info: Rect,
    pub scene: Rect,
    pub summary: Rect,
    pub footer: Rect,
}

/// Width of the parameter panes for a terminal this wide.
pub fn panes_width(columns: u16) -> u16 {
    if columns >= WIDE { 56 } else { 31 }
}

/// Splits the screen: header, panes (`rows` parameter rows) and info on
/// the left, the scene on the right, two summary lines and a footer.
pub fn areas(area: Rect, rows: usize) -> Areas {
    let [header, main, summary, footer] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Min(0),
        Constraint::Length(2),
        Constraint::Length(1),
    ])
    .areas(area);
    let [left, scene] = Layout::horizontal([
        Constraint::Length(panes_width(area.width)),
        Constraint::Min(0),
    ])
    .areas(main);
    // One row per parameter, a header and two borders; the info box keeps
    // its lines (status, errors, range) and the panes scroll when short.
    let [panes, info] = Layout::vertical([
        Constraint::Max(rows as u16 + 3),
        Constraint::Min(INFO_LINES),
    ])
    .areas(left);
    Areas {
        header,
        panes,
        info,
        scene,
        summary,
        footer,
    }
}

/// The scene area for a terminal of `size`.
pub fn scene(size: (u16, u16)) -> Rect {
    areas(Rect::new(0, 0, size.0, size.1), 0).scene
}

/// Plotting width, in columns, of a full-width chart of the scene.
pub fn chart_columns(size: (u16, u16)) -> u16 {
    scene(size).width.saturating_sub(GUTTER).max(1)
}

/// Lines the info box keeps under the panes.
pub const INFO_LINES: u16 = 4;

/// Parameter rows visible in a pane of `height` (border, header, border).
pub fn visible_rows(height: u16) -> usize {
    usize::from(height.saturating_sub(3)).max(1)
}

/// The first row shown when `selected` must be visible among `visible` rows.
pub fn pane_offset(visible: usize, selected: usize) -> usize {
    (selected + 1).saturating_sub(visible)
}

/// The parameter pane row under a click: (set, row).
pub fn pane_hit(
    size: (u16, u16),
    rows: usize,
    selected: usize,
    column: u16,
    row: u16,
) -> Option<(usize, usize)> {
    let a = areas(Rect::new(0, 0, size.0, size.1), rows);
    let first = a.panes.y + 2; // border, header
    let offset = pane_offset(visible_rows(a.panes.height), selected);
    let index = row.checked_sub(first)? as usize + offset;
    if index >= rows || row >= a.panes.bottom() || column <= a.panes.x || column >= a.panes.right()
    {
        return None;
    }
    // The two value columns are the last 2 × 10 columns inside the border.
    let values = a.panes.right().saturating_sub(1 + 2 * 10);
    let set = usize::from(column >= values + 10);
    Some((set, index))
}

/// Where a click in the scene falls along a full-width time axis, as a
/// fraction 0..1 of the plot width; `None` outside the plot.
pub fn time_fraction(size: (u16, u16), column: u16, row: u16) -> Option<f64> {
    let s = scene(size);
    let left = s.x + GUTTER;
    if row < s.y || row >= s.bottom() || column < left || column >= s.right() {
        return None;
    }
    Some((f64::from(column - left) + 0.5) / f64::from(s.right() - left))
}
