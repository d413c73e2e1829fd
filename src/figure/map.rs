//! The scene `map`: the left structure's spectral region (SPEC §7) over
//! the plane of Π_ω1 and the frequency ratio μ, one shaded cell per grid
//! point, with a marker at the parameter set's own point. The cells come
//! from [`crate::analysis::map`], the same computation as `pounding map`.

use crate::analysis::grid::Grid;
use crate::analysis::map::{Axis, MapPlan, compute};
use crate::analysis::spectrum::Region;
use crate::model::{Method, Params};

use super::FigureError;
use super::caption::{method_text, params_text};
use super::spec::{Cell, Figure, Panel, Series, Stroke};

/// The default Π_ω1 axis of the map figure (coarser than a spectrum's:
/// each cell is two runs).
pub const DEFAULT_OMEGA1: &str = "omega1=0.1:3.0:0.05";
/// The μ axis of the map figure.
pub const DEFAULT_MU: &str = "mu=1:10:0.25";

/// The region map of `params` (named `name`) over Π_ω1 (`grid`, else
/// [`DEFAULT_OMEGA1`]) and μ ([`DEFAULT_MU`]).
pub fn map_scene(
    name: &str,
    params: &Params,
    grid: Option<Grid>,
    method: Method,
) -> Result<Figure, FigureError> {
    let input = |e: crate::analysis::map::MapError| FigureError::Input(e.to_string());
    let x_text = match grid {
        Some(g) => format!("omega1={g}"),
        None => DEFAULT_OMEGA1.to_string(),
    };
    let x = Axis::parse("--omega1", &x_text).map_err(input)?;
    let y = Axis::parse("map μ axis", DEFAULT_MU).map_err(input)?;
    let base = Params {
        method,
        ..params.clone()
    };
    let mu = base.mu();
    let plan = MapPlan::new(base, mu, x, y).map_err(input)?;
    let (cells, _) = compute(&plan);
    let xs = plan.x.values();
    let ys = plan.y.values();
    let half = |v: &[f64]| {
        if v.len() > 1 {
            0.5 * (v[1] - v[0])
        } else {
            0.5
        }
    };
    let (hx, hy) = (half(&xs), half(&ys));
    let mut panel = Panel::new(
        0,
        "Spectral region of the left structure",
        "Π_ω1",
        "μ = Π_ω2/Π_ω1",
    );
    panel.cells = cells
        .iter()
        .filter(|c| c.region != Region::None)
        .map(|c| Cell {
            x: (c.x - hx, c.x + hx),
            y: (c.y - hy, c.y + hy),
            region: c.region,
        })
        .collect();
    panel.x_range = Some((xs[0] - hx, xs[xs.len() - 1] + hx));
    panel.y_range = Some((ys[0] - hy, ys[ys.len() - 1] + hy));
    panel.series.push(Series::new(
        format!("{name} (Π_ω1 = {}, μ = {:.3})", params.omega1, params.mu()),
        0,
        Stroke::Solid,
        cross(params.omega1, params.mu(), 2.0 * hx, 2.0 * hy),
    ));
    let amplified = cells
        .iter()
        .filter(|c| c.region == Region::Amplification)
        .count();
    let suppressed = cells
        .iter()
        .filter(|c| c.region == Region::Suppression)
        .count();
    Ok(Figure {
        title: format!("{name}: regions over Π_ω1 and μ"),
        panels: vec![panel],
        caption: format!(
            "{}; {} × {} cells ({}, {}): {amplified} amplified, {suppressed} suppressed, the rest no influence (2 %); {}",
            params_text(&plan.base, &["omega1", "omega2"]),
            xs.len(),
            ys.len(),
            plan.x,
            plan.y,
            method_text(&plan.base, method)
        ),
    })
}

/// A small cross at (x, y), as one polyline.
fn cross(x: f64, y: f64, wx: f64, wy: f64) -> Vec<(f64, f64)> {
    vec![
        (x - wx, y - wy),
        (x + wx, y + wy),
        (x, y),
        (x - wx, y + wy),
        (x + wx, y - wy),
    ]
}
