//! Figures of a suite study (SPEC §11, §12): the IDA curves, the fragility
//! curves and the separation at a probability. The runs and the statistics
//! are [`crate::analysis`]'s (`suite`, `ida`, [`fragility`],
//! [`separation`]); this module only turns them into a [`Figure`].
//!
//! - [`ida_figure`]: IM against the left structure's peak drift, one faint
//!   curve per record, the median and the 16–84 % band, with pounding
//!   (solid, blue) and without (gap = ∞; dashed, orange). IM is vertical,
//!   demand horizontal (Vamvatsikos and Cornell 2002).
//! - [`fragility_figure`]: P(exceed | IM = x) = Φ(ln(x/θ)/β) of each limit
//!   state, fitted (lines) and observed k/n (markers), with pounding solid
//!   and without dashed; a limit state with no fit shows its markers and
//!   says why in the legend.
//! - [`separation_figure`]: the empirical distribution of the records'
//!   Π_d,min (mm), its lognormal fit, the gap at each probability asked, the
//!   preset's gap and the code rules on the median peaks.

use crate::analysis::fragility::{self, Fragility, LevelCount, describe};
use crate::analysis::ida::{LimitStateFragility, fragilities};
use crate::analysis::limit_state::LimitState;
use crate::analysis::separation::{
    self, LognormalFit, RecordGap, SeparationStudy, probability_of_pounding,
};
use crate::analysis::statistics::Summary;
use crate::analysis::subject::runs::{plan, plan_levels, run_levels, run_suite};
use crate::analysis::suite::{SuiteCase, SuiteRun};
use crate::model::intensity::IntensityMeasure;
use crate::model::params::echo::g4;
use crate::model::suite::SuiteMember;

use super::FigureError;
use super::caption::num;
use super::spec::{Area, Figure, Guide, GuideAt, Panel, Pen, Series, Stroke};

/// A suite study to draw: the buildings and scaling, the records, and what
/// each figure asks of them.
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteStudy {
    /// The preset's name and the suite as given (`synthetic:20`, a path), for
    /// the title and caption.
    pub preset: String,
    pub suite: String,
    pub case: SuiteCase,
    pub members: Vec<SuiteMember>,
    /// The IDA's intensity levels (g), ascending (ida, fragility).
    pub levels: Vec<f64>,
    /// The limit states beside pounding (fragility).
    pub states: Vec<LimitState>,
    /// The probabilities of non-pounding asked for (separation).
    pub probabilities: Vec<f64>,
}

/// Colours (palette indices) of the runs with and without pounding.
const WITH: usize = 0;
const WITHOUT: usize = 1;

/// The axis label of an intensity measure, in g.
pub fn intensity_label(measure: IntensityMeasure) -> String {
    match measure {
        IntensityMeasure::Pga => "PGA (g)".into(),
        IntensityMeasure::Sa { period } => format!("Sa(T = {} s, ξ = 5 %) (g)", num(period)),
    }
}

fn run_error(r: &SuiteRun) -> Option<FigureError> {
    if let Some(why) = r.result.unreliable() {
        return Some(FigureError::Run(format!("record `{}`: {why}", r.name)));
    }
    (!r.free.completed).then(|| {
        FigureError::Run(format!(
            "record `{}`: the run without contact stopped before its end",
            r.name
        ))
    })
}

/// Every record at every level (level by level), or the first run that
/// cannot be trusted.
fn ida_runs(study: &SuiteStudy) -> Result<Vec<Vec<SuiteRun>>, FigureError> {
    if study.levels.is_empty() {
        return Err(FigureError::Input("an IDA needs --levels".into()));
    }
    let plans = plan_levels(&study.case, &study.members, &study.levels)
        .map_err(|e| FigureError::Input(e.to_string()))?;
    let runs = run_levels(&study.case, &study.members, &plans, &|_: &SuiteRun| {})
        .map_err(|e| FigureError::Input(e.to_string()))?;
    match runs.iter().flatten().find_map(run_error) {
        Some(e) => Err(e),
        None => Ok(runs),
    }
}

/// A length in m as a caption writes it: mm to four digits, or `inf`.
pub(super) fn mm(v: f64) -> String {
    if v.is_finite() {
        format!("{} mm", g4(v * 1e3))
    } else {
        "inf".into()
    }
}

