//! `pounding suite --buildings`: a row's suite report in every format, per
//! record one line per building and per joint (SPEC §12, §13), and the
//! opening lines every row study's report shares ([`RowHeader`]).

use std::fmt::Write as _;

use serde::Serialize;

use crate::analysis::subject::row::{RowDemands, RowSuiteCase, RowSuiteRun};
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::cli::description::{Provenance, ScalingReport};
use crate::cli::output::num;
use crate::cli::study_tables::{clip, name_width, over_suite_table};
use crate::model::buildings::matrices::periods;
use crate::model::params::echo::g4;
use crate::output::report::Report;

/// The report of the row suite `runs` of `case` (suite `suite`).
pub fn report<'a>(
    case: &'a RowSuiteCase,
    suite: &'a str,
    runs: &[RowSuiteRun],
    elapsed_ms: f64,
) -> RowSuiteReport<'a> {
    RowSuiteReport {
        row: RowHeader::new(case, suite),
        records: runs.iter().map(RowSuiteRow::of).collect(),
        statistics: SuiteStatistics::of(case, runs),
        elapsed_ms,
    }
}

/// SI units of a row's suite reports.
pub const UNITS: &str = "SI (m, g, kN) for the demands, g for intensities; drift ratios Δ/h";

/// One building of the row, as a suite report names it.
#[derive(Debug, Serialize)]
pub struct BuildingHeader {
    name: String,
    storeys: usize,
    /// The fundamental period T₁ (s).
    period_s: f64,
}

impl BuildingHeader {
    pub fn name(&self) -> &str {
        &self.name
    }
}

/// One joint, as a suite report names it.
#[derive(Debug, Serialize)]
pub struct JointHeader {
    left: String,
    right: String,
    /// The gap at rest (m).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    gap_m: f64,
}

/// What every row suite report says before its results: the row, the
/// suite, the contact law and method, and the scaling.
#[derive(Debug, Serialize)]
pub struct RowHeader<'a> {
    #[serde(flatten)]
    pub provenance: Provenance<'a>,
    pub suite: &'a str,
    pub model: &'static str,
    pub method: &'static str,
    pub buildings: Vec<BuildingHeader>,
    pub joints: Vec<JointHeader>,
    pub scaling: ScalingReport,
}

impl<'a> RowHeader<'a> {
    pub fn new(case: &'a RowSuiteCase, suite: &'a str) -> Self {
        let row = &case.row;
        RowHeader {
            provenance: Provenance::new(&row.name, UNITS),
            suite,
            model: row.model.name(),
            method: "exact",
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
            scaling: ScalingReport {
                measure: case.scaling.measure.to_string(),
                level_g: case.scaling.level,
            },
        }
    }

    /// The opening lines of a table: the suite, the row and `scaling`, the
    /// scaling in words.
    pub fn table(&self, records: usize, scaling: &str, s: &mut String) {
        let level = scaling;
        let _ = writeln!(
            s,
            "suite {} ({records} records), row {}: {}, {} method; {level}",
            self.suite, self.provenance.preset, self.model, self.method
        );
        let buildings: Vec<String> = self
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
        let joints: Vec<String> = self
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

impl RowSuiteRow {
    pub fn of(r: &RowSuiteRun) -> RowSuiteRow {
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

    /// The CSV columns of a record's lines: one line per building, then one
    /// per joint, the cells that do not apply empty.
    pub const CSV_COLUMNS: [&'static str; 19] = [
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
    ];

    /// The lines of [`RowSuiteRow::CSV_COLUMNS`]; `measure` names the IM.
    pub fn csv_lines(&self, measure: &str) -> Vec<Vec<String>> {
        let head = |element: &str, name: &str, impacts: usize, force: f64| {
            vec![
                self.record.clone(),
                num(self.scale),
                measure.to_string(),
                num(self.intensity_g),
                self.demands.pounded.to_string(),
                element.to_string(),
                name.to_string(),
                impacts.to_string(),
                num(force),
            ]
        };
        let d = &self.demands;
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
            line.extend(
                [
                    joint.gap.min_gap,
                    joint.gap.abs,
                    joint.gap.srss,
                    joint.gap.ddc,
                ]
                .map(num),
            );
            lines.push(line);
        }
        lines
    }
}

/// The per-record tables of a row suite: the impacts and gaps per joint,
/// then per building its demands with and without pounding.
pub fn records_table(s: &mut String, records: &[RowSuiteRow]) {
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

/// `pounding suite --buildings` in every format.
#[derive(Debug, Serialize)]
pub struct RowSuiteReport<'a> {
    #[serde(flatten)]
    pub(super) row: RowHeader<'a>,
    records: Vec<RowSuiteRow>,
    pub(super) statistics: SuiteStatistics,
    elapsed_ms: f64,
}

impl Report for RowSuiteReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units"];
        h.extend(RowSuiteRow::CSV_COLUMNS);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for r in &self.records {
            for line in r.csv_lines(&self.row.scaling.measure) {
                let mut row = vec![env!("CARGO_PKG_VERSION").to_string(), UNITS.to_string()];
                row.extend(line);
                rows.push(row);
            }
        }
        rows
    }

    fn table(&self) -> String {
        let mut s = String::new();
        self.row
            .table(self.records.len(), &self.row.scaling.words(), &mut s);
        records_table(&mut s, &self.records);
        over_suite_table(&mut s, &self.statistics);
        let _ = writeln!(s, "elapsed {:.0} ms", self.elapsed_ms);
        s
    }
}
