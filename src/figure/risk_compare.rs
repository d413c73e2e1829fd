//! Figures of one suite study on several variants of a row, a retrofit say
//! (`figure ida|fragility|separation --buildings ROW --compare ROW2,…`;
//! SPEC §12–§14): the variants overlaid on the same axes, one palette
//! colour per variant, each legend entry naming its variant. Each
//! variant's runs and fits are those [`super::risk_row`] draws of it alone.
//!
//! - [`compare_ida_figure`]: one panel per building, IM against its
//!   largest storey drift ratio max_i |Δ_i|/h_i (%): each variant's median
//!   and 16–84 % band with pounding (solid), and its median with every
//!   joint open (dashed). A collapsed record (an infinite demand, SPEC §15)
//!   draws its median and band at the flatline, as the single figure does.
//! - [`compare_fragility_figure`]: one panel per limit state, each
//!   variant's P(exceed | IM = x) = Φ(ln(x/θ)/β), fitted (line) and
//!   observed k/n (markers), with pounding solid and apart dashed.
//! - [`compare_separation_figure`]: one panel per joint, each variant's
//!   records' gaps that prevent pounding as an empirical step curve
//!   (solid), its lognormal fit (dashed), its gap d_(⌈pN⌉) at each
//!   probability (markers) and its gap at rest (a guide in its colour);
//!   the code rules on the median peaks are in the caption.

use crate::analysis::ida::fragilities;
use crate::analysis::separation::{JointSeparation, joint_separations};
use crate::analysis::statistics::Summary;
use crate::analysis::subject::row::RowSuiteRun;
use crate::analysis::subject::runs::{plan, run_suite};
use crate::model::params::echo::g4;

use super::FigureError;
use super::caption::num;
use super::risk::{
    Flatline, intensity_label, levels_text, limit_state_series, lognormal_curve, mm,
    probability_marks, scaling_text, step_curve, title,
};
use super::risk_row::{RowSuiteStudy, row_text, runs};
use super::spec::{Area, Figure, Guide, GuideAt, Panel, Pen, Series, Stroke};

/// One variant of the row: its name in the legend (its file stem) and its study.
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    pub name: String,
    pub study: RowSuiteStudy,
}

/// The variants' names, for a title.
fn names(variants: &[Variant]) -> String {
    let names: Vec<&str> = variants.iter().map(|v| v.name.as_str()).collect();
    names.join(" vs ")
}

/// Every variant's row and contact law, the common suite and `note`, for
/// the caption.
fn compare_caption(variants: &[Variant], note: &str) -> String {
    let rows: Vec<String> = variants
        .iter()
        .map(|v| {
            let law = v.study.case.row.model.name();
            format!("{} ({law} contact)", row_text(&v.study))
        })
        .collect();
    let first = &variants[0].study;
    format!(
        "{}; suite {} ({} records), {note}; exact method",
        rows.join("; "),
        first.suite,
        first.members.len()
    )
}

/// The title of figure `kind` of the variants under their common suite.
fn compare_title(kind: &str, variants: &[Variant]) -> String {
    let first = &variants[0].study;
    title(kind, &names(variants), &first.suite, first.members.len())
}

