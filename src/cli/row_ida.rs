//! `pounding ida --buildings PRESET`: a row of buildings under every record
//! at every intensity level, the statistics per level, and the lognormal
//! fragility of each limit state with and without pounding (SPEC §12,
//! §13). The study is [`crate::analysis::subject::runs`] with [`crate::analysis::limit_state`]; this module parses,
//! runs and prints.

use std::fmt::Write as _;
use std::time::Instant;

use serde::Serialize;

use super::CliError;
use super::limit_states::{LimitStateArgs, RowLimitArgs, limit_states};
use super::output::{Emit, num};
use super::progress::Progress;
use super::row_suite::{
    RowHeader, RowStudyArgs, RowSuiteRow, UNITS, case_of, failed, record_steps, work_of,
};
use super::study_tables::closing_tables;
use crate::analysis::ida::{LimitStateFragility, fragilities, parse_levels};
use crate::analysis::limit_state::LimitState;
use crate::analysis::row_suite::{RowSuiteRun, statistics};
use crate::analysis::subject::runs::{plan_levels, run_levels};
use crate::analysis::suite::SuiteStatistics;
use crate::model::params::echo::g4;
use crate::output::report::Report;

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

/// `ida --buildings` as the command line asks for it.
#[derive(Debug, Clone, Copy)]
pub struct RowIdaArgs<'a> {
    pub study: RowStudyArgs<'a>,
    /// `--levels`.
    pub levels: &'a str,
    pub limits: &'a LimitStateArgs,
    pub row_limits: &'a RowLimitArgs,
}

/// `pounding ida --buildings`: its typed report handed to `emit`.
pub fn report_with(
    args: &RowIdaArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let levels = parse_levels(args.levels).map_err(usage)?;
    let (case, members) = case_of(&args.study)?;
    let states = limit_states(args.limits, args.row_limits, Some(&case.row))?;
    let plans = plan_levels(&case, &members, &levels).map_err(failed)?;
    let work = work_of(&case.row, &members, levels.len());
    work.check("ida --buildings", args.study.allow_long, true)?;
    let progress = Progress::start(&work);
    let start = Instant::now();
    // The units level by level, each in suite order.
    let units: Vec<_> = plans
        .iter()
        .flat_map(|level| level.iter().enumerate())
        .collect();
    let Some((flat, merged_ms)) = super::shard::suite::runs(
        args.study.shard,
        "ida",
        args.study.buildings,
        &case,
        &members,
        &units,
        &(&levels, &states),
        failed,
        || {
            let done = |r: &RowSuiteRun| progress.add(record_steps(&case.row, r.samples, r.dt));
            let runs = run_levels(&case, &members, &plans, &done).map_err(failed)?;
            Ok(runs.into_iter().flatten().collect())
        },
    )?
    else {
        return Ok(());
    };
    let mut flat = flat.into_iter();
    let runs: Vec<Vec<RowSuiteRun>> = plans
        .iter()
        .map(|level| flat.by_ref().take(level.len()).collect())
        .collect();
    let fragility = fragilities(&case, &levels, &runs, &states);
    drop(progress);
    let report = RowIdaReport {
        row: RowHeader::new(&case, args.study.suite),
        scaled_as_a_whole: case.scaling.as_a_whole(),
        records_per_level: members.len(),
        levels: levels
            .iter()
            .zip(&runs)
            .map(|(&level, at)| LevelReport {
                level_g: level,
                statistics: statistics(at),
                records: at.iter().map(RowSuiteRow::of).collect(),
            })
            .collect(),
        limit_states: states,
        fragility,
        elapsed_ms: merged_ms.unwrap_or(start.elapsed().as_secs_f64() * 1e3),
    };
    emit(&report)
}

/// One intensity level: its statistics and its records (those of `pounding
/// suite --buildings --level` at that level).
#[derive(Debug, Serialize)]
struct LevelReport {
    level_g: f64,
    statistics: SuiteStatistics,
    records: Vec<RowSuiteRow>,
}

/// `pounding ida --buildings` in every format.
#[derive(Debug, Serialize)]
struct RowIdaReport<'a> {
    #[serde(flatten)]
    row: RowHeader<'a>,
    /// Set when the levels scale the suite as a whole ([`crate::analysis::suite::Scaling::as_a_whole`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    scaled_as_a_whole: Option<String>,
    records_per_level: usize,
    levels: Vec<LevelReport>,
    /// The limit states, in the order of `fragility`.
    limit_states: Vec<LimitState>,
    /// Per limit state: counts at each level and the maximum-likelihood
    /// lognormal fragility (SPEC §12), with pounding and without.
    fragility: Vec<LimitStateFragility>,
    elapsed_ms: f64,
}

impl Report for RowIdaReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["version", "units", "level_g"];
        h.extend(RowSuiteRow::CSV_COLUMNS);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for l in &self.levels {
            for r in &l.records {
                for line in r.csv_lines(&self.row.scaling.measure) {
                    let mut row = vec![
                        env!("CARGO_PKG_VERSION").to_string(),
                        UNITS.to_string(),
                        num(l.level_g),
                    ];
                    row.extend(line);
                    rows.push(row);
                }
            }
        }
        rows
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "IDA at {} levels of {}, {} records a level",
            self.levels.len(),
            self.row.scaling.measure,
            self.records_per_level
        );
        let scaling = self.scaled_as_a_whole.clone().unwrap_or_else(|| {
            format!(
                "each record scaled to every level of {}",
                self.row.scaling.measure
            )
        });
        self.row.table(self.records_per_level, &scaling, &mut s);
        let _ = writeln!(s);
        // One line per level: who pounded, each building's median drift
        // (16–84 %) and acceleration, each joint's median gap needed.
        let _ = write!(s, "{:>8} {:>8}", "level g", "pounded");
        for b in &self.row.buildings {
            let _ = write!(
                s,
                " {:>24} {:>8}",
                format!("{} drift % (16–84)", b.name()),
                "A g"
            );
        }
        for (j, _) in self.row.joints.iter().enumerate() {
            let _ = write!(s, " {:>12}", format!("j{} d_min mm", j + 1));
        }
        let _ = writeln!(s);
        for l in &self.levels {
            let st = &l.statistics;
            let get = |key: &str| {
                st.demands
                    .iter()
                    .find(|d| d.demand == key)
                    .map(|d| d.summary)
            };
            let _ = write!(
                s,
                "{:>8} {:>8}",
                g4(l.level_g),
                format!("{}/{}", st.pounded, st.records)
            );
            for b in &self.row.buildings {
                let drift =
                    get(&format!("{}.max_drift_ratio", b.name())).map_or(String::new(), |d| {
                        format!(
                            "{} ({}–{})",
                            g4(d.median * 100.0),
                            g4(d.p16 * 100.0),
                            g4(d.p84 * 100.0)
                        )
                    });
                let acc = get(&format!("{}.max_absolute_acceleration_g", b.name()))
                    .map_or(String::new(), |d| g4(d.median));
                let _ = write!(s, " {drift:>24} {acc:>8}");
            }
            for (j, _) in self.row.joints.iter().enumerate() {
                let gap = get(&format!("joint{}.min_gap_m", j + 1))
                    .map_or(String::new(), |d| g4(d.median * 1e3));
                let _ = write!(s, " {gap:>12}");
            }
            let _ = writeln!(s);
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
