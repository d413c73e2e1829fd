//! Drawing a [`Figure`] with plotters, on its SVG or its bitmap back end.
//!
//! Layout, top to bottom: the title; the shared legend (one entry per
//! distinct series, then the shaded regions); the panels in a grid (one
//! row of two for two panels, two by two for four); the caption, wrapped.
//! Sizes scale with the canvas, from a 1200 × 900 reference.

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::FigureError;
use super::font::{self, FAMILY};
use super::spec::{Figure, GuideAt, LegendEntry, Panel, Pen, Stroke};
use crate::analysis::spectrum::Region;

/// Smallest and largest canvas side, in pixels.
pub const MIN_SIDE: u32 = 200;
pub const MAX_SIDE: u32 = 10_000;

/// The Okabe–Ito palette (distinguishable with every common colour-vision deficiency).
const PALETTE: [(u8, u8, u8); 6] = [
    (0, 114, 178),
    (213, 94, 0),
    (0, 158, 115),
    (204, 121, 167),
    (230, 159, 0),
    (86, 180, 233),
];

/// The colour of series `index`; dashed series take a darker shade of the
/// same hue, so a curve and its no-pounding twin read as a pair but stay
/// distinct.
pub fn series_color(index: usize, stroke: Stroke) -> RGBColor {
    let (r, g, b) = PALETTE[index % PALETTE.len()];
    match stroke {
        Stroke::Solid => RGBColor(r, g, b),
        Stroke::Dashed => {
            let dark = |c: u8| (f64::from(c) * 0.55).round() as u8;
            RGBColor(dark(r), dark(g), dark(b))
        }
    }
}

/// The grey of a faint series (one record of many).
const FAINT: RGBColor = RGBColor(150, 150, 150);

/// The colour of a guide: its palette colour, else a dark grey.
fn guide_color(color: Option<usize>) -> RGBColor {
    color.map_or(RGBColor(90, 90, 90), |c| series_color(c, Stroke::Solid))
}

/// The fill of a shaded area: a light tint of its palette colour (the
/// dashed shade would turn grey when this light).
fn area_color(color: usize, _stroke: Stroke) -> RGBAColor {
    series_color(color, Stroke::Solid).mix(0.2)
}

/// The shading of a spectral region.
pub fn region_color(region: Region) -> RGBAColor {
    match region {
        Region::Amplification => RGBColor(213, 94, 0).mix(0.16),
        Region::Suppression => RGBColor(0, 114, 178).mix(0.16),
        Region::None => RGBColor(255, 255, 255).mix(0.0),
    }
}

fn draw_error(e: impl std::fmt::Display) -> FigureError {
    FigureError::Draw(e.to_string())
}

/// The figure as an SVG document.
pub fn svg(fig: &Figure, size: (u32, u32)) -> Result<String, FigureError> {
    font::register();
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, size).into_drawing_area();
        draw(&root, fig, false).map_err(draw_error)?;
        root.present().map_err(draw_error)?;
    }
    Ok(buf)
}

/// The figure as PNG bytes.
pub fn png(fig: &Figure, size: (u32, u32)) -> Result<Vec<u8>, FigureError> {
    font::register();
    let (w, h) = size;
    let mut rgb = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
        draw(&root, fig, true).map_err(draw_error)?;
        root.present().map_err(draw_error)?;
    }
    let image =
        image::RgbImage::from_raw(w, h, rgb).ok_or_else(|| draw_error("bitmap size mismatch"))?;
    let mut out = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut out),
            image::ImageOutputFormat::Png,
        )
        .map_err(draw_error)?;
    Ok(out)
}

type Area<DB> = DrawingArea<DB, Shift>;
type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// Font sizes and strokes for one canvas.
struct Look {
    scale: f64,
    /// Draw solid curves segment by segment. The bitmap back end joins a
    /// thick polyline with unbounded miters, so a sharp reversal (an impact
    /// spike) would grow a long false spike; separate segments have none.
    segments: bool,
}