/// IDA curves of each building's largest storey drift ratio (%) against
/// IM (g), one colour per variant.
pub fn compare_ida_figure(variants: &[Variant]) -> Result<Figure, FigureError> {
    let ran: Vec<Vec<Vec<RowSuiteRun>>> = variants
        .iter()
        .map(|v| runs(&v.study))
        .collect::<Result<_, _>>()?;
    let first = &variants[0].study;
    let measure = first.case.scaling.measure;
    let levels = &first.levels;
    let drift = |v: usize, l: usize, b: usize, pounding: bool| -> Vec<f64> {
        ran[v][l]
            .iter()
            .map(|r| {
                let of = if pounding {
                    &r.demands.buildings
                } else {
                    &r.demands.no_pounding
                };
                of[b].max_drift_ratio * 100.0
            })
            .collect()
    };
    let panels = first
        .case
        .row
        .buildings
        .iter()
        .enumerate()
        .map(|(b, building)| {
            let mut panel = Panel::new(
                b,
                format!("{}: median and 16–84 % over the records", building.name),
                &format!("Largest storey drift ratio of {} (%)", building.name),
                &intensity_label(measure),
            );
            // A collapsed record's demand is infinite (SPEC §15): drawn at
            // 1.15 times the largest finite demand of any variant.
            let all: Vec<f64> = (0..variants.len())
                .flat_map(|v| (0..levels.len()).map(move |l| (v, l)))
                .flat_map(|(v, l)| [drift(v, l, b, true), drift(v, l, b, false)])
                .flatten()
                .collect();
            let flatline = Flatline::over(all.iter().copied());
            let shown = |d: f64| flatline.shown(d);
            for (v, variant) in variants.iter().enumerate() {
                for (pounding, stroke, style) in [
                    (true, Stroke::Solid, "with pounding"),
                    (false, Stroke::Dashed, "every joint open"),
                ] {
                    let summaries: Vec<(f64, Summary)> = levels
                        .iter()
                        .enumerate()
                        .map(|(l, &x)| (x, Summary::of(&drift(v, l, b, pounding))))
                        .collect();
                    if pounding {
                        let mut outline = vec![(0.0, 0.0)];
                        outline.extend(summaries.iter().map(|(x, s)| (shown(s.p16), *x)));
                        outline.extend(summaries.iter().rev().map(|(x, s)| (shown(s.p84), *x)));
                        panel.areas.push(Area {
                            label: format!("{}: 16–84 %, {style}", variant.name),
                            color: v,
                            stroke,
                            outline,
                        });
                    }
                    let mut median = vec![(0.0, 0.0)];
                    median.extend(summaries.iter().map(|(x, s)| (shown(s.median), *x)));
                    panel.series.push(Series::new(
                        format!("{}: median, {style}", variant.name),
                        v,
                        stroke,
                        median,
                    ));
                }
            }
            flatline.mark(&mut panel);
            panel
        })
        .collect();
    Ok(Figure {
        title: compare_title("IDA", variants),
        panels,
        caption: compare_caption(
            variants,
            &format!(
                "{}; curves: each building's largest storey drift ratio max |Δ_i|/h_i at each \
                 level, median and 16–84 % over the records, one colour per variant; dashed: \
                 every joint open",
                levels_text(measure, levels)
            ),
        ),
    })
}

/// P(exceed | IM) of each limit state, one panel per limit state, one
/// colour per variant; with pounding solid, with every joint open dashed.
pub fn compare_fragility_figure(variants: &[Variant]) -> Result<Figure, FigureError> {
    let mut curves = Vec::new();
    for v in variants {
        let runs = runs(&v.study)?;
        curves.push(fragilities(
            &v.study.case,
            &v.study.levels,
            &runs,
            &v.study.states,
        ));
    }
    // The limit states of every variant, in order of first appearance:
    // `--collapse` asks one of each building with P-Δ, which a variant may
    // have and another not.
    let mut states: Vec<&str> = Vec::new();
    for c in curves.iter().flatten() {
        if !states.contains(&c.limit_state.as_str()) {
            states.push(&c.limit_state);
        }
    }
    let first = &variants[0].study;
    let measure = first.case.scaling.measure;
    let levels = &first.levels;
    let x_max = 1.05 * levels[levels.len() - 1];
    let panels = states
        .iter()
        .enumerate()
        .map(|(k, state)| {
            let mut panel = Panel::new(
                k,
                format!("{state}: P(exceed | IM = x) = Φ(ln(x/θ)/β)"),
                &intensity_label(measure),
                "P(exceed)",
            );
            for (v, variant) in variants.iter().enumerate() {
                if let Some(c) = curves[v].iter().find(|c| c.limit_state == *state) {
                    let label = format!("{}: {}", variant.name, c.limit_state);
                    panel.series.extend(limit_state_series(c, &label, v, x_max));
                }
            }
            panel.x_range = Some((0.0, x_max));
            panel.y_range = Some((-0.03, 1.03));
            panel
        })
        .collect();
    Ok(Figure {
        title: compare_title("Fragility", variants),
        panels,
        caption: compare_caption(
            variants,
            &format!(
                "{}; lines: maximum-likelihood lognormal fits (SPEC §12), markers: observed \
                 fractions k/n; one colour per variant; solid with pounding, dashed with every \
                 joint open",
                levels_text(measure, levels)
            ),
        ),
    })
}

