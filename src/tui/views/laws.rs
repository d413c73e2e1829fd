//! Scene (v): the active set under several contact laws (SPEC §4, §10),
//! overlaid: the pounding force f_p(τ) (the Kelvin element pulls before
//! separation, f_p < 0), the left displacement x1(τ), and the
//! force–penetration loop f_p against δ = x1 − x2 − Π_d while in contact.
//! Each law keeps its fixed colour and marker whatever the active set.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use super::chart::{self, ChartSpec, Series};
use super::history::{FP, X1, spans, time_spec};
use super::units::Units;
use crate::model::ContactModel;
use crate::tui::app::App;
use crate::tui::look::{model_color, model_marker};
use crate::tui::worker::{RunOutput, Slot};

/// The slot computing `law` on the active set: the set's own run for its
/// own law, a run of its own otherwise.
pub fn slot(app: &App, law: ContactModel) -> Slot {
    if law == app.model() {
        Slot::Set(app.active)
    } else {
        Slot::Law(law)
    }
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let runs: Vec<(ContactModel, &RunOutput)> = app
        .view
        .laws
        .shown(app.model())
        .into_iter()
        .filter_map(|m| app.shown(slot(app, m)).map(|r| (m, r)))
        .collect();
    if runs.is_empty() {
        frame.render_widget("computing…", area);
        return;
    }
    let u = Units::active(app);
    let named = |m: ContactModel, s: Series| s.marked(model_marker(m));
    let series = |channel: usize, k: f64| -> Vec<Series> {
        runs.iter()
            .map(|(m, r)| {
                named(
                    *m,
                    Series::spans(
                        m.name(),
                        model_color(*m),
                        spans(&r.history, channel, 0.0, &u, k),
                    ),
                )
            })
            .collect()
    };
    let loops: Vec<Series> = runs
        .iter()
        .map(|(m, r)| {
            let points = r
                .history
                .contact
                .iter()
                .map(|&(d, f)| (d * u.length, f * u.force))
                .collect();
            named(*m, Series::line(m.name(), model_color(*m), points))
        })
        .collect();
    let tau_end = runs[0].1.spec.params.tau_end();
    // One legend for the three charts, wrapped over two rows when long.
    let sample = |m: ContactModel| {
        if app.look.color && !app.look.ascii {
            "──".to_string()
        } else {
            model_marker(m).to_string().repeat(2)
        }
    };
    let rows = legend_rows(
        &runs
            .iter()
            .map(|(m, _)| (*m, sample(*m)))
            .collect::<Vec<_>>(),
        area.width as usize,
    );
    let [charts, legend_area] =
        Layout::vertical([Constraint::Min(0), Constraint::Length(rows.len() as u16)]).areas(area);
    let lines: Vec<Line> = rows
        .into_iter()
        .map(|row| {
            let mut spans = Vec::new();
            for (k, (m, sample)) in row.into_iter().enumerate() {
                if k > 0 {
                    spans.push(Span::raw("  "));
                }
                let style = if app.look.color {
                    Style::new().fg(model_color(m))
                } else {
                    Style::new()
                };
                spans.push(Span::styled(sample, style));
                spans.push(Span::raw(format!(" {}", m.name())));
            }
            Line::from(spans)
        })
        .collect();
    frame.render_widget(Paragraph::new(lines), legend_area);
    let [left, right] =
        Layout::horizontal([Constraint::Ratio(3, 5), Constraint::Ratio(2, 5)]).areas(charts);
    let [a, b] = Layout::vertical([Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)]).areas(left);
    let buf = frame.buffer_mut();
    let spec = |title: String, x_labels| ChartSpec {
        no_legend: true,
        ..time_spec(app, &u, tau_end, title, x_labels)
    };
    let title = app.view.laws.title(app.model());
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
    let loop_spec = ChartSpec {
        title: format!("f_p(δ) {title} (b)"),
        x_title: u.title("δ", u.length_unit),
        x_labels: true,
        no_legend: true,
        ..Default::default()
    };
    chart::draw(buf, right, app.look, &loop_spec, &loops);
}

/// The legend entries (law, sample) in rows of at most `width` columns.
fn legend_rows(
    entries: &[(ContactModel, String)],
    width: usize,
) -> Vec<Vec<(ContactModel, String)>> {
    let mut rows: Vec<Vec<(ContactModel, String)>> = vec![Vec::new()];
    let mut used = 0;
    for (m, sample) in entries {
        let w = sample.chars().count() + 1 + m.name().len();
        let sep = if used == 0 { 0 } else { 2 };
        if used > 0 && used + sep + w > width {
            rows.push(Vec::new());
            used = 0;
        } else {
            used += sep;
        }
        used += w;
        if let Some(row) = rows.last_mut() {
            row.push((*m, sample.clone()));
        }
    }
    rows
}
