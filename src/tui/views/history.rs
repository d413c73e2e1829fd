//! Scene (t): time histories of the active set — displacements x1, x2 and
//! the contact line x2 + Π_d (contact while x1 is above it, SPEC §4),
//! velocities, and the pounding force f_p — over the visible window, with
//! the cursor.

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
        cursor: app.view.cursor.map(|c| c * u.time),
    }
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
    if gap.is_finite() {
        displacement.push(Series::spans(
            "x2+Π_d",
            palette::CONTACT_LINE,
            spans(h, X2, gap, &u, u.length),
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
    let [a, b, c] = Layout::vertical([
        Constraint::Ratio(1, 3),
        Constraint::Ratio(1, 3),
        Constraint::Ratio(1, 3),
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
        &spec(u.title("f_p", u.force_unit), true),
        &force,
    );
}
