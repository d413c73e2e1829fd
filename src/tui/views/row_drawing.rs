//! The row drawn at one instant (SPEC §13): each building a shear frame of
//! Braille lines, its floors at their true elevations and moved sideways by
//! their displacement u_i(t) times the exaggeration X; joints open by d·X
//! at rest, so floors drawn touching are floors in contact. Floors in
//! contact at that instant are drawn in the contact colour and marked.
//!
//! Horizontal lengths are metres times X except the buildings' widths,
//! which are schematic (a fraction of the tallest height): the model has no
//! plan dimension. Pure: a function of the row, its run and the time.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};

use super::chart;
use super::raster::Raster;
use super::row_retrofit::Mark;
use crate::model::buildings::Row;
use crate::solver::buildings::{RowRun, RowTrace};
use crate::tui::look::{Look, palette};

/// Width of every building drawn, as a fraction of the tallest height.
pub const WIDTH: f64 = 0.2;
/// Largest sway drawn, as a fraction of a building's width, when X is automatic.
pub const SWAY: f64 = 0.5;
/// Space between buildings whose joint never closes (d = ∞), in widths.
const OPEN_JOINT: f64 = 0.4;

/// Colours of the buildings, left to right.
pub const COLORS: [Color; 5] = [
    palette::LEFT,
    palette::RIGHT,
    Color::LightGreen,
    Color::LightBlue,
    Color::LightRed,
];

/// One building at the instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    pub name: String,
    /// Left edge at rest.
    pub rest_left: f64,
    /// Offset u_i·X of floor i, ground (i = 0, offset 0) first.
    pub offsets: Vec<f64>,
    /// Elevation of floor i (m), ground first.
    pub elevations: Vec<f64>,
    /// Whether floor i is in contact with a neighbour's, ground first.
    pub contact: Vec<bool>,
}

/// The row at one instant, in drawing coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct Drawing {
    pub frames: Vec<Outline>,
    /// Width of every building drawn.
    pub width: f64,
    pub exaggeration: f64,
    /// Horizontal and vertical bounds of the picture.
    pub x: [f64; 2],
    pub y: [f64; 2],
    /// Each joint's gap at rest (m) and the middle of its opening.
    pub joints: Vec<(f64, f64)>,
    /// The bumpers and links (SPEC §14, [`super::row_retrofit`]).
    pub retrofits: Vec<super::row_retrofit::Segment>,
}

impl Drawing {
    /// Where floor `floor` (0: ground) of building `b` is drawn: its left
    /// edge and its elevation.
    pub fn floor(&self, b: usize, floor: usize) -> (f64, f64) {
        let f = &self.frames[b];
        (f.rest_left + f.offsets[floor], f.elevations[floor])
    }
}

/// The nearest of 1, 2 and 5 times a power of ten to `x`, on a log scale.
fn round_125(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .min_by(|a, b| (x / a).ln().abs().total_cmp(&(x / b).ln().abs()))
        .unwrap_or(p)
}

/// Tallest building (m).
fn tallest(row: &Row) -> f64 {
    row.buildings
        .iter()
        .map(|b| b.elevation(b.storeys()))
        .fold(0.0, f64::max)
}

/// The exaggeration that draws the largest peak displacement of `run` as
/// [`SWAY`] of a building's width, rounded to 1, 2 or 5 × 10ⁿ.
pub fn automatic(row: &Row, run: &RowRun) -> f64 {
    let peak = run
        .floors
        .iter()
        .flatten()
        .map(|f| f.displacement)
        .fold(0.0, f64::max);
    round_125(SWAY * WIDTH * tallest(row) / peak)
}

/// Whether each floor pair is in contact at `t`: inside one of its impacts.
pub fn contacts_at(run: &RowRun, t: f64) -> Vec<bool> {
    run.pairs
        .iter()
        .map(|p| {
            p.impacts
                .iter()
                .any(|i| i.start <= t && (i.end.is_nan() || t <= i.end))
        })
        .collect()
}

