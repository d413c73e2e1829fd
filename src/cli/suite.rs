//! `pounding suite`: one physical pair of buildings under every record of a
//! suite, each scaled to an intensity, with the demands of SPEC §6 per
//! record and their statistics over the suite (SPEC §12). The study itself
//! is [`crate::analysis::suite`]; this module parses, runs and prints.

use std::fmt::Write as _;

use clap::Args;
use serde::Serialize;

use super::CliError;
use super::budget::{LongArg, Work, run_steps};
use super::description::{Provenance, ScalingReport};
use super::output::{Emit, FormatArg, num, printer};
use super::params::ParamArgs;
use super::records::members;
use super::row_suite::RowStudyArgs;
use super::study_tables::{clip, over_suite_table};
use super::subject::{CliSubject, run_levels_or_shard};
use crate::analysis::demands::{DemandsSi, Scales};
use crate::analysis::subject::runs::plan;
use crate::analysis::suite::{MemberPlan, Scaling, SuiteCase, SuiteRun, SuiteStatistics};
use crate::model::intensity::IntensityMeasure;
use crate::model::physical::G;
use crate::model::{Method, Params};
use crate::output::report::Report;
use crate::solver::StructurePeaks;

#[derive(Debug, Clone, Default, Args)]
pub struct SuiteArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// The records: a directory (every record file in it, in name order), a
    /// text file with one `PATH [SCALE]` a line (`#` comments), or
    /// `synthetic:N[@SEED]` (N simulated records, made in memory).
    #[arg(long, value_name = "SUITE")]
    pub suite: String,
    /// Intensity measure: `pga`, or `sa:T`, the 5 %-damped pseudo-spectral
    /// acceleration at period T seconds, 0 < T ≤ 10 (SPEC §12) [default: pga];
    /// with --buildings, `sa` alone is Sa at the leftmost building's T₁.
    #[arg(long, value_name = "pga|sa:T")]
    pub im: Option<String>,
    /// Scale each record so that its intensity measure equals X, in g
    /// (`0.3` or `0.3g`); without it each record runs at its list's scale.
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub level: Option<String>,
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub long: LongArg,
    /// Exit 0 even when a record's result is unreliable (it is still flagged).
    #[arg(long)]
    pub allow_unreliable: bool,
    #[command(flatten)]
    pub shard: super::shard::ShardArgs,
    /// A row of shear buildings (SPEC §13) instead of the preset's pair: a
    /// built-in row (two-buildings, block-and-frame, three-in-series, block-and-frame-pdelta,
    /// block-and-frame-retrofit) or a
    /// path to a row preset; `--im sa` is then Sa at the leftmost building's
    /// T₁ (to four significant digits).
    #[arg(long, value_name = "NAME|PATH")]
    pub buildings: Option<String>,
    /// An IDA of a suite scaled to a target: its levels scale the suite as a
    /// whole (set by `ida --target`, not a flag of its own).
    #[arg(skip)]
    pub collective: bool,
    /// Scale the records to a target spectrum by the code's rule (see
    /// `records scale`) instead of --level; the suite's name then says so.
    #[command(flatten)]
    pub design: super::design::TargetArgs,
    /// With --target: T1 (s) [default: the pair's left T1, or the row's longest T1].
    #[arg(long, value_name = "T1")]
    pub period: Option<String>,
}

/// `--suite`, `--im` and `--level` for a command that runs one set or,
/// given `--suite`, a suite of records (`gap`, `map`).
#[derive(Debug, Clone, Default, Args)]
pub struct SuiteOptions {
    /// Over a suite of records, as `pounding suite --suite` takes it.
    #[arg(long, value_name = "SUITE")]
    pub suite: Option<String>,
    /// With --suite: the intensity measure, pga or sa:T [default: pga].
    #[arg(long, value_name = "pga|sa:T")]
    pub im: Option<String>,
    /// With --suite: scale each record so that its intensity measure equals X (g).
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub level: Option<String>,
    /// With --suite: scale the records to a target spectrum by the code's
    /// rule (T1: `--period`, else the buildings').
    #[command(flatten)]
    pub design: super::design::TargetArgs,
}

