//! Time-history figures: the paper's Figures 3 to 6 (SPEC §2–4) and the
//! scenes `history`, `loops` and `contact-laws` for any parameter set.
//!
//! A history is drawn from every accepted state, reduced for the page: a
//! channel against τ keeps the minimum and maximum of each of
//! [`TIME_BUCKETS`] time buckets, in the order they occurred (so peaks and
//! impact spikes survive); a loop (one channel against another) keeps every
//! k-th state, at most [`LOOP_POINTS`].

use crate::model::{ContactModel, Method, Params, SET1, SET2};
use crate::solver::{FullHistory, Sample};

use super::FigureError;
use super::caption::{method_text, params_text};
use super::runs::history;
use super::spec::{Figure, Panel, Series, Stroke};

/// Time buckets of a history curve (two points each).
pub const TIME_BUCKETS: usize = 1500;
/// Most points of a force–drift loop.
pub const LOOP_POINTS: usize = 6000;

type Channel = fn(&Sample) -> f64;
const X1: Channel = |s| s.x[0];
const X2: Channel = |s| s.x[1];
const V1: Channel = |s| s.v[0];
const V2: Channel = |s| s.v[1];
const FS1: Channel = |s| s.fs[0];
const FS2: Channel = |s| s.fs[1];
const FP: Channel = |s| s.fp;
const TAU: Channel = |s| s.tau;

/// A channel against τ: per time bucket its minimum and maximum, in time order.
pub fn envelope(h: &FullHistory, channel: Channel, buckets: usize) -> Vec<(f64, f64)> {
    let Some(last) = h.samples.last() else {
        return Vec::new();
    };
    let width = last.tau / buckets.max(1) as f64;
    let mut out = Vec::with_capacity(2 * buckets + 2);
    let mut i = 0;
    while i < h.samples.len() {
        let bucket = if width > 0.0 {
            (h.samples[i].tau / width) as usize
        } else {
            0
        };
        let (mut lo, mut hi) = (i, i);
        let mut j = i;
        while j < h.samples.len() && (width <= 0.0 || (h.samples[j].tau / width) as usize == bucket)
        {
            if channel(&h.samples[j]) < channel(&h.samples[lo]) {
                lo = j;
            }
            if channel(&h.samples[j]) > channel(&h.samples[hi]) {
                hi = j;
            }
            j += 1;
        }
        for k in if lo <= hi { [lo, hi] } else { [hi, lo] } {
            out.push((h.samples[k].tau, channel(&h.samples[k])));
        }
        i = j;
    }
    out.dedup();
    out
}

/// One channel against another, every k-th state (at most `max_points`).
pub fn trace(h: &FullHistory, x: Channel, y: Channel, max_points: usize) -> Vec<(f64, f64)> {
    let stride = h.samples.len().div_ceil(max_points.max(1)).max(1);
    h.samples
        .iter()
        .step_by(stride)
        .chain(h.samples.last())
        .map(|s| (x(s), y(s)))
        .collect()
}

/// One channel against τ at full resolution inside [t0, t1].
pub fn window(h: &FullHistory, channel: Channel, t0: f64, t1: f64) -> Vec<(f64, f64)> {
    h.samples
        .iter()
        .filter(|s| s.tau >= t0 && s.tau <= t1)
        .map(|s| (TAU(s), channel(s)))
        .collect()
}

fn law_label(m: ContactModel) -> &'static str {
    match m {
        ContactModel::Kelvin => "Kelvin",
        ContactModel::ImprovedKelvin => "improved Kelvin",
        other => other.name(),
    }
}

fn with_model(p: &Params, model: ContactModel) -> Params {
    Params { model, ..p.clone() }
}

fn free(p: &Params) -> Params {
    Params {
        gap: f64::INFINITY,
        ..p.clone()
    }
}

fn caption(name: &str, p: &Params, law: &str, method: Method) -> String {
    format!(
        "{name}: {}; {law}; {}",
        params_text(p, &[]),
        method_text(p, method)
    )
}

fn tau_panel(index: usize, title: &str, y_label: &str, p: &Params) -> Panel {
    let mut panel = Panel::new(index, title, "τ", y_label);
    panel.x_range = Some((0.0, p.tau_end()));
    panel
}

