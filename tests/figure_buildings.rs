//! `figure buildings` (SPEC §13): the impact panel draws the contact force of
//! each floor pair over time, from the exact method's force history. Each
//! pair that pounds has one polyline whose largest point is the run's
//! `max_force` of that pair: exactly in the figure's data, and within 1.5
//! pixels of the force axis in the SVG (whose coordinates are whole pixels;
//! the axis is read back from its own tick marks and labels).

use pounding::figure::buildings::row_figure;
use pounding::figure::render::{series_color, svg};
use pounding::figure::spec::Stroke;
use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, run_row};

/// Points "x,y x,y …" of an SVG polyline.
fn points(node: roxmltree::Node) -> Vec<(f64, f64)> {
    node.attribute("points")
        .unwrap_or("")
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

#[test]
fn the_impact_panel_draws_each_pairs_force_over_time() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load("block-and-frame").unwrap();
    let duration = ground.end() + 2.0;
    let options = RowOptions {
        forces: true,
        ..RowOptions::lasting(duration)
    };
    let with = run_row(&row, &ground, &options).unwrap();
    // The history costs the run nothing else: the same impacts and peaks.
    let plain = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
    assert_eq!(with.pairs, plain.pairs);
    assert_eq!(with.floors, plain.floors);
    let without = run_row(&row.apart(), &ground, &RowOptions::lasting(duration)).unwrap();
    let fig = row_figure(&row, &with, &without, "test");
    let panel = &fig.panels[3];
    assert_eq!(panel.title, "impact forces");

    // In the figure's data: one series a pounding pair, its top the pair's
    // max_force (kN), and a history that rises from 0 at each onset.
    let pounding: Vec<usize> = (0..with.pairs.len())
        .filter(|&k| !with.pairs[k].impacts.is_empty())
        .collect();
    assert!(pounding.len() >= 2, "{pounding:?}");
    assert_eq!(panel.series.len(), pounding.len());
    let history = with.forces.as_ref().unwrap();
    for (series, &k) in panel.series.iter().zip(&pounding) {
        let want = with.pairs[k].max_force() / 1e3;
        let top = series.points.iter().fold(f64::MIN, |m, p| m.max(p.1));
        assert!((top - want).abs() <= 1e-12 * want, "pair {k}: {top} {want}");
        for impact in &with.pairs[k].impacts {
            assert!(history.pairs[k].contains(&(impact.start, 0.0)), "pair {k}");
        }
        // Many points a pulse, not one marker per impact.
        assert!(series.points.len() > 10 * with.pairs[k].impacts.len());
    }

    // In the SVG: the force axis from its tick marks (black, 5 px left of
    // the axis line) and their labels.
    let text = svg(&fig, (1400, 1000)).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let lines: Vec<(String, Vec<(f64, f64)>)> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "polyline")
        .map(|n| (n.attribute("stroke").unwrap_or("").to_string(), points(n)))
        .collect();
    // Panel (d)'s y axis: the long vertical black line lowest and furthest
    // right (the x axes' tick marks are short ones).
    let axis = lines
        .iter()
        .filter(|(s, p)| s == "#000000" && p.len() == 2 && p[0].0 == p[1].0)
        .filter(|(_, p)| (p[0].1 - p[1].1).abs() > 100.0)
        .map(|(_, p)| (p[0].0, p[0].1.min(p[1].1), p[0].1.max(p[1].1)))
        .fold(
            (0.0, 0.0, 0.0),
            |a, b| if (b.0, b.2) > (a.0, a.2) { b } else { a },
        );
    let (ax, top_px, bottom_px) = axis;
    let labels: Vec<(f64, f64)> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "text")
        .filter(|n| n.attribute("text-anchor") == Some("end"))
        .filter_map(|n| {
            let x: f64 = n.attribute("x")?.parse().ok()?;
            let y: f64 = n.attribute("y")?.parse().ok()?;
            let v: f64 = n.text()?.trim().parse().ok()?;
            (x < ax && x > ax - 20.0 && y >= top_px && y <= bottom_px).then_some((y, v))
        })
        .collect();
    assert!(labels.len() >= 3, "{labels:?}");
    // Least squares v = a + b·y over the labelled ticks.
    let n = labels.len() as f64;
    let (sy, sv) = labels
        .iter()
        .fold((0.0, 0.0), |a, l| (a.0 + l.0, a.1 + l.1));
    let (my, mv) = (sy / n, sv / n);
    let b = labels.iter().map(|l| (l.0 - my) * (l.1 - mv)).sum::<f64>()
        / labels.iter().map(|l| (l.0 - my).powi(2)).sum::<f64>();
    let value = |y: f64| mv + b * (y - my);
    for &k in &pounding {
        let c = series_color(row.buildings.len() + k, Stroke::Solid);
        let hex = format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
        let curve = lines
            .iter()
            .filter(|(s, _)| *s == hex)
            .map(|(_, p)| p)
            .max_by_key(|p| p.len())
            .unwrap_or_else(|| panic!("pair {k}: no polyline in {hex}"));
        assert!(curve.len() > 10, "pair {k}: {} points", curve.len());
        assert!(
            curve.iter().all(|p| p.0 > ax),
            "pair {k}: outside panel (d)"
        );
        let peak = value(curve.iter().fold(f64::MAX, |m, p| m.min(p.1)));
        let want = with.pairs[k].max_force() / 1e3;
        println!(
            "pair {k}: {peak:.1} kN drawn, {want:.1} kN run, {:.1} kN a pixel",
            b.abs()
        );
        assert!(
            (peak - want).abs() <= 1.5 * b.abs(),
            "pair {k}: {peak} kN drawn, {want} kN run ({} kN a pixel)",
            b.abs()
        );
    }
}
