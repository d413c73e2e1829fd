//! Spectrum figures: the paper's Figure 7 (self-similarity, SPEC §8) and
//! Figures 8–10 (families, SPEC §7), and the scene `spectrum`.
//!
//! The left structure's spectral regions are shaded on its panels. They are
//! the maximal runs of consecutive grid points in one region
//! ([`region_ranges`]) of a reference curve (the family member with the
//! preset's own value); each band reaches half a grid step beyond its end
//! points, so adjacent bands meet and a one-point island stays visible.

use std::f64::consts::PI;

use crate::analysis::family::Family;
use crate::analysis::grid::Grid;
use crate::analysis::spectrum::{Region, SpectrumPoint, region_ranges};
use crate::analysis::spectrum_spec::PresetSpectrum;
use crate::analysis::sweep::{Curve, curve_specs};
use crate::model::physical::{G, Physical};
use crate::model::{Method, Params, preset};

use super::FigureError;
use super::caption::{method_text, num, params_text, symbol};
use super::runs::{levels, spectra};
use super::spec::{Band, Figure, Panel, Series, Stroke};

/// ω_p of Figure 7's physical system (rad/s): a 1 s excitation period. The
/// paper does not state it; the dimensionless panels do not depend on it.
pub const FIG7_OMEGA_P: f64 = 2.0 * PI;
/// Figure 7's excitation amplitudes, in g.
pub const FIG7_LEVELS: [f64; 3] = [0.2, 0.5, 0.8];

/// What a spectrum figure sweeps: base parameters, μ, family and grid.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumInput {
    pub name: String,
    pub params: Params,
    pub mu: f64,
    pub family: Option<Family>,
    pub grid: Grid,
}

impl SpectrumInput {
    /// A built-in preset with its `[spectrum]` table; `grid` overrides its grid.
    pub fn builtin(name: &str, grid: Option<Grid>) -> Result<SpectrumInput, FigureError> {
        let bad = |e: &dyn std::fmt::Display| FigureError::Input(format!("{name}: {e}"));
        let preset = preset::builtin(name).ok_or_else(|| bad(&"no such built-in preset"))?;
        let own = PresetSpectrum::of(preset.spectrum.as_ref(), preset.params.clone())
            .map_err(|e| bad(&e))?;
        Ok(SpectrumInput {
            name: name.to_string(),
            params: preset.params,
            mu: own.mu,
            family: own.family,
            grid: grid.unwrap_or(own.grid),
        })
    }

    fn caption(&self, skip: &[&str], extra: &str, method: Method) -> String {
        let mut skip = skip.to_vec();
        skip.extend(["omega1", "omega2"]);
        format!(
            "{}: {}, μ = {} (Π_ω2 = μ Π_ω1){extra}; {} contact; {}; Π_ω1 = {} ({} points)",
            self.name,
            params_text(&self.params, &skip),
            num(self.mu),
            self.params.model,
            method_text(&self.params, method),
            self.grid,
            self.grid.len()
        )
    }
}

/// The shaded bands of the left structure's regions along `points`.
pub fn bands(points: &[SpectrumPoint], step: f64) -> Vec<Band> {
    let (lo, hi) = match (points.first(), points.last()) {
        (Some(a), Some(b)) => (a.omega1, b.omega1),
        _ => return Vec::new(),
    };
    region_ranges(points)
        .into_iter()
        .filter(|r| r.region != Region::None)
        .map(|r| Band {
            region: r.region,
            from: (r.from - 0.5 * step).max(lo),
            to: (r.to + 0.5 * step).min(hi),
        })
        .collect()
}

