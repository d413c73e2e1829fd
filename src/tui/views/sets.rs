//! Scene (c): set 1 against set 2. Side by side (displacements and pounding
//! force of each), or with `o` overlaid: x1 and f_p of both sets on common
//! charts, one scale, each set in its own colour. Side by side, the two
//! columns also share their y scales, so heights compare directly.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};

use super::chart::{self, Series, data_range};
use super::history::{FP, X1, X2, spans, time_spec};
use super::units::{PI_UNITS, Units};
use crate::tui::app::App;
use crate::tui::look::palette;
use crate::tui::worker::{RunOutput, Slot};

fn union(a: Option<[f64; 2]>, b: Option<[f64; 2]>) -> Option<[f64; 2]> {
    match (a, b) {
        (Some(a), Some(b)) => Some([a[0].min(b[0]), a[1].max(b[1])]),
        (a, b) => a.or(b),
    }
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let runs: Vec<Option<&RunOutput>> = (0..2).map(|i| app.shown(Slot::Set(i))).collect();
    // One unit for both: physical only when both sets have it.
    let units = [Units::of(app, 0), Units::of(app, 1)];
    let u = if units[0].physical && units[1].physical {
        units[app.active]
    } else {
        PI_UNITS
    };
    let tau_end = runs
        .iter()
        .flatten()
        .map(|r| r.spec.params.tau_end())
        .fold(0.0, f64::max);
    let disp = |r: &RunOutput, i: usize| -> Vec<Series> {
        if app.view.overlay {
            vec![Series::spans(
                format!("set {} x1", i + 1),
                palette::SETS[i],
                spans(&r.history, X1, 0.0, &u, u.length),
            )]
        } else {
            vec![
                Series::spans(
                    "x1",
                    palette::LEFT,
                    spans(&r.history, X1, 0.0, &u, u.length),
                ),
                Series::spans(
                    "x2",
                    palette::RIGHT,
                    spans(&r.history, X2, 0.0, &u, u.length),
                ),
            ]
        }
    };
    let force = |r: &RunOutput, i: usize| -> Series {
        let (name, color) = if app.view.overlay {
            (format!("set {} f_p", i + 1), palette::SETS[i])
        } else {
            ("f_p".to_string(), palette::FORCE)
        };
        Series::spans(name, color, spans(&r.history, FP, 0.0, &u, u.force))
    };
    let disp_series: Vec<Vec<Series>> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| r.map(|r| disp(r, i)).unwrap_or_default())
        .collect();
    let force_series: Vec<Vec<Series>> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| r.map(|r| vec![force(r, i)]).unwrap_or_default())
        .collect();
    let common = |s: &[Vec<Series>]| s.iter().map(|v| data_range(v, |p| p.1)).fold(None, union);
    let (disp_range, force_range) = (common(&disp_series), common(&force_series));
    let buf = frame.buffer_mut();
    let spec = |title: String, x_labels, range| {
        let mut s = time_spec(app, &u, tau_end, title, x_labels);
        s.y_range = range;
        s
    };
    let x_title = u.title("x", u.length_unit);
    let f_title = u.title("f_p", u.force_unit);
    if app.view.overlay {
        let [a, b] =
            Layout::vertical([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
        let all = |s: Vec<Vec<Series>>| s.into_iter().flatten().collect::<Vec<_>>();
        chart::draw(
            buf,
            a,
            app.look,
            &spec(x_title, false, disp_range),
            &all(disp_series),
        );
        chart::draw(
            buf,
            b,
            app.look,
            &spec(f_title, true, force_range),
            &all(force_series),
        );
        return;
    }
    let columns: [Rect; 2] =
        Layout::horizontal([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(area);
    for (i, column) in columns.into_iter().enumerate() {
        if runs[i].is_none() {
            buf.set_string(
                column.x,
                column.y,
                "computing…",
                ratatui::style::Style::new(),
            );
            continue;
        }
        let [a, b] =
            Layout::vertical([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(column);
        let title = format!("set {} x [{}]", i + 1, u.length_unit);
        chart::draw(
            buf,
            a,
            app.look,
            &spec(title, false, disp_range),
            &disp_series[i],
        );
        chart::draw(
            buf,
            b,
            app.look,
            &spec(f_title.clone(), true, force_range),
            &force_series[i],
        );
    }
}
