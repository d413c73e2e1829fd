//! Figures as files: the paper's Figures 3–10 and the explorer's scenes,
//! drawn with plotters as SVG or PNG. A library layer above [`crate::analysis`];
//! it knows nothing of terminals.
//!
//! - [`spec`]: what a figure shows (panels, series, bands, legend, caption);
//! - [`runs`]: the runs behind it, with the chosen integrator;
//! - [`history`]: Figures 3–6 and the scenes `history`, `loops`, `contact-laws`;
//! - [`spectra`]: Figures 7–10 and the scene `spectrum`, regions shaded;
//! - [`risk`]: a suite study's IDA curves, fragility curves and separation;
//! - [`matching`]: a suite against its target spectrum (`figure match`);
//! - [`risk_row`]: the same three figures of a row of buildings;
//! - [`risk_compare`]: the same three figures of several variants of a row, overlaid;
//! - [`caption`]: the caption line (every Π, the law, the method);
//! - [`render`]: plotters, SVG and bitmap back ends;
//! - [`font`]: the embedded typeface (no system fonts needed);
//!
//! ```no_run
//! use pounding::figure::{FigureName, Options, Format, build, encode};
//! let fig = build(FigureName::Fig3, &Options::default()).unwrap();
//! let png = encode(&fig, Format::Png, (1200, 900)).unwrap();
//! ```

pub mod buildings;
pub mod caption;
pub mod font;
pub mod history;
pub mod map;
pub mod matching;
pub mod render;
pub mod retrofit_map;
pub mod risk;
pub mod risk_compare;
pub mod risk_row;
pub mod runs;
pub mod spec;
pub mod spectra;

use std::fmt;
use std::str::FromStr;

use crate::analysis::grid::Grid;
use crate::model::{Method, Params};

pub use risk::SuiteStudy;
pub use risk_row::RowSuiteStudy;
pub use spec::{Band, Figure, LegendEntry, Panel, Pen, Series, Stroke};
pub use spectra::SpectrumInput;

/// Why a figure could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FigureError {
    /// Bad input (a name, a size, a preset): exit code 2 at the command line.
    #[error("{0}")]
    Input(String),
    /// A run that cannot be trusted (stopped early, non-finite, energy not balanced).
    #[error("a run failed: {0}")]
    Run(String),
    #[error("drawing failed: {0}")]
    Draw(String),
}

/// Every figure `pounding figure` can draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FigureName {
    Fig3,
    Fig4,
    Fig5,
    Fig6,
    Fig7,
    Fig8,
    Fig9,
    Fig10,
    History,
    Loops,
    ContactLaws,
    Spectrum,
    Map,
    Ida,
    Fragility,
    Separation,
}

impl FigureName {
    /// The paper's figures, in order (what `figure all` writes).
    pub const PAPER: [FigureName; 8] = [
        FigureName::Fig3,
        FigureName::Fig4,
        FigureName::Fig5,
        FigureName::Fig6,
        FigureName::Fig7,
        FigureName::Fig8,
        FigureName::Fig9,
        FigureName::Fig10,
    ];
    /// The figures of a suite study (SPEC §11, §12), drawn from
    /// [`Options::suite`].
    pub const RISK: [FigureName; 3] = [
        FigureName::Ida,
        FigureName::Fragility,
        FigureName::Separation,
    ];
    /// The scenes, drawn for any parameter set.
    pub const SCENES: [FigureName; 5] = [
        FigureName::History,
        FigureName::Loops,
        FigureName::ContactLaws,
        FigureName::Spectrum,
        FigureName::Map,
    ];

    pub fn name(self) -> &'static str {
        match self {
            FigureName::Fig3 => "fig3",
            FigureName::Fig4 => "fig4",
            FigureName::Fig5 => "fig5",
            FigureName::Fig6 => "fig6",
            FigureName::Fig7 => "fig7",
            FigureName::Fig8 => "fig8",
            FigureName::Fig9 => "fig9",
            FigureName::Fig10 => "fig10",
            FigureName::History => "history",
            FigureName::Loops => "loops",
            FigureName::ContactLaws => "contact-laws",
            FigureName::Spectrum => "spectrum",
            FigureName::Map => "map",
            FigureName::Ida => "ida",
            FigureName::Fragility => "fragility",
            FigureName::Separation => "separation",
        }
    }

    pub fn is_paper(self) -> bool {
        FigureName::PAPER.contains(&self)
    }

    /// Whether the figure draws a suite study.
    pub fn is_risk(self) -> bool {
        FigureName::RISK.contains(&self)
    }

    /// Whether the figure is a spectrum (many runs; its grid can be set).
    pub fn is_spectrum(self) -> bool {
        matches!(
            self,
            FigureName::Fig7
                | FigureName::Fig8
                | FigureName::Fig9
                | FigureName::Fig10
                | FigureName::Spectrum
                | FigureName::Map
        )
    }

    /// Every accepted name, for messages.
    pub fn allowed() -> String {
        let names: Vec<&str> = FigureName::PAPER
            .iter()
            .chain(&FigureName::SCENES)
            .chain(&FigureName::RISK)
            .map(|n| n.name())
            .collect();
        format!("{}, all", names.join(", "))
    }
}