/// Figure 3: displacement and pounding-force histories and the force–drift
/// loops of set 1 (the paper's nine poundings; the left structure yields,
/// the right one stays elastic).
pub fn fig3(method: Method) -> Result<Figure, FigureError> {
    let p = SET1;
    let (_, h) = history(&p, method)?;
    let mut panels = vec![
        tau_panel(0, "Displacement histories", "x1, x2", &p),
        tau_panel(1, "Pounding force history", "f_p", &p),
        Panel::new(2, "Force–drift loop, left structure", "x1", "f_s1"),
        Panel::new(3, "Force–drift loop, right structure", "x2", "f_s2"),
    ];
    let left = |pts| Series::new("left structure (1)", 0, Stroke::Solid, pts);
    let right = |pts| Series::new("right structure (2)", 1, Stroke::Solid, pts);
    panels[0].series = vec![
        left(envelope(&h, X1, TIME_BUCKETS)),
        right(envelope(&h, X2, TIME_BUCKETS)),
    ];
    panels[1].series = vec![Series::new(
        "pounding force f_p",
        2,
        Stroke::Solid,
        envelope(&h, FP, TIME_BUCKETS),
    )];
    panels[2].series = vec![left(trace(&h, X1, FS1, LOOP_POINTS))];
    panels[3].series = vec![right(trace(&h, X2, FS2, LOOP_POINTS))];
    Ok(Figure {
        title: "Figure 3: time histories and force–drift loops, parameter set 1".into(),
        panels,
        caption: caption("set1", &p, "improved Kelvin contact", method),
    })
}

/// Figures 4 and 5: displacement and velocity histories of both structures
/// under the improved Kelvin and the Kelvin element, and without pounding.
pub fn fig4_5(number: u8, method: Method) -> Result<Figure, FigureError> {
    let (name, p) = if number == 4 {
        ("set1", SET1)
    } else {
        ("set2", SET2)
    };
    let (_, improved) = history(&with_model(&p, ContactModel::ImprovedKelvin), method)?;
    let (_, kelvin) = history(&with_model(&p, ContactModel::Kelvin), method)?;
    let (_, none) = history(&free(&p), method)?;
    let quantities: [(&str, &str, Channel); 4] = [
        ("Displacement of the left structure", "x1", X1),
        ("Velocity of the left structure", "v1", V1),
        ("Displacement of the right structure", "x2", X2),
        ("Velocity of the right structure", "v2", V2),
    ];
    let panels = quantities
        .iter()
        .enumerate()
        .map(|(i, (title, y, ch))| {
            let mut panel = tau_panel(i, title, y, &p);
            panel.series = vec![
                Series::new(
                    "improved Kelvin",
                    0,
                    Stroke::Solid,
                    envelope(&improved, *ch, TIME_BUCKETS),
                ),
                Series::new(
                    "Kelvin",
                    1,
                    Stroke::Solid,
                    envelope(&kelvin, *ch, TIME_BUCKETS),
                ),
                Series::new(
                    "no pounding",
                    2,
                    Stroke::Dashed,
                    envelope(&none, *ch, TIME_BUCKETS),
                ),
            ];
            panel
        })
        .collect();
    Ok(Figure {
        title: format!(
            "Figure {number}: histories under both contact elements and without pounding, parameter {}",
            name.replace("set", "set ")
        ),
        panels,
        caption: caption(
            name,
            &p,
            "improved Kelvin and Kelvin contact, and gap = inf",
            method,
        ),
    })
}

/// Figure 6: the pounding force of set 1 under both laws; (b) enlarges the
/// Kelvin impact with the largest tension (f_p < 0 before separation).
pub fn fig6(method: Method) -> Result<Figure, FigureError> {
    let p = SET1;
    let (_, improved) = history(&with_model(&p, ContactModel::ImprovedKelvin), method)?;
    let (kr, kelvin) = history(&with_model(&p, ContactModel::Kelvin), method)?;
    let series = |a: Vec<(f64, f64)>, b: Vec<(f64, f64)>| {
        vec![
            Series::new("improved Kelvin", 0, Stroke::Solid, a),
            Series::new("Kelvin", 1, Stroke::Solid, b),
        ]
    };
    let mut whole = tau_panel(0, "Pounding force histories", "f_p", &p);
    whole.series = series(
        envelope(&improved, FP, TIME_BUCKETS),
        envelope(&kelvin, FP, TIME_BUCKETS),
    );
    // The impact around the Kelvin run's most negative force.
    let tension_at = kelvin
        .samples
        .iter()
        .min_by(|a, b| a.fp.total_cmp(&b.fp))
        .map_or(0.0, |s| s.tau);
    let impact = kr
        .impacts
        .iter()
        .find(|i| i.start <= tension_at && tension_at <= i.end + p.dt)
        .or(kr.impacts.first());
    let (t0, t1) = impact.map_or((0.0, p.tau_end()), |i| {
        let d = (i.end - i.start).max(p.dt);
        (i.start - 0.6 * d, i.end + 0.6 * d)
    });
    let mut zoom = Panel::new(
        1,
        format!("Enlarged: the impact at τ ≈ {:.2}", 0.5 * (t0 + t1)),
        "τ",
        "f_p",
    );
    zoom.x_range = Some((t0, t1));
    zoom.series = series(window(&improved, FP, t0, t1), window(&kelvin, FP, t0, t1));
    Ok(Figure {
        title: "Figure 6: pounding force under the improved Kelvin and the Kelvin element, set 1"
            .into(),
        panels: vec![whole, zoom],
        caption: caption("set1", &p, "improved Kelvin and Kelvin contact", method),
    })
}

