//! The physical pair's spelling of the suite studies' reports: its two
//! buildings as the `[physical]` table gives them, and per record each
//! structure's demands of SPEC §6 in SI and in Π (SPEC §12) under `left`
//! and `right`.

use std::fmt::Write as _;

use serde::Serialize;

use super::{IdaOpening, Spelling, StudyHead};
use crate::analysis::demands::{DemandsSi, Scales};
use crate::analysis::separation::{JointSeparation, SeparationStudy};
use crate::analysis::suite::{SuiteCase, SuiteRun};
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::gap_suite::study_table;
use crate::cli::output::num;
use crate::cli::study_tables::{band, clip, median, name_width};
use crate::model::Params;
use crate::model::params::echo::g4;
use crate::model::physical::G;
use crate::output::report::{Column, column_cells, column_header};
use crate::solver::StructurePeaks;

/// The buildings (SI), as the preset's `[physical]` table gives them.
#[derive(Debug, Serialize)]
pub struct PairBuildings {
    period1_s: f64,
    period2_s: f64,
    mass1_kg: f64,
    mass2_kg: f64,
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    yield1_m: f64,
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    yield2_m: f64,
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    gap_m: f64,
}

/// One structure of one record, in SI and in Π (SPEC §6).
#[derive(Debug, Serialize)]
pub struct StructureRow {
    #[serde(flatten)]
    si: DemandsSi,
    /// The same demands in Π form (units of SPEC §1).
    pi: StructurePeaks,
}

/// One record of the suite.
#[derive(Debug, Serialize)]
pub struct SuiteRow {
    record: String,
    samples: usize,
    /// Sample interval DT (s).
    dt: f64,
    scale: f64,
    /// IM of the scaled record (g).
    intensity_g: f64,
    /// a_p (m/s²) and ω_p (rad/s) of the scaled record, and the scales from Π to SI.
    #[serde(flatten)]
    scales: Scales,
    left: StructureRow,
    right: StructureRow,
    /// Both structures' demands (SI) in the run without contact (gap = ∞).
    no_pounding: [DemandsSi; 2],
    impacts: usize,
    max_force_kn: f64,
    /// Π_d,min of SPEC §11 (m): the gap at which this record would not pound.
    min_gap_m: f64,
    /// The same in Π form.
    min_gap: f64,
    /// The record's Π-groups and settings (`pounding run` of this set gives
    /// this row).
    params: Params,
    reliable: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    unreliable_reason: Option<String>,
}

/// A record's CSV columns before the intensity measure's name.
const RECORD_COLUMNS: &[Column<SuiteRow>] = &[
    ("record", |r| r.record.clone()),
    ("samples", |r| r.samples.to_string()),
    ("dt", |r| num(r.dt)),
    ("scale", |r| num(r.scale)),
];

/// A record's CSV columns of its scaling, after the intensity measure's name.
const SCALING_COLUMNS: &[Column<SuiteRow>] = &[
    ("intensity_g", |r| num(r.intensity_g)),
    ("ap", |r| num(r.scales.ap)),
    ("omega_p", |r| num(r.scales.omega_p)),
];

/// A record's CSV columns after both structures'.
const RESULT_COLUMNS: &[Column<SuiteRow>] = &[
    ("impacts", |r| r.impacts.to_string()),
    ("max_force_kn", |r| num(r.max_force_kn)),
    ("min_gap_m", |r| num(r.min_gap_m)),
    ("min_gap", |r| num(r.min_gap)),
    ("reliable", |r| r.reliable.to_string()),
];

