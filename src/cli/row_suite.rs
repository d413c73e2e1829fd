//! `pounding suite --buildings PRESET`: a row of buildings under every
//! record of a suite, each scaled to an intensity, with each building's and
//! joint's demands per record and their statistics (SPEC §12, §13). The
//! study is [`crate::analysis::row_suite`]; this module parses, runs and
//! prints, and gives `ida` and `gap` on rows the same parsing and running.

use std::fmt::Write as _;

use serde::Serialize;

use super::CliError;
use super::budget::{SECONDS_PER_STEP, Work};
use super::buildings::BuildingsArgs;
use super::description::Provenance;
use super::description::ScalingReport;
use super::output::{Emit, num};
use super::params::ParamArgs;
use super::records::members;
use super::shard::ShardArgs;
use super::study_tables::{clip, over_suite_table};
use super::subject::{CliSubject, run_levels_or_shard};
use crate::analysis::row_suite::{
    RowDemands, RowSuiteCase, RowSuiteError, RowSuiteRun, row_intensity, statistics,
};
use crate::analysis::subject::row::record_seconds;
use crate::analysis::subject::runs::plan;
use crate::analysis::suite::{Scaling, SuiteStatistics};
use crate::model::buildings::Row;
use crate::model::buildings::matrices::periods;
use crate::model::intensity::IntensityMeasure;
use crate::model::params::echo::g4;
use crate::model::suite::SuiteMember;
use crate::output::report::Report;

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

/// A study on a row as the command line asks for it (`--buildings`):
/// what `suite`, `ida` and `gap` on a row share.
#[derive(Debug, Clone, Copy)]
pub struct RowStudyArgs<'a> {
    /// `--buildings`: a built-in row or a path.
    pub buildings: &'a str,
    /// `--set`, `--model`, and the pair's flags a row refuses.
    pub params: &'a ParamArgs,
    pub suite: &'a str,
    pub im: Option<&'a str>,
    /// `--level` (g).
    pub level: Option<f64>,
    pub allow_long: bool,
    /// `--shard`, `--part`, `--skip-done` (and a merge's parts).
    pub shard: &'a ShardArgs,
    /// An IDA's levels scale the suite as a whole ([`Scaling::collective`]).
    pub collective: bool,
}

/// The row study of `args`, checked: the row with `--set` and `--model`
/// applied, its scaling and its records.
pub fn case_of(args: &RowStudyArgs) -> Result<(RowSuiteCase, Vec<SuiteMember>), CliError> {
    let p = args.params;
    let refused = [
        ("--preset", p.preset.is_some(), "a row is its own preset"),
        (
            "--excitation",
            p.excitation.is_some(),
            "a suite runs the records of --suite",
        ),
        ("--dt", p.dt.is_some(), "a row suite runs the exact method"),
        (
            "--cycles",
            p.cycles.is_some(),
            "records have their own length",
        ),
        (
            "--no-pounding",
            p.no_pounding,
            "each record also runs without contact; both are reported",
        ),
        (
            "--presets",
            p.presets.is_some(),
            "rows are read by --buildings",
        ),
    ];
    if let Some((flag, _, why)) = refused.iter().find(|(_, given, _)| *given) {
        return Err(usage(format!(
            "{flag}: not with --buildings ({why}); drop {flag}"
        )));
    }
    if let Some(m) = p.method.as_deref().filter(|m| *m != "exact") {
        return Err(usage(format!(
            "--method {}: a row suite runs the exact method; drop --method or give exact",
            crate::model::params::echo::text(m)
        )));
    }
    let row = BuildingsArgs {
        buildings: Some(args.buildings.to_string()),
        ..BuildingsArgs::default()
    }
    .row(&p.overrides, p.model.as_deref())?;
    let measure = match args.im.map(str::trim) {
        None => IntensityMeasure::Pga,
        Some(text) if text.eq_ignore_ascii_case("sa") => row_intensity(&row),
        Some(text) => IntensityMeasure::parse(text).map_err(|e| {
            usage(format!(
                "--im {e}; or sa alone for a row: Sa(T₁) of its leftmost building"
            ))
        })?,
    };
    let level = args.level;
    let members = members(args.suite)?;
    Ok((
        RowSuiteCase {
            row,
            scaling: Scaling {
                measure,
                level,
                collective: args.collective,
            },
        },
        members,
    ))
}

