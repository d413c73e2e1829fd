//! The figure of a row of buildings (SPEC §13): envelopes over height of
//! peak floor displacement, storey drift ratio and floor acceleration, with
//! pounding (solid) and without it (dashed), one colour per building; and
//! the contact force of each floor pair that pounds over time, one colour
//! per pair, from the exact method's force history
//! ([`crate::solver::buildings::ForceHistory`]).

use crate::model::buildings::{Ground, Row};
use crate::model::record::STANDARD_GRAVITY;
use crate::solver::buildings::{RowError, RowOptions, RowRun, run_row};

use super::spec::{Figure, Panel, Series, Stroke};

/// The size `figure buildings` draws at (pixels; an SVG's view box).
pub const ROW_FIGURE_SIZE: (u32, u32) = (1400, 1000);

/// `figure buildings` of `row` under `ground` (named `excitation` in the
/// caption) for `duration` s: the exact method's run with contact, its
/// force history kept, and the run with every joint open.
pub fn row_figure_of(
    row: &Row,
    ground: &Ground,
    excitation: &str,
    duration: f64,
) -> Result<Figure, RowError> {
    let traced = RowOptions {
        forces: true,
        ..RowOptions::lasting(duration)
    };
    let with = run_row(row, ground, &traced)?;
    let without = run_row(&row.apart(), ground, &RowOptions::lasting(duration))?;
    let caption = format!(
        "{} excitation, {} contact, exact method, {:.3} s; dashed: without pounding",
        excitation,
        row.model.name(),
        duration
    );
    Ok(row_figure(row, &with, &without, &caption))
}

/// The figure from a run with contact (its force history asked for:
/// [`crate::solver::buildings::RowOptions::forces`]) and one without.
pub fn row_figure(row: &Row, with: &RowRun, without: &RowRun, caption: &str) -> Figure {
    let titles = [
        ("peak floor displacement", "u (mm)"),
        ("peak storey drift ratio", "drift (%)"),
        ("peak floor acceleration", "A (g)"),
    ];
    let mut panels: Vec<Panel> = titles
        .iter()
        .enumerate()
        .map(|(i, (t, x))| Panel::new(i, *t, x, "height (m)"))
        .collect();
    for (b, building) in row.buildings.iter().enumerate() {
        for (run, stroke, tag) in [
            (with, Stroke::Solid, ""),
            (without, Stroke::Dashed, " apart"),
        ] {
            let floors = &run.floors[b];
            // Floor i at its elevation; storey i's drift at mid-storey.
            let at = |i: usize| building.elevation(i + 1);
            let mid = |i: usize| building.elevation(i) + 0.5 * building.height[i];
            let mut pts = [vec![(0.0, 0.0)], Vec::new(), vec![(0.0, 0.0)]];
            for (i, f) in floors.iter().enumerate() {
                pts[0].push((f.displacement * 1e3, at(i)));
                pts[1].push((f.drift_ratio * 100.0, mid(i)));
                pts[2].push((f.absolute_acceleration / STANDARD_GRAVITY, at(i)));
            }
            for (panel, points) in panels.iter_mut().zip(pts) {
                panel.series.push(Series::new(
                    format!("{}{tag}", building.name),
                    b,
                    stroke,
                    points,
                ));
            }
        }
    }
    let mut forces = Panel::new(3, "impact forces", "t (s)", "force (kN)");
    let history = with.forces.as_ref();
    for (k, (p, r)) in row.pairs().iter().zip(&with.pairs).enumerate() {
        let Some(points) = history.map(|h| &h.pairs[k]) else {
            continue;
        };
        if r.impacts.is_empty() {
            continue;
        }
        // At rest before the first impact and after the last.
        let mut line = vec![(0.0, 0.0)];
        line.extend(points.iter().map(|&(t, f)| (t, f / 1e3)));
        if r.impacts.last().is_some_and(|i| !i.end.is_nan()) {
            line.push((with.duration, 0.0));
        }
        forces.series.push(Series::new(
            row.pair_name(p),
            row.buildings.len() + k,
            Stroke::Solid,
            line,
        ));
    }
    panels.push(forces);
    Figure {
        title: format!("{}: envelopes over height and impact forces", row.name),
        panels,
        caption: caption.to_string(),
    }
}