/// The row of `run` at time `t`, displacements times `exaggeration`.
pub fn geometry(row: &Row, run: &RowRun, trace: &RowTrace, t: f64, exaggeration: f64) -> Drawing {
    let u = trace.at(t);
    let width = WIDTH * tallest(row);
    let offsets = row.offsets();
    let mut contact: Vec<Vec<bool>> = row
        .buildings
        .iter()
        .map(|b| vec![false; b.storeys() + 1])
        .collect();
    for (pair, &on) in row.pairs().iter().zip(&contacts_at(run, t)) {
        if on {
            contact[pair.left][pair.left_floor] = true;
            contact[pair.right][pair.right_floor] = true;
        }
    }
    let mut frames = Vec::new();
    let mut joints = Vec::new();
    let mut left = 0.0;
    for (k, b) in row.buildings.iter().enumerate() {
        let mut offs = vec![0.0];
        offs.extend((0..b.storeys()).map(|i| u[offsets[k] + i] * exaggeration));
        let elevations = (0..=b.storeys()).map(|i| b.elevation(i)).collect();
        frames.push(Outline {
            name: b.name.clone(),
            rest_left: left,
            offsets: offs,
            elevations,
            contact: contact[k].clone(),
        });
        left += width;
        if let Some(j) = row.joints.get(k) {
            let opening = if j.gap.is_finite() {
                j.gap * exaggeration
            } else {
                OPEN_JOINT * width
            };
            joints.push((j.gap, left + 0.5 * opening));
            left += opening;
        }
    }
    let margin = 0.45 * width;
    let mut drawing = Drawing {
        frames,
        width,
        exaggeration,
        x: [-margin, left + margin],
        y: [0.0, 1.05 * tallest(row)],
        joints,
        retrofits: Vec::new(),
    };
    let frames = super::row_retrofit::Frames {
        floor: &|b, floor| drawing.floor(b, floor),
        width: drawing.width,
        exaggeration,
        height: drawing.y[1] - drawing.y[0],
    };
    let peaks: Vec<f64> = run.links.iter().map(|l| l.max_force).collect();
    drawing.retrofits = super::row_retrofit::segments(row, trace, &peaks, t, &frames);
    drawing
}

/// The plot's cells in `area`: all but the title row and the name row.
pub fn plot_area(area: Rect) -> Rect {
    Rect {
        x: area.x,
        y: area.y + 1.min(area.height),
        width: area.width,
        height: area.height.saturating_sub(2),
    }
}

/// The raster of `drawing` over `plot`: series k is building k; the
/// contact colour is series `frames.len()`, and the retrofits' marks the
/// series after it, in the order of [`Mark::ALL`].
pub fn raster(drawing: &Drawing, plot: Rect, braille: bool) -> Raster {
    let mut r = Raster::new(plot, braille, drawing.x, drawing.y);
    let contact = drawing.frames.len();
    for (k, f) in drawing.frames.iter().enumerate() {
        let w = drawing.width;
        for i in 1..f.offsets.len() {
            let (x0, y0) = (f.rest_left + f.offsets[i - 1], f.elevations[i - 1]);
            let (x1, y1) = (f.rest_left + f.offsets[i], f.elevations[i]);
            r.segment((x0, y0), (x1, y1), k);
            r.segment((x0 + w, y0), (x1 + w, y1), k);
            let series = if f.contact[i] { contact } else { k };
            r.segment((x1, y1), (x1 + w, y1), series);
        }
    }
    for &(a, b, mark) in &drawing.retrofits {
        let k = Mark::ALL.iter().position(|&m| m == mark).unwrap_or(0);
        r.segment(a, b, contact + 1 + k);
    }
    r
}

