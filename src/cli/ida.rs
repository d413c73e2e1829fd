//! `pounding ida`: incremental dynamic analysis of a suite (every record at
//! every intensity level), the statistics per level, and the lognormal
//! fragility of each limit state with and without pounding (SPEC §12). The
//! study is [`crate::analysis::ida`]; this module parses, runs and prints.

use std::fmt::Write as _;
use std::time::Instant;

use clap::Args;
use serde::Serialize;

use super::CliError;
use super::description::Provenance;
use super::limit_states::{LimitStateArgs, RowLimitArgs, limit_states};
use super::output::{Emit, printer};
use super::progress::Progress;
use super::records::members;
use super::row_ida::RowIdaArgs;
use super::study_tables::closing_tables;
use super::suite::{SuiteArgs, SuiteRow, case_of, record_steps, work_of};
use crate::analysis::ida::{LimitStateFragility, fragilities, parse_levels};
use crate::analysis::subject::runs::{plan_levels, run_levels};
use crate::analysis::suite::{SuiteRun, SuiteStatistics};
use crate::model::Method;
use crate::model::params::echo::g4;
use crate::output::report::Report;

#[derive(Debug, Clone, Default, Args)]
pub struct IdaArgs {
    /// The preset, suite, intensity measure and output options of `pounding suite`.
    #[command(flatten)]
    pub suite: SuiteArgs,
    /// Intensity levels in g: START:STOP:STEP (e.g. 0.05:1.0:0.05) or a
    /// list X1,X2,…, ascending and > 0.
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub levels: String,
    #[command(flatten)]
    pub limits: LimitStateArgs,
    #[command(flatten)]
    pub row_limits: RowLimitArgs,
}

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

pub fn execute(args: &IdaArgs) -> Result<(), CliError> {
    report_with(args, printer(args.suite.output.format))
}

/// The IDA of `args` with its fragilities, its typed report handed to `emit`.
pub fn report_with(
    args: &IdaArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    if args.suite.level.is_some() {
        return Err(usage(
            "--level: an IDA runs every level of --levels; use `pounding suite` for one".into(),
        ));
    }
    // With --target, the records are first scaled to the design spectrum by
    // the code's rule, and each level then scales that suite as a whole
    // (FEMA P-695), keeping the code's proportions between records.
    let args = &IdaArgs {
        suite: SuiteArgs {
            collective: args.suite.design.target.is_some(),
            ..args.suite.at_design_level()?
        },
        ..args.clone()
    };
    if let Some(study) = args.suite.row_study()? {
        let row = RowIdaArgs {
            study,
            levels: &args.levels,
            limits: &args.limits,
            row_limits: &args.row_limits,
        };
        return super::row_ida::report_with(&row, emit);
    }
    args.row_limits.refuse_on_a_pair()?;
    let levels = parse_levels(&args.levels).map_err(usage)?;
    let states = limit_states(&args.limits, &args.row_limits, None)?;
    let (preset, case) = case_of(&args.suite)?;
    let members = members(&args.suite.suite)?;
    let plans = plan_levels(&case, &members, &levels).map_err(|e| usage(e.to_string()))?;
    let work = work_of(plans.iter().flatten());
    work.check("ida", args.suite.long.allow_long, false)?;
    let progress = Progress::start(&work);
    let start = Instant::now();
    let units: Vec<_> = plans.iter().flat_map(|at| at.iter().enumerate()).collect();
    let failed = |e: crate::analysis::suite::SuiteRunError| usage(e.to_string());
    let whole = || {
        let done = |r: &SuiteRun| progress.add(record_steps(&r.params));
        let runs = run_levels(&case, &members, &plans, &done).map_err(failed)?;
        Ok(runs.into_iter().flatten().collect())
    };
    let extra = (&levels, &states);
    let shard = &args.suite.shard;
    let Some((runs, merged_ms)) = super::shard::suite::runs(
        shard,
        "ida",
        &preset.name,
        &case,
        &members,
        &units,
        &extra,
        failed,
        whole,
    )?
    else {
        return Ok(());
    };
    let runs: Vec<Vec<SuiteRun>> = runs
        .chunks(members.len().max(1))
        .map(<[_]>::to_vec)
        .collect();
    let fragility = fragilities(&case, &levels, &runs, &states);
    drop(progress);
    let elapsed_ms = merged_ms.unwrap_or(start.elapsed().as_secs_f64() * 1e3);

    let report = IdaReport {
        provenance: Provenance::new(&preset.name, UNITS),
        suite: &args.suite.suite,
        model: case.settings.model.name(),
        method: case.settings.method,
        measure: case.scaling.measure.to_string(),
        scaled_as_a_whole: case.scaling.as_a_whole(),
        records_per_level: members.len(),
        levels: levels
            .iter()
            .zip(&runs)
            .map(|(&level, at)| LevelReport {
                level_g: level,
                statistics: SuiteStatistics::of(at),
                records: at.iter().map(SuiteRow::of).collect(),
            })
            .collect(),
        fragility,
        elapsed_ms,
    };
    emit(&report)?;
    let unreliable = runs
        .iter()
        .flatten()
        .filter(|r| r.result.unreliable().is_some())
        .count();
    if unreliable > 0 && !args.suite.allow_unreliable {
        return Err(CliError::Failed(format!(
            "unreliable result for {unreliable} of {} runs (flagged in the output); \
             pass --allow-unreliable to accept them",
            runs.iter().map(Vec::len).sum::<usize>()
        )));
    }
    Ok(())
}

