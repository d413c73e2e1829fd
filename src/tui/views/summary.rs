//! The two summary lines: per run the scene shows, Π_u and Π_v of both
//! structures (SPEC §6), impacts, the force range, the accuracy, the
//! compute time, then the demands of SPEC §6 (A, μ, r, E_h), parts left out
//! from the end when the line is narrow; a run being recomputed says so. With the cursor shown, they read out the
//! active run at the cursor instead.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use super::compact::{fit, num, pair};
use super::history::{FP, FS1, FS2, V1, V2, X1, X2};
use super::units::Units;
use crate::solver::StructurePeaks;
use crate::tui::app::App;
use crate::tui::scene::Scene;
use crate::tui::worker::{RunOutput, Slot};

/// One run in one line of at most `width` characters.
pub fn line(label: &str, run: &RunOutput, u: &Units, current: bool, width: usize) -> String {
    let r = &run.result;
    // Newmark's actual error against the exact method; an exact run says so.
    let accuracy = match run.error_vs_exact {
        Some(e) => format!("err {e:.0e}"),
        None => r.method.name().to_string(),
    };
    let label = if current {
        format!("{label}:")
    } else {
        format!("{label} computing…, was:")
    };
    let (peak_u, peak_v) = if u.physical {
        ("u_max", "v_max")
    } else {
        ("Π_u", "Π_v")
    };
    // One quantity of both structures, scaled to the view's units.
    let both = |name: &str, of: fn(&StructurePeaks) -> f64, scale: f64| {
        pair(name, of(&r.left) * scale, of(&r.right) * scale)
    };
    let parts = [
        label,
        both(peak_u, |s| s.peak_displacement, u.length),
        both(peak_v, |s| s.peak_velocity, u.velocity),
        format!("impacts {}", r.impacts.len()),
        format!(
            "f_p {}..{}",
            num(r.min_force * u.force),
            num(r.max_force * u.force)
        ),
        accuracy,
        format!("res {:.0e}", r.energy.residual),
        format!("{:.1} ms", run.elapsed_ms),
        // The demands of SPEC §6 where the line is wide enough.
        both("A", |s| s.peak_absolute_acceleration, u.acceleration),
        both("μ", |s| s.ductility, 1.0),
        both("r", |s| s.residual_displacement, u.length),
        both("E_h", |s| s.hysteretic_energy, u.energy),
    ];
    fit(&parts, width)
}

/// The gap that prevents pounding (SPEC §11) of one set's run: the exact
/// Π_d,min beside the set's own Π_d (pounds or clear), then the code rules
/// (absolute sum, SRSS, double difference with its ρ) as room allows.
pub fn gap_line(label: &str, run: &RunOutput, u: &Units, width: usize) -> Option<String> {
    let g = run.min_gap.as_ref()?;
    let gap = run.spec.params.gap;
    let (min, set) = if u.physical {
        ("d_min", "d")
    } else {
        ("Π_d,min", "Π_d")
    };
    let verdict = if run.result.impacts.is_empty() {
        "clear"
    } else {
        "pounds"
    };
    let set_gap = if gap.is_finite() {
        format!("{set} {} {verdict}", num(gap * u.length))
    } else {
        format!("{set} inf")
    };
    let r = &g.rules;
    let parts = [
        format!("{label} {min} {}", num(g.exact * u.length)),
        set_gap,
        format!("ABS {}", num(r.absolute_sum * u.length)),
        format!("SRSS {}", num(r.srss * u.length)),
        format!(
            "DDC {} (ρ {})",
            num(r.double_difference * u.length),
            num(r.correlation)
        ),
    ];
    Some(fit(&parts, width))
}

fn slots(app: &App) -> Vec<(String, Slot)> {
    let set = |i: usize| (format!("set {}", i + 1), Slot::Set(i));
    match app.view.scene {
        Scene::History
        | Scene::Loops
        | Scene::Spectrum
        | Scene::Impacts
        | Scene::Map
        | Scene::Risk
        | Scene::Buildings => {
            vec![set(app.active)]
        }
        Scene::Sets => vec![set(0), set(1)],
        Scene::Laws => app
            .view
            .laws
            .shown(app.model())
            .into_iter()
            .map(|m| (m.name().to_string(), super::laws::slot(app, m)))
            .collect(),
    }
}

/// The readout of the active run at the cursor, in two lines.
pub fn readout(app: &App, run: &RunOutput, tau: f64, width: usize) -> Option<[String; 2]> {
    let (at, v) = run.history.at(tau)?;
    let u = Units::active(app);
    let time = if u.physical {
        format!("t {} s", num(at * u.time))
    } else {
        format!("τ {} ({} cyc)", num(at), num(at / std::f64::consts::TAU))
    };
    let first = [
        format!("cursor {time}"),
        format!("x1 {}", num(v[X1] * u.length)),
        format!("x2 {}", num(v[X2] * u.length)),
        format!("f_p {}", num(v[FP] * u.force)),
    ];
    let second = [
        format!("ẋ1 {}", num(v[V1] * u.velocity)),
        format!("ẋ2 {}", num(v[V2] * u.velocity)),
        format!("f_s1 {}", num(v[FS1] * u.force)),
        format!("f_s2 {}", num(v[FS2] * u.force)),
    ];
    Some([fit(&first, width), fit(&second, width)])
}

pub fn render(app: &App, frame: &mut Frame, area: Rect) {
    let width = area.width as usize;
    if app.view.scene == Scene::Buildings {
        let lines = super::row::summary(app, width);
        let lines: Vec<Line> = lines.iter().map(|l| Line::from(app.look.text(l))).collect();
        frame.render_widget(Paragraph::new(lines), area);
        return;
    }
    let active = app.shown(Slot::Set(app.active));
    let cursor = app.view.cursor.filter(|_| app.view.scene.timed());
    if let (Some(tau), Some(run)) = (cursor, active)
        && let Some(lines) = readout(app, run, tau, width)
    {
        let lines: Vec<Line> = lines.iter().map(|l| Line::from(app.look.text(l))).collect();
        frame.render_widget(Paragraph::new(lines), area);
        return;
    }
    let slots = slots(app);
    let single = slots.len() == 1;
    let mut lines: Vec<Line> = slots
        .into_iter()
        .map(|(label, slot)| {
            let u = match slot {
                Slot::Set(i) => Units::of(app, i),
                Slot::Law(_) => Units::active(app),
            };
            let text = match app.shown(slot) {
                Some(run) => line(&label, run, &u, app.jobs.is_current(slot), width),
                None => format!("{label}: computing…"),
            };
            Line::from(app.look.text(&text))
        })
        .collect();
    // One run shown: the second line tells the gap that prevents pounding.
    if single
        && let Some(run) = active
        && let Some(text) = gap_line("gap:", run, &Units::active(app), width)
    {
        lines.push(Line::from(app.look.text(&text)));
    }
    frame.render_widget(Paragraph::new(lines), area);
}