/// Scene `history`: displacements with and without pounding, and the force.
pub fn history_scene(name: &str, p: &Params, method: Method) -> Result<Figure, FigureError> {
    let (r, h) = history(p, method)?;
    let mut disp = tau_panel(0, "Displacement histories", "x1, x2", p);
    disp.series = vec![
        Series::new(
            "left structure (1)",
            0,
            Stroke::Solid,
            envelope(&h, X1, TIME_BUCKETS),
        ),
        Series::new(
            "right structure (2)",
            1,
            Stroke::Solid,
            envelope(&h, X2, TIME_BUCKETS),
        ),
    ];
    if p.pounding() {
        let (_, none) = history(&free(p), method)?;
        disp.series.push(Series::new(
            "left, no pounding",
            0,
            Stroke::Dashed,
            envelope(&none, X1, TIME_BUCKETS),
        ));
        disp.series.push(Series::new(
            "right, no pounding",
            1,
            Stroke::Dashed,
            envelope(&none, X2, TIME_BUCKETS),
        ));
    }
    let mut force = tau_panel(
        1,
        format!("Pounding force ({} impacts)", r.impacts.len()).as_str(),
        "f_p",
        p,
    );
    force.series = vec![Series::new(
        "pounding force f_p",
        2,
        Stroke::Solid,
        envelope(&h, FP, TIME_BUCKETS),
    )];
    Ok(Figure {
        title: format!("{name}: time histories"),
        panels: vec![disp, force],
        caption: caption(name, p, &format!("{} contact", law_label(p.model)), method),
    })
}

/// Scene `loops`: the force–drift loop of each structure.
pub fn loops_scene(name: &str, p: &Params, method: Method) -> Result<Figure, FigureError> {
    let (_, h) = history(p, method)?;
    let mut left = Panel::new(0, "Force–drift loop, left structure", "x1", "f_s1");
    left.series = vec![Series::new(
        "left structure (1)",
        0,
        Stroke::Solid,
        trace(&h, X1, FS1, LOOP_POINTS),
    )];
    let mut right = Panel::new(1, "Force–drift loop, right structure", "x2", "f_s2");
    right.series = vec![Series::new(
        "right structure (2)",
        1,
        Stroke::Solid,
        trace(&h, X2, FS2, LOOP_POINTS),
    )];
    Ok(Figure {
        title: format!("{name}: force–drift loops"),
        panels: vec![left, right],
        caption: caption(name, p, &format!("{} contact", law_label(p.model)), method),
    })
}

/// Scene `contact-laws`: the pounding force and the left displacement under
/// the Kelvin and the improved Kelvin element.
pub fn contact_laws_scene(name: &str, p: &Params, method: Method) -> Result<Figure, FigureError> {
    let (_, improved) = history(&with_model(p, ContactModel::ImprovedKelvin), method)?;
    let (_, kelvin) = history(&with_model(p, ContactModel::Kelvin), method)?;
    let pair = |ch: Channel| {
        vec![
            Series::new(
                "improved Kelvin",
                0,
                Stroke::Solid,
                envelope(&improved, ch, TIME_BUCKETS),
            ),
            Series::new(
                "Kelvin",
                1,
                Stroke::Solid,
                envelope(&kelvin, ch, TIME_BUCKETS),
            ),
        ]
    };
    let mut force = tau_panel(0, "Pounding force", "f_p", p);
    force.series = pair(FP);
    let mut disp = tau_panel(1, "Displacement of the left structure", "x1", p);
    disp.series = pair(X1);
    Ok(Figure {
        title: format!("{name}: Kelvin against improved Kelvin"),
        panels: vec![force, disp],
        caption: caption(name, p, "improved Kelvin and Kelvin contact", method),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn envelope_keeps_extremes_in_time_order() {
        let h = FullHistory {
            samples: (0..=1000)
                .map(|i| Sample {
                    tau: i as f64 / 100.0,
                    x: [(i as f64 / 7.0).sin(), 0.0],
                    ..Default::default()
                })
                .collect(),
        };
        let e = envelope(&h, X1, 20);
        let max = e.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        let true_max = h.samples.iter().map(|s| s.x[0]).fold(f64::MIN, f64::max);
        assert_eq!(max, true_max);
        assert!(e.windows(2).all(|w| w[0].0 <= w[1].0));
        assert!(e.len() <= 2 * 21);
    }
}