/// The buildings, the suite and the scaling, for every caption.
fn caption(study: &SuiteStudy, scaling: &str) -> String {
    let phys = &study.case.physical;
    let period = |i: usize| g4(std::f64::consts::TAU / phys.omega[i]);
    format!(
        "{}: T1 = {} s, T2 = {} s, m1 = {} t, m2 = {} t, u_y1 = {}, u_y2 = {}, gap = {}; \
         suite {} ({} records), {scaling}; {} contact; {} method",
        study.preset,
        period(0),
        period(1),
        g4(phys.mass[0] / 1e3),
        g4(phys.mass[1] / 1e3),
        mm(phys.yield_displacement[0]),
        mm(phys.yield_displacement[1]),
        mm(phys.gap),
        study.suite,
        study.members.len(),
        study.case.settings.model,
        study.case.settings.method.name(),
    )
}

/// A one-panel figure of `study`, titled by its `kind`, with the caption
/// of the buildings and suite followed by `note`.
fn figure(kind: &str, study: &SuiteStudy, panel: Panel, note: &str) -> Figure {
    Figure {
        title: title(kind, &study.preset, &study.suite, study.members.len()),
        panels: vec![panel],
        caption: caption(study, note),
    }
}

/// A suite figure's title: `kind` of the buildings `name` under the suite.
pub(super) fn title(kind: &str, name: &str, suite: &str, records: usize) -> String {
    format!("{kind}: {name} under suite {suite} ({records} records)")
}

/// The scaling of an IDA at `levels` (g) of `measure`, for a caption.
pub(super) fn levels_text(measure: IntensityMeasure, levels: &[f64]) -> String {
    let (first, last) = (levels[0], levels[levels.len() - 1]);
    format!(
        "each record scaled to {measure} = {}–{} g ({} levels)",
        g4(first),
        g4(last),
        levels.len()
    )
}

/// The styles of the runs with pounding and without (gap = ∞).
const STYLES: [(bool, usize, Stroke, &str); 2] = [
    (true, WITH, Stroke::Solid, "with pounding"),
    (false, WITHOUT, Stroke::Dashed, "without pounding (gap = ∞)"),
];

/// IDA curves of one demand against IM (Vamvatsikos and Cornell 2002):
/// `demand(l, j, pounding)` of record j at level l, one faint curve per
/// record from (0, 0), the median and the 16–84 % band over the records at
/// each level, with pounding (solid) and without (dashed). IM is vertical.
/// A collapsed record (an infinite demand, SPEC §15) ends at the flatline,
/// marked, and the medians and bands run along it where they are infinite.
pub(super) fn ida_panel(
    index: usize,
    title: &str,
    x_label: &str,
    (measure, levels): (IntensityMeasure, &[f64]),
    records: usize,
    demand: impl Fn(usize, usize, bool) -> f64,
) -> Panel {
    let mut panel = Panel::new(index, title, x_label, &intensity_label(measure));
    // A record whose building collapsed has an infinite demand (SPEC §15):
    // its curve runs out to the flatline, drawn at 1.15 times the largest
    // finite demand, and stops there with a marker.
    let all = || {
        STYLES.iter().flat_map(move |&(pounding, ..)| {
            (0..levels.len()).flat_map(move |l| (0..records).map(move |j| (l, j, pounding)))
        })
    };
    let flatline = Flatline::over(all().map(|(l, j, p)| demand(l, j, p)));
    let flat = flatline.at;
    let shown = |d: f64| flatline.shown(d);
    let mut medians = Vec::new();
    for &(pounding, color, stroke, name) in &STYLES {
        let mut ends = Vec::new();
        for j in 0..records {
            let mut points = vec![(0.0, 0.0)];
            for (l, &x) in levels.iter().enumerate() {
                let d = demand(l, j, pounding);
                points.push((shown(d), x));
                if d == f64::INFINITY {
                    ends.push((flat, x));
                    break;
                }
            }
            panel.series.push(
                Series::new(format!("each record, {name}"), color, stroke, points)
                    .with_pen(Pen::Faint),
            );
        }
        if !ends.is_empty() {
            panel.series.push(
                Series::new(format!("collapse, {name}"), color, stroke, ends)
                    .with_pen(Pen::Markers),
            );
        }
        let summaries: Vec<(f64, Summary)> = levels
            .iter()
            .enumerate()
            .map(|(l, &x)| {
                let values: Vec<f64> = (0..records).map(|j| demand(l, j, pounding)).collect();
                let mut summary = Summary::of(&values);
                summary.median = shown(summary.median);
                summary.p16 = shown(summary.p16);
                summary.p84 = shown(summary.p84);
                (x, summary)
            })
            .collect();
        let mut outline = vec![(0.0, 0.0)];
        outline.extend(summaries.iter().map(|(x, s)| (s.p16, *x)));
        outline.extend(summaries.iter().rev().map(|(x, s)| (s.p84, *x)));
        panel.areas.push(Area {
            label: format!("16–84 %, {name}"),
            color,
            stroke,
            outline,
        });
        let mut median = vec![(0.0, 0.0)];
        median.extend(summaries.iter().map(|(x, s)| (s.median, *x)));
        medians.push(Series::new(
            format!("median, {name}"),
            color,
            stroke,
            median,
        ));
    }
    // The medians go over every record's curve.
    panel.series.extend(medians);
    flatline.mark(&mut panel);
    panel
}

