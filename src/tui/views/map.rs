//! Scene (a): the left structure's region (SPEC §7), or its amplification
//! ratio Π_u1/Π_u1,free (key o), over Π_ω1 across and a second parameter
//! down (key y: μ, Π_d, Π_m, Π_e), for the active set. Two map rows per
//! terminal row in colour (half blocks, one half in the foreground colour,
//! the other in the background; see `half_cell`), one row per terminal row in shading
//! characters under NO_COLOR or `--ascii`. A marker sits at the set's own
//! point, the cursor cell is read out below, and rows not yet computed show
//! their nearest computed neighbour, so the coarse picture comes first.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Line;

use super::chart::GUTTER;
use super::ticks;
use crate::analysis::map::MapCell;
use crate::analysis::spectrum::Region;
use crate::model::params::field;
use crate::tui::app::App;
use crate::tui::map_grid::{FRAME_ROWS, own_cell};

/// The symbol of the y axis.
fn y_symbol(key: &str) -> &'static str {
    if key == "mu" {
        "μ"
    } else {
        field(key).map_or("?", |f| f.symbol)
    }
}

/// Amplification-ratio bins: upper bounds, colours and shading characters.
const RATIO_BINS: [(f64, Color, char); 6] = [
    (0.7, Color::Blue, ' '),
    (0.95, Color::Cyan, '-'),
    (1.05, Color::DarkGray, '.'),
    (1.3, Color::Yellow, '+'),
    (2.0, Color::LightRed, '#'),
    (f64::INFINITY, Color::Red, '@'),
];

/// The colour and shading character of a cell.
fn paint(cell: &MapCell, ratio: bool) -> (Color, char) {
    if ratio {
        let r = cell.left_amplification;
        let bin = RATIO_BINS
            .iter()
            .find(|b| r < b.0)
            .unwrap_or(&RATIO_BINS[RATIO_BINS.len() - 1]);
        (bin.1, bin.2)
    } else {
        match cell.region {
            Region::Amplification => (Color::Red, '#'),
            Region::Suppression => (Color::Blue, '+'),
            Region::None => (Color::DarkGray, '.'),
        }
    }
}

/// The legend line.
fn legend(ratio: bool) -> String {
    if ratio {
        "Π_u1/Π_u1,free: ' '<0.7 -<0.95 .≈1 +<1.3 #<2 @≥2".into()
    } else {
        "# amplified  + suppressed  . none  X set".into()
    }
}

/// The legend as coloured spans (colour look).
fn legend_colored(ratio: bool) -> Line<'static> {
    let mut spans = Vec::new();
    let mut item = |color: Color, text: String| {
        spans.push(ratatui::text::Span::styled("██", Style::new().fg(color)));
        spans.push(ratatui::text::Span::raw(format!(" {text}  ")));
    };
    if ratio {
        let mut lo = String::from("<");
        for (bound, color, _) in RATIO_BINS {
            let text = if bound.is_finite() {
                format!("{lo}{bound}")
            } else {
                "≥2".to_string()
            };
            item(color, text);
            lo = String::from("<");
        }
    } else {
        item(Color::Red, "amplified".into());
        item(Color::Blue, "suppressed".into());
        item(Color::DarkGray, "none".into());
    }
    Line::from(spans)
}

/// The readout of one cell.
pub fn readout(cell: &MapCell, y_key: &str) -> String {
    let region = match cell.region {
        Region::Amplification => "amplified",
        Region::Suppression => "suppressed",
        Region::None => "none",
    };
    format!(
        "Π_ω1 {:.2}  {} {:.3}  {region} ×{:.2}  Π_u1 {:.2} (free {:.2})  {} impacts",
        cell.omega1,
        y_symbol(y_key),
        cell.y,
        cell.left_amplification,
        cell.left.peak_displacement,
        cell.free_left.peak_displacement,
        cell.impacts
    )
}

