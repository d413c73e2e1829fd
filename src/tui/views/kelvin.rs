//! Scene (v): the active set under both contact elements (SPEC §4): the
//! pounding force (the Kelvin element pulls before separation, f_p < 0) and
//! the left displacement, overlaid, each element in its own fixed colour.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, Series};
use super::history::{FP, X1, spans, time_spec};
use super::units::Units;
use crate::tui::app::App;
use crate::tui::look::model_color;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let mut runs: Vec<_> = [Slot::Set(app.active), Slot::Twin]
        .into_iter()
        .filter_map(|s| app.shown(s))
        .collect();
    if runs.is_empty() {
        frame.render_widget("computing…", area);
        return;
    }
    // Improved Kelvin first, whichever is the set's own: the order and
    // colours do not change when `m` is pressed.
    runs.sort_by_key(|r| r.spec.params.model.name() != "improved-kelvin");
    let u = Units::active(app);
    let name = |r: &crate::tui::worker::RunOutput| match r.spec.params.model.name() {
        "kelvin" => "Kelvin",
        _ => "improved",
    };
    let series = |channel: usize, k: f64| -> Vec<Series> {
        runs.iter()
            .map(|r| {
                Series::spans(
                    name(r),
                    model_color(r.spec.params.model),
                    spans(&r.history, channel, 0.0, &u, k),
                )
            })
            .collect()
    };
    let tau_end = runs[0].spec.params.tau_end();
    let [a, b] = Layout::vertical([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
    let buf = frame.buffer_mut();
    let spec = |title: String, x_labels| time_spec(app, &u, tau_end, title, x_labels);
    chart::draw(
        buf,
        a,
        app.look,
        &spec(u.title("f_p", u.force_unit), false),
        &series(FP, u.force),
    );
    chart::draw(
        buf,
        b,
        app.look,
        &spec(u.title("x1", u.length_unit), true),
        &series(X1, u.length),
    );
}