impl Look {
    fn px(&self, v: f64) -> i32 {
        (v * self.scale).round() as i32
    }
    fn font(&self, size: f64) -> TextStyle<'static> {
        TextStyle::from((FAMILY, size * self.scale).into_font()).color(&BLACK)
    }
    fn title(&self) -> TextStyle<'static> {
        TextStyle::from(
            (FAMILY, 22.0 * self.scale)
                .into_font()
                .style(FontStyle::Bold),
        )
        .color(&BLACK)
    }
}

/// Splits `text` into lines no wider than `width` pixels.
fn wrap<DB: DrawingBackend>(
    area: &Area<DB>,
    text: &str,
    style: &TextStyle,
    width: f64,
) -> Result<Vec<String>, DrawingAreaErrorKind<DB::ErrorType>> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let candidate = if line.is_empty() {
            word.to_string()
        } else {
            format!("{line} {word}")
        };
        if !line.is_empty() && f64::from(area.estimate_text_size(&candidate, style)?.0) > width {
            lines.push(std::mem::replace(&mut line, word.to_string()));
        } else {
            line = candidate;
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    Ok(lines)
}

fn draw<DB: DrawingBackend>(root: &Area<DB>, fig: &Figure, segments: bool) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let (w, h) = root.dim_in_pixel();
    let look = Look {
        scale: (f64::from(w) / 1200.0).min(f64::from(h) / 900.0),
        segments,
    };
    let small = look.font(13.0);
    let margin = look.px(12.0);

    let caption = wrap(
        root,
        &fig.caption,
        &small,
        f64::from(w) - 2.0 * f64::from(margin),
    )?;
    let line = look.px(13.0 * 1.4);
    let caption_h = line * caption.len() as i32 + look.px(8.0);
    let title_h = look.px(22.0 * 1.7);
    let legend_rows = legend_layout(root, &fig.legend(), &look, w as i32 - 2 * margin)?;
    let legend_row_h = look.px(15.0 * 1.6);
    let legend_h = legend_row_h * legend_rows.len() as i32 + look.px(4.0);

    let (title_area, rest) = root.split_vertically(title_h);
    let (legend_area, rest) = rest.split_vertically(legend_h);
    let (panels_area, caption_area) =
        rest.split_vertically(h as i32 - title_h - legend_h - caption_h);

    let title_style = look.title().pos(Pos::new(HPos::Center, VPos::Center));
    title_area.draw(&Text::new(
        fig.title.clone(),
        (w as i32 / 2, title_h / 2),
        title_style,
    ))?;

    for (row, entries) in legend_rows.iter().enumerate() {
        let y = legend_row_h * row as i32 + legend_row_h / 2;
        for (entry, x) in entries {
            draw_legend_entry(&legend_area, entry, *x + margin, y, &look)?;
        }
    }

    let grid = match fig.panels.len() {
        0 | 1 => (1, 1),
        2 => (1, 2),
        n => (n.div_ceil(2), 2),
    };
    for (area, panel) in panels_area.split_evenly(grid).iter().zip(&fig.panels) {
        draw_panel(area, panel, &look)?;
    }

    for (i, text) in caption.iter().enumerate() {
        let pos = (margin, look.px(4.0) + line * i as i32);
        caption_area.draw(&Text::new(
            text.clone(),
            pos,
            small.clone().pos(Pos::new(HPos::Left, VPos::Top)),
        ))?;
    }
    Ok(())
}

/// Legend rows: each entry with its x offset, wrapped at `width`.
#[allow(clippy::type_complexity)]
fn legend_layout<DB: DrawingBackend>(
    area: &Area<DB>,
    entries: &[LegendEntry],
    look: &Look,
    width: i32,
) -> Result<Vec<Vec<(LegendEntry, i32)>>, DrawingAreaErrorKind<DB::ErrorType>> {
    let style = look.font(15.0);
    let mut rows: Vec<Vec<(LegendEntry, i32)>> = vec![Vec::new()];
    let mut x = 0;
    for e in entries {
        let entry_w = look.px(44.0) + area.estimate_text_size(&e.label(), &style)?.0 as i32;
        if x > 0 && x + entry_w > width {
            rows.push(Vec::new());
            x = 0;
        }
        if let Some(row) = rows.last_mut() {
            row.push((e.clone(), x));
        }
        x += entry_w + look.px(22.0);
    }
    Ok(rows)
}