/// Whole items of `text` (split at double spaces) that fit in `width`.
fn fit(text: &str, width: usize) -> String {
    let mut line = String::new();
    for item in text.split("  ") {
        let sep = if line.is_empty() { 0 } else { 2 };
        if line.chars().count() + sep + item.chars().count() > width {
            break;
        }
        if sep > 0 {
            line.push_str("  ");
        }
        line.push_str(item);
    }
    line
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let look = app.look;
    let Some(m) = &app.jobs.map else {
        frame.render_widget(look.text("map: μ undefined (Π_ω1 = 0)"), area);
        return;
    };
    if area.height <= FRAME_ROWS || area.width <= GUTTER + 2 {
        return;
    }
    let key = m.spec.plan.y.key;
    let ratio = app.view.map_ratio;
    let (nx, ny) = (m.spec.columns(), m.spec.rows());
    let progress = if m.done() < m.cells.len() {
        format!(" {}%", 100 * m.done() / m.cells.len().max(1))
    } else {
        String::new()
    };
    let what = if ratio {
        "Π_u1/Π_u1,free"
    } else {
        "left region"
    };
    let title = format!(
        "{what} over Π_ω1 × {}{progress}  (y: axis, o: {})",
        y_symbol(key),
        if ratio { "region" } else { "ratio" }
    );
    let buf = frame.buffer_mut();
    let right = area.right();
    put(
        buf,
        area.x,
        area.y,
        &fit(&look.text(&title), area.width as usize),
        right,
    );
    if let Some(e) = &m.error {
        put(buf, area.x, area.y + 1, &look.text(e), right);
        return;
    }
    let plot = Rect {
        x: area.x + GUTTER,
        y: area.y + 1,
        width: (area.width - GUTTER).min(nx as u16),
        height: area.height - FRAME_ROWS,
    };
    let half = look.color && !look.ascii;
    let per_row = if half { 2 } else { 1 };
    // Map row (from the lowest y) drawn at terminal row `r`, half `h`.
    let map_row = |r: u16, h: usize| -> Option<usize> {
        let from_top = usize::from(r) * per_row + h;
        ny.checked_sub(1 + from_top)
    };
    let own = own_cell(&m.spec, app.active_params());
    let cursor = app
        .view
        .map_cursor
        .map(|(c, r)| (c.min(nx - 1), r.min(ny - 1)))
        .unwrap_or(own);
    for r in 0..plot.height {
        // The colours the terminal has after the cell on the left.
        let mut pen = (Color::Reset, Color::Reset);
        for c in 0..plot.width {
            let col = usize::from(c);
            let top = map_row(r, 0)
                .and_then(|y| m.cell(col, y))
                .map(|x| paint(x, ratio));
            let cell = &mut buf[(plot.x + c, plot.y + r)];
            if half {
                let bottom = map_row(r, 1)
                    .and_then(|y| m.cell(col, y))
                    .map(|x| paint(x, ratio));
                let colour = |p: Option<(Color, char)>| p.map_or(Color::Reset, |p| p.0);
                let (symbol, fg, bg) = half_cell(colour(top), colour(bottom), pen);
                cell.set_symbol(symbol).set_fg(fg).set_bg(bg);
                pen = (if symbol == " " { pen.0 } else { fg }, bg);
            } else {
                cell.set_symbol(&top.map_or(' ', |p| p.1).to_string());
            }
            let here = |x: (usize, usize)| {
                x.0 == col && (map_row(r, 0) == Some(x.1) || (half && map_row(r, 1) == Some(x.1)))
            };
            if here(own) {
                cell.set_symbol(if look.ascii { "X" } else { "◆" });
                if half {
                    cell.set_fg(Color::White);
                }
            }
            if here(cursor) && app.view.map_cursor.is_some() {
                cell.set_style(Style::new().add_modifier(Modifier::REVERSED));
                if matches!(cell.symbol(), " " | "▀" | "▄") {
                    cell.set_symbol("+");
                }
            }
        }
    }
    // The y axis: its name on the top row, tick labels at their rows.
    let axis_x = area.x + GUTTER - 1;
    let ys = m.spec.plan.y.values();
    let (y0, y1) = (ys[0], ys[ys.len() - 1]);
    for r in 0..plot.height {
        buf[(axis_x, plot.y + r)].set_symbol("│");
    }
    let yt = ticks::ticks(y0, y1, (plot.height as usize / 3).max(1), false);
    let rows_span = f64::from(plot.height.saturating_sub(1)).max(1.0);
    let mut used = None;
    for (v, label) in yt.values.iter().zip(&yt.labels) {
        let r = ((y1 - v) / (y1 - y0) * rows_span).round() as u16;
        if r >= plot.height || used == Some(r) {
            continue;
        }
        used = Some(r);
        buf[(axis_x, plot.y + r)].set_symbol("┤");
        let w = label.chars().count().min(ticks::LABEL_WIDTH) as u16;
        put(
            buf,
            area.x + ticks::LABEL_WIDTH as u16 - w,
            plot.y + r,
            label,
            axis_x,
        );
    }
    // The x axis: round Π_ω1 values and the axis names.
    let xr = area.y + 1 + plot.height;
    let xs = m.spec.plan.x.values();
    let (x0, x1) = (xs[0], xs[xs.len() - 1]);
    let names = look.text(&format!(
        "Π_ω1 →  {}{} ↑",
        y_symbol(key),
        ticks::scale_note(yt.exponent)
    ));
    let names_w = names.chars().count() as u16;
    let limit = right.saturating_sub(names_w + 2);
    let xt = ticks::ticks(x0, x1, (plot.width as usize / 9).max(1), false);
    let mut next_free = area.x;
    for (v, label) in xt.values.iter().zip(&xt.labels) {
        let col = ((v - x0) / (x1 - x0) * f64::from(plot.width.saturating_sub(1))).round() as u16;
        let w = label.chars().count() as u16;
        let start = (plot.x + col).saturating_sub(w / 2).max(area.x);
        if start < next_free || start + w > limit {
            continue;
        }
        put(buf, start, xr, label, right);
        next_free = start + w + 2;
    }
    if names_w < area.width {
        put(buf, right - names_w, xr, &names, right);
    }
    let legend_row = xr + 1;
    if look.color && !look.ascii {
        let line = legend_colored(ratio);
        frame.render_widget(line, Rect::new(area.x, legend_row, area.width, 1));
    } else {
        put(
            frame.buffer_mut(),
            area.x,
            legend_row,
            &fit(&look.text(&legend(ratio)), area.width as usize),
            right,
        );
    }
    let text = m
        .cells
        .get(cursor.1 * nx + cursor.0)
        .copied()
        .flatten()
        .map_or_else(|| "cursor cell: computing…".into(), |c| readout(&c, key));
    let label = if app.view.map_cursor.is_some() {
        ""
    } else {
        "set: "
    };
    put(
        frame.buffer_mut(),
        area.x,
        legend_row + 1,
        &fit(&look.text(&format!("{label}{text}")), area.width as usize),
        right,
    );
}

/// One terminal cell of two map rows, `top` over `bottom`, as (symbol,
/// foreground, background), given the colours `pen` the terminal has from
/// the cell on its left. Two equal halves are a blank in the background
/// colour (one byte, and no foreground to set); two different ones an
/// upper half block `▀` or a lower one `▄` with the colours swapped,
/// whichever keeps more of `pen`: the same picture in fewer colour changes.
fn half_cell(top: Color, bottom: Color, pen: (Color, Color)) -> (&'static str, Color, Color) {
    if top == bottom {
        return (" ", Color::Reset, bottom);
    }
    let kept = |fg: Color, bg: Color| usize::from(pen.0 == fg) + usize::from(pen.1 == bg);
    if kept(bottom, top) > kept(top, bottom) {
        ("▄", bottom, top)
    } else {
        ("▀", top, bottom)
    }
}

fn put(buf: &mut ratatui::buffer::Buffer, x: u16, y: u16, text: &str, right: u16) {
    for (col, c) in (x..right).zip(text.chars()) {
        let mut tmp = [0u8; 4];
        buf[(col, y)].set_symbol(c.encode_utf8(&mut tmp));
    }
}
