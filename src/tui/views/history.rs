//! Scene (t): time histories of the active set — displacements x1, x2,
//! their difference x1 − x2 against the gap Π_d (contact while it is
//! above, SPEC §4; its peak in a run without contact is Π_d,min, SPEC §11),
//! velocities, the pounding force f_p, and the ground acceleration g(τ)
//! that drives them (SPEC §9: sin τ for the sine, the pulse or the record)
//! — over the visible window, with the cursor.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, ChartSpec, Series};
use super::units::Units;
use crate::solver::observer::CHANNEL_NAMES;
use crate::tui::app::App;
use crate::tui::look::palette;
use crate::tui::trace::Trace;
use crate::tui::worker::Slot;

/// Channel indices of [`CHANNEL_NAMES`].
pub const X1: usize = 0;
pub const V1: usize = 1;
pub const X2: usize = 3;
pub const V2: usize = 4;
pub const FS1: usize = 6;
pub const FS2: usize = 7;
pub const FP: usize = 8;
const _: () = assert!(CHANNEL_NAMES.len() == 9);

/// A channel of a trace as chart spans in the given units.
pub fn spans(h: &Trace, channel: usize, offset: f64, u: &Units, k: f64) -> Vec<(f64, f64, f64)> {
    Units::scale_spans(h.spans(channel, offset), u.time, k)
}

/// The x range and cursor of a time chart.
pub fn time_spec(app: &App, u: &Units, tau_end: f64, title: String, x_labels: bool) -> ChartSpec {
    let [a, b] = app.view.window(tau_end);
    ChartSpec {
        title,
        x_title: u.time_axis.to_string(),
        x_bounds: Some([a * u.time, b * u.time]),
        y_range: None,
        x_labels,
        no_legend: false,
        cursor: app.view.cursor.map(|c| c * u.time),
    }
}

/// Ground acceleration g(τ) over `[a, b]` as one (τ, min, max) span per
/// bucket, from several samples of each, so that a record's peaks between
/// two buckets survive.
pub fn ground_spans(
    p: &crate::model::Params,
    [a, b]: [f64; 2],
    buckets: usize,
) -> Vec<(f64, f64, f64)> {
    const SUB: usize = 8;
    let g = p.ground();
    let n = buckets.max(1);
    let width = (b - a) / n as f64;
    (0..n)
        .map(|i| {
            let t0 = a + i as f64 * width;
            let (lo, hi) = (0..=SUB)
                .map(|k| g.at(t0 + width * k as f64 / SUB as f64))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                    (l.min(v), h.max(v))
                });
            (t0, lo, hi)
        })
        .collect()
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(run) = app.shown(Slot::Set(app.active)) else {
        frame.render_widget("computing…", area);
        return;
    };
    let u = Units::active(app);
    let h = &run.history;
    let gap = run.spec.params.gap;
    let tau_end = run.spec.params.tau_end();
    let mut displacement = vec![
        Series::spans("x1", palette::LEFT, spans(h, X1, 0.0, &u, u.length)),
        Series::spans("x2", palette::RIGHT, spans(h, X2, 0.0, &u, u.length)),
    ];
    displacement.push(Series::spans(
        "x1−x2",
        palette::RELATIVE,
        Units::scale_spans(h.relative_spans(), u.time, u.length),
    ));
    if gap.is_finite() {
        let [a, b] = h.window;
        let level = gap * u.length;
        displacement.push(Series::line(
            "Π_d",
            palette::CONTACT_LINE,
            vec![(a * u.time, level), (b * u.time, level)],
        ));
    }
    let velocity = [
        Series::spans("ẋ1", palette::LEFT, spans(h, V1, 0.0, &u, u.velocity)),
        Series::spans("ẋ2", palette::RIGHT, spans(h, V2, 0.0, &u, u.velocity)),
    ];
    let force = [Series::spans(
        "f_p",
        palette::FORCE,
        spans(h, FP, 0.0, &u, u.force),
    )];
    let window = app.view.window(tau_end);
    let ground = [Series::spans(
        "g",
        palette::GROUND,
        Units::scale_spans(
            ground_spans(&run.spec.params, window, h.slices.len()),
            u.time,
            u.acceleration,
        ),
    )];
    // The ground row is the smallest: its header, two plot rows and the
    // time labels at least.
    let ground_rows = (area.height * 2 / 11).max(chart::MIN_ROWS);
    let [a, b, c, d] = Layout::vertical([
        Constraint::Fill(1),
        Constraint::Fill(1),
        Constraint::Fill(1),
        Constraint::Length(ground_rows),
    ])
    .areas(area);
    let buf = frame.buffer_mut();
    let spec = |title: String, x_labels| time_spec(app, &u, tau_end, title, x_labels);
    chart::draw(
        buf,
        a,
        app.look,
        &spec(u.title("x", u.length_unit), false),
        &displacement,
    );
    chart::draw(
        buf,
        b,
        app.look,
        &spec(u.title("ẋ", u.velocity_unit), false),
        &velocity,
    );
    chart::draw(
        buf,
        c,
        app.look,
        &spec(u.title("f_p", u.force_unit), false),
        &force,
    );
    chart::draw(
        buf,
        d,
        app.look,
        &spec(u.title("g", u.acceleration_unit), true),
        &ground,
    );
}
