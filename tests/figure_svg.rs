//! Every figure as SVG: it parses as XML and holds the paper's panels, one
//! stroke colour per series, one legend entry per series and region, and
//! every axis label. The spectrum figures run on a coarse Π_ω1 grid (16
//! points) to keep the test short; their structure does not depend on it.

use std::collections::BTreeSet;

use pounding::figure::{self, Figure, FigureName, Options, SpectrumInput};

/// Stroke colours that are not series: axes and the grid.
const FRAME_COLORS: [&str; 2] = ["#000000", "#E1E1E1"];

struct Svg {
    texts: Vec<String>,
    series_colors: BTreeSet<String>,
}

fn parse(svg: &str) -> Svg {
    let doc = roxmltree::Document::parse(svg).expect("the SVG is well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let texts = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "text")
        .map(|n| n.text().unwrap_or("").trim().to_string())
        .collect();
    let series_colors = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "polyline")
        .filter_map(|n| n.attribute("stroke"))
        .filter(|c| !FRAME_COLORS.contains(c))
        .map(str::to_string)
        .collect();
    Svg {
        texts,
        series_colors,
    }
}

fn coarse() -> Options {
    Options {
        grid: Some("0.5:2.0:0.1".parse().unwrap()),
        ..Options::default()
    }
}

/// Builds `name`, renders it as SVG and checks it against the counts
/// expected from the paper's figure.
fn check(
    name: FigureName,
    options: &Options,
    panels: usize,
    series: usize,
    regions: usize,
) -> Figure {
    let fig = figure::build(name, options).unwrap();
    let svg = parse(&figure::render::svg(&fig, (1200, 900)).unwrap());
    // Panels: one title "(a) …", "(b) …" each.
    let tags: Vec<&String> = svg
        .texts
        .iter()
        .filter(|t| t.len() > 3 && t.starts_with('(') && t.as_bytes()[2] == b')')
        .collect();
    assert_eq!(tags.len(), panels, "{name}: panel titles {tags:?}");
    assert_eq!(fig.panels.len(), panels);
    // Series: one stroke colour each.
    assert_eq!(
        svg.series_colors.len(),
        series,
        "{name}: {:?}",
        svg.series_colors
    );
    // Legend: every series style and region once.
    let legend = fig.legend();
    assert_eq!(legend.len(), series + regions, "{name}: legend {legend:?}");
    for entry in &legend {
        let n = svg.texts.iter().filter(|t| **t == entry.label()).count();
        assert_eq!(
            n,
            1,
            "{name}: legend entry `{}` appears {n} times",
            entry.label()
        );
    }
    // Axis labels.
    for p in &fig.panels {
        for label in [&p.x_label, &p.y_label] {
            assert!(
                svg.texts.contains(label),
                "{name}: axis label `{label}` missing"
            );
        }
    }
    // The caption names the method.
    assert!(fig.caption.contains("Newmark-β"), "{name}: {}", fig.caption);
    fig
}

#[test]
fn paper_history_figures() {
    let o = Options::default();
    let fig3 = check(FigureName::Fig3, &o, 4, 3, 0);
    assert_eq!(fig3.panels[0].y_label, "x1, x2");
    assert_eq!(fig3.panels[2].x_label, "x1");
    check(FigureName::Fig4, &o, 4, 3, 0);
    check(FigureName::Fig5, &o, 4, 3, 0);
    let fig6 = check(FigureName::Fig6, &o, 2, 2, 0);
    // The enlarged impact shows the Kelvin element pulling (f_p < 0).
    let kelvin_min = fig6.panels[1].series[1]
        .points
        .iter()
        .map(|p| p.1)
        .fold(f64::MAX, f64::min);
    let improved_min = fig6.panels[1].series[0]
        .points
        .iter()
        .map(|p| p.1)
        .fold(f64::MAX, f64::min);
    assert!(kelvin_min < -1.0, "{kelvin_min}");
    assert!(improved_min >= -1e-9, "{improved_min}");
}

#[test]
fn scenes() {
    let o = Options::default();
    check(FigureName::History, &o, 2, 5, 0);
    check(FigureName::Loops, &o, 2, 2, 0);
    check(FigureName::ContactLaws, &o, 2, 2, 0);
}

#[test]
fn paper_spectrum_figures_on_a_coarse_grid() {
    let o = coarse();
    // Figure 7: three levels, each with and without pounding; both regions.
    let fig7 = check(FigureName::Fig7, &o, 4, 6, 2);
    // Dimensionless curves coincide across levels (SPEC §8); dimensional ones scale 1 : 2.5 : 4.
    let b = &fig7.panels[1].series;
    for (p, q) in b[0].points.iter().zip(&b[4].points) {
        assert!(
            (p.1 - q.1).abs() <= 1e-9 * p.1.abs().max(1.0),
            "{p:?} {q:?}"
        );
    }
    let a = &fig7.panels[0].series;
    let ratio = a[4].points[5].1 / a[0].points[5].1;
    assert!((ratio - 4.0).abs() < 1e-9, "{ratio}");
    // The bands lie where the guide's region table (docs/src/verification.md) puts them (within the coarse step).
    let amp = fig7.panels[0]
        .bands
        .iter()
        .find(|b| b.region.name() == "amplification")
        .unwrap();
    assert!((amp.from - 0.5).abs() <= 0.05 + 1e-9, "{amp:?}");
    check(FigureName::Fig8, &o, 4, 3, 2);
    check(FigureName::Fig9, &o, 4, 4, 2);
    check(FigureName::Fig10, &o, 4, 4, 2);
}

#[test]
fn spectrum_scene_with_a_family() {
    let p = pounding::model::SET1;
    let family = pounding::analysis::family::Family::parse("gap=0.2,inf", &p).unwrap();
    let o = Options {
        scene: figure::Scene {
            name: "set1".into(),
            params: p.clone(),
            spectrum: Some(SpectrumInput {
                name: "set1".into(),
                params: p,
                mu: 2.25,
                family: Some(family),
                grid: "0.5:2.0:0.1".parse().unwrap(),
            }),
        },
        ..Options::default()
    };
    // Two members, the gap = inf one dashed (its own baseline).
    check(FigureName::Spectrum, &o, 4, 2, 2);
}

#[test]
fn map_scene_shades_the_regions_of_each_cell() {
    let o = Options {
        grid: Some("0.5:1.5:0.25".parse().unwrap()),
        ..Options::default()
    };
    // One panel, the set's marker, both regions shaded.
    let fig = check(FigureName::Map, &o, 1, 1, 2);
    let panel = &fig.panels[0];
    // The μ row of the set itself (2.25) agrees with the spectrum there.
    let p = figure::Scene::default().params;
    let row: Vec<_> = panel
        .cells
        .iter()
        .filter(|c| ((c.y.0 + c.y.1) / 2.0 - 2.25).abs() < 1e-9)
        .collect();
    assert!(row.len() >= 3, "{} shaded cells at μ = 2.25", row.len());
    for cell in row {
        let omega1 = (cell.x.0 + cell.x.1) / 2.0;
        let point = pounding::analysis::spectrum::point(&p, omega1, 2.25);
        assert_eq!(point.region, cell.region, "Π_ω1 = {omega1}");
    }
    assert!(fig.caption.contains("5 × 37 cells"), "{}", fig.caption);
}