impl SuiteOptions {
    /// The suite request, with the command's own options, or `None`
    /// without `--suite`; `others` names the suite-only flags given (by
    /// their flags) that are refused without it.
    pub fn request(
        &self,
        params: &ParamArgs,
        output: FormatArg,
        long: LongArg,
        others: &[(&str, bool)],
    ) -> Result<Option<SuiteArgs>, CliError> {
        let Some(suite) = &self.suite else {
            let flags = [
                ("--im", self.im.is_some()),
                ("--level", self.level.is_some()),
                ("--target", self.design.target.is_some()),
            ];
            if let Some((flag, _)) = flags.iter().chain(others).find(|(_, given)| *given) {
                return Err(usage(format!(
                    "{flag}: applies to a suite of records; give --suite SUITE"
                )));
            }
            return Ok(None);
        };
        Ok(Some(SuiteArgs {
            params: params.clone(),
            suite: suite.clone(),
            im: self.im.clone(),
            level: self.level.clone(),
            output,
            long,
            allow_unreliable: true,
            shard: Default::default(),
            buildings: None,
            collective: false,
            design: self.design.clone(),
            period: None,
        }))
    }
}

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

impl SuiteArgs {
    /// These arguments with `--target` written into the suite's name
    /// ([`super::design_suite`]): the records scaled to the target by the
    /// code's rule, T1 `--period` or the buildings'.
    pub fn at_design_level(&self) -> Result<SuiteArgs, CliError> {
        let name = super::design_suite::scaled_name(
            &self.suite,
            &self.design,
            self.period.as_deref(),
            self.level.as_deref(),
            || match &self.buildings {
                Some(b) => super::design_suite::row_period(
                    &super::buildings::BuildingsArgs {
                        buildings: Some(b.clone()),
                        ..Default::default()
                    }
                    .row(&self.params.overrides, self.params.model.as_deref())?,
                ),
                None => super::design_suite::pair_period(&self.params),
            },
        )?;
        Ok(match name {
            Some(suite) => SuiteArgs {
                suite,
                design: Default::default(),
                period: None,
                ..self.clone()
            },
            None => self.clone(),
        })
    }

    /// The study on a row that `--buildings` asks for (`--level` read), or
    /// `None` without it.
    pub fn row_study(&self) -> Result<Option<RowStudyArgs<'_>>, CliError> {
        let Some(buildings) = &self.buildings else {
            return Ok(None);
        };
        Ok(Some(RowStudyArgs {
            buildings,
            params: &self.params,
            suite: &self.suite,
            im: self.im.as_deref(),
            level: self.level.as_deref().map(parse_level).transpose()?,
            allow_long: self.long.allow_long,
            shard: &self.shard,
            collective: self.collective,
        }))
    }
}

/// `--level X`: a positive, finite level in g (`0.3` or `0.3g`).
pub fn parse_level(text: &str) -> Result<f64, CliError> {
    let t = text.trim();
    let v = t.strip_suffix('g').unwrap_or(t).trim().parse::<f64>();
    match v {
        Ok(v) if v > 0.0 && v.is_finite() => Ok(v),
        _ => Err(usage(format!(
            "--level {}: must be a positive intensity in g, e.g. 0.3 or 0.3g",
            crate::model::params::echo::text(text)
        ))),
    }
}

/// The study asked for: the buildings, settings and scaling, checked.
pub fn case_of(args: &SuiteArgs) -> Result<(crate::model::Preset, SuiteCase), CliError> {
    if args.params.excitation.is_some() {
        return Err(usage(
            "--excitation: a suite runs the records of --suite; drop --excitation".into(),
        ));
    }
    let (preset, settings) = args.params.resolve_for_many()?;
    let physical = args.params.physical(&preset)?.ok_or_else(|| {
        usage(format!(
            "preset `{}` has no [physical] table: a suite shakes the same physical buildings \
             with every record, each record's own a_p and ω_p setting the Π-groups (SPEC §12); \
             use a preset with [physical], such as two-buildings",
            preset.name
        ))
    })?;
    let measure = match &args.im {
        Some(text) => IntensityMeasure::parse(text).map_err(|e| usage(format!("--im {e}")))?,
        None => IntensityMeasure::Pga,
    };
    let level = args.level.as_deref().map(parse_level).transpose()?;
    Ok((
        preset,
        SuiteCase {
            physical,
            settings,
            scaling: Scaling {
                measure,
                level,
                collective: args.collective,
            },
        },
    ))
}

/// A suite that ran: its preset, study, runs (in suite order) and wall time.
pub struct Ran {
    pub preset: crate::model::Preset,
    pub case: SuiteCase,
    pub runs: Vec<SuiteRun>,
    pub elapsed_ms: f64,
}

/// The work of one planned record: a pounding run and at most one run
/// without contact, each counted at its nominal steps.
pub fn record_steps(params: &Params) -> f64 {
    2.0 * run_steps(params)
}