/// Each joint's separation at the common scaling, one panel per joint, one
/// colour per variant.
pub fn compare_separation_figure(variants: &[Variant]) -> Result<Figure, FigureError> {
    let mut ran: Vec<(Vec<RowSuiteRun>, Vec<JointSeparation>)> = Vec::new();
    for v in variants {
        let s = &v.study;
        let scales = plan(&s.case, &s.members).map_err(|e| FigureError::Input(e.to_string()))?;
        let runs = run_suite(&s.case, &s.members, &scales, &|_: &RowSuiteRun| {})
            .map_err(|e| FigureError::Run(e.to_string()))?;
        let joints = joint_separations(&s.case, &runs, &s.probabilities);
        ran.push((runs, joints));
    }
    let first = &variants[0].study;
    let mmf = 1e3;
    let panels = ran[0]
        .1
        .iter()
        .enumerate()
        .map(|(j, joint)| {
            let gaps = |v: usize| -> Vec<f64> {
                ran[v]
                    .0
                    .iter()
                    .map(|r| r.demands.joints[j].gap.min_gap)
                    .collect()
            };
            // The x axis reaches past every finite value drawn.
            let largest = (0..variants.len())
                .flat_map(|v| {
                    let at = &ran[v].1[j];
                    gaps(v)
                        .into_iter()
                        .chain([at.gap_m])
                        .chain(at.study.at_probability.iter().map(|a| a.empirical))
                })
                .filter(|d| d.is_finite())
                .fold(0.0f64, f64::max);
            let x_max = 1.1 * mmf * largest.max(1e-6);
            let mut panel = Panel::new(
                j,
                format!(
                    "Joint {}–{}: each record's gap that prevents pounding (SPEC §13)",
                    joint.left, joint.right
                ),
                "Separation d (mm)",
                "P(Π_d,min ≤ d): share of records that do not pound",
            );
            for (v, variant) in variants.iter().enumerate() {
                let at = &ran[v].1[j];
                let shown: Vec<f64> = gaps(v).iter().map(|d| d * mmf).collect();
                panel.series.push(Series::new(
                    format!("{}: records (empirical, N = {})", variant.name, shown.len()),
                    v,
                    Stroke::Solid,
                    step_curve(&shown, x_max),
                ));
                if let Some(fit) = at.study.lognormal {
                    let points = lognormal_curve(&fit, x_max);
                    panel.series.push(Series::new(
                        format!(
                            "{}: lognormal fit, median {} mm, β = {:.3}",
                            variant.name,
                            g4(fit.median * mmf),
                            fit.dispersion
                        ),
                        v,
                        Stroke::Dashed,
                        points,
                    ));
                }
                let marks = probability_marks(&at.study);
                let gaps_at: Vec<String> = at
                    .study
                    .at_probability
                    .iter()
                    .map(|a| format!("{} at p = {}", mm(a.empirical), num(a.probability)))
                    .collect();
                panel.series.push(
                    Series::new(
                        format!("{}: gap d_(⌈pN⌉) {}", variant.name, gaps_at.join(", ")),
                        v,
                        Stroke::Solid,
                        marks,
                    )
                    .with_pen(Pen::Markers),
                );
                if at.gap_m.is_finite() {
                    panel.guides.push(Guide {
                        at: GuideAt::X(at.gap_m * mmf),
                        color: Some(v),
                        tag: "gap".into(),
                        label: format!(
                            "{}: the joint's gap {}, P(pounding) = {}",
                            variant.name,
                            mm(at.gap_m),
                            g4(at.pounding_probability_at_gap)
                        ),
                    });
                }
            }
            for p in &first.probabilities {
                panel.guides.push(Guide {
                    at: GuideAt::Y(*p),
                    color: None,
                    tag: format!("p = {}", num(*p)),
                    label: String::new(),
                });
            }
            panel.x_range = Some((0.0, x_max));
            panel.y_range = Some((0.0, 1.04));
            panel
        })
        .collect();
    // The code rules on the median peaks of each variant, per joint.
    let rules: Vec<String> = variants
        .iter()
        .zip(&ran)
        .flat_map(|(variant, (_, joints))| {
            joints.iter().map(move |joint| {
                let each: Vec<String> = joint
                    .study
                    .rules
                    .iter()
                    .map(|r| format!("{} {}", r.rule, mm(r.at_median_peaks)))
                    .collect();
                format!(
                    "{} {}–{}: {}",
                    variant.name,
                    joint.left,
                    joint.right,
                    each.join(", ")
                )
            })
        })
        .collect();
    let scaling = &first.case.scaling;
    Ok(Figure {
        title: compare_title("Separation", variants),
        panels,
        caption: compare_caption(
            variants,
            &format!(
                "{}; each record's gap at a joint from its run with every joint open: the \
                 largest u_A − u_B over its paired floors; one colour per variant; code rules \
                 on the median peaks: {}",
                scaling_text(scaling.measure, scaling.level),
                rules.join("; ")
            ),
        ),
    })
}