/// Where an IDA panel draws an infinite demand, a record whose building
/// collapsed (SPEC §15): the flatline, at 1.15 times the largest finite
/// demand of the panel.
pub(super) struct Flatline {
    pub at: f64,
    /// Whether any demand is infinite (the flatline is drawn).
    pub collapsed: bool,
}

impl Flatline {
    /// The flatline of a panel's `demands`.
    pub(super) fn over(demands: impl Iterator<Item = f64> + Clone) -> Flatline {
        let largest = demands
            .clone()
            .filter(|d| d.is_finite())
            .fold(0.0, f64::max);
        Flatline {
            at: 1.15 * largest.max(f64::MIN_POSITIVE),
            collapsed: demands.into_iter().any(|d| d == f64::INFINITY),
        }
    }

    /// Demand `d` as drawn: at the flatline when infinite.
    pub(super) fn shown(&self, d: f64) -> f64 {
        if d == f64::INFINITY { self.at } else { d }
    }

    /// Draws the flatline on `panel` when a demand is infinite, with room
    /// to its right for its tag.
    pub(super) fn mark(&self, panel: &mut Panel) {
        if self.collapsed {
            panel.x_range = Some((0.0, 1.12 * self.at));
            panel.guides.push(Guide {
                at: GuideAt::X(self.at),
                color: None,
                tag: "collapse".into(),
                label: String::new(),
            });
        }
    }
}

/// IDA curves of the left structure's peak drift (mm) against IM (g).
pub fn ida_figure(study: &SuiteStudy) -> Result<Figure, FigureError> {
    let runs = ida_runs(study)?;
    let measure = study.case.scaling.measure;
    let mut panel = ida_panel(
        0,
        "Left structure",
        "Peak drift of the left structure u1,max (mm)",
        (measure, &study.levels),
        study.members.len(),
        |l, j, pounding| {
            let r = &runs[l][j];
            let si = if pounding { &r.si } else { &r.free_si };
            si.left.peak_displacement_m * 1e3
        },
    );
    let gap = study.case.physical.gap;
    if gap.is_finite() {
        panel.guides.push(Guide {
            at: GuideAt::X(gap * 1e3),
            color: None,
            tag: format!("gap {} mm", g4(gap * 1e3)),
            label: String::new(),
        });
    }
    Ok(figure(
        "IDA",
        study,
        panel,
        &format!(
            "{}; curves: peak drift of the left structure at each level, \
             median and 16–84 % over the records",
            levels_text(measure, &study.levels)
        ),
    ))
}

/// The observed fractions k/n of `counts` as (x, k/n).
fn observed(counts: &[LevelCount]) -> Vec<(f64, f64)> {
    counts
        .iter()
        .filter(|c| c.runs > 0)
        .map(|c| (c.level, c.exceeded as f64 / c.runs as f64))
        .collect()
}

/// A fitted curve over (0, x_max], or none.
fn fitted_curve(f: &Fragility, x_max: f64) -> Option<Vec<(f64, f64)>> {
    let Fragility::Fitted { theta, beta, .. } = *f else {
        return None;
    };
    const POINTS: usize = 240;
    Some(
        (1..=POINTS)
            .map(|i| {
                let x = x_max * i as f64 / POINTS as f64;
                (x, fragility::probability(x, theta, beta))
            })
            .collect(),
    )
}

