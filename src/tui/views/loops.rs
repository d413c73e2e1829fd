//! Scene (f): force–drift loops (x_i, f_s,i) of both structures of the
//! active set (SPEC §3), over the visible time window.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, ChartSpec, Series};
use super::history::{FS1, FS2, X1, X2};
use super::units::Units;
use crate::tui::app::App;
use crate::tui::look::palette;
use crate::tui::worker::Slot;

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let Some(run) = app.shown(Slot::Set(app.active)) else {
        frame.render_widget("computing…", area);
        return;
    };
    let u = Units::active(app);
    let [left, right] =
        Layout::horizontal([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
    for (area, name, x, cx, cy, color) in [
        (left, "f_s1", "x1", X1, FS1, palette::LEFT),
        (right, "f_s2", "x2", X2, FS2, palette::RIGHT),
    ] {
        let points = run
            .history
            .pairs(cx, cy)
            .into_iter()
            .map(|(a, b)| (a * u.length, b * u.force))
            .collect();
        let spec = ChartSpec {
            title: u.title(name, u.force_unit),
            x_title: u.title(x, u.length_unit),
            x_labels: true,
            ..Default::default()
        };
        chart::draw(
            frame.buffer_mut(),
            area,
            app.look,
            &spec,
            &[Series::line(format!("{name}({x})"), color, points)],
        );
    }
}
