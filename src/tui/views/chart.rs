//! The explorer's line chart, drawn cell by cell so that every label has its
//! place and none touches another:
//!
//! ```text
//! title [scaling] ×1eN        ── x1  ── x2      <- header: title left, legend right
//!    4┤      ⡠⠊⠉⠢⡀                               <- y labels in a 5-column gutter
//!    0┼┄┄┄┄┄⡜┄┄┄┄┄⢣┄┄┄┄                             zero line where the data is not
//!   -4┤⠊         ⠑                                 cursor: a vertical line
//!     0    10    20    30        τ [2π = 1 cycle]  <- x labels (last chart only), title right
//! ```
//!
//! Ticks are round ([`super::ticks`]). Lines are Braille when colours tell
//! series apart (or there is one series); otherwise each series has its own
//! character marker, shown in the legend, so overlays stay readable under
//! NO_COLOR and `--ascii`. The legend sits in the header row, never over data.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};

use super::raster::Raster;
use super::ticks::{self, LABEL_WIDTH};
use crate::tui::fit::fit;
use crate::tui::look::Look;

/// Columns left of the plot: the tick labels and the axis line.
pub const GUTTER: u16 = LABEL_WIDTH as u16 + 1;

/// Markers of the series when colours cannot tell them apart.
const MARKERS: [char; 5] = ['*', '+', 'o', '#', 'x'];

/// How a series is drawn.
#[derive(Debug, Clone)]
enum Shape {
    /// A polyline through the points.
    Line(Vec<(f64, f64)>),
    /// A vertical span (x, lo, hi) per time bucket, each joined to the next.
    Spans(Vec<(f64, f64, f64)>),
    /// Vertical bars (x, lo, hi), each on its own (a 16–84 % range).
    Bars(Vec<(f64, f64, f64)>),
    /// Points on their own, each drawn as the series' marker character.
    Points(Vec<(f64, f64)>),
}

/// One named series of a chart, in its quantity's fixed colour.
#[derive(Debug, Clone)]
pub struct Series {
    pub name: String,
    pub color: Color,
    /// Its own marker without colours (else the chart's, by position).
    marker: Option<char>,
    shape: Shape,
    /// Whether the legend names it (a range drawn beside its median is not).
    listed: bool,
}

impl Series {
    pub fn line(name: impl Into<String>, color: Color, points: Vec<(f64, f64)>) -> Series {
        Series {
            name: name.into(),
            color,
            marker: None,
            shape: Shape::Line(points),
            listed: true,
        }
    }

    /// Vertical bars (x, lo, hi), not joined.
    pub fn bars(name: impl Into<String>, color: Color, bars: Vec<(f64, f64, f64)>) -> Series {
        Series {
            name: name.into(),
            color,
            marker: None,
            shape: Shape::Bars(bars),
            listed: true,
        }
    }

    /// Points drawn as `marker`, in colour or not.
    pub fn points(
        name: impl Into<String>,
        color: Color,
        marker: char,
        points: Vec<(f64, f64)>,
    ) -> Series {
        Series {
            name: name.into(),
            color,
            marker: Some(marker),
            shape: Shape::Points(points),
            listed: true,
        }
    }

    /// The same series left out of the legend.
    pub fn unlisted(mut self) -> Series {
        self.listed = false;
        self
    }

    /// The same series with a fixed marker for charts without colours.
    pub fn marked(mut self, marker: char) -> Series {
        self.marker = Some(marker);
        self
    }

    fn marker(&self, index: usize) -> char {
        self.marker.unwrap_or(MARKERS[index % MARKERS.len()])
    }

    pub fn spans(name: impl Into<String>, color: Color, spans: Vec<(f64, f64, f64)>) -> Series {
        Series {
            name: name.into(),
            color,
            marker: None,
            shape: Shape::Spans(spans),
            listed: true,
        }
    }

    fn values(&self) -> Box<dyn Iterator<Item = (f64, f64)> + '_> {
        match &self.shape {
            Shape::Line(p) | Shape::Points(p) => Box::new(p.iter().copied()),
            Shape::Spans(s) | Shape::Bars(s) => {
                Box::new(s.iter().flat_map(|&(x, a, b)| [(x, a), (x, b)]))
            }
        }
    }
}

/// The range of `pick` over all finite points; `None` without any.
pub fn data_range(series: &[Series], pick: impl Fn((f64, f64)) -> f64) -> Option<[f64; 2]> {
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.values())
        .map(pick)
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    lo.is_finite().then_some([lo, hi])
}