/// The estimated work of one record's runs ([`record_seconds`]), in the
/// commands' steps. `samples` at interval `dt` (s).
pub fn record_steps(row: &Row, samples: usize, dt: f64) -> f64 {
    record_seconds(row, samples, dt) / SECONDS_PER_STEP
}

/// The work of running every member `times` times (levels of an IDA).
pub fn work_of(row: &Row, members: &[SuiteMember], times: usize) -> Work {
    Work {
        steps: times as f64
            * members
                .iter()
                .map(|m| record_steps(row, m.record.acceleration.len(), m.record.dt))
                .sum::<f64>(),
        rows: 0.0,
    }
}

/// A failed row study as the command line reports it: a record that cannot
/// be scaled is bad input, a runaway run a failure.
pub fn failed(e: RowSuiteError) -> CliError {
    match &e {
        RowSuiteError::Run {
            error: crate::solver::buildings::RowError::Runaway(_),
            ..
        } => CliError::Failed(e.to_string()),
        _ => usage(e.to_string()),
    }
}

/// A row suite that ran: its study, records, runs (in suite order) and wall time.
pub struct RowRan {
    pub case: RowSuiteCase,
    pub members: Vec<SuiteMember>,
    pub runs: Vec<RowSuiteRun>,
    pub elapsed_ms: f64,
}

/// Runs the row suite of `args` within the work bound, with progress, or
/// with `--shard` one shard of it (then `None`: its part was written), or
/// under `pounding merge` its runs from the parts. `command` names the
/// request in the bound's message and in its parts.
pub fn run(args: &RowStudyArgs, command: &str) -> Result<Option<RowRan>, CliError> {
    let (case, members) = case_of(args)?;
    let plans = [plan(&case, &members).map_err(failed)?];
    let (name, shard) = (args.buildings, args.shard);
    let Some((runs, elapsed_ms)) = run_levels_or_shard(
        &case,
        name,
        &members,
        &plans,
        command,
        shard,
        args.allow_long,
        &(),
    )?
    else {
        return Ok(None);
    };
    Ok(Some(RowRan {
        case,
        members,
        runs: runs.into_iter().flatten().collect(),
        elapsed_ms,
    }))
}

/// `pounding suite --buildings`: its typed report handed to `emit`.
pub fn report_with(
    args: &RowStudyArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let Some(RowRan {
        case,
        runs,
        elapsed_ms,
        ..
    }) = run(args, "suite")?
    else {
        return Ok(());
    };
    let report = RowSuiteReport {
        row: RowHeader::new(&case, args.suite),
        records: runs.iter().map(RowSuiteRow::of).collect(),
        statistics: statistics(&runs),
        elapsed_ms,
    };
    emit(&report)
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
    let width = records
        .iter()
        .map(|r| r.record.chars().count())
        .max()
        .unwrap_or(6)
        .clamp(6, 40);
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
struct RowSuiteReport<'a> {
    #[serde(flatten)]
    row: RowHeader<'a>,
    records: Vec<RowSuiteRow>,
    statistics: SuiteStatistics,
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

impl CliSubject for RowSuiteCase {
    fn work_of(&self, members: &[SuiteMember], plans: &[Vec<(f64, f64)>]) -> Work {
        work_of(&self.row, members, plans.len())
    }

    fn check(&self, work: &Work, command: &str, allow_long: bool) -> Result<(), CliError> {
        work.check(&format!("{command} --buildings"), allow_long, true)
    }

    fn steps(&self, run: &RowSuiteRun) -> f64 {
        record_steps(&self.row, run.samples, run.dt)
    }

    fn failed(e: RowSuiteError) -> CliError {
        failed(e)
    }
}
