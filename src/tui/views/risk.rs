//! Scene (x): the risk of pounding of the active set's buildings over a
//! suite (SPEC §11, §12), in three charts stacked:
//!
//! 1. P(pounding) against the gap d (mm) at the design level: the fraction
//!    of records whose Π_d,min exceeds d, a step line, with the set's own
//!    gap as a vertical line and its probability in the title;
//! 2. the IDA of the left building's peak drift: the median against the
//!    level with its 16–84 % range as bars, with pounding and without contact;
//! 3. the pounding fragility P(pounding | IM = x): the fraction that
//!    pounded at each level (markers) and the fitted lognormal (line), or
//!    why there is no fit.
//!
//! Above them, the suite, the intensity measure and the design level
//! (`[ ]` move it), and, for a set without `[physical]`, the base at which
//! its Π-groups became buildings. Drawn from the state handed to it: the
//! coarse pass first, then the whole suite.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Wrap};

use super::chart::{self, ChartSpec, MIN_ROWS, Series};
use super::compact::num;
use crate::analysis::fragility::{self, Fragility, LevelCount};
use crate::analysis::risk::RiskPicture;
use crate::model::intensity::IntensityMeasure;
use crate::tui::jobs::RiskState;
use crate::tui::look::{Look, palette};

/// The note for a set without `[physical]`, in the words the screen shows.
pub const REFERENCE_NOTE: &str = "buildings from the Π set at a_p 0.5 g, ω_p 2π rad/s, m2 1e6 kg";

/// The marker of the fractions that pounded.
const FRACTION_MARKER: char = 'o';

/// A number in at most 6 characters without trailing zeros: 0.3, 25, 0.12.
fn short(v: f64) -> String {
    let s = num(v);
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The measure as the screen names it: `Sa(0.95 s)` or `PGA`.
pub fn measure_name(m: &IntensityMeasure) -> String {
    match m {
        IntensityMeasure::Pga => "PGA".into(),
        IntensityMeasure::Sa { period } => format!("Sa({period} s)"),
    }
}

/// The first of `titles` that fits in `width` columns (the last otherwise:
/// the chart then ends it with "…").
fn widest_fitting(titles: Vec<String>, width: usize) -> String {
    let last = titles.len().saturating_sub(1);
    titles
        .into_iter()
        .enumerate()
        .find(|(i, t)| t.chars().count() <= width || *i == last)
        .map(|(_, t)| t)
        .unwrap_or_default()
}

/// The title of the P(pounding) chart: the probability at the set's gap,
/// its count and the gap; shorter where the chart is narrow.
pub fn probability_title(p: &RiskPicture, width: usize) -> String {
    let (q, k, n) = (p.probability_at_gap(), p.pounded_at_gap(), p.records);
    let d = short(p.gap_m * 1e3);
    widest_fitting(
        vec![
            format!("P(pounding) {q:.2} ({k}/{n}) at d {d} mm"),
            format!("P {q:.2} ({k}/{n}) at d {d} mm"),
        ],
        width,
    )
}

/// The fragility in a few words: θ and β, or why there is no fit.
pub fn fragility_text(f: &Fragility) -> String {
    match *f {
        Fragility::Fitted {
            theta,
            beta,
            extrapolated,
            ..
        } => {
            let outside = if extrapolated { " extrapolated," } else { "" };
            format!("θ {} g{outside} β {:.2}", short(theta), beta)
        }
        Fragility::TooFewRecords => "no fit: under 2 records".into(),
        Fragility::NeverExceeded => "no fit: never pounds".into(),
        Fragility::AlwaysExceeded => "no fit: pounds at every level".into(),
        Fragility::OneLevel { level, .. } => format!("no fit: one level, {} g", short(level)),
        Fragility::Separated { below, above } if below == above => {
            format!("no fit: mixed only at {} g", short(below))
        }
        Fragility::Separated { below, above } => {
            format!("no fit: crossed {}–{} g", short(below), short(above))
        }
        Fragility::NotIncreasing { .. } => "no fit: does not rise".into(),
    }
}

/// `text` broken at spaces into lines of at most `width` characters (a
/// word longer than that on a line of its own, cut).
fn wrapped(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.chars().take(width).collect()),
        }
    }
    lines
}

/// Items joined by "  " as many as fit in `width`, in order.
fn items(parts: &[String], width: usize) -> String {
    let mut out = String::new();
    for p in parts {
        let sep = if out.is_empty() { 0 } else { 2 };
        if out.chars().count() + sep + p.chars().count() > width {
            continue;
        }
        if sep > 0 {
            out.push_str("  ");
        }
        out.push_str(p);
    }
    out
}