/// What a chart shows besides its series.
#[derive(Debug, Clone, Default)]
pub struct ChartSpec {
    /// The quantity and its scaling, e.g. `x [a_p/ω_p²]`.
    pub title: String,
    /// The x axis name and scaling, drawn right of the x labels.
    pub x_title: String,
    /// x range; `None` fits the data.
    pub x_bounds: Option<[f64; 2]>,
    /// y range before snapping to round ticks; `None` fits the data (a
    /// common scale passes the same range to several charts).
    pub y_range: Option<[f64; 2]>,
    /// Whether this chart draws the x labels (the last of a stack does).
    pub x_labels: bool,
    /// A vertical line at this x (the cursor, or the current Π_ω1).
    pub cursor: Option<f64>,
    /// No legend in the header (the scene draws one for several charts).
    pub no_legend: bool,
}

/// Rows a chart needs at least: header, two plot rows, x labels.
pub const MIN_ROWS: u16 = 4;

/// The plot's cells in `area` (for mouse hits and the history's width).
pub fn plot_area(area: Rect, x_labels: bool) -> Rect {
    let labels = u16::from(x_labels);
    Rect {
        x: area.x + GUTTER.min(area.width),
        y: area.y + 1.min(area.height),
        width: area.width.saturating_sub(GUTTER),
        height: area.height.saturating_sub(1 + labels),
    }
}

/// Writes `text` from column `x` of row `y`, stopping before `right`;
/// the column after it.
pub fn put(buf: &mut Buffer, x: u16, y: u16, text: &str, style: Style, right: u16) -> u16 {
    let mut col = x;
    for c in text.chars() {
        if col >= right {
            break;
        }
        let mut tmp = [0u8; 4];
        buf[(col, y)]
            .set_symbol(c.encode_utf8(&mut tmp))
            .set_style(style);
        col += 1;
    }
    col
}

fn width(s: &str) -> u16 {
    s.chars().count() as u16
}

/// Draws one series into the raster, as series `index`.
fn trace(raster: &mut Raster, s: &Series, index: usize) {
    match &s.shape {
        Shape::Line(points) => {
            if points.len() == 1 {
                raster.segment(points[0], points[0], index);
            }
            for w in points.windows(2) {
                raster.segment(w[0], w[1], index);
            }
        }
        Shape::Spans(spans) => {
            let mut previous: Option<(f64, f64, f64)> = None;
            for &(x, lo, hi) in spans {
                // Join to the previous bucket so the trace is continuous.
                let (a, b) = match previous {
                    Some((_, plo, phi)) => (lo.min(phi), hi.max(plo)),
                    None => (lo, hi),
                };
                raster.segment((x, a), (x, b), index);
                previous = Some((x, lo, hi));
            }
        }
        Shape::Bars(bars) => {
            for &(x, lo, hi) in bars {
                raster.segment((x, lo), (x, hi), index);
            }
        }
        Shape::Points(points) => {
            for &p in points {
                raster.segment(p, p, index);
            }
        }
    }
}

