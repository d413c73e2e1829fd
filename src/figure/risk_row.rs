//! Figures of a suite study on a row of buildings (SPEC §12, §13): the IDA
//! curves of each building's storey drift ratio, the fragility curves of
//! the row's limit states and each joint's separation. The runs and the
//! fits are [`crate::analysis::subject::runs`]' and
//! [`crate::analysis::separation`]'s, the drawing [`super::risk`]'s, so
//! a row's figures read as the pair's do.
//!
//! - [`row_ida_figure`]: one panel per building, IM against its largest
//!   storey drift ratio max_i |Δ_i|/h_i (%), one faint curve per record,
//!   the median and the 16–84 % band, with pounding (solid) and with every
//!   joint open (dashed).
//! - [`row_fragility_figure`]: P(exceed | IM = x) = Φ(ln(x/θ)/β) of
//!   pounding and of each limit state asked (`--drift`, `--acceleration`,
//!   `--force`, each of a named building or of any).
//! - [`row_separation_figure`]: one panel per joint, the records' gaps that
//!   prevent pounding there (from the runs apart) as an empirical step
//!   curve with its lognormal fit, the gap at each probability, the
//!   joint's gap and the code rules on the median peaks of its paired floors.

use crate::analysis::ida::fragilities;
use crate::analysis::limit_state::LimitState;
use crate::analysis::separation::joint_separations;
use crate::analysis::subject::row::{RowSuiteCase, RowSuiteRun};
use crate::analysis::subject::runs::{plan, plan_levels, run_levels, run_suite};
use crate::model::buildings::matrices::periods;
use crate::model::params::echo::g4;
use crate::model::suite::SuiteMember;

use super::FigureError;
use super::risk::{
    fragility_note, fragility_panel, ida_panel, levels_text, mm, scaling_text, separation_panel,
    title,
};
use super::spec::Figure;

/// A suite study on a row to draw: the row and scaling, the records, the
/// IDA's levels and the limit states beside pounding.
#[derive(Debug, Clone, PartialEq)]
pub struct RowSuiteStudy {
    /// The suite as given (`synthetic:20`, a path), for the title and caption.
    pub suite: String,
    pub case: RowSuiteCase,
    pub members: Vec<SuiteMember>,
    /// Intensity levels (g), ascending (ida, fragility).
    pub levels: Vec<f64>,
    /// The limit states, pounding first (as `ida --buildings` reads them).
    pub states: Vec<LimitState>,
    /// The probabilities of no pounding asked for (separation).
    pub probabilities: Vec<f64>,
}

/// Every record at every level (level by level), or the first run that failed.
pub(super) fn runs(study: &RowSuiteStudy) -> Result<Vec<Vec<RowSuiteRun>>, FigureError> {
    if study.levels.is_empty() {
        return Err(FigureError::Input("an IDA needs --levels".into()));
    }
    let plans = plan_levels(&study.case, &study.members, &study.levels)
        .map_err(|e| FigureError::Input(e.to_string()))?;
    run_levels(&study.case, &study.members, &plans, &|_: &RowSuiteRun| {})
        .map_err(|e| FigureError::Run(e.to_string()))
}

/// The row, the suite and `note`, for every caption: each building's
/// storeys and T₁, each joint's gap, the contact law.
fn caption(study: &RowSuiteStudy, note: &str) -> String {
    format!(
        "{}; suite {} ({} records), {note}; {} contact; exact method",
        row_text(study),
        study.suite,
        study.members.len(),
        study.case.row.model.name(),
    )
}