/// The band limits as text, for the caption.
fn bands_text(bands: &[Band]) -> String {
    bands
        .iter()
        .map(|b| format!("{} {:.3}–{:.3}", b.region.name(), b.from, b.to))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The four peaks of a point: [Π_u1, Π_v1, Π_u2, Π_v2] with or without pounding.
fn peak(pt: &SpectrumPoint, quantity: usize, pounding: bool) -> f64 {
    pt.peaks()[quantity + if pounding { 0 } else { 4 }]
}

fn curve_points(
    points: &[SpectrumPoint],
    quantity: usize,
    pounding: bool,
    scale: f64,
) -> Vec<(f64, f64)> {
    points
        .iter()
        .map(|pt| (pt.omega1, scale * peak(pt, quantity, pounding)))
        .collect()
}

const QUANTITIES: [(&str, &str); 4] = [
    ("Peak displacement of the left structure", "Π_u1"),
    ("Peak velocity of the left structure", "Π_v1"),
    ("Peak displacement of the right structure", "Π_u2"),
    ("Peak velocity of the right structure", "Π_v2"),
];

/// The index of the family member with the base preset's own value (else 0).
fn reference_curve(curves: &[Curve], input: &SpectrumInput) -> usize {
    curves
        .iter()
        .position(|c| c.spec.params == input.params && c.spec.mu == input.mu)
        .unwrap_or(0)
}

fn member_label(c: &Curve) -> String {
    match &c.spec.member {
        Some(m) if m.key == "gap" && c.spec.params.gap.is_infinite() => {
            "no pounding (Π_d = inf)".into()
        }
        Some(m) => format!("{} = {}", symbol(&m.key), m.text),
        None => "with pounding".into(),
    }
}

/// Figures 8–10 and the scene `spectrum`: Π_u and Π_v of both structures
/// against Π_ω1, one curve per family member; the reference curve's
/// no-pounding baseline dashed (unless a member is itself gap = inf).
pub fn family_figure(
    title: &str,
    input: &SpectrumInput,
    method: Method,
) -> Result<Figure, FigureError> {
    let specs = curve_specs(&input.params, input.mu, input.family.as_ref())
        .map_err(|e| FigureError::Input(e.to_string()))?;
    let curves = spectra(&specs, &input.grid.values(), method)?;
    let reference = reference_curve(&curves, input);
    let has_free_member = curves.iter().any(|c| !c.spec.params.pounding());
    let shaded = bands(&curves[reference].points, input.grid.step);
    let panels = QUANTITIES
        .iter()
        .enumerate()
        .map(|(q, (title, y))| {
            let mut panel = Panel::new(q, *title, "Π_ω1", y);
            for (i, c) in curves.iter().enumerate() {
                let stroke = if c.spec.params.pounding() {
                    Stroke::Solid
                } else {
                    Stroke::Dashed
                };
                panel.series.push(Series::new(
                    member_label(c),
                    i,
                    stroke,
                    curve_points(&c.points, q, true, 1.0),
                ));
            }
            if !has_free_member {
                let r = &curves[reference];
                let label = match &r.spec.member {
                    Some(_) => format!("no pounding ({})", member_label(r)),
                    None => "no pounding".into(),
                };
                panel.series.push(Series::new(
                    label,
                    reference,
                    Stroke::Dashed,
                    curve_points(&r.points, q, false, 1.0),
                ));
            }
            if q < 2 {
                panel.bands = shaded.clone();
            }
            panel
        })
        .collect();
    let skip: Vec<&str> = input.family.iter().map(|f| f.key.as_str()).collect();
    let extra = match &input.family {
        Some(f) => format!(
            "; curves {} = {}; shaded: regions of the {} curve: {}",
            symbol(&f.key),
            f.members
                .iter()
                .map(|m| m.text.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            member_label(&curves[reference]),
            bands_text(&shaded)
        ),
        None => format!("; shaded: {}", bands_text(&shaded)),
    };
    Ok(Figure {
        title: title.to_string(),
        panels,
        caption: input.caption(&skip, &extra, method),
    })
}

/// Figure 7: peak displacements at a_p = 0.2, 0.5 and 0.8 g in metres
/// ((a), (c): X_max = Π_u a_p/ω_p²) and dimensionless ((b), (d)), with and
/// without pounding. The yield drifts and the gap scale with a_p (similar
/// structures), so every level has the same Π-groups, computed apart.
pub fn fig7(grid: Option<Grid>, method: Method) -> Result<Figure, FigureError> {
    let input = SpectrumInput::builtin("fig7", grid)?;
    let amplitudes: Vec<f64> = FIG7_LEVELS.iter().map(|g| g * G).collect();
    let physical = Physical::from_params(&input.params, amplitudes[0], FIG7_OMEGA_P, 1.0);
    let runs = levels(
        &physical,
        &input.params,
        &amplitudes,
        &input.grid.values(),
        input.mu,
        method,
    )?;
    let panel_specs: [(&str, &str, usize, bool); 4] = [
        ("Left structure, dimensional", "X_max,1 (m)", 0, true),
        ("Left structure, dimensionless", "Π_u1", 0, false),
        ("Right structure, dimensional", "X_max,2 (m)", 2, true),
        ("Right structure, dimensionless", "Π_u2", 2, false),
    ];
    let shaded = bands(&runs[0].curve.points, input.grid.step);
    let panels = panel_specs
        .iter()
        .enumerate()
        .map(|(i, (title, y, q, metres))| {
            let mut panel = Panel::new(i, *title, "Π_ω1", y);
            for (k, level) in runs.iter().enumerate() {
                let scale = if *metres { level.length_scale() } else { 1.0 };
                let ap = format!("a_p = {}g", FIG7_LEVELS[k]);
                panel.series.push(Series::new(
                    ap.clone(),
                    k,
                    Stroke::Solid,
                    curve_points(&level.curve.points, *q, true, scale),
                ));
                panel.series.push(Series::new(
                    format!("{ap}, no pounding"),
                    k,
                    Stroke::Dashed,
                    curve_points(&level.curve.points, *q, false, scale),
                ));
            }
            if *q == 0 {
                panel.bands = shaded.clone();
            }
            panel
        })
        .collect();
    let extra = format!(
        "; a_p = 0.2g, 0.5g, 0.8g at ω_p = 2π rad/s, yield drifts and gap scaled with a_p; shaded: {}",
        bands_text(&shaded)
    );
    Ok(Figure {
        title:
            "Figure 7: dimensional and dimensionless peak displacements at three excitation levels"
                .into(),
        panels,
        caption: input.caption(&[], &extra, method),
    })
}
