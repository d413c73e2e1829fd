//! Scene (b): force–drift loops (x_i, f_s,i) of both structures of the
//! active set (SPEC §3).

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, ChartSpec, FS1, FS2, Series, X1, X2};
use crate::tui::app::App;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(run) = app.shown(Slot::Set(app.active)) else {
        frame.render_widget("computing…", area);
        return;
    };
    let [left, right] =
        Layout::horizontal([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
    for (area, title, name, cx, cy) in [
        (left, "left structure", "f_s1(x1)", X1, FS1),
        (right, "right structure", "f_s2(x2)", X2, FS2),
    ] {
        let spec = ChartSpec {
            title,
            x_title: "x",
            x_bounds: None,
            x_labels: true,
        };
        chart::draw(
            frame,
            area,
            app.look,
            &spec,
            &[Series::new(name, chart::pairs(&run.history, cx, cy))],
        );
    }
}