/// The row of `study` for a caption: its name, each building's storeys and
/// T₁, each joint's gap.
pub(super) fn row_text(study: &RowSuiteStudy) -> String {
    let row = &study.case.row;
    let buildings: Vec<String> = row
        .buildings
        .iter()
        .map(|b| {
            format!(
                "{} ({} storeys, T1 = {} s)",
                b.name,
                b.storeys(),
                g4(periods(b)[0])
            )
        })
        .collect();
    let gaps: Vec<String> = row
        .joints
        .iter()
        .enumerate()
        .map(|(j, joint)| {
            let [a, b] = [j, j + 1].map(|k| &row.buildings[k].name);
            format!("{a}–{b} {}", mm(joint.gap))
        })
        .collect();
    format!(
        "{}: {}; gaps {}",
        row.name,
        buildings.join(", "),
        gaps.join(", ")
    )
}

/// IDA curves of each building's largest storey drift ratio (%) against IM (g).
pub fn row_ida_figure(study: &RowSuiteStudy) -> Result<Figure, FigureError> {
    let runs = runs(study)?;
    let measure = study.case.scaling.measure;
    let panels = study
        .case
        .row
        .buildings
        .iter()
        .enumerate()
        .map(|(b, building)| {
            ida_panel(
                b,
                &building.name,
                &format!("Largest storey drift ratio of {} (%)", building.name),
                (measure, &study.levels),
                study.members.len(),
                |l, j, pounding| {
                    let d = &runs[l][j].demands;
                    let of = if pounding {
                        &d.buildings
                    } else {
                        &d.no_pounding
                    };
                    of[b].max_drift_ratio * 100.0
                },
            )
        })
        .collect();
    Ok(Figure {
        title: title(
            "IDA",
            &study.case.row.name,
            &study.suite,
            study.members.len(),
        ),
        panels,
        caption: caption(
            study,
            &format!(
                "{}; curves: each building's largest storey drift ratio max |Δ_i|/h_i at each \
                 level, median and 16–84 % over the records; dashed: every joint open",
                levels_text(measure, &study.levels)
            ),
        ),
    })
}

/// P(exceed | IM) of pounding and of each limit state asked, with pounding
/// (solid) and with every joint open (dashed).
pub fn row_fragility_figure(study: &RowSuiteStudy) -> Result<Figure, FigureError> {
    let runs = runs(study)?;
    let curves = fragilities(&study.case, &study.levels, &runs, &study.states);
    let measure = study.case.scaling.measure;
    Ok(Figure {
        title: title(
            "Fragility",
            &study.case.row.name,
            &study.suite,
            study.members.len(),
        ),
        panels: vec![fragility_panel(&curves, measure, &study.levels)],
        caption: caption(study, &fragility_note(measure, &study.levels)),
    })
}

/// Each joint's separation at the case's scaling: one panel per joint.
pub fn row_separation_figure(study: &RowSuiteStudy) -> Result<Figure, FigureError> {
    let row = &study.case.row;
    let scales =
        plan(&study.case, &study.members).map_err(|e| FigureError::Input(e.to_string()))?;
    let runs = run_suite(&study.case, &study.members, &scales, &|_: &RowSuiteRun| {})
        .map_err(|e| FigureError::Run(e.to_string()))?;
    let joints = joint_separations(&study.case, &runs, &study.probabilities);
    let panels = joints
        .iter()
        .enumerate()
        .map(|(j, joint)| {
            let gaps: Vec<f64> = runs
                .iter()
                .map(|r| r.demands.joints[j].gap.min_gap)
                .collect();
            separation_panel(
                j,
                &format!(
                    "Joint {}–{}: each record's gap that prevents pounding (SPEC §13)",
                    joint.left, joint.right
                ),
                &gaps,
                &joint.study,
                ("the joint's gap", joint.gap_m),
                &format!("{}–{}: ", joint.left, joint.right),
            )
        })
        .collect();
    let scaling = &study.case.scaling;
    Ok(Figure {
        title: title("Separation", &row.name, &study.suite, study.members.len()),
        panels,
        caption: caption(
            study,
            &format!(
                "{}; each record's gap at a joint from its run with every joint open: the largest \
                 u_A − u_B over its paired floors; code rules on the median peaks of the paired \
                 floors, the largest over them",
                scaling_text(scaling.measure, scaling.level)
            ),
        ),
    })
}
