//! `pounding suite` of the physical pair: its report in every format, per
//! record each structure's demands of SPEC §6 in SI and in Π (SPEC §12).

use std::fmt::Write as _;

use serde::Serialize;

use crate::analysis::demands::{DemandsSi, Scales};
use crate::analysis::suite::{SuiteCase, SuiteRun};
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::description::{Provenance, ScalingReport};
use crate::cli::output::num;
use crate::cli::study_tables::{clip, name_width, over_suite_table};
use crate::model::params::echo::g4;
use crate::model::physical::G;
use crate::model::{Method, Params};
use crate::output::report::{Column, Report, column_cells, column_header};
use crate::solver::StructurePeaks;

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

impl SuiteRow {
    pub fn of(r: &SuiteRun) -> SuiteRow {
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

    /// The CSV columns of a row, after `version` and `units`.
    pub fn csv_header() -> Vec<&'static str> {
        let mut h = column_header(&[], RECORD_COLUMNS);
        h.push("intensity_measure");
        h.extend(column_header(&[], SCALING_COLUMNS));
        h.extend(SIDE_COLUMNS.concat());
        h.extend(column_header(&[], RESULT_COLUMNS));
        h
    }

    /// The cells of [`SuiteRow::csv_header`]; `measure` names the IM.
    pub fn csv_cells(&self, measure: &str) -> Vec<String> {
        let r = self;
        let mut row: Vec<String> = column_cells(RECORD_COLUMNS, r).collect();
        row.push(measure.to_string());
        row.extend(column_cells(SCALING_COLUMNS, r));
        for s in [&r.left, &r.right] {
            row.extend(
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
                .map(num),
            );
        }
        row.extend(column_cells(RESULT_COLUMNS, r));
        row
    }
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

/// A record's CSV columns after both structures' ([`SIDE_COLUMNS`]).
const RESULT_COLUMNS: &[Column<SuiteRow>] = &[
    ("impacts", |r| r.impacts.to_string()),
    ("max_force_kn", |r| num(r.max_force_kn)),
    ("min_gap_m", |r| num(r.min_gap_m)),
    ("min_gap", |r| num(r.min_gap)),
    ("reliable", |r| r.reliable.to_string()),
];

/// `pounding suite` in every format.
#[derive(Debug, Serialize)]
pub struct SuiteReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    suite: &'a str,
    model: &'static str,
    method: Method,
    /// The buildings (SI), as the preset's [physical] table gives them.
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
    scaling: ScalingReport,
    records: Vec<SuiteRow>,
    statistics: SuiteStatistics,
    elapsed_ms: f64,
}

/// SI for the demands, Π-groups beside them.
const UNITS: &str = "SI (m, m/s, g, kN, kJ) for the demands; Π-groups of SPEC §1 under `pi`";

impl<'a> SuiteReport<'a> {
    pub fn new(
        preset: &'a str,
        suite: &'a str,
        case: &SuiteCase,
        runs: &[SuiteRun],
        elapsed_ms: f64,
    ) -> Self {
        let phys = &case.physical;
        let records = runs.iter().map(SuiteRow::of).collect();
        SuiteReport {
            provenance: Provenance::new(preset, UNITS),
            suite,
            model: case.settings.model.name(),
            method: case.settings.method,
            period1_s: std::f64::consts::TAU / phys.omega[0],
            period2_s: std::f64::consts::TAU / phys.omega[1],
            mass1_kg: phys.mass[0],
            mass2_kg: phys.mass[1],
            yield1_m: phys.yield_displacement[0],
            yield2_m: phys.yield_displacement[1],
            gap_m: phys.gap,
            scaling: ScalingReport {
                measure: case.scaling.measure.to_string(),
                level_g: case.scaling.level,
            },
            records,
            statistics: SuiteStatistics::of(case, runs),
            elapsed_ms,
        }
    }
}

impl Report for SuiteReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units"];
        h.extend(SuiteRow::csv_header());
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        self.records
            .iter()
            .map(|r| {
                let mut row = vec![env!("CARGO_PKG_VERSION").to_string(), UNITS.to_string()];
                row.extend(r.csv_cells(&self.scaling.measure));
                row
            })
            .collect()
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let level = self.scaling.words();
        let _ = writeln!(
            s,
            "suite {} ({} records), preset {}: {}, {} method",
            self.suite,
            self.records.len(),
            self.provenance.preset,
            self.model,
            self.method.name()
        );
        let _ = writeln!(
            s,
            "buildings: T1 = {} s, T2 = {} s, m1 = {} kg, m2 = {} kg, gap = {} mm; {level}",
            g4(self.period1_s),
            g4(self.period2_s),
            g4(self.mass1_kg),
            g4(self.mass2_kg),
            g4(self.gap_m * 1e3)
        );
        let _ = writeln!(s);
        let name_width = name_width(self.records.iter().map(|r| r.record.as_str()));
        let _ = writeln!(
            s,
            "{:<name_width$} {:>7} {:>5} {:>8} {:>8} {:>8} {:>7} {:>9} {:>9}",
            "record", "samples", "dt s", "scale", "IM g", "a_p g", "ω_p r/s", "impacts", "F_max kN"
        );
        for r in &self.records {
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
                format!("{title}"),
                "u mm",
                "v m/s",
                "A g",
                "μ",
                "resid mm",
                "E_h kJ",
                "d_min mm"
            );
            for r in &self.records {
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
        over_suite_table(&mut s, &self.statistics);
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}

/// The per-structure CSV columns, left then right: SI, then Π.
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