/// The work of every planned record of a study.
pub fn work_of<'a>(plans: impl IntoIterator<Item = &'a MemberPlan>) -> Work {
    Work {
        steps: plans.into_iter().map(|m| record_steps(&m.params)).sum(),
        rows: 0.0,
    }
}

/// Loads the suite of `args`, plans every record before any run (a zero
/// record or Π-groups out of range fail at once, naming the record), and
/// runs them in parallel with progress; or with `--shard` one shard of it
/// (then `None`: its part was written), or under `pounding merge` the runs
/// from the parts. `what` names the request in the work bound's message
/// and in its parts.
pub fn run_or_shard(args: &SuiteArgs, what: &str) -> Result<Option<Ran>, CliError> {
    let (preset, case) = case_of(args)?;
    let members = members(&args.suite)?;
    let plans = [plan(&case, &members).map_err(|e| usage(e.to_string()))?];
    let (shard, allow_long) = (&args.shard, args.long.allow_long);
    let Some((runs, elapsed_ms)) = run_levels_or_shard(
        &case,
        &preset.name,
        &members,
        &plans,
        what,
        shard,
        allow_long,
        &(),
    )?
    else {
        return Ok(None);
    };
    Ok(Some(Ran {
        preset,
        case,
        runs: runs.into_iter().flatten().collect(),
        elapsed_ms,
    }))
}

pub fn execute(args: &SuiteArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The suite study of `args`, its typed report handed to `emit`.
pub fn report_with(
    args: &SuiteArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let args = &args.at_design_level()?;
    if let Some(study) = args.row_study()? {
        return super::row_suite::report_with(&study, emit);
    }
    let Some(Ran {
        preset,
        case,
        runs,
        elapsed_ms,
    }) = run_or_shard(args, "suite")?
    else {
        return Ok(());
    };
    let report = SuiteReport::new(&preset.name, &args.suite, &case, &runs, elapsed_ms);
    emit(&report)?;
    let unreliable: Vec<String> = runs
        .iter()
        .filter_map(|r| {
            r.result
                .unreliable()
                .map(|why| format!("{}: {why}", r.name))
        })
        .collect();
    if !unreliable.is_empty() && !args.allow_unreliable {
        return Err(CliError::Failed(format!(
            "unreliable result for {} of {} records ({}); pass --allow-unreliable to accept them",
            unreliable.len(),
            runs.len(),
            unreliable.join("; ")
        )));
    }
    Ok(())
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
        let mut h = vec![
            "record",
            "samples",
            "dt",
            "scale",
            "intensity_measure",
            "intensity_g",
            "ap",
            "omega_p",
        ];
        for side in SIDE_COLUMNS {
            h.extend(side);
        }
        h.extend([
            "impacts",
            "max_force_kn",
            "min_gap_m",
            "min_gap",
            "reliable",
        ]);
        h
    }

    /// The cells of [`SuiteRow::csv_header`]; `measure` names the IM.
    pub fn csv_cells(&self, measure: &str) -> Vec<String> {
        let r = self;
        let mut row = vec![
            r.record.clone(),
            r.samples.to_string(),
            num(r.dt),
            num(r.scale),
            measure.to_string(),
            num(r.intensity_g),
            num(r.scales.ap),
            num(r.scales.omega_p),
        ];
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
        row.extend([
            r.impacts.to_string(),
            num(r.max_force_kn),
            num(r.min_gap_m),
            num(r.min_gap),
            r.reliable.to_string(),
        ]);
        row
    }
}

/// `pounding suite` in every format.
#[derive(Debug, Serialize)]
struct SuiteReport<'a> {
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
    fn new(
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
            statistics: SuiteStatistics::of(runs),
            elapsed_ms,
        }
    }
}

/// A number for a table: four significant digits, `inf` for infinity.
fn g4(v: f64) -> String {
    crate::model::params::echo::g4(v)
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
        let name_width = self
            .records
            .iter()
            .map(|r| r.record.chars().count())
            .max()
            .unwrap_or(6)
            .clamp(6, 40);
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

impl CliSubject for SuiteCase {
    fn work_of(&self, _: &[crate::model::suite::SuiteMember], plans: &[Vec<MemberPlan>]) -> Work {
        work_of(plans.iter().flatten())
    }

    fn check(&self, work: &Work, command: &str, allow_long: bool) -> Result<(), CliError> {
        work.check(command, allow_long, false)
    }

    fn steps(&self, run: &SuiteRun) -> f64 {
        record_steps(&run.params)
    }

    fn failed(e: crate::analysis::suite::SuiteRunError) -> CliError {
        CliError::Usage(e.to_string())
    }
}
