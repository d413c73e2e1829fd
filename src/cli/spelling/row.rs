//! A row's spelling of the suite studies' reports (SPEC §12, §13): its
//! buildings and joints by name, and per record one line per building and
//! per joint.

use std::fmt::Write as _;

use serde::Serialize;

use super::{GapOpening, IdaOpening, Spelling, StudyHead};
use crate::analysis::gap::JointGap;
use crate::analysis::separation::JointSeparation;
use crate::analysis::subject::row::{RowDemands, RowSuiteCase, RowSuiteRun};
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::description::ScalingReport;
use crate::cli::gap_suite::study_table;
use crate::cli::output::num;
use crate::cli::study_tables::{band, clip, median, name_width};
use crate::model::buildings::matrices::periods;
use crate::model::params::echo::g4;

/// One building of the row, as a report names it.
#[derive(Debug, Serialize)]
pub struct BuildingHeader {
    name: String,
    storeys: usize,
    /// The fundamental period T₁ (s).
    period_s: f64,
}

/// One joint, as a report names it.
#[derive(Debug, Serialize)]
pub struct JointHeader {
    left: String,
    right: String,
    /// The gap at rest (m).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    gap_m: f64,
}

/// The row's buildings and joints, left to right.
#[derive(Debug, Serialize)]
pub struct RowBuildings {
    buildings: Vec<BuildingHeader>,
    joints: Vec<JointHeader>,
}

/// What a row's IDA and separation study say after the method: the
/// buildings, and the scaling.
#[derive(Debug, Serialize)]
pub struct Scaled {
    #[serde(flatten)]
    buildings: RowBuildings,
    scaling: ScalingReport,
}

/// One record of a row suite.
#[derive(Debug, Serialize)]
pub struct RowSuiteRow {
    record: String,
    samples: usize,
    /// Sample interval (s).
    dt: f64,
    scale: f64,
    /// IM of the scaled record (g).
    intensity_g: f64,
    /// Length of the runs (s): the record and the free tail.
    duration_s: f64,
    #[serde(flatten)]
    demands: RowDemands,
}

/// One record at one joint: its gap that prevents pounding and code rules
/// (m), and its impacts at the preset's gap.
#[derive(Debug, Serialize)]
pub struct RecordJoint {
    #[serde(flatten)]
    gap: JointGap,
    impacts_at_gap: usize,
}

/// One record of a separation study: its scaling and each joint's gaps.
#[derive(Debug, Serialize)]
pub struct GapRow {
    record: String,
    scale: f64,
    intensity_g: f64,
    joints: Vec<RecordJoint>,
}

/// What a row's separation study says before its records: the contact
/// law and method, the buildings and the scaling. Its joints head the
/// table only: in JSON each joint is the study's own entry ([`GapTail`]),
/// which names its buildings and gap too, under the one key `joints`.
#[derive(Debug)]
pub struct GapHead {
    model: &'static str,
    method: &'static str,
    scaled: Scaled,
}

impl Serialize for GapHead {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut m = s.serialize_struct("GapHead", 4)?;
        m.serialize_field("model", self.model)?;
        m.serialize_field("method", self.method)?;
        m.serialize_field("buildings", &self.scaled.buildings.buildings)?;
        m.serialize_field("scaling", &self.scaled.scaling)?;
        m.end()
    }
}

/// Per joint, left to right: the separation study over the records.
#[derive(Debug, Serialize)]
pub struct GapTail {
    joints: Vec<JointSeparation>,
}

/// SI units of a row's reports.
const UNITS: &str = "SI (m, g, kN) for the demands, g for intensities; drift ratios Δ/h";

impl RowSuiteCase {
    /// The buildings and the scaling.
    fn scaled(&self) -> Scaled {
        Scaled {
            buildings: self.described_buildings(),
            scaling: ScalingReport::of(&self.scaling),
        }
    }
}