/// Draws the row into `area`: a title line, the frames, and under them
/// each building's name and each joint's gap.
pub fn render(buf: &mut Buffer, area: Rect, look: Look, drawing: &Drawing, title: &str) {
    let area = area.intersection(buf.area);
    if area.height < 4 || area.width < 8 {
        return;
    }
    let right = area.right();
    let put = |buf: &mut Buffer, x: u16, y: u16, text: &str, style: Style| {
        chart::put(buf, x, y, &look.text(text), style, right);
    };
    put(buf, area.x, area.y, title, Style::new());
    let plot = plot_area(area);
    let braille = !look.ascii;
    let r = raster(drawing, plot, braille);
    let contact = drawing.frames.len();
    for row in 0..r.rows {
        for col in 0..r.cols {
            let i = row * r.cols + col;
            let Some(owner) = r.owner[i] else {
                continue;
            };
            let symbol = if braille {
                char::from_u32(0x2800 + r.bits[i] as u32).unwrap_or('*')
            } else if owner == contact {
                '#'
            } else {
                '*'
            };
            let color = if owner == contact {
                palette::FORCE
            } else if owner > contact {
                Mark::ALL[(owner - contact - 1).min(Mark::ALL.len() - 1)].color()
            } else {
                COLORS[owner % COLORS.len()]
            };
            let mut tmp = [0u8; 4];
            let cell = &mut buf[(plot.x + col as u16, plot.y + row as u16)];
            cell.set_symbol(symbol.encode_utf8(&mut tmp));
            if look.color {
                cell.set_fg(color);
            }
        }
    }
    // Contacts marked where colour cannot tell them: at the left floor's
    // right edge, a cross in the cell.
    if !look.color {
        for f in drawing.frames.iter().take(drawing.frames.len() - 1) {
            for (i, &on) in f.contact.iter().enumerate() {
                if on {
                    let x = f.rest_left + f.offsets[i] + drawing.width;
                    let (c, rr) = (r.col(x), r.row(f.elevations[i]));
                    buf[(plot.x + c as u16, plot.y + rr as u16)].set_symbol("X");
                }
            }
        }
    }
    // Names under the buildings, then the gaps where they do not overlap a name.
    let names_y = area.bottom() - 1;
    let mut taken: Vec<(u16, u16)> = Vec::new();
    let mut label = |buf: &mut Buffer, at: u16, text: &str, style: Style| {
        let (a, b) = (at, at + text.chars().count() as u16);
        if b > area.right() || taken.iter().any(|&(x, y)| a <= y && x <= b) {
            return;
        }
        taken.push((a, b));
        put(buf, a, names_y, text, style);
    };
    for f in &drawing.frames {
        let c = r.col(f.rest_left) as u16;
        label(buf, plot.x + c, &f.name, Style::new());
    }
    for &(gap, middle) in &drawing.joints {
        let text = if gap.is_finite() {
            format!("{:.0} mm", gap * 1e3)
        } else {
            "open".into()
        };
        let c = (r.col(middle) as u16).saturating_sub(text.len() as u16 / 2);
        let style = Style::new().fg(palette::CONTACT_LINE);
        label(buf, plot.x + c, &text, style);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_exaggerations() {
        assert_eq!(round_125(347.0), 500.0);
        assert_eq!(round_125(280.0), 200.0);
        assert_eq!(round_125(0.9), 1.0);
        assert_eq!(round_125(1000.0), 1000.0);
        assert_eq!(round_125(f64::INFINITY), 1.0);
    }
}

#[cfg(test)]
mod retrofit_tests {
    use super::*;
    use crate::model::buildings::{Ground, load};
    use crate::solver::buildings::{RowOptions, run_row};
    use crate::tui::views::row_retrofit::{Mark, velocities};

    /// Three lines a bumper floor, one a link, the link's colour the share
    /// of its peak that |k_l Δu + c_l Δv| from the trace is; a bare row
    /// draws none.
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
            let share = (4.0e6 * (v[2] - v[5])).abs() / run.links[0].max_force;
            let want = if share >= 0.5 {
                Mark::Heavy
            } else if share >= 0.1 {
                Mark::Loaded
            } else {
                Mark::Unloaded
            };
            assert_eq!(link.2, want, "t = {t}");
            signs.push(link.2);
        }
        assert!(signs.contains(&Mark::Heavy) && signs.len() == 5);
        let bare = load("block-and-frame").unwrap();
        let d = geometry(&bare, &run, trace, 1.0, 50.0);
        assert!(d.retrofits.is_empty());
    }
}
