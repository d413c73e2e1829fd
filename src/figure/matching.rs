//! `figure match`: a suite against its target spectrum (SPEC §12,
//! [`crate::analysis::record_scaling`]). One panel, Sa (g) against T (s):
//! each record's spectrum at its factor in grey, the suite's mean and its
//! 16–84 % band, the target, the band between the target and 90 % of it
//! over the rule's range shaded, and T1 and the range's ends marked. The
//! caption gives the rule's verdict, its worst ratio and where.

use super::FigureError;
use super::spec::{Area, Figure, Guide, GuideAt, Panel, Series, Stroke};
use crate::analysis::record_scaling::{Binding, Design, FRACTION, Matching, spectra};
use crate::analysis::statistics::quantile;
use crate::model::params::echo::g4;
use crate::model::suite::SuiteMember;

/// Periods drawn (s), evenly spaced, besides the rule's grid.
const DRAWN: usize = 160;

/// The periods drawn: from the target's first period (at least 0.01 s) to
/// twice the range's top (within the target), with the rule's grid.
fn drawn_periods(design: &Design, matching: &Matching) -> Vec<f64> {
    let (first, last) = design.target.periods();
    let low = first.max(0.01);
    let high = (2.0 * design.range.high * design.period).min(last);
    let mut periods: Vec<f64> = (0..DRAWN)
        .map(|k| low + (high - low) * k as f64 / (DRAWN - 1) as f64)
        .chain(matching.periods.iter().copied())
        .collect();
    periods.sort_by(f64::total_cmp);
    periods.dedup();
    periods
}

/// The figure of `members` at the factors of `matching` against `design`.
pub fn match_figure(
    suite: &str,
    design: &Design,
    members: &[SuiteMember],
    matching: &Matching,
) -> Result<Figure, FigureError> {
    let periods = drawn_periods(design, matching);
    let factors: Vec<f64> = matching.records.iter().map(|r| r.factor).collect();
    let scaled: Vec<Vec<f64>> = spectra(members, &periods)
        .into_iter()
        .zip(&factors)
        .map(|(s, f)| s.into_iter().map(|v| f * v).collect())
        .collect();
    let target: Vec<f64> = periods
        .iter()
        .map(|&t| design.target.sa(t).unwrap_or(f64::NAN))
        .collect();
    let points = |values: &[f64]| -> Vec<(f64, f64)> {
        periods
            .iter()
            .copied()
            .zip(values.iter().copied())
            .collect()
    };
    let mut panel = Panel::new(
        0,
        format!(
            "{} records against {}",
            members.len(),
            design.target.label()
        ),
        "Period T (s)",
        "Sa, 5 % damped (g)",
    );
    for s in &scaled {
        panel.series.push(
            Series::new("each record at its factor", 0, Stroke::Solid, points(s))
                .with_pen(super::Pen::Faint),
        );
    }
    let column = |k: usize| -> Vec<f64> {
        let mut c: Vec<f64> = scaled.iter().map(|s| s[k]).collect();
        c.sort_by(f64::total_cmp);
        c
    };
    let n = scaled.len() as f64;
    let mean: Vec<f64> = (0..periods.len())
        .map(|k| scaled.iter().map(|s| s[k]).sum::<f64>() / n)
        .collect();
    let mut band: Vec<(f64, f64)> = (0..periods.len())
        .map(|k| (periods[k], quantile(&column(k), 0.16)))
        .collect();
    band.extend(
        (0..periods.len())
            .rev()
            .map(|k| (periods[k], quantile(&column(k), 0.84))),
    );
    panel.areas.push(Area {
        label: "16–84 % of the records".into(),
        color: 0,
        stroke: Stroke::Solid,
        outline: band,
    });
    let (low, high) = (
        design.range.low * design.period,
        design.range.high * design.period,
    );
    let inside: Vec<usize> = (0..periods.len())
        .filter(|&k| periods[k] >= low && periods[k] <= high)
        .collect();
    let mut shaded: Vec<(f64, f64)> = inside.iter().map(|&k| (periods[k], target[k])).collect();
    shaded.extend(
        inside
            .iter()
            .rev()
            .map(|&k| (periods[k], FRACTION * target[k])),
    );
    panel.areas.push(Area {
        label: format!("target to {} % of it, over the range", FRACTION * 100.0),
        color: 1,
        stroke: Stroke::Dashed,
        outline: shaded,
    });
    panel
        .series
        .push(Series::new("suite mean", 0, Stroke::Solid, points(&mean)));
    panel.series.push(Series::new(
        design.target.label(),
        1,
        Stroke::Solid,
        points(&target),
    ));
    panel.series.push(Series::new(
        format!("{} % of the target", FRACTION * 100.0),
        1,
        Stroke::Dashed,
        inside
            .iter()
            .map(|&k| (periods[k], FRACTION * target[k]))
            .collect(),
    ));
    for (t, tag) in [
        (design.period, format!("T1 = {} s", g4(design.period))),
        (low, format!("{}·T1", design.range.low)),
        (high, format!("{}·T1", design.range.high)),
    ] {
        panel.guides.push(Guide {
            at: GuideAt::X(t),
            color: None,
            tag,
            label: String::new(),
        });
    }
    let c = &matching.check;
    let verdict = c.verdict();
    Ok(Figure {
        title: format!("Suite {suite} against its target spectrum"),
        panels: vec![panel],
        caption: format!(
            "{} at T1 = {} s, range {}–{} s; {}; mean/target min {:.4} at T = {} s; {verdict}",
            design.target.label(),
            g4(design.period),
            g4(low),
            g4(high),
            match matching.binding {
                Binding::List => "records at their list's scales".to_string(),
                _ => format!(
                    "records at their factors (common factor {})",
                    g4(matching.common_factor)
                ),
            },
            c.min_ratio,
            g4(c.at_period_s)
        ),
    })
}