/// The opening lines of a row's table: the suite of `records` and the row
/// `row` named `preset` (with its contact law and method), and `level`, the
/// scaling in words.
fn opening(
    [suite, preset, model, method]: [&str; 4],
    row: &RowBuildings,
    records: usize,
    level: &str,
    s: &mut String,
) {
    let _ = writeln!(
        s,
        "suite {suite} ({records} records), row {preset}: {model}, {method} method; {level}"
    );
    let buildings: Vec<String> = row
        .buildings
        .iter()
        .map(|b| {
            format!(
                "{} ({} storeys, T1 = {} s)",
                b.name,
                b.storeys,
                g4(b.period_s)
            )
        })
        .collect();
    let joints: Vec<String> = row
        .joints
        .iter()
        .map(|j| format!("{}–{} {} mm", j.left, j.right, g4(j.gap_m * 1e3)))
        .collect();
    let _ = writeln!(
        s,
        "buildings: {}; gaps: {}",
        buildings.join(", "),
        joints.join(", ")
    );
}

/// The suite, the row, its contact law and method of `head`, as
/// [`opening`] takes them.
fn names<'a, B>(head: &StudyHead<'a, B>) -> [&'a str; 4] {
    let preset = head.provenance.preset;
    [head.suite, preset, head.model, head.method]
}

