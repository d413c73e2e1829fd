//! What a figure shows, before any drawing: panels, their axes, series and
//! shaded bands, a legend and a caption. Builders fill it from computed
//! runs; [`super::render`] draws it with plotters. Tests can count what is
//! here and what ends up in the SVG.

use crate::analysis::spectrum::Region;

/// How a series is stroked: solid (with pounding) or dashed (no pounding).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Stroke {
    Solid,
    Dashed,
}

/// One curve of a panel.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; series with the same label and style share one legend entry.
    pub label: String,
    /// Index into the figure palette; a dashed series of the same index is
    /// drawn in a darker shade of the same hue.
    pub color: usize,
    pub stroke: Stroke,
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(
        label: impl Into<String>,
        color: usize,
        stroke: Stroke,
        points: Vec<(f64, f64)>,
    ) -> Self {
        Series {
            label: label.into(),
            color,
            stroke,
            points,
        }
    }

    /// The key of this series' legend entry.
    pub fn legend_key(&self) -> (String, usize, Stroke) {
        (self.label.clone(), self.color, self.stroke)
    }
}

/// A shaded Π_ω1 interval of a spectrum panel: one run of consecutive grid
/// points in the same spectral region (SPEC §7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    pub region: Region,
    pub from: f64,
    pub to: f64,
}

/// One cell of a region map: a rectangle of the (x, y) plane in one region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub region: Region,
}

/// One panel: "(a)" to "(d)", its title, axis labels and content.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// "(a)", "(b)", ...
    pub tag: String,
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub bands: Vec<Band>,
    /// Region-map cells, drawn under the series.
    pub cells: Vec<Cell>,
    /// A fixed x range; `None` spans the data.
    pub x_range: Option<(f64, f64)>,
    /// A fixed y range; `None` spans the data.
    pub y_range: Option<(f64, f64)>,
}

impl Panel {
    pub fn new(index: usize, title: impl Into<String>, x_label: &str, y_label: &str) -> Panel {
        Panel {
            tag: format!("({})", (b'a' + index as u8) as char),
            title: title.into(),
            x_label: x_label.to_string(),
            y_label: y_label.to_string(),
            series: Vec::new(),
            bands: Vec::new(),
            cells: Vec::new(),
            x_range: None,
            y_range: None,
        }
    }
}

/// A whole figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub title: String,
    pub panels: Vec<Panel>,
    /// The caption line(s): parameters, contact law, method, grid.
    pub caption: String,
}

/// One entry of the figure's shared legend.
#[derive(Debug, Clone, PartialEq)]
pub enum LegendEntry {
    Line {
        label: String,
        color: usize,
        stroke: Stroke,
    },
    Region(Region),
}

impl LegendEntry {
    pub fn label(&self) -> String {
        match self {
            LegendEntry::Line { label, .. } => label.clone(),
            LegendEntry::Region(r) => region_label(*r).to_string(),
        }
    }
}

/// The legend text of a shaded region.
pub fn region_label(r: Region) -> &'static str {
    match r {
        Region::Amplification => "amplification region (Π_u1 up > 2 %)",
        Region::Suppression => "suppression region (Π_u1 down > 2 %)",
        Region::None => "no influence",
    }
}

impl Figure {
    /// The shared legend: each distinct series (label, colour, stroke) once,
    /// in order of first appearance, then each shaded region once.
    pub fn legend(&self) -> Vec<LegendEntry> {
        let mut seen = Vec::new();
        let mut entries = Vec::new();
        for s in self.panels.iter().flat_map(|p| &p.series) {
            let key = s.legend_key();
            if !seen.contains(&key) {
                seen.push(key);
                entries.push(LegendEntry::Line {
                    label: s.label.clone(),
                    color: s.color,
                    stroke: s.stroke,
                });
            }
        }
        for r in [Region::Amplification, Region::Suppression] {
            if self.panels.iter().any(|p| {
                p.bands.iter().any(|b| b.region == r) || p.cells.iter().any(|c| c.region == r)
            }) {
                entries.push(LegendEntry::Region(r));
            }
        }
        entries
    }
}