/// Draws `series` into `area` with the labels laid out by the rules above.
pub fn draw(buf: &mut Buffer, area: Rect, look: Look, spec: &ChartSpec, series: &[Series]) {
    let area = area.intersection(buf.area);
    if area.height == 0 || area.width == 0 {
        return;
    }
    let braille = !look.ascii && (look.color || series.len() <= 1);
    let plot = plot_area(area, spec.x_labels);
    let axis = Style::new().fg(Color::Reset);
    let x_range = spec
        .x_bounds
        .or_else(|| data_range(series, |p| p.0))
        .unwrap_or([0.0, 1.0]);
    let x_range = if x_range[1] > x_range[0] {
        x_range
    } else {
        [x_range[0] - 0.5, x_range[0] + 0.5]
    };
    let y_data = spec
        .y_range
        .or_else(|| data_range(series, |p| p.1))
        .unwrap_or([0.0, 1.0]);
    // Two intervals at least: one would round the step up to the whole
    // span, and a short chart would read twice its data's range.
    let y_count = (plot.height as usize / 2).max(2);
    let yt = ticks::ticks(y_data[0], y_data[1], y_count, true);
    let xt = ticks::ticks(
        x_range[0],
        x_range[1],
        (plot.width as usize / 9).max(1),
        false,
    );

    let title = look.text(&format!("{}{}", spec.title, ticks::scale_note(yt.exponent)));
    let entries = if spec.no_legend {
        Vec::new()
    } else {
        legend(look, series, braille)
    };
    let short_title = look.text(&format!(
        "{}{}",
        without_scaling(&spec.title),
        ticks::scale_note(yt.exponent)
    ));
    let rows = header(buf, area, &title, &short_title, &entries);
    let mut plot = plot;
    if rows == 2 {
        plot.y += 1;
        plot.height = plot.height.saturating_sub(1);
    }
    if plot.width < 2 || plot.height < 1 {
        return;
    }

    let mut raster = Raster::new(plot, braille, x_range, yt.bounds);
    for (i, s) in series.iter().enumerate() {
        trace(&mut raster, s, i);
    }
    // Data cells, each in its series' colour (the blanks between them are
    // sent in whatever colour is set: the terminal backend sees to that). A
    // cell that several series cross takes the colour of the last one drawn,
    // or, in colour, that of the cell on its left when one of them has it: a
    // trace keeps its colour through a crossing, and the terminal changes
    // colour where the series change, not at every shared cell.
    let plain = Style::new().fg(Color::Reset).bg(Color::Reset);
    for r in 0..raster.rows {
        let mut left: Option<Color> = None;
        for c in 0..raster.cols {
            let i = r * raster.cols + c;
            let Some(owner) = raster.owner[i] else {
                continue;
            };
            let point = matches!(series[owner].shape, Shape::Points(_));
            let symbol = if braille && !point {
                char::from_u32(0x2800 + raster.bits[i] as u32).unwrap_or('*')
            } else {
                series[owner].marker(owner)
            };
            let y = plot.y + r as u16;
            let mut tmp = [0u8; 4];
            buf[(plot.x + c as u16, y)].set_symbol(symbol.encode_utf8(&mut tmp));
            if look.color {
                let through = raster.through[i];
                let crossing = |k: usize, s: &Series| {
                    through & 1u64.checked_shl(k as u32).unwrap_or(0) != 0 && Some(s.color) == left
                };
                let color = if series.iter().enumerate().any(|(k, s)| crossing(k, s)) {
                    left.unwrap_or(series[owner].color)
                } else {
                    series[owner].color
                };
                buf[(plot.x + c as u16, y)].set_fg(color);
                left = Some(color);
            }
        }
    }
    let empty = |raster: &Raster, r: usize, c: usize| raster.owner[r * raster.cols + c].is_none();
    // The zero line, where there is no data, and the cursor, in the
    // default colour (a colour of their own would cost a change per cell).
    let zero_row = (yt.bounds[0] < 0.0 && yt.bounds[1] > 0.0).then(|| raster.row(0.0));
    if let Some(r) = zero_row {
        for c in 0..raster.cols {
            if empty(&raster, r, c) {
                buf[(plot.x + c as u16, plot.y + r as u16)]
                    .set_symbol("┄")
                    .set_style(plain);
            }
        }
    }
    if let Some(x) = spec
        .cursor
        .filter(|x| (x_range[0]..=x_range[1]).contains(x))
    {
        let c = raster.col(x);
        for r in 0..raster.rows {
            let cell = &mut buf[(plot.x + c as u16, plot.y + r as u16)];
            if empty(&raster, r, c) || Some(r) == zero_row && cell.symbol() == "┄" {
                cell.set_symbol("│").set_style(plain);
            }
        }
    }
    // The y axis and its labels, one label per row at most.
    let axis_x = area.x + GUTTER - 1;
    if axis_x < area.right() {
        for r in 0..plot.height {
            buf[(axis_x, plot.y + r)].set_symbol("│").set_style(axis);
        }
    }
    // Where two ticks fall in one row, the row shows the one nearest its
    // middle, and the zero row always shows 0 (it carries the zero line).
    let mut chosen: Vec<Option<(f64, &String)>> = vec![None; raster.rows];
    for (v, label) in yt.values.iter().zip(&yt.labels) {
        let r = raster.row(*v);
        let middle = ((r * raster.dy) as f64 + (raster.dy as f64 - 1.0) / 2.0).max(0.0);
        let distance = if *v == 0.0 {
            -1.0
        } else {
            (raster.py(*v) - middle).abs()
        };
        if chosen[r].is_none_or(|(d, _)| distance < d) {
            chosen[r] = Some((distance, label));
        }
    }
    for (r, pick) in chosen.iter().enumerate() {
        let Some((_, label)) = pick else {
            continue;
        };
        let y = plot.y + r as u16;
        let mark = if Some(r) == zero_row { "┼" } else { "┤" };
        if axis_x < area.right() {
            buf[(axis_x, y)].set_symbol(mark).set_style(axis);
        }
        let w = width(label).min(LABEL_WIDTH as u16);
        let x = (area.x + LABEL_WIDTH as u16).saturating_sub(w);
        put(buf, x, y, label, Style::new(), axis_x);
    }
    if spec.x_labels {
        x_labels(buf, area, plot, look, spec, &xt, &raster);
    }
}