impl Spelling for RowSuiteCase {
    const SUITE_UNITS: &'static str = UNITS;
    const IDA_UNITS: &'static str = UNITS;
    const GAP_UNITS: &'static str = UNITS;
    const NAMES_LIMIT_STATES: bool = true;
    const GAP_COLUMNS: &'static [&'static str] = &[
        "joint",
        "left",
        "right",
        "min_gap_m",
        "abs_m",
        "srss_m",
        "ddc_m",
        "impacts_at_gap",
    ];

    type Buildings = RowBuildings;
    type Record = RowSuiteRow;
    type IdaHead = Scaled;
    type GapHead = GapHead;
    type GapTail = GapTail;
    type GapRecord = GapRow;

    fn preset<'a>(&'a self, _: &'a str) -> &'a str {
        &self.row.name
    }

    fn model_method(&self) -> (&'static str, &'static str) {
        (self.row.model.name(), "exact")
    }

    fn described_buildings(&self) -> RowBuildings {
        let row = &self.row;
        RowBuildings {
            buildings: row
                .buildings
                .iter()
                .map(|b| BuildingHeader {
                    name: b.name.clone(),
                    storeys: b.storeys(),
                    period_s: periods(b)[0],
                })
                .collect(),
            joints: row
                .joints
                .iter()
                .enumerate()
                .map(|(j, joint)| JointHeader {
                    left: row.buildings[j].name.clone(),
                    right: row.buildings[j + 1].name.clone(),
                    gap_m: joint.gap,
                })
                .collect(),
        }
    }

    /// One line per building, then one per joint, the cells that do not
    /// apply empty.
    fn record_columns() -> Vec<&'static str> {
        vec![
            "record",
            "scale",
            "intensity_measure",
            "intensity_g",
            "pounded",
            "element",
            "name",
            "impacts",
            "max_force_kn",
            "max_drift_ratio",
            "max_absolute_acceleration_g",
            "max_residual_drift_m",
            "no_pounding_max_drift_ratio",
            "no_pounding_max_absolute_acceleration_g",
            "no_pounding_max_residual_drift_m",
            "min_gap_m",
            "abs_m",
            "srss_m",
            "ddc_m",
        ]
    }

    fn record_row(r: &RowSuiteRun) -> RowSuiteRow {
        RowSuiteRow {
            record: r.name.clone(),
            samples: r.samples,
            dt: r.dt,
            scale: r.scale,
            intensity_g: r.intensity,
            duration_s: r.duration,
            demands: r.demands.clone(),
        }
    }

    fn record_lines(r: &RowSuiteRow, measure: &str) -> Vec<Vec<String>> {
        let head = |element: &str, name: &str, impacts: usize, force: f64| {
            vec![
                r.record.clone(),
                num(r.scale),
                measure.to_string(),
                num(r.intensity_g),
                r.demands.pounded.to_string(),
                element.to_string(),
                name.to_string(),
                impacts.to_string(),
                num(force),
            ]
        };
        let d = &r.demands;
        let mut lines = Vec::new();
        for (b, free) in d.buildings.iter().zip(&d.no_pounding) {
            let mut line = head("building", &b.name, b.impacts, b.max_force_kn);
            line.extend(
                [
                    b.max_drift_ratio,
                    b.max_absolute_acceleration_g,
                    b.max_residual_drift_m,
                    free.max_drift_ratio,
                    free.max_absolute_acceleration_g,
                    free.max_residual_drift_m,
                ]
                .map(num),
            );
            line.extend(std::iter::repeat_n(String::new(), 4));
            lines.push(line);
        }
        for (j, joint) in d.joints.iter().enumerate() {
            let name = format!("joint{} {}–{}", j + 1, joint.gap.left, joint.gap.right);
            let mut line = head("joint", &name, joint.impacts, joint.max_force_kn);
            line.extend(std::iter::repeat_n(String::new(), 6));
            let g = &joint.gap;
            line.extend([g.min_gap, g.abs, g.srss, g.ddc].map(num));
            lines.push(line);
        }
        lines
    }

    fn suite_opening(head: &StudyHead<RowBuildings>, records: usize, level: &str, s: &mut String) {
        opening(names(head), &head.buildings, records, level, s);
    }

    /// The impacts and gaps per joint, then per building its demands with
    /// and without pounding.
    fn records_table(records: &[RowSuiteRow], s: &mut String) {
        let width = name_width(records.iter().map(|r| r.record.as_str()));
        let Some(first) = records.first() else {
            return;
        };
        let _ = writeln!(s);
        let _ = write!(s, "{:<width$} {:>8} {:>8}", "record", "scale", "IM g");
        for (j, _) in first.demands.joints.iter().enumerate() {
            let _ = write!(
                s,
                " {:>10} {:>11} {:>11}",
                format!("j{} impacts", j + 1),
                "F_max kN",
                "d_min mm"
            );
        }
        let _ = writeln!(s);
        for r in records {
            let _ = write!(
                s,
                "{:<width$} {:>8} {:>8}",
                clip(&r.record, width),
                g4(r.scale),
                g4(r.intensity_g)
            );
            for j in &r.demands.joints {
                let _ = write!(
                    s,
                    " {:>10} {:>11} {:>11}",
                    j.impacts,
                    g4(j.max_force_kn),
                    g4(j.gap.min_gap * 1e3)
                );
            }
            let _ = writeln!(s);
        }
        for (i, b) in first.demands.buildings.iter().enumerate() {
            let _ = writeln!(s);
            let _ = writeln!(
                s,
                "{:<width$} {:>9} {:>8} {:>10} {:>9} {:>10}   (without pounding)",
                b.name, "drift %", "A g", "resid mm", "drift %", "A g"
            );
            for r in records {
                let (d, free) = (&r.demands.buildings[i], &r.demands.no_pounding[i]);
                let _ = writeln!(
                    s,
                    "{:<width$} {:>9} {:>8} {:>10} {:>9} {:>10}",
                    clip(&r.record, width),
                    g4(d.max_drift_ratio * 100.0),
                    g4(d.max_absolute_acceleration_g),
                    g4(d.max_residual_drift_m * 1e3),
                    g4(free.max_drift_ratio * 100.0),
                    g4(free.max_absolute_acceleration_g)
                );
            }
        }
    }

    fn ida_head(&self) -> Scaled {
        self.scaled()
    }

    fn ida_opening(o: &IdaOpening<Scaled>, s: &mut String) {
        let measure = &o.head.buildings.scaling.measure;
        let _ = writeln!(
            s,
            "IDA at {} levels of {measure}, {} records a level",
            o.levels, o.records_per_level
        );
        let scaling = o.scaled_as_a_whole.map_or_else(
            || format!("each record scaled to every level of {measure}"),
            str::to_string,
        );
        let row = &o.head.buildings.buildings;
        opening(names(o.head), row, o.records_per_level, &scaling, s);
    }

    /// One line per level: who pounded, each building's median drift
    /// (16–84 %) and acceleration, each joint's median gap needed.
    fn levels_table(head: &Scaled, levels: &[(f64, &SuiteStatistics)], s: &mut String) {
        let row = &head.buildings;
        let _ = write!(s, "{:>8} {:>8}", "level g", "pounded");
        for b in &row.buildings {
            let _ = write!(
                s,
                " {:>24} {:>8}",
                format!("{} drift % (16–84)", b.name),
                "A g"
            );
        }
        for (j, _) in row.joints.iter().enumerate() {
            let _ = write!(s, " {:>12}", format!("j{} d_min mm", j + 1));
        }
        let _ = writeln!(s);
        for (level_g, st) in levels {
            let pounded = format!("{}/{}", st.pounded, st.records);
            let _ = write!(s, "{:>8} {pounded:>8}", g4(*level_g));
            for b in &row.buildings {
                let drift = band(st, &format!("{}.max_drift_ratio", b.name), 100.0);
                let key = format!("{}.max_absolute_acceleration_g", b.name);
                let _ = write!(s, " {drift:>24} {:>8}", median(st, &key, 1.0));
            }
            for (j, _) in row.joints.iter().enumerate() {
                let gap = median(st, &format!("joint{}.min_gap_m", j + 1), 1e3);
                let _ = write!(s, " {gap:>12}");
            }
            let _ = writeln!(s);
        }
    }

    fn gap_parts(&self, joints: Vec<JointSeparation>) -> (GapHead, GapTail) {
        let (model, method) = self.model_method();
        let head = GapHead {
            model,
            method,
            scaled: self.scaled(),
        };
        (head, GapTail { joints })
    }

    fn gap_record(r: &RowSuiteRun) -> GapRow {
        let joints = r.demands.joints.iter().map(|j| RecordJoint {
            impacts_at_gap: j.impacts,
            gap: j.gap.clone(),
        });
        GapRow {
            record: r.name.clone(),
            scale: r.scale,
            intensity_g: r.intensity,
            joints: joints.collect(),
        }
    }

    fn gap_lines(r: &GapRow) -> (&str, f64, f64, Vec<Vec<String>>) {
        let line = |(j, joint): (usize, &RecordJoint)| {
            let g = &joint.gap;
            let mut line = vec![format!("joint{}", j + 1), g.left.clone(), g.right.clone()];
            line.extend([g.min_gap, g.abs, g.srss, g.ddc].map(num));
            line.push(joint.impacts_at_gap.to_string());
            line
        };
        let lines = r.joints.iter().enumerate().map(line).collect();
        (&r.record, r.scale, r.intensity_g, lines)
    }

    /// Per joint: the largest u_left − u_right over its paired floors, and
    /// its separation study.
    fn gap_table(o: &GapOpening<Self>, s: &mut String) {
        let scaled = &o.head.scaled;
        let names = [o.suite, o.preset, o.head.model, o.head.method];
        let words = scaled.scaling.words();
        opening(names, &scaled.buildings, o.records.len(), &words, s);
        for (j, joint) in o.tail.joints.iter().enumerate() {
            let _ = writeln!(s);
            let _ = writeln!(
                s,
                "joint{} {}–{} (gap {} mm): per record the largest u_{} − u_{} over its paired floors",
                j + 1,
                joint.left,
                joint.right,
                g4(joint.gap_m * 1e3),
                joint.left,
                joint.right
            );
            let paired = o
                .records
                .first()
                .is_some_and(|r| !r.joints[j].gap.floors.is_empty());
            if !paired {
                let _ = writeln!(
                    s,
                    "no floors pair up at this joint (none at the same elevation within 1 mm): \
                     it cannot pound, and needs no gap"
                );
            }
            study_table(
                s,
                &joint.study,
                joint.gap_m,
                joint.pounding_probability_at_gap,
            );
        }
    }
}