fn draw_legend_entry<DB: DrawingBackend>(
    area: &Area<DB>,
    entry: &LegendEntry,
    x: i32,
    y: i32,
    look: &Look,
) -> DrawResult<DB> {
    let sample = [(x, y), (x + look.px(36.0), y)];
    let half = look.px(7.0);
    match entry {
        LegendEntry::Line {
            color,
            stroke,
            line,
            markers,
            ..
        } => {
            let (rgb, width) = match line {
                Some(Pen::Faint) => (FAINT, look.px(1.2).max(1) as u32),
                _ => (series_color(*color, *stroke), look.px(2.5).max(1) as u32),
            };
            let style = rgb.stroke_width(width);
            match (line, stroke) {
                (None, _) => {}
                (Some(_), Stroke::Solid) => area.draw(&PathElement::new(sample.to_vec(), style))?,
                (Some(_), Stroke::Dashed) => area.draw(&DashedPathElement::new(
                    sample,
                    look.px(7.0),
                    look.px(4.0),
                    style,
                ))?,
            }
            if *markers {
                draw_marker(area, (x + look.px(18.0), y), *color, *stroke, look)?;
            }
        }
        LegendEntry::Area { color, stroke, .. } => {
            area.draw(&Rectangle::new(
                [(x, y - half), (x + look.px(36.0), y + half)],
                area_color(*color, *stroke).filled(),
            ))?;
        }
        LegendEntry::Guide { color, .. } => {
            let style = guide_color(*color).stroke_width(look.px(1.5).max(1) as u32);
            area.draw(&DashedPathElement::new(
                sample,
                look.px(3.0),
                look.px(3.0),
                style,
            ))?;
        }
        LegendEntry::Region(r) => {
            area.draw(&Rectangle::new(
                [(x, y - half), (x + look.px(36.0), y + half)],
                region_color(*r).filled(),
            ))?;
        }
    }
    let style = look.font(15.0).pos(Pos::new(HPos::Left, VPos::Center));
    area.draw(&Text::new(entry.label(), (x + look.px(44.0), y), style))
}

/// An observed value: filled for a solid series, hollow for a dashed one,
/// in the shape of its colour (see [`marker`]).
fn draw_marker<DB: DrawingBackend>(
    area: &Area<DB>,
    at: (i32, i32),
    color: usize,
    stroke: Stroke,
    look: &Look,
) -> DrawResult<DB> {
    area.draw(&marker(at, color, stroke, look))
}

/// The marker of palette colour `color`: a circle, a square, a triangle or
/// a diamond, in turn, so that the observed fractions of two series that
/// fall on one point (every record pounds, every record exceeds 1 g) stay
/// both visible, one shape inside or around the other. Sizes are in pixels
/// about the point, whatever the axes.
fn marker<'a, C: Clone + 'a, DB: DrawingBackend + 'a>(
    at: C,
    color: usize,
    stroke: Stroke,
    look: &Look,
) -> DynElement<'a, DB, C> {
    let rgb = series_color(color, stroke);
    let style = match stroke {
        Stroke::Solid => rgb.filled(),
        Stroke::Dashed => rgb.stroke_width(look.px(1.8).max(1) as u32),
    };
    let r = look.px(4.5).max(2);
    let at = EmptyElement::at(at);
    let corners = match color % 4 {
        0 => return (at + Circle::new((0, 0), r, style)).into_dyn(),
        1 => {
            let h = r * 4 / 5;
            vec![(-h, -h), (h, -h), (h, h), (-h, h)]
        }
        2 => {
            let (w, top, base) = (r * 6 / 5, -(r * 6 / 5), r * 4 / 5);
            vec![(0, top), (w, base), (-w, base)]
        }
        _ => {
            let d = r * 6 / 5;
            vec![(0, -d), (d, 0), (0, d), (-d, 0)]
        }
    };
    if style.filled {
        (at + Polygon::new(corners, style)).into_dyn()
    } else {
        let mut closed = corners.clone();
        closed.push(corners[0]);
        (at + PathElement::new(closed, style)).into_dyn()
    }
}