/// The line above the charts: design level, measure, suite, progress.
fn info(state: &RiskState, width: usize) -> String {
    let spec = &state.spec;
    let progress = match &state.picture {
        _ if state.error.is_some() => None,
        None => Some("computing…".to_string()),
        Some(_) if state.stale => Some("computing…".to_string()),
        Some(p) if !state.full => Some(format!(
            "first pass: {} records, {} levels",
            p.records,
            p.drift.len()
        )),
        Some(_) => None,
    };
    let mut parts = vec![
        format!("design {} g ([ ])", short(spec.design_level)),
        format!("IM {}", measure_name(&spec.measure)),
    ];
    // A row's joint first (what the picture is of), then the rest.
    if let Some(r) = &spec.row {
        let b = &r.row.buildings;
        parts.push(format!(
            "joint {} {}|{} (y)",
            r.joint + 1,
            b[r.joint].name,
            b[r.joint + 1].name
        ));
    }
    parts.extend(progress);
    parts.push(spec.suite.clone());
    if spec.row.is_none() && !spec.reference {
        parts.push("buildings: preset's [physical]".into());
    }
    items(&parts, width)
}

pub fn render(state: Option<&RiskState>, look: Look, frame: &mut Frame, area: Rect) {
    let Some(state) = state else {
        return;
    };
    let width = area.width as usize;
    // The reference note wraps onto as many lines as it needs, when the
    // charts keep their rows.
    let note = if state.spec.reference {
        wrapped(&look.text(REFERENCE_NOTE), width)
    } else {
        Vec::new()
    };
    let note = if area.height as usize >= 1 + note.len() + 3 * MIN_ROWS as usize {
        note
    } else {
        Vec::new()
    };
    let [info_area, note_area, body] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Length(note.len() as u16),
        Constraint::Min(0),
    ])
    .areas(area);
    frame.render_widget(Line::from(look.text(&info(state, width))), info_area);
    let note: Vec<Line> = note.into_iter().map(Line::from).collect();
    frame.render_widget(Paragraph::new(note), note_area);
    if let Some(e) = &state.error {
        frame.render_widget(
            Paragraph::new(look.text(&format!("no risk picture: {e}"))).wrap(Wrap { trim: true }),
            body,
        );
        return;
    }
    let Some(p) = &state.picture else {
        return;
    };
    let [gap_area, ida_area, fragility_area] = Layout::vertical([
        Constraint::Fill(1),
        Constraint::Fill(1),
        Constraint::Fill(1),
    ])
    .areas(body);
    let buf = frame.buffer_mut();
    draw_probability(buf, gap_area, look, p);
    let levels = LevelCharts {
        look,
        picture: p,
        x_title: format!("{} [g]", measure_name(&state.spec.measure)),
        x_end: p.drift.last().map_or(1.0, |d| d.level),
    };
    levels.draw_drift(buf, ida_area);
    levels.draw_fragility(buf, fragility_area);
}

/// The two charts against the intensity level, from 0 to the highest level.
struct LevelCharts<'a> {
    look: Look,
    picture: &'a RiskPicture,
    /// The measure and its unit.
    x_title: String,
    x_end: f64,
}

/// Chart 1: P(pounding) against the gap (mm) at the design level.
fn draw_probability(buf: &mut ratatui::buffer::Buffer, area: Rect, look: Look, p: &RiskPicture) {
    let largest = p.min_gaps_m.iter().copied().fold(p.gap_m, f64::max);
    let end = if largest > 0.0 && largest.is_finite() {
        1.1 * largest
    } else {
        0.1
    };
    let curve: Vec<(f64, f64)> = p
        .probability_curve(end)
        .into_iter()
        .map(|(d, q)| (d * 1e3, q))
        .collect();
    let spec = ChartSpec {
        title: probability_title(p, area.width as usize),
        x_title: "gap d [mm]".into(),
        x_bounds: Some([0.0, end * 1e3]),
        y_range: Some([0.0, 1.0]),
        x_labels: true,
        cursor: p.gap_m.is_finite().then_some(p.gap_m * 1e3),
        no_legend: true,
    };
    let series = [Series::line("P(pounding)", palette::FORCE, curve)];
    chart::draw(buf, area, look, &spec, &series);
}