/// The right end of text in `area`: one blank column is kept before a
/// neighbour (a chart to the right), so labels of two charts never touch.
fn margin(buf: &Buffer, area: Rect) -> u16 {
    if area.right() < buf.area.right() {
        area.right() - 1
    } else {
        area.right()
    }
}

/// The legend entries: a marker sample in the series' colour and the name.
fn legend(look: Look, series: &[Series], braille: bool) -> Vec<(String, String, Style)> {
    series
        .iter()
        .enumerate()
        .filter(|(_, s)| s.listed)
        .map(|(i, s)| {
            let point = matches!(s.shape, Shape::Points(_));
            let sample = if braille && !point {
                "──".to_string()
            } else {
                s.marker(i).to_string().repeat(2)
            };
            let style = if look.color {
                Style::new().fg(s.color)
            } else {
                Style::new()
            };
            (sample, format!(" {}", look.text(&s.name)), style)
        })
        .collect()
}

fn legend_width(entries: &[(String, String, Style)], compact: bool) -> u16 {
    let (sample, gap) = if compact { (1, 1) } else { (2, 2) };
    let w: u16 = entries
        .iter()
        .map(|(_, name, _)| sample + width(name))
        .sum();
    w + gap * entries.len().saturating_sub(1) as u16
}

/// The header: the title left and the legend right on one row, or the
/// legend on a second row when both do not fit and the chart is tall
/// enough. Where they still do not fit, the legend closes up (a one-cell
/// sample, one space between entries), then the title gives up its scaling
/// (`short_title`, kept where the chart is wide enough for it), and a title
/// wider than the chart ends with "…" after its last whole word; entries that
/// still do not fit are left out rather than drawn over each other. Returns
/// the rows used.
fn header(
    buf: &mut Buffer,
    area: Rect,
    title: &str,
    short_title: &str,
    entries: &[(String, String, Style)],
) -> u16 {
    let right = margin(buf, area);
    let second_row = area.height >= 7;
    // Where the legend goes after `title`, and how many of its entries fit there.
    let place = |title: &str, compact: bool| {
        let end = area.x + width(title);
        let one_row = end + 2 + legend_width(entries, compact) <= right;
        let (row, left) = if one_row || !second_row {
            (area.y, end + 2)
        } else {
            (area.y + 1, area.x + GUTTER)
        };
        let mut fitting = 0;
        while fitting < entries.len() && left + legend_width(&entries[..=fitting], compact) <= right
        {
            fitting += 1;
        }
        (row, fitting)
    };
    // The first layout that shows the most entries, and its whole title.
    let score = |t: &str, c: bool| (place(t, c).1, area.x + width(t) <= right);
    let layouts = [(title, false), (title, true), (short_title, true)];
    let best = layouts.iter().map(|(t, c)| score(t, *c)).max();
    let (title, compact) = layouts
        .into_iter()
        .find(|(t, c)| Some(score(t, *c)) == best)
        .unwrap_or((title, false));
    // A title wider than the chart even without its scaling gives up whole
    // words and says so.
    let title = fit(title, usize::from(right.saturating_sub(area.x)));
    let title = title.as_str();
    let (row, fitting) = place(title, compact);
    put(buf, area.x, area.y, title, Style::new(), right);
    let mut x = right - legend_width(&entries[..fitting], compact);
    for (k, (sample, name, style)) in entries[..fitting].iter().enumerate() {
        if k > 0 {
            x += if compact { 1 } else { 2 };
        }
        let sample = if compact {
            sample.chars().next().map(String::from).unwrap_or_default()
        } else {
            sample.clone()
        };
        x = put(buf, x, row, &sample, *style, right);
        x = put(buf, x, row, name, Style::new(), right);
    }
    if row == area.y { 1 } else { 2 }
}

/// A title without its bracketed scaling: `x [a_p/ω_p²]` → `x`.
fn without_scaling(title: &str) -> String {
    match (title.find(" ["), title.find(']')) {
        (Some(a), Some(b)) if b > a => format!("{}{}", &title[..a], &title[b + 1..]),
        _ => title.to_string(),
    }
}