/// The x range (fixed or the data's) and a y range padded by 6 % (from 0
/// when every value is positive and the smallest is near 0).
fn ranges(panel: &Panel) -> ((f64, f64), (f64, f64)) {
    if let (Some(x), Some(y)) = (panel.x_range, panel.y_range) {
        return (x, y);
    }
    let guides = panel.guides.iter().map(|g| match g.at {
        GuideAt::X(x) => (x, f64::NAN),
        GuideAt::Y(y) => (f64::NAN, y),
    });
    let all = || {
        panel
            .series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .chain(panel.areas.iter().flat_map(|a| a.outline.iter().copied()))
            .chain(guides.clone())
            .filter(|(x, y)| x.is_finite() || y.is_finite())
    };
    let (x0, x1) = panel.x_range.unwrap_or_else(|| {
        all()
            .filter(|(x, _)| x.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (x, _)| {
                (a.min(x), b.max(x))
            })
    });
    let (mut y0, mut y1) = all()
        .filter(|(x, y)| (x.is_nan() || (*x >= x0 && *x <= x1)) && y.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (_, y)| {
            (a.min(y), b.max(y))
        });
    if !(y0.is_finite() && y1.is_finite()) {
        (y0, y1) = (0.0, 1.0);
    }
    if y0 >= 0.0 && y0 < 0.3 * y1 {
        y0 = 0.0;
    }
    let pad = if y1 > y0 { 0.06 * (y1 - y0) } else { 1.0 };
    let x = if x1 > x0 {
        (x0, x1)
    } else {
        (x0 - 1.0, x0 + 1.0)
    };
    (x, (if y0 == 0.0 { 0.0 } else { y0 - pad }, y1 + pad))
}

/// A tick value without binary noise (0.30000000000000004 → 0.3).
fn tick(v: &f64) -> String {
    let r = (v * 1e9).round() / 1e9;
    if r == 0.0 { "0".into() } else { format!("{r}") }
}

