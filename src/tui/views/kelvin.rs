//! Scene (c): the active set under both contact elements (SPEC §4): the
//! pounding force (the Kelvin element pulls before separation, f_p < 0) and
//! the left displacement, overlaid; the summary lines compare the numbers.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, ChartSpec, FP, Series, X1};
use crate::tui::app::App;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let runs: Vec<_> = [Slot::Set(app.active), Slot::Twin]
        .into_iter()
        .filter_map(|s| app.shown(s))
        .collect();
    if runs.is_empty() {
        frame.render_widget("computing…", area);
        return;
    }
    let name = |r: &crate::tui::worker::RunOutput| r.spec.params.model.name().to_string();
    let force: Vec<Series> = runs
        .iter()
        .map(|r| Series::new(name(r), chart::spans(&r.history, FP, 0.0)))
        .collect();
    let disp: Vec<Series> = runs
        .iter()
        .map(|r| Series::new(name(r), chart::spans(&r.history, X1, 0.0)))
        .collect();
    let tau = Some([0.0, runs[0].spec.params.tau_end()]);
    let [a, b] = Layout::vertical([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
    let tension: Vec<String> = runs
        .iter()
        .map(|r| format!("{} min f_p {}", name(r), chart::short(r.result.min_force)))
        .collect();
    let title = format!("pounding force: {}", tension.join(", "));
    let spec = |title, x_labels| ChartSpec {
        title,
        x_title: "τ",
        x_bounds: tau,
        x_labels,
    };
    chart::draw(frame, a, app.look, &spec(&title, false), &force);
    chart::draw(
        frame,
        b,
        app.look,
        &spec("left displacement x1", true),
        &disp,
    );
}
