//! The summary lines: one per run the scene shows, with Π_u and Π_v of both
//! structures (SPEC §6), impacts, max and min pounding force, the energy
//! residual and the compute time.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use super::chart::short;
use crate::tui::app::{App, Scene};
use crate::tui::worker::{RunOutput, Slot};

/// One run in one line.
pub fn line(label: &str, run: &RunOutput) -> String {
    let r = &run.result;
    // Newmark's actual error against the exact method; an exact run says so.
    let accuracy = match run.error_vs_exact {
        Some(e) => format!("err {e:.0e}"),
        None => r.method.name().to_string(),
    };
    format!(
        "{label}: Π_u {}/{} Π_v {}/{} impacts {} f_p {}..{} {accuracy} res {:.0e} {:.1} ms",
        short(r.left.peak_displacement),
        short(r.right.peak_displacement),
        short(r.left.peak_velocity),
        short(r.right.peak_velocity),
        r.impacts.len(),
        short(r.min_force),
        short(r.max_force),
        r.energy.residual,
        run.elapsed_ms,
    )
}

fn slots(app: &App) -> Vec<(String, Slot)> {
    let active = Slot::Set(app.active);
    let set = |i: usize| (format!("set {}", i + 1), Slot::Set(i));
    match app.scene {
        Scene::History | Scene::Loops | Scene::Spectrum => vec![set(app.active)],
        Scene::Sets => vec![set(0), set(1)],
        Scene::Kelvin => vec![
            (app.model().name().to_string(), active),
            (app.model().toggled().name().to_string(), Slot::Twin),
        ],
    }
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let lines: Vec<Line> = slots(app)
        .into_iter()
        .map(|(label, slot)| match app.shown(slot) {
            Some(run) => Line::from(line(&label, run)),
            None => Line::from(format!("{label}: computing…")),
        })
        .collect();
    frame.render_widget(Paragraph::new(lines), area);
}