fn x_labels(
    buf: &mut Buffer,
    area: Rect,
    plot: Rect,
    look: Look,
    spec: &ChartSpec,
    xt: &ticks::Ticks,
    raster: &Raster,
) {
    let y = area.bottom() - 1;
    let right = margin(buf, area);
    let title = look.text(&format!(
        "{}{}",
        spec.x_title,
        ticks::scale_note(xt.exponent)
    ));
    let tw = width(&title);
    // The labels that fit left of `limit`, at least two spaces apart.
    let place = |limit: u16| {
        let mut placed = Vec::new();
        let mut next_free = area.x;
        for (v, label) in xt.values.iter().zip(&xt.labels) {
            let w = width(label);
            let center = plot.x + raster.col(*v) as u16;
            let start = center.saturating_sub(w / 2).max(area.x);
            if start < next_free || start + w > limit {
                continue;
            }
            placed.push((start, label.clone()));
            next_free = start + w + 2;
        }
        placed
    };
    // The axis title goes right of the labels when a label still fits
    // beside it; otherwise the labels alone.
    let with_title = (tw + 2 < right.saturating_sub(area.x))
        .then(|| place(right - tw - 2))
        .filter(|p| !p.is_empty());
    let placed = match with_title {
        Some(p) => {
            put(buf, right - tw, y, &title, Style::new(), right);
            p
        }
        None => place(right),
    };
    for (start, label) in placed {
        put(buf, start, y, &label, Style::new(), right);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(buf: &Buffer) -> String {
        let mut s = String::new();
        for y in 0..buf.area.height {
            for x in 0..buf.area.width {
                s.push_str(buf[(x, y)].symbol());
            }
            s.push('\n');
        }
        s
    }

    #[test]
    fn labels_legend_and_zero_line_have_their_places() {
        let area = Rect::new(0, 0, 40, 8);
        let mut buf = Buffer::empty(area);
        let look = Look {
            ascii: false,
            color: false,
        };
        let s = [
            Series::line("x1", Color::Cyan, vec![(0.0, -2.93), (50.0, 3.2)]),
            Series::line("x2", Color::Yellow, vec![(0.0, 1.0), (50.0, -1.0)]),
        ];
        let spec = ChartSpec {
            title: "x [l]".into(),
            x_title: "τ".into(),
            x_bounds: Some([0.0, 50.0]),
            x_labels: true,
            ..Default::default()
        };
        draw(&mut buf, area, look, &spec, &s);
        let t = text(&buf);
        let lines: Vec<&str> = t.lines().collect();
        assert!(lines[0].starts_with("x [l]"), "{t}");
        assert!(lines[0].ends_with("** x1  ++ x2"), "{t}");
        assert!(t.contains("0┼"), "{t}");
        assert!(lines[7].starts_with("      0"), "{t}");
        assert!(lines[7].ends_with("τ"), "{t}");
    }

    /// In a narrow chart the legend closes up, then the title gives up its
    /// scaling, before any entry is left out; a title with no legend beside
    /// it keeps its scaling, and one that would be cut gives it up.
    #[test]
    fn a_narrow_header_closes_up_before_it_leaves_an_entry_out() {
        let look = Look {
            ascii: false,
            color: false,
        };
        let four = [
            Series::line("x1", Color::Cyan, vec![(0.0, -2.0), (50.0, 3.0)]),
            Series::line("x2", Color::Yellow, vec![(0.0, 1.0), (50.0, -1.0)]),
            Series::line("x1−x2", Color::Green, vec![(0.0, 0.0), (50.0, 1.0)]),
            Series::line("Π_d", Color::Red, vec![(0.0, 0.2), (50.0, 0.2)]),
        ];
        let spec = ChartSpec {
            title: "x [a_p/ω_p²]".into(),
            x_title: "τ".into(),
            ..Default::default()
        };
        let first_line = |width: u16, series: &[Series], spec: &ChartSpec| {
            let area = Rect::new(0, 0, width, 4);
            let mut buf = Buffer::empty(area);
            draw(&mut buf, area, look, spec, series);
            text(&buf).lines().next().unwrap().trim_end().to_string()
        };
        // Wide: the whole title and two-cell samples two spaces apart.
        let wide = first_line(60, &four, &spec);
        assert!(
            wide.starts_with("x [a_p/ω_p²]") && wide.ends_with("## Π_d"),
            "{wide}"
        );
        // 29 columns (the 60 × 20 layout): every entry, closed up, title short.
        let narrow = first_line(29, &four, &spec);
        assert_eq!(narrow, "x     * x1 + x2 o x1−x2 # Π_d");
        // No legend: the whole title.
        let spec_alone = ChartSpec {
            no_legend: true,
            ..spec.clone()
        };
        assert_eq!(first_line(14, &four, &spec_alone), "x [a_p/ω_p²]");
        // A title that would be cut gives up its scaling instead.
        let cut = first_line(12, &four[..1], &spec);
        assert!(cut.starts_with("x ") && !cut.contains('['), "{cut}");
    }
}