/// One limit state's series in one style: the fit (if any) and the markers,
/// sharing one legend entry that gives θ, β or why there is no fit.
fn fragility_series(
    state: &str,
    name: Option<&str>,
    color: usize,
    stroke: Stroke,
    counts: &[LevelCount],
    fit: &Fragility,
    x_max: f64,
) -> Vec<Series> {
    let label = match name {
        Some(name) => format!("{state}, {name}: {}", describe(fit)),
        None => format!("{state}: {}", describe(fit)),
    };
    let mut series = Vec::new();
    if let Some(points) = fitted_curve(fit, x_max) {
        series.push(Series::new(label.clone(), color, stroke, points));
    }
    series.push(Series::new(label, color, stroke, observed(counts)).with_pen(Pen::Markers));
    series
}

/// P(exceed | IM) of the pounding limit state and each limit state asked,
/// with pounding (solid) and without (dashed).
pub fn fragility_figure(study: &SuiteStudy) -> Result<Figure, FigureError> {
    let runs = ida_runs(study)?;
    let curves: Vec<LimitStateFragility> =
        fragilities(&study.case, &study.levels, &runs, &study.states);
    let measure = study.case.scaling.measure;
    Ok(figure(
        "Fragility",
        study,
        fragility_panel(&curves, measure, &study.levels),
        &fragility_note(measure, &study.levels),
    ))
}

/// The fragility curves of `curves` over `levels` (g) of `measure`: each
/// limit state's fit and observed fractions, with pounding solid and
/// without dashed.
pub(super) fn fragility_panel(
    curves: &[LimitStateFragility],
    measure: IntensityMeasure,
    levels: &[f64],
) -> Panel {
    let x_max = 1.05 * levels[levels.len() - 1];
    let mut panel = Panel::new(
        0,
        "Fragility: P(exceed | IM = x) = Φ(ln(x/θ)/β)",
        &intensity_label(measure),
        "P(exceed)",
    );
    for (i, c) in curves.iter().enumerate() {
        panel
            .series
            .extend(limit_state_series(c, &c.limit_state, i, x_max));
    }
    panel.x_range = Some((0.0, x_max));
    panel.y_range = Some((-0.03, 1.03));
    panel
}

/// One limit state's series in colour `color`, its legend entries named
/// `state`: with pounding (solid) and without (dashed), each its fit and
/// observed fractions.
pub(super) fn limit_state_series(
    c: &LimitStateFragility,
    state: &str,
    color: usize,
    x_max: f64,
) -> Vec<Series> {
    // The pounding limit state exists with pounding only.
    let with = c.no_pounding_fragility.is_some().then_some("with pounding");
    let mut series = fragility_series(
        state,
        with,
        color,
        Stroke::Solid,
        &c.counts,
        &c.fragility,
        x_max,
    );
    if let (Some(counts), Some(fit)) = (&c.no_pounding_counts, &c.no_pounding_fragility) {
        series.extend(fragility_series(
            state,
            Some("without pounding"),
            color,
            Stroke::Dashed,
            counts,
            fit,
            x_max,
        ));
    }
    series
}

/// What a fragility figure's caption says of its curves.
pub(super) fn fragility_note(measure: IntensityMeasure, levels: &[f64]) -> String {
    format!(
        "{}; lines: maximum-likelihood lognormal fits (SPEC §12), markers: \
         observed fractions k/n; solid with pounding, dashed without (gap = ∞)",
        levels_text(measure, levels)
    )
}