/// The per-structure CSV columns, left then right: SI, then Π
/// ([`side_cells`]).
const SIDE_COLUMNS: [[&str; 11]; 2] = [
    [
        "left_peak_displacement_m",
        "left_peak_velocity_m_s",
        "left_peak_absolute_acceleration_g",
        "left_ductility",
        "left_residual_displacement_m",
        "left_hysteretic_energy_kj",
        "left_peak_displacement",
        "left_peak_velocity",
        "left_peak_absolute_acceleration",
        "left_residual_displacement",
        "left_hysteretic_energy",
    ],
    [
        "right_peak_displacement_m",
        "right_peak_velocity_m_s",
        "right_peak_absolute_acceleration_g",
        "right_ductility",
        "right_residual_displacement_m",
        "right_hysteretic_energy_kj",
        "right_peak_displacement",
        "right_peak_velocity",
        "right_peak_absolute_acceleration",
        "right_residual_displacement",
        "right_hysteretic_energy",
    ],
];

/// A structure's cells under its [`SIDE_COLUMNS`].
fn side_cells(s: &StructureRow) -> [String; 11] {
    [
        s.si.peak_displacement_m,
        s.si.peak_velocity_m_s,
        s.si.peak_absolute_acceleration_g,
        s.si.ductility,
        s.si.residual_displacement_m,
        s.si.hysteretic_energy_kj,
        s.pi.peak_displacement,
        s.pi.peak_velocity,
        s.pi.peak_absolute_acceleration,
        s.pi.residual_displacement,
        s.pi.hysteretic_energy,
    ]
    .map(num)
}

/// One record of a separation study: its scaling, Π_d,min and separate
/// peaks (m).
#[derive(Debug, Serialize)]
pub struct GapRow {
    record: String,
    scale: f64,
    intensity_g: f64,
    /// Π_d,min of SPEC §11 in m.
    min_gap_m: f64,
    /// Peak drifts of the separate buildings (the run without contact).
    free_peak_left_m: f64,
    free_peak_right_m: f64,
    /// Impacts of the run at the preset's own gap.
    impacts_at_gap: usize,
}

/// What the pair's separation study says before its records: the scaling,
/// the preset's own gap (m) and the fraction of records whose Π_d,min
/// exceeds it.
#[derive(Debug, Serialize)]
pub struct GapHead {
    measure: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    level_g: Option<f64>,
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    gap_m: f64,
    pounding_probability_at_gap: f64,
}

/// The pair's one joint's separation study, after its records.
#[derive(Debug, Serialize)]
pub struct GapTail {
    study: SeparationStudy,
}

/// The intensity measure, which the pair's IDA names where a row names its
/// buildings and scaling.
#[derive(Debug, Serialize)]
pub struct Measure {
    measure: String,
}

