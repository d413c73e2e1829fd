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

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Pen {
    /// A line in its palette colour.
    Line,
    /// A thin grey line, one of many alike (each record of a suite); its
    /// colour index is not used.
    Faint,
    /// A marker at each point and no line (observed values): filled when
    /// solid, hollow when dashed.
    Markers,
}

/// One curve of a panel.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; series with the same label, colour and stroke share one
    /// legend entry (a line with a marker when one is a line and the other
    /// markers).
    pub label: String,
    /// Index into the figure palette; a dashed series of the same index is
    /// drawn in a darker shade of the same hue.
    pub color: usize,
    pub stroke: Stroke,
    pub pen: Pen,
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
            pen: Pen::Line,
            points,
        }
    }

    /// The same series drawn with `pen`.
    pub fn with_pen(mut self, pen: Pen) -> Self {
        self.pen = pen;
        self
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

/// A shaded area of a panel (a 16–84 % band): the polygon `outline`,
/// filled with a light tint of the colour of series `color`, `stroke`.
#[derive(Debug, Clone, PartialEq)]
pub struct Area {
    /// Legend text (one entry per distinct label, colour and stroke).
    pub label: String,
    pub color: usize,
    pub stroke: Stroke,
    pub outline: Vec<(f64, f64)>,
}

/// Where a guide lies: x = value (vertical) or y = value (horizontal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GuideAt {
    X(f64),
    Y(f64),
}

/// A straight reference line across a panel (a gap, a code rule, a
/// probability), a thin line in palette colour `color` (`None`: grey), with
/// a short `tag` written beside it and a `label` in the legend (none when
/// empty).
#[derive(Debug, Clone, PartialEq)]
pub struct Guide {
    pub at: GuideAt,
    pub color: Option<usize>,
    pub tag: String,
    pub label: String,
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
    /// Shaded areas, drawn under the series.
    pub areas: Vec<Area>,
    /// Reference lines, drawn under the series.
    pub guides: Vec<Guide>,
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
            areas: Vec::new(),
            guides: Vec::new(),
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
    /// A series: its line (`Pen::Line` or `Pen::Faint`; `None` for markers
    /// only) and whether markers go with it.
    Line {
        label: String,
        color: usize,
        stroke: Stroke,
        line: Option<Pen>,
        markers: bool,
    },
    /// A shaded area.
    Area {
        label: String,
        color: usize,
        stroke: Stroke,
    },
    /// A reference line.
    Guide {
        label: String,
        color: Option<usize>,
    },
    Region(Region),
}

impl LegendEntry {
    pub fn label(&self) -> String {
        match self {
            LegendEntry::Line { label, .. }
            | LegendEntry::Area { label, .. }
            | LegendEntry::Guide { label, .. } => label.clone(),
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
    /// in order of first appearance, then each shaded area, each labelled
    /// guide and each shaded region once.
    pub fn legend(&self) -> Vec<LegendEntry> {
        let mut seen = Vec::new();
        let mut entries: Vec<LegendEntry> = Vec::new();
        for s in self.panels.iter().flat_map(|p| &p.series) {
            let key = s.legend_key();
            let index = match seen.iter().position(|k| *k == key) {
                Some(i) => i,
                None => {
                    seen.push(key);
                    entries.push(LegendEntry::Line {
                        label: s.label.clone(),
                        color: s.color,
                        stroke: s.stroke,
                        line: None,
                        markers: false,
                    });
                    entries.len() - 1
                }
            };
            if let LegendEntry::Line { line, markers, .. } = &mut entries[index] {
                match s.pen {
                    Pen::Markers => *markers = true,
                    pen => *line = line.or(Some(pen)),
                }
            }
        }
        for a in self.panels.iter().flat_map(|p| &p.areas) {
            let entry = LegendEntry::Area {
                label: a.label.clone(),
                color: a.color,
                stroke: a.stroke,
            };
            if !entries.contains(&entry) {
                entries.push(entry);
            }
        }
        for g in self.panels.iter().flat_map(|p| &p.guides) {
            let entry = LegendEntry::Guide {
                label: g.label.clone(),
                color: g.color,
            };
            if !g.label.is_empty() && !entries.contains(&entry) {
                entries.push(entry);
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