/// The records' empirical distribution of `gaps` (mm) as a step curve from
/// 0 to `x_max`.
pub(super) fn step_curve(gaps: &[f64], x_max: f64) -> Vec<(f64, f64)> {
    let mut sorted: Vec<f64> = gaps.iter().copied().filter(|d| d.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    let n = gaps.len() as f64;
    let mut points = vec![(0.0, 0.0)];
    for (k, d) in sorted.iter().enumerate() {
        points.push((*d, k as f64 / n));
        points.push((*d, (k + 1) as f64 / n));
    }
    points.push((x_max, sorted.len() as f64 / n));
    points
}

/// The separation study of one suite at one scaling: the distribution of
/// Π_d,min (mm), the gap at each probability, the preset's gap and the code
/// rules on the median peaks.
pub fn separation_figure(study: &SuiteStudy) -> Result<Figure, FigureError> {
    let plans = plan(&study.case, &study.members).map_err(|e| FigureError::Input(e.to_string()))?;
    let runs = run_suite(&study.case, &study.members, &plans, &|_: &SuiteRun| {})
        .map_err(|e| FigureError::Input(e.to_string()))?;
    if let Some(e) = runs.iter().find_map(run_error) {
        return Err(e);
    }
    let records: Vec<RecordGap> = runs.iter().map(RecordGap::of).collect();
    let gaps: Vec<f64> = records.iter().map(|r| r.min_gap).collect();
    let result = separation::study(&records, &study.probabilities);
    let panel = separation_panel(
        0,
        "Minimum separation of each record, Π_d,min (SPEC §11)",
        &gaps,
        &result,
        ("the preset's gap", study.case.physical.gap),
        "",
    );
    let mm = 1e3;
    Ok(figure(
        "Separation",
        study,
        panel,
        &format!(
            "{}; Π_d,min of each record from its run without contact; \
             code rules on the median peaks of the separate structures ({} mm, {} mm; ρ = {:.3})",
            scaling_text(study.case.scaling.measure, study.case.scaling.level),
            g4(result.median_peaks[0] * mm),
            g4(result.median_peaks[1] * mm),
            result.correlation
        ),
    ))
}

/// How a suite at one scaling is scaled, for a caption.
pub(super) fn scaling_text(measure: IntensityMeasure, level: Option<f64>) -> String {
    match level {
        Some(x) => format!("each record scaled to {measure} = {} g", g4(x)),
        None => "records at their list's scale".into(),
    }
}

/// The lognormal fit of the records' gaps, P(Π_d,min ≤ d), over d from 0
/// to `x_max` (mm).
pub(super) fn lognormal_curve(fit: &LognormalFit, x_max: f64) -> Vec<(f64, f64)> {
    const POINTS: usize = 300;
    (0..=POINTS)
        .map(|i| {
            let d = x_max * i as f64 / POINTS as f64;
            (d, fit.probability(d / 1e3))
        })
        .collect()
}

/// The gap d_(⌈pN⌉) at each probability p of `result` as (d in mm, p),
/// where it is finite.
pub(super) fn probability_marks(result: &SeparationStudy) -> Vec<(f64, f64)> {
    result
        .at_probability
        .iter()
        .filter(|a| a.empirical.is_finite())
        .map(|a| (a.empirical * 1e3, a.probability))
        .collect()
}

/// The records' gaps that prevent pounding (`gaps`, m) as an empirical step
/// curve (mm) with its lognormal fit, each probability of `result` a
/// horizontal line with its gap written, the gap at rest (`gap`: its name
/// and value, m) and the code rules on the median peaks as labelled
/// vertical lines, each with its probability of pounding. `whose` starts
/// the legend entries that differ from panel to panel (the fit, the gap,
/// the rules), so that each names its panel.
pub(super) fn separation_panel(
    index: usize,
    title: &str,
    gaps: &[f64],
    result: &SeparationStudy,
    (gap_name, gap): (&str, f64),
    whose: &str,
) -> Panel {
    let mm = 1e3;
    // The x axis reaches past every finite value drawn.
    let largest = gaps
        .iter()
        .copied()
        .chain(result.rules.iter().map(|r| r.at_median_peaks))
        .chain([gap])
        .filter(|v| v.is_finite())
        .fold(0.0f64, f64::max);
    let x_max = 1.1 * mm * largest.max(1e-6);

    let mut panel = Panel::new(
        index,
        title,
        "Separation d (mm)",
        "P(Π_d,min ≤ d): share of records that do not pound",
    );
    panel.series.push(Series::new(
        format!("records (empirical, N = {})", gaps.len()),
        0,
        Stroke::Solid,
        step_curve(&gaps.iter().map(|d| d * mm).collect::<Vec<_>>(), x_max),
    ));
    if let Some(fit) = result.lognormal {
        let points = lognormal_curve(&fit, x_max);
        panel.series.push(Series::new(
            format!(
                "{whose}lognormal fit: median {} mm, β = {:.3}",
                g4(fit.median * mm),
                fit.dispersion
            ),
            1,
            Stroke::Solid,
            points,
        ));
    }
    let marks = probability_marks(result);
    panel.series.push(
        Series::new("gap at probability p: d_(⌈pN⌉)", 0, Stroke::Solid, marks)
            .with_pen(Pen::Markers),
    );
    for a in &result.at_probability {
        let length = |d: f64| {
            if d.is_finite() {
                format!("{} mm", g4(d * mm))
            } else {
                "∞".into()
            }
        };
        let value = match a.lognormal {
            Some(d) => format!("{} (lognormal {})", length(a.empirical), length(d)),
            None => length(a.empirical),
        };
        panel.guides.push(Guide {
            at: GuideAt::Y(a.probability),
            color: None,
            tag: format!("p = {}: {value}", num(a.probability)),
            label: String::new(),
        });
    }
    if gap.is_finite() {
        panel.guides.push(Guide {
            at: GuideAt::X(gap * mm),
            color: None,
            tag: "gap".into(),
            label: format!(
                "{whose}{gap_name}: {} mm, P(pounding) = {}",
                g4(gap * mm),
                g4(probability_of_pounding(gaps, gap))
            ),
        });
    }
    for (i, r) in result.rules.iter().enumerate() {
        panel.guides.push(Guide {
            at: GuideAt::X(r.at_median_peaks * mm),
            color: Some(2 + i),
            tag: r.rule.to_string(),
            label: format!(
                "{whose}{} on the median peaks: {} mm, P(pounding) = {}",
                r.rule,
                g4(r.at_median_peaks * mm),
                g4(r.pounding_probability)
            ),
        });
    }
    panel.x_range = Some((0.0, x_max));
    panel.y_range = Some((0.0, 1.04));
    panel
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::spec::LegendEntry;

    /// A riser and a tread per finite record; a zero rises at 0, an
    /// infinite gap never arrives (the curve ends below 1).
    #[test]
    fn step_curve_rises_one_record_at_a_time() {
        let third = 1.0 / 3.0;
        assert_eq!(
            step_curve(&[1.0, 0.0, f64::INFINITY], 2.0),
            vec![
                (0.0, 0.0),
                (0.0, 0.0),
                (0.0, third),
                (1.0, third),
                (1.0, 2.0 * third),
                (2.0, 2.0 * third),
            ]
        );
    }

    /// A fit's line and its markers share one legend entry; a limit state
    /// with no fit has markers only.
    #[test]
    fn a_fit_and_its_markers_share_one_legend_entry() {
        let counts = [
            LevelCount {
                level: 0.2,
                runs: 4,
                exceeded: 1,
            },
            LevelCount {
                level: 0.4,
                runs: 4,
                exceeded: 2,
            },
            LevelCount {
                level: 0.8,
                runs: 4,
                exceeded: 3,
            },
        ];
        let fit = fragility::fit(&counts);
        let fitted = fragility_series("ductility>2", None, 0, Stroke::Solid, &counts, &fit, 1.0);
        let never = Fragility::NeverExceeded;
        let bare = fragility_series("force>500kN", None, 1, Stroke::Solid, &counts, &never, 1.0);
        assert_eq!(fitted.len(), 2);
        assert_eq!(bare.len(), 1);
        let mut panel = Panel::new(0, "", "x", "y");
        panel.series.extend(fitted.into_iter().chain(bare));
        let fig = Figure {
            title: String::new(),
            panels: vec![panel],
            caption: String::new(),
        };
        let legend = fig.legend();
        assert_eq!(legend.len(), 2, "{legend:?}");
        let LegendEntry::Line { line, markers, .. } = &legend[0] else {
            panic!("{legend:?}");
        };
        assert_eq!((*line, *markers), (Some(Pen::Line), true));
        assert!(legend[0].label().starts_with("ductility>2: θ = "));
        assert_eq!(legend[1].label(), "force>500kN: never exceeded");
    }

    /// A median beyond the levels run is marked in the legend entry.
    #[test]
    fn an_extrapolated_median_is_marked_in_the_legend() {
        // 1, 2 and 3 of 8 exceed at 0.2, 0.4 and 0.8 g: θ is above 0.8 g.
        let counts: Vec<LevelCount> = [(0.2, 1), (0.4, 2), (0.8, 3)]
            .map(|(level, exceeded)| LevelCount {
                level,
                runs: 8,
                exceeded,
            })
            .to_vec();
        let fit = fragility::fit(&counts);
        let Fragility::Fitted { theta, .. } = fit else {
            panic!("{fit:?}");
        };
        assert!(theta > 0.8, "θ = {theta}");
        let series = fragility_series("ductility>4", None, 0, Stroke::Solid, &counts, &fit, 1.0);
        assert!(
            series[0].label.starts_with("ductility>4: θ = ")
                && series[0].label.contains(" g (extrapolated), β = "),
            "{}",
            series[0].label
        );
    }
}
