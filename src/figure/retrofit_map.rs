//! `figure map --buildings`: a row's retrofit map (SPEC §12, §14) as
//! families of curves, each quantity against the x key, one curve per
//! value of the y key: (a) P(pounding) per joint, (b) the median peak
//! drift ratio and (c) the median peak floor acceleration per building
//! (the first building solid, the others dashed), (d) the median peak
//! force per link. The cells are [`crate::analysis::suite_map::row`]'s,
//! the same as `pounding map --buildings` prints.

use super::spec::{Figure, Panel, Series, Stroke};
use crate::analysis::suite_map::{MapAxis, RowMapCell};
use crate::model::params::echo::g4;

/// What the map is of: the row, the suite and its scaling, and the names
/// of its joints, buildings and links.
#[derive(Debug, Clone)]
pub struct RetrofitMap<'a> {
    pub row: &'a str,
    /// `synthetic:20 (20 records, each scaled to pga = 0.3 g)`.
    pub suite: String,
    pub joints: &'a [String],
    pub buildings: &'a [String],
    pub links: &'a [String],
    pub x: &'a MapAxis,
    pub y: &'a MapAxis,
    /// Row after row (y), x along each row.
    pub cells: &'a [RowMapCell],
}

/// The figure of `map`.
pub fn retrofit_map_figure(map: &RetrofitMap) -> Figure {
    type Get = fn(&RowMapCell, usize) -> f64;
    let quantities: [(&str, &[String], Get); 4] = [
        ("P(pounding)", map.joints, |c, i| c.pounding_probability[i]),
        ("median peak drift ratio (%)", map.buildings, |c, i| {
            100.0 * c.median_drift_ratio[i]
        }),
        (
            "median peak floor acceleration (g)",
            map.buildings,
            |c, i| c.median_acceleration_g[i],
        ),
        ("median peak link force (kN)", map.links, |c, i| {
            c.median_link_force_kn[i]
        }),
    ];
    let width = map.x.values.len();
    let panels = quantities
        .iter()
        .filter(|(_, names, _)| !names.is_empty())
        .enumerate()
        .map(|(p, (title, names, get))| {
            let mut panel = Panel::new(p, *title, &map.x.key, title);
            if names == &map.joints {
                panel.y_range = Some((0.0, 1.05));
            }
            for (i, name) in names.iter().enumerate() {
                for (row, yv) in map.y.values.iter().enumerate() {
                    let points = map.cells[row * width..(row + 1) * width]
                        .iter()
                        .map(|c| (c.x, get(c, i)))
                        .collect();
                    let stroke = if i == 0 {
                        Stroke::Solid
                    } else {
                        Stroke::Dashed
                    };
                    let label = format!("{name}, {} = {}", map.y.key, g4(*yv));
                    panel.series.push(Series::new(label, row, stroke, points));
                }
            }
            panel
        })
        .collect();
    Figure {
        title: format!(
            "{}: what a retrofit buys over {} and {}",
            map.row, map.x.key, map.y.key
        ),
        panels,
        caption: format!(
            "suite {}; {} × {} cells; medians over the records, with contact (SPEC §12, §14)",
            map.suite,
            width,
            map.y.values.len()
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_curve_per_name_and_y_value() {
        let x = MapAxis {
            key: "link1.damping".into(),
            values: vec![1e6, 2e6, 3e6],
        };
        let y = MapAxis {
            key: "joint1.gap".into(),
            values: vec![0.004, 0.005],
        };
        let cells: Vec<RowMapCell> = (0..6)
            .map(|k| RowMapCell {
                x: x.values[k % 3],
                y: y.values[k / 3],
                pounding_probability: vec![0.5],
                median_drift_ratio: vec![0.001, 0.002 * k as f64],
                median_acceleration_g: vec![1.0, 2.0],
                median_link_force_kn: vec![100.0 * k as f64],
                records: 4,
            })
            .collect();
        let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let (joints, buildings, links) = (
            names(&["joint1"]),
            names(&["block", "frame"]),
            names(&["link1"]),
        );
        let fig = retrofit_map_figure(&RetrofitMap {
            row: "r",
            suite: "s".into(),
            joints: &joints,
            buildings: &buildings,
            links: &links,
            x: &x,
            y: &y,
            cells: &cells,
        });
        let counts: Vec<usize> = fig.panels.iter().map(|p| p.series.len()).collect();
        assert_eq!(counts, vec![2, 4, 4, 2]);
        // The frame's drift at the second gap, in %: cells 3, 4, 5.
        let frame = &fig.panels[1].series[3];
        assert_eq!(frame.stroke, Stroke::Dashed);
        assert_eq!(frame.points[2], (3e6, 100.0 * 0.002 * 5.0));
        assert_eq!(fig.panels[3].series[1].points[0], (1e6, 300.0));
    }
}