fn draw_panel<DB: DrawingBackend>(area: &Area<DB>, panel: &Panel, look: &Look) -> DrawResult<DB> {
    let ((x0, x1), (y0, y1)) = ranges(panel);
    let mut chart = ChartBuilder::on(area)
        .margin(look.px(10.0))
        .caption(format!("{} {}", panel.tag, panel.title), look.font(16.0))
        .x_label_area_size(look.px(48.0))
        .y_label_area_size(look.px(72.0))
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_labels(7)
        .y_labels(6)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .label_style(look.font(13.0))
        .axis_desc_style(look.font(15.0))
        .bold_line_style(RGBColor(225, 225, 225))
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    chart.draw_series(
        panel
            .bands
            .iter()
            .map(|b| Rectangle::new([(b.from, y0), (b.to, y1)], region_color(b.region).filled())),
    )?;
    chart.draw_series(panel.cells.iter().map(|c| {
        Rectangle::new(
            [(c.x.0, c.y.0), (c.x.1, c.y.1)],
            region_color(c.region).filled(),
        )
    }))?;
    for a in &panel.areas {
        chart.draw_series(std::iter::once(Polygon::new(
            a.outline.clone(),
            area_color(a.color, a.stroke).filled(),
        )))?;
    }
    draw_guides(&mut chart, panel, look, ((x0, x1), (y0, y1)))?;
    for s in &panel.series {
        let (rgb, width) = match s.pen {
            Pen::Faint => (FAINT, look.px(1.0).max(1) as u32),
            _ => (series_color(s.color, s.stroke), look.px(2.0).max(1) as u32),
        };
        let style = rgb.stroke_width(width);
        let points = s
            .points
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite());
        if s.pen == Pen::Markers {
            let plot = chart.plotting_area();
            for p in points {
                plot.draw(&marker(p, s.color, s.stroke, look))?;
            }
            continue;
        }
        match s.stroke {
            Stroke::Solid if look.segments => {
                let points: Vec<(f64, f64)> = points.collect();
                chart.draw_series(
                    points
                        .windows(2)
                        .map(|w| PathElement::new(vec![w[0], w[1]], style)),
                )?;
            }
            Stroke::Solid => {
                chart.draw_series(LineSeries::new(points, style))?;
            }
            Stroke::Dashed => {
                let (dash, space) = match s.pen {
                    Pen::Faint => (look.px(5.0), look.px(4.0)),
                    _ => (look.px(8.0), look.px(5.0)),
                };
                chart.draw_series(DashedLineSeries::new(points, dash, space, style))?;
            }
        }
    }
    Ok(())
}

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The guides of a panel: dashed thin lines across it, each with its tag.
/// Vertical guides' tags stand at the top, right of the line, in the first
/// row where they overlap no tag already placed; horizontal ones' at the
/// left, above the line.
fn draw_guides<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    panel: &Panel,
    look: &Look,
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
) -> DrawResult<DB> {
    let font = look.font(13.0);
    let row_h = look.px(13.0 * 1.35);
    let pad = look.px(4.0);
    // Pixel spans taken by tags, per row.
    let mut rows: Vec<Vec<(i32, i32)>> = Vec::new();
    let mut vertical: Vec<_> = panel
        .guides
        .iter()
        .filter_map(|g| match g.at {
            GuideAt::X(x) if x.is_finite() && x >= x0 && x <= x1 => Some((x, g)),
            _ => None,
        })
        .collect();
    vertical.sort_by(|a, b| a.0.total_cmp(&b.0));
    let area = chart.plotting_area().strip_coord_spec();
    for (x, g) in vertical {
        let style = guide_color(g.color).stroke_width(look.px(1.5).max(1) as u32);
        chart.draw_series(std::iter::once(DashedPathElement::new(
            vec![(x, y0), (x, y1)],
            look.px(3.0),
            look.px(3.0),
            style,
        )))?;
        let (px, top) = chart.backend_coord(&(x, y1));
        let w = area.estimate_text_size(&g.tag, &font)?.0 as i32;
        let (from, to) = (px + pad, px + pad + w);
        let row = match rows
            .iter()
            .position(|r| r.iter().all(|&(a, b)| to + pad < a || from > b + pad))
        {
            Some(i) => i,
            None => {
                rows.push(Vec::new());
                rows.len() - 1
            }
        };
        rows[row].push((from, to));
        let (ox, oy) = area.get_base_pixel();
        area.draw(&Text::new(
            g.tag.clone(),
            (from - ox, top - oy + pad + row_h * row as i32),
            font.clone()
                .color(&guide_color(g.color))
                .pos(Pos::new(HPos::Left, VPos::Top)),
        ))?;
    }
    for g in &panel.guides {
        let GuideAt::Y(y) = g.at else { continue };
        if !(y.is_finite() && y >= y0 && y <= y1) {
            continue;
        }
        let style = guide_color(g.color).stroke_width(look.px(1.5).max(1) as u32);
        chart.draw_series(std::iter::once(DashedPathElement::new(
            vec![(x0, y), (x1, y)],
            look.px(3.0),
            look.px(3.0),
            style,
        )))?;
        let (left, py) = chart.backend_coord(&(x0, y));
        let (ox, oy) = area.get_base_pixel();
        area.draw(&Text::new(
            g.tag.clone(),
            (left - ox + pad, py - oy - look.px(2.0)),
            font.clone()
                .color(&guide_color(g.color))
                .pos(Pos::new(HPos::Left, VPos::Bottom)),
        ))?;
    }
    Ok(())
}