const UNITS: &str = "SI (m, m/s, g, kN, kJ) for the demands, g for intensities; \
                     Π-groups of SPEC §1 under `pi`";

/// One intensity level: its statistics and its rows (those of `pounding
/// suite --level` at that level).
#[derive(Debug, Serialize)]
struct LevelReport {
    level_g: f64,
    statistics: SuiteStatistics,
    records: Vec<SuiteRow>,
}

/// `pounding ida` in every format.
#[derive(Debug, Serialize)]
struct IdaReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    suite: &'a str,
    model: &'static str,
    method: Method,
    measure: String,
    /// Set when the levels scale the suite as a whole ([`crate::analysis::suite::Scaling::as_a_whole`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    scaled_as_a_whole: Option<String>,
    records_per_level: usize,
    levels: Vec<LevelReport>,
    /// Per limit state: counts at each level and the maximum-likelihood
    /// lognormal fragility (SPEC §12), with pounding and without.
    fragility: Vec<LimitStateFragility>,
    elapsed_ms: f64,
}

impl Report for IdaReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units", "level_g"];
        h.extend(SuiteRow::csv_header());
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for l in &self.levels {
            for r in &l.records {
                let mut row = vec![
                    env!("CARGO_PKG_VERSION").to_string(),
                    UNITS.to_string(),
                    super::output::num(l.level_g),
                ];
                row.extend(r.csv_cells(&self.measure));
                rows.push(row);
            }
        }
        rows
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "IDA of suite {} ({} records) at {} levels of {}, preset {}: {}, {} method",
            self.suite,
            self.records_per_level,
            self.levels.len(),
            self.measure,
            self.provenance.preset,
            self.model,
            self.method.name()
        );
        if let Some(words) = &self.scaled_as_a_whole {
            let _ = writeln!(s, "{words}");
        }
        let _ = writeln!(s);
        // One line per level: the medians that matter, with the 16–84 % band of drift.
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
        for l in &self.levels {
            let st = &l.statistics;
            let get = |key: &str| {
                st.demands
                    .iter()
                    .find(|d| d.demand == key)
                    .map(|d| d.summary)
            };
            let band = |key: &str, unit: f64| {
                get(key).map_or(String::new(), |d| {
                    format!(
                        "{} ({}–{})",
                        g4(d.median * unit),
                        g4(d.p16 * unit),
                        g4(d.p84 * unit)
                    )
                })
            };
            let median =
                |key: &str, unit: f64| get(key).map_or(String::new(), |d| g4(d.median * unit));
            let _ = writeln!(
                s,
                "{:>8} {:>8} {:>22} {:>8} {:>8} {:>22} {:>8} {:>10}",
                g4(l.level_g),
                format!("{}/{}", st.pounded, st.records),
                band("left.peak_displacement_m", 1e3),
                median("left.ductility", 1.0),
                median("left.peak_absolute_acceleration_g", 1.0),
                band("right.peak_displacement_m", 1e3),
                median("right.ductility", 1.0),
                median("min_gap_m", 1e3)
            );
        }
        let levels: Vec<(f64, &SuiteStatistics)> = self
            .levels
            .iter()
            .map(|l| (l.level_g, &l.statistics))
            .collect();
        closing_tables(&mut s, &self.fragility, &levels, self.elapsed_ms);
        s
    }
}
