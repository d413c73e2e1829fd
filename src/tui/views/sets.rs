//! Scene (d): set 1 against set 2, side by side: displacements and pounding
//! force of each.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, ChartSpec, FP, Series, X1, X2};
use crate::tui::app::App;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let columns: [Rect; 2] =
        Layout::horizontal([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
    for (i, column) in columns.into_iter().enumerate() {
        let Some(run) = app.shown(Slot::Set(i)) else {
            frame.render_widget("computing…", column);
            continue;
        };
        let h = &run.history;
        let tau = Some([0.0, run.spec.params.tau_end()]);
        let [a, b] =
            Layout::vertical([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(column);
        let title = format!("set {} ({}) displacement", i + 1, app.sets[i].preset.name);
        let spec = |title, x_labels| ChartSpec {
            title,
            x_title: "τ",
            x_bounds: tau,
            x_labels,
        };
        let disp = [
            Series::new("x1", chart::spans(h, X1, 0.0)),
            Series::new("x2", chart::spans(h, X2, 0.0)),
        ];
        chart::draw(frame, a, app.look, &spec(&title, false), &disp);
        chart::draw(
            frame,
            b,
            app.look,
            &spec("pounding force", true),
            &[Series::new("f_p", chart::spans(h, FP, 0.0))],
        );
    }
}