impl Spelling for SuiteCase {
    const SUITE_UNITS: &'static str =
        "SI (m, m/s, g, kN, kJ) for the demands; Π-groups of SPEC §1 under `pi`";
    const IDA_UNITS: &'static str = "SI (m, m/s, g, kN, kJ) for the demands, g for intensities; \
                                     Π-groups of SPEC §1 under `pi`";
    const GAP_UNITS: &'static str = "m for gaps and peak drifts, g for intensities";
    const NAMES_LIMIT_STATES: bool = false;
    const GAP_COLUMNS: &'static [&'static str] = &[
        "min_gap_m",
        "free_peak_left_m",
        "free_peak_right_m",
        "impacts_at_gap",
    ];

    type Buildings = PairBuildings;
    type Record = SuiteRow;
    type IdaHead = Measure;
    type GapHead = GapHead;
    type GapTail = GapTail;
    type GapRecord = GapRow;

    fn preset<'a>(&'a self, name: &'a str) -> &'a str {
        name
    }

    fn record_columns() -> Vec<&'static str> {
        let mut h = column_header(&[], RECORD_COLUMNS);
        h.push("intensity_measure");
        h.extend(column_header(&[], SCALING_COLUMNS));
        h.extend(SIDE_COLUMNS.concat());
        h.extend(column_header(&[], RESULT_COLUMNS));
        h
    }

    fn model_method(&self) -> (&'static str, &'static str) {
        (self.settings.model.name(), self.settings.method.name())
    }

    fn described_buildings(&self) -> PairBuildings {
        let phys = &self.physical;
        PairBuildings {
            period1_s: std::f64::consts::TAU / phys.omega[0],
            period2_s: std::f64::consts::TAU / phys.omega[1],
            mass1_kg: phys.mass[0],
            mass2_kg: phys.mass[1],
            yield1_m: phys.yield_displacement[0],
            yield2_m: phys.yield_displacement[1],
            gap_m: phys.gap,
        }
    }

    fn record_row(r: &SuiteRun) -> SuiteRow {
        let unreliable_reason = r.result.unreliable();
        SuiteRow {
            record: r.name.clone(),
            samples: r.samples,
            dt: r.dt,
            scale: r.scale,
            intensity_g: r.intensity,
            scales: r.si.scales,
            left: StructureRow {
                si: r.si.left,
                pi: r.result.left,
            },
            right: StructureRow {
                si: r.si.right,
                pi: r.result.right,
            },
            no_pounding: [r.free_si.left, r.free_si.right],
            impacts: r.result.impacts.len(),
            max_force_kn: r.max_force_kn(),
            min_gap_m: r.min_gap_m(),
            min_gap: r.min_gap,
            params: r.params.clone(),
            reliable: unreliable_reason.is_none(),
            unreliable_reason,
        }
    }

    fn record_lines(r: &SuiteRow, measure: &str) -> Vec<Vec<String>> {
        let mut row: Vec<String> = column_cells(RECORD_COLUMNS, r).collect();
        row.push(measure.to_string());
        row.extend(column_cells(SCALING_COLUMNS, r));
        for side in [&r.left, &r.right] {
            row.extend(side_cells(side));
        }
        row.extend(column_cells(RESULT_COLUMNS, r));
        vec![row]
    }

    fn suite_opening(head: &StudyHead<PairBuildings>, records: usize, level: &str, s: &mut String) {
        let b = &head.buildings;
        let _ = writeln!(
            s,
            "suite {} ({records} records), preset {}: {}, {} method",
            head.suite, head.provenance.preset, head.model, head.method
        );
        let _ = writeln!(
            s,
            "buildings: T1 = {} s, T2 = {} s, m1 = {} kg, m2 = {} kg, gap = {} mm; {level}",
            g4(b.period1_s),
            g4(b.period2_s),
            g4(b.mass1_kg),
            g4(b.mass2_kg),
            g4(b.gap_m * 1e3)
        );
        let _ = writeln!(s);
    }

    fn records_table(records: &[SuiteRow], s: &mut String) {
        let name_width = name_width(records.iter().map(|r| r.record.as_str()));
        let _ = writeln!(
            s,
            "{:<name_width$} {:>7} {:>5} {:>8} {:>8} {:>8} {:>7} {:>9} {:>9}",
            "record", "samples", "dt s", "scale", "IM g", "a_p g", "ω_p r/s", "impacts", "F_max kN"
        );
        for r in records {
            let _ = writeln!(
                s,
                "{:<name_width$} {:>7} {:>5} {:>8} {:>8} {:>8} {:>7} {:>9} {:>9}{}",
                clip(&r.record, name_width),
                r.samples,
                g4(r.dt),
                g4(r.scale),
                g4(r.intensity_g),
                g4(r.scales.ap / G),
                g4(r.scales.omega_p),
                r.impacts,
                g4(r.max_force_kn),
                if r.reliable { "" } else { "  unreliable" }
            );
        }
        for (title, side) in [("left", 0), ("right", 1)] {
            let _ = writeln!(s);
            let _ = writeln!(
                s,
                "{:<name_width$} {:>9} {:>8} {:>7} {:>7} {:>10} {:>9} {:>9}",
                title, "u mm", "v m/s", "A g", "μ", "resid mm", "E_h kJ", "d_min mm"
            );
            for r in records {
                let d = if side == 0 { &r.left.si } else { &r.right.si };
                let _ = writeln!(
                    s,
                    "{:<name_width$} {:>9} {:>8} {:>7} {:>7} {:>10} {:>9} {:>9}",
                    clip(&r.record, name_width),
                    g4(d.peak_displacement_m * 1e3),
                    g4(d.peak_velocity_m_s),
                    g4(d.peak_absolute_acceleration_g),
                    g4(d.ductility),
                    g4(d.residual_displacement_m * 1e3),
                    g4(d.hysteretic_energy_kj),
                    g4(r.min_gap_m * 1e3)
                );
            }
        }
    }

    fn ida_head(&self) -> Measure {
        Measure {
            measure: self.scaling.measure.to_string(),
        }
    }

    fn ida_opening(o: &IdaOpening<Measure>, s: &mut String) {
        let h = o.head;
        let _ = writeln!(
            s,
            "IDA of suite {} ({} records) at {} levels of {}, preset {}: {}, {} method",
            h.suite,
            o.records_per_level,
            o.levels,
            h.buildings.measure,
            h.provenance.preset,
            h.model,
            h.method
        );
        if let Some(words) = o.scaled_as_a_whole {
            let _ = writeln!(s, "{words}");
        }
    }

    /// One line per level: the medians that matter, with the 16–84 % band
    /// of drift.
    fn levels_table(_: &Measure, levels: &[(f64, &SuiteStatistics)], s: &mut String) {
        let _ = writeln!(
            s,
            "{:>8} {:>8} {:>22} {:>8} {:>8} {:>22} {:>8} {:>10}",
            "level g",
            "pounded",
            "left u mm (16–84 %)",
            "left μ",
            "left A g",
            "right u mm (16–84 %)",
            "right μ",
            "d_min mm"
        );
        for (level_g, st) in levels {
            let (band, median) = (
                |key, unit| band(st, key, unit),
                |key, unit| median(st, key, unit),
            );
            let _ = writeln!(
                s,
                "{:>8} {:>8} {:>22} {:>8} {:>8} {:>22} {:>8} {:>10}",
                g4(*level_g),
                format!("{}/{}", st.pounded, st.records),
                band("left.peak_displacement_m", 1e3),
                median("left.ductility", 1.0),
                median("left.peak_absolute_acceleration_g", 1.0),
                band("right.peak_displacement_m", 1e3),
                median("right.ductility", 1.0),
                median("min_gap_m", 1e3)
            );
        }
    }

    fn gap_parts(&self, joints: Vec<JointSeparation>) -> (GapHead, GapTail) {
        let joint = joints.into_iter().next().expect("the pair has one joint");
        let head = GapHead {
            measure: self.scaling.measure.to_string(),
            level_g: self.scaling.level,
            gap_m: joint.gap_m,
            pounding_probability_at_gap: joint.pounding_probability_at_gap,
        };
        (head, GapTail { study: joint.study })
    }

    fn gap_record(r: &SuiteRun) -> GapRow {
        GapRow {
            record: r.name.clone(),
            scale: r.scale,
            intensity_g: r.intensity,
            min_gap_m: r.min_gap_m(),
            free_peak_left_m: r.free_si.left.peak_displacement_m,
            free_peak_right_m: r.free_si.right.peak_displacement_m,
            impacts_at_gap: r.result.impacts.len(),
        }
    }

    fn gap_lines(r: &GapRow) -> (&str, f64, f64, Vec<Vec<String>>) {
        let cells = vec![
            num(r.min_gap_m),
            num(r.free_peak_left_m),
            num(r.free_peak_right_m),
            r.impacts_at_gap.to_string(),
        ];
        (&r.record, r.scale, r.intensity_g, vec![cells])
    }

    fn gap_table(o: &super::GapOpening<Self>, s: &mut String) {
        let (h, st) = (o.head, &o.tail.study);
        let scaling = match h.level_g {
            Some(x) => format!("each record scaled to {} = {} g", h.measure, num(x)),
            None => "records at their list's scale".to_string(),
        };
        let _ = writeln!(
            s,
            "separation over suite {} ({} records), preset {}; {scaling}",
            o.suite, st.records, o.preset
        );
        study_table(s, st, h.gap_m, h.pounding_probability_at_gap);
    }
}
