//! Scene (a): time histories of the active set — displacements x1, x2 and
//! the contact line x2 + Π_d (contact while x1 is above it, SPEC §4),
//! velocities, and the pounding force f_p.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, ChartSpec, FP, Series, V1, V2, X1, X2};
use crate::tui::app::App;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(run) = app.shown(Slot::Set(app.active)) else {
        frame.render_widget("computing…", area);
        return;
    };
    let h = &run.history;
    let gap = run.spec.params.gap;
    let tau = Some([0.0, run.spec.params.tau_end()]);
    let mut displacement = vec![
        Series::new("x1", chart::spans(h, X1, 0.0)),
        Series::new("x2", chart::spans(h, X2, 0.0)),
    ];
    if gap.is_finite() {
        displacement.push(Series::new("x2+Π_d", chart::spans(h, X2, gap)));
    }
    let velocity = [
        Series::new("ẋ1", chart::spans(h, V1, 0.0)),
        Series::new("ẋ2", chart::spans(h, V2, 0.0)),
    ];
    let force = [Series::new("f_p", chart::spans(h, FP, 0.0))];
    let [a, b, c] = Layout::vertical([
        Constraint::Ratio(1, 3),
        Constraint::Ratio(1, 3),
        Constraint::Ratio(1, 3),
    ])
    .areas(area);
    let spec = |title, x_labels| ChartSpec {
        title,
        x_title: "τ",
        x_bounds: tau,
        x_labels,
    };
    let title = format!("set {} displacement", app.active + 1);
    chart::draw(frame, a, app.look, &spec(&title, false), &displacement);
    chart::draw(frame, b, app.look, &spec("velocity", false), &velocity);
    chart::draw(frame, c, app.look, &spec("pounding force", true), &force);
}