impl fmt::Display for FigureName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for FigureName {
    type Err = FigureError;
    fn from_str(s: &str) -> Result<Self, FigureError> {
        FigureName::PAPER
            .iter()
            .chain(&FigureName::SCENES)
            .chain(&FigureName::RISK)
            .copied()
            .find(|n| n.name() == s.trim())
            .ok_or_else(|| {
                FigureError::Input(format!(
                    "figure `{s}`: unknown; must be one of {}",
                    FigureName::allowed()
                ))
            })
    }
}

/// An output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    Svg,
    Png,
}

impl Format {
    pub fn extension(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Png => "png",
        }
    }
}

/// The scenes' parameter set, and the spectrum scene's sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The preset's name, for the title and caption.
    pub name: String,
    pub params: Params,
    /// The spectrum scene's μ, family and grid.
    pub spectrum: Option<SpectrumInput>,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            name: "set1".into(),
            params: crate::model::SET1,
            spectrum: None,
        }
    }
}

/// How to compute a figure.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Options {
    pub method: Method,
    /// Overrides the Π_ω1 grid of the paper's spectrum figures (a coarse
    /// grid previews them quickly).
    pub grid: Option<Grid>,
    pub scene: Scene,
    /// The suite study of `ida`, `fragility` and `separation`.
    pub suite: Option<RiskStudy>,
}

/// A suite study: of the pair of buildings, or of a row.
// Made once per figure: the variants' sizes do not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum RiskStudy {
    Pair(SuiteStudy),
    Row(RowSuiteStudy),
    /// The same study on each variant of a row (`--compare`), overlaid.
    Compare(Vec<risk_compare::Variant>),
}

/// Computes a figure.
pub fn build(name: FigureName, options: &Options) -> Result<Figure, FigureError> {
    let m = options.method;
    let scene = &options.scene;
    let paper = |preset: &str, title: &str| {
        let input = SpectrumInput::builtin(preset, options.grid)?;
        spectra::family_figure(title, &input, m)
    };
    match name {
        FigureName::Fig3 => history::fig3(m),
        FigureName::Fig4 => history::fig4_5(4, m),
        FigureName::Fig5 => history::fig4_5(5, m),
        FigureName::Fig6 => history::fig6(m),
        FigureName::Fig7 => spectra::fig7(options.grid, m),
        FigureName::Fig8 => paper(
            "fig8-gap",
            "Figure 8: spectra for gaps Π_d = 0.2, 1.5 and no pounding",
        ),
        FigureName::Fig9 => paper(
            "fig9-mass-ratio",
            "Figure 9: spectra for mass ratios Π_m = 0.1, 0.5, 0.9",
        ),
        FigureName::Fig10 => paper(
            "fig10-frequency-ratio",
            "Figure 10: spectra for frequency ratios μ = 1.5, 4, 10",
        ),
        FigureName::History => history::history_scene(&scene.name, &scene.params, m),
        FigureName::Loops => history::loops_scene(&scene.name, &scene.params, m),
        FigureName::ContactLaws => history::contact_laws_scene(&scene.name, &scene.params, m),
        FigureName::Spectrum => {
            let input = scene.spectrum.clone().unwrap_or_else(|| SpectrumInput {
                name: scene.name.clone(),
                params: scene.params.clone(),
                mu: scene.params.mu(),
                family: None,
                grid: options.grid.unwrap_or_default(),
            });
            spectra::family_figure(&format!("{}: response spectra", input.name), &input, m)
        }
        FigureName::Map => map::map_scene(&scene.name, &scene.params, options.grid, m),
        FigureName::Ida | FigureName::Fragility | FigureName::Separation => {
            let study = options.suite.as_ref().ok_or_else(|| {
                FigureError::Input(format!(
                    "figure {name}: draws a suite study; give --preset (with [physical]) and --suite"
                ))
            })?;
            match (name, study) {
                (FigureName::Ida, RiskStudy::Pair(s)) => risk::ida_figure(s),
                (FigureName::Fragility, RiskStudy::Pair(s)) => risk::fragility_figure(s),
                (_, RiskStudy::Pair(s)) => risk::separation_figure(s),
                (FigureName::Ida, RiskStudy::Row(s)) => risk_row::row_ida_figure(s),
                (FigureName::Fragility, RiskStudy::Row(s)) => risk_row::row_fragility_figure(s),
                (_, RiskStudy::Row(s)) => risk_row::row_separation_figure(s),
                (FigureName::Ida, RiskStudy::Compare(v)) => risk_compare::compare_ida_figure(v),
                (FigureName::Fragility, RiskStudy::Compare(v)) => {
                    risk_compare::compare_fragility_figure(v)
                }
                (_, RiskStudy::Compare(v)) => risk_compare::compare_separation_figure(v),
            }
        }
    }
}

/// Checks a canvas size against [`render::MIN_SIDE`]..=[`render::MAX_SIDE`].
pub fn check_size(width: u32, height: u32) -> Result<(u32, u32), FigureError> {
    for (key, v) in [("--width", width), ("--height", height)] {
        if !(render::MIN_SIDE..=render::MAX_SIDE).contains(&v) {
            return Err(FigureError::Input(format!(
                "{key} {v}: must be an integer in [{}, {}] pixels",
                render::MIN_SIDE,
                render::MAX_SIDE
            )));
        }
    }
    Ok((width, height))
}

/// The figure's file contents in `format` at `size` pixels.
pub fn encode(fig: &Figure, format: Format, size: (u32, u32)) -> Result<Vec<u8>, FigureError> {
    match format {
        Format::Svg => render::svg(fig, size).map(String::into_bytes),
        Format::Png => render::png(fig, size),
    }
}