impl LevelCharts<'_> {
    /// Chart 2: the left drift's median and 16–84 % range against the level.
    fn draw_drift(&self, buf: &mut ratatui::buffer::Buffer, area: Rect) {
        let (p, x_end) = (self.picture, self.x_end);
        // The ranges sit a little either side of their level, so both show.
        let step = match p.drift.as_slice() {
            [a, b, ..] => b.level - a.level,
            _ => 0.1 * x_end,
        };
        let mm = 1e3;
        let median = |free: bool| {
            p.drift
                .iter()
                .map(|d| {
                    let s = if free { d.free } else { d.pounding };
                    (d.level, s.median * mm)
                })
                .collect()
        };
        let range = |free: bool, shift: f64| {
            p.drift
                .iter()
                .map(|d| {
                    let s = if free { d.free } else { d.pounding };
                    (d.level + shift * step, s.p16 * mm, s.p84 * mm)
                })
                .collect()
        };
        // The ranges first, so that the medians are drawn over them.
        let series = [
            Series::bars("", palette::LEFT, range(false, 0.12))
                .marked(':')
                .unlisted(),
            Series::bars("", palette::FREE, range(true, -0.12))
                .marked('.')
                .unlisted(),
            Series::line("pounding", palette::LEFT, median(false)).marked('*'),
            Series::line("free", palette::FREE, median(true)).marked('+'),
        ];
        let spec = ChartSpec {
            title: format!("{} (16–84 %)", p.drift_title),
            x_title: self.x_title.clone(),
            x_bounds: Some([0.0, x_end]),
            y_range: None,
            x_labels: true,
            cursor: Some(p.design_level),
            no_legend: false,
        };
        chart::draw(buf, area, self.look, &spec, &series);
    }

    /// Chart 3: the fraction that pounded at each level and the fitted fragility.
    fn draw_fragility(&self, buf: &mut ratatui::buffer::Buffer, area: Rect) {
        let (p, x_end) = (self.picture, self.x_end);
        // The fraction of records exceeding at each level, and the fit's curve.
        let fractions = |counts: &[LevelCount]| -> Vec<(f64, f64)> {
            counts
                .iter()
                .filter(|c| c.runs > 0)
                .map(|c| (c.level, c.exceeded as f64 / c.runs as f64))
                .collect()
        };
        let fitted = |f: &Fragility| match *f {
            Fragility::Fitted { theta, beta, .. } => {
                let n = 120;
                Some(
                    (1..=n)
                        .map(|k| {
                            let x = x_end * k as f64 / n as f64;
                            (x, fragility::probability(x, theta, beta))
                        })
                        .collect::<Vec<_>>(),
                )
            }
            _ => None,
        };
        let mut series = Vec::new();
        if let Some(line) = fitted(&p.fragility) {
            let extrapolated = matches!(
                p.fragility,
                Fragility::Fitted {
                    extrapolated: true,
                    ..
                }
            );
            let name = if extrapolated {
                "fit, θ extrapolated"
            } else {
                "fit"
            };
            series.push(Series::line(name, palette::FORCE, line).marked('*'));
        }
        series.push(Series::points(
            "records",
            palette::LEFT,
            FRACTION_MARKER,
            fractions(&p.pounding),
        ));
        let mut titles = vec![
            format!("P(pounding | IM) {}", fragility_text(&p.fragility)),
            fragility_text(&p.fragility),
        ];
        // A row with P-Δ: P(collapse | IM) beside it (SPEC §15).
        if let Some(c) = &p.collapse {
            if let Some(line) = fitted(&c.fragility) {
                series.push(Series::line("collapse fit", palette::RIGHT, line));
            }
            series.push(Series::points(
                "collapsed",
                palette::RIGHT,
                FRACTION_MARKER,
                fractions(&c.counts),
            ));
            // The widest title that fits, keeping collapse in it as long as it can.
            let (pounding, collapse) = (fragility_text(&p.fragility), fragility_text(&c.fragility));
            titles.splice(
                0..0,
                [
                    format!("P(pounding | IM) {pounding}; P(collapse | IM) {collapse}"),
                    format!("pounding {pounding}; collapse {collapse}"),
                    format!("P(collapse | IM) {collapse}"),
                ],
            );
        }
        let spec = ChartSpec {
            title: widest_fitting(titles, area.width as usize),
            x_title: self.x_title.clone(),
            x_bounds: Some([0.0, x_end]),
            y_range: Some([0.0, 1.0]),
            x_labels: true,
            cursor: Some(p.design_level),
            no_legend: false,
        };
        chart::draw(buf, area, self.look, &spec, &series);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_median_outside_the_levels_says_so_in_the_scene() {
        let fit = |extrapolated| Fragility::Fitted {
            theta: 1.8,
            beta: 0.41,
            log_likelihood: -3.0,
            extrapolated,
        };
        assert_eq!(fragility_text(&fit(true)), "θ 1.8 g extrapolated, β 0.41");
        assert_eq!(fragility_text(&fit(false)), "θ 1.8 g β 0.41");
    }
}
