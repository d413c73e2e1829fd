//! `pounding gap --suite`: the separation that prevents pounding with a
//! chosen probability over a suite of records, beside the code rules
//! (SPEC §11, §12), for the pair's joint (`--preset`) or each joint of a row
//! (`--buildings`, SPEC §13). Each record's gap at a joint comes from its
//! run without contact; the study of those values is
//! [`crate::analysis::separation::joint_separations`], one path for both
//! subjects. This module runs it, and [`report`] writes it, one writer for
//! both subjects; with `--compare`, on each variant of a row, side by side
//! (module `compare`).

use std::fmt::Write as _;

mod compare;
pub mod report;

use super::CliError;
use super::output::{Emit, num};
use super::spelling::Spelling;
use super::subject::{CliSubject, Study};
use super::suite::{Chosen, SuiteArgs};
use crate::analysis::separation::{
    GapAtProbability, JointSeparation, RuleOnSuite, SeparationStudy, joint_separations,
    parse_probabilities,
};
use crate::model::params::echo::g4;
use crate::output::report::{TableColumn, aligned};

/// The CSV columns every record's line of a separation study begins with,
/// the pair's and a row's alike; [`record_cells`] fills them.
pub const RECORD_COLUMNS: [&str; 6] = [
    "version",
    "units",
    "record",
    "scale",
    "intensity_measure",
    "intensity_g",
];

/// The cells of [`RECORD_COLUMNS`] for a record run at `scale`, where its
/// intensity `measure` is `intensity_g`.
pub fn record_cells(
    units: &str,
    record: &str,
    scale: f64,
    measure: &str,
    intensity_g: f64,
) -> Vec<String> {
    vec![
        env!("CARGO_PKG_VERSION").to_string(),
        units.to_string(),
        record.to_string(),
        num(scale),
        measure.to_string(),
        num(intensity_g),
    ]
}

/// The probabilities reported when `--probability` is not given.
pub const DEFAULT_PROBABILITIES: &str = "0.5,0.84,0.9";

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

/// The probabilities of `--probability` ([`DEFAULT_PROBABILITIES`] when
/// `None`), each in (0, 1).
pub fn probabilities(probability: Option<&str>) -> Result<Vec<f64>, CliError> {
    parse_probabilities(
        "--probability",
        probability.unwrap_or(DEFAULT_PROBABILITIES),
    )
    .map_err(|e| usage(e.to_string()))
}

/// Runs the suite of `suite_args` on the subject `--preset` or
/// `--buildings` chooses and reports, per joint, the separation at each of
/// `probability` (a list, [`DEFAULT_PROBABILITIES`] when `None`), its typed
/// report handed to `emit`.
pub fn report_with(
    suite_args: &SuiteArgs,
    probability: Option<&str>,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let probabilities = probabilities(probability)?;
    if !suite_args.compare.is_empty() {
        return compare::gap(suite_args, probabilities, emit);
    }
    match Chosen::of(suite_args)? {
        Chosen::Pair(study) => separation(&study, suite_args, &probabilities, emit),
        Chosen::Row(study) => separation(&study, suite_args, &probabilities, emit),
    }
}

/// The separation of `study` at `probabilities`: its records run (or
/// sharded, or merged), each joint's study, reported.
fn separation<S: Spelling>(
    study: &Study<S>,
    args: &SuiteArgs,
    probabilities: &[f64],
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let Some(ran) = separated(study, args, probabilities)? else {
        return Ok(());
    };
    let subject = &study.subject;
    let (name, suite) = (&study.name, &args.suite);
    emit(&report::report(
        subject,
        name,
        suite,
        &ran.runs,
        ran.joints,
        ran.elapsed_ms,
    ))
}

/// A separation study that ran: the records' runs, each joint's study and
/// the wall time (ms).
struct Separated<R> {
    runs: Vec<R>,
    joints: Vec<JointSeparation>,
    elapsed_ms: f64,
}

/// The records of `study` run (or sharded, or merged) and each joint's
/// separation at `probabilities`; `None` when a shard's part was written.
/// A record whose run without contact stopped early fails the study (exit
/// 1): its gap would cover only part of the record.
fn separated<S: CliSubject>(
    study: &Study<S>,
    args: &SuiteArgs,
    probabilities: &[f64],
) -> Result<Option<Separated<S::Run>>, CliError> {
    let Some((runs, elapsed_ms)) = study.run("gap", &args.shard, args.long.allow_long)? else {
        return Ok(None);
    };
    let subject = &study.subject;
    if let Some(r) = runs.iter().find(|r| subject.free_run_stopped(r)) {
        return Err(CliError::Failed(format!(
            "record `{}`: the run without contact stopped before its end; its minimum gap \
             covers only the part that was run",
            S::record_name(r)
        )));
    }
    let joints = joint_separations(subject, &runs, probabilities);
    Ok(Some(Separated {
        runs,
        joints,
        elapsed_ms,
    }))
}

/// A separation study (SPEC §12) as a table: the minimum gaps' median and
/// fit, the gap at each probability, P(pounding) at the preset's gap
/// `gap_m` (m) and the code rules; for a pair, or for one joint of a row.
pub fn study_table(
    s: &mut String,
    st: &SeparationStudy,
    gap_m: f64,
    pounding_probability_at_gap: f64,
) {
    let _ = writeln!(
        s,
        "Π_d,min of each record from its run without contact (SPEC §11): median {} mm{}",
        g4(st.median_min_gap * 1e3),
        st.lognormal.map_or(String::new(), |f| format!(
            ", lognormal median {} mm, β = {:.3}",
            g4(f.median * 1e3),
            f.dispersion
        ))
    );
    let _ = writeln!(s);
    s.push_str(&aligned(PROBABILITY_TABLE, &st.at_probability));
    let _ = writeln!(s);
    let pounded = (pounding_probability_at_gap * st.records as f64).round() as usize;
    let _ = writeln!(
        s,
        "at the preset's gap of {} mm: P(pounding) = {} ({} of {} records)",
        g4(gap_m * 1e3),
        g4(pounding_probability_at_gap),
        pounded,
        st.records
    );
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "code rules (SPEC §11) on each record's separate peaks, and on the median peaks \
         ({} mm, {} mm; ρ = {:.3}):",
        g4(st.median_peaks[0] * 1e3),
        g4(st.median_peaks[1] * 1e3),
        st.correlation
    );
    s.push_str(&aligned(RULE_TABLE, &st.rules));
}

/// The gap at each probability: the records' d_(⌈pN⌉) and the lognormal
/// fit's (mm). Each column after the first is one wider than its numbers,
/// for two spaces between columns.
const PROBABILITY_TABLE: &[TableColumn<GapAtProbability>] = &[
    ("probability", 11, |a| num(a.probability)),
    ("gap d_(⌈pN⌉) mm", 23, |a| g4(a.empirical * 1e3)),
    ("lognormal mm", 15, |a| {
        a.lognormal.map_or("-".to_string(), |v| g4(v * 1e3))
    }),
];

/// Each code rule over the suite: the share of records it holds for, its
/// gap on the median peaks (mm), P(pounding) there, and the probabilities
/// at which it is enough.
const RULE_TABLE: &[TableColumn<RuleOnSuite>] = &[
    ("rule", -5, |r| r.rule.to_string()),
    ("holds (records)", 16, |r| {
        format!("{:.0} %", 100.0 * r.holds)
    }),
    ("on medians mm", 18, |r| g4(r.at_median_peaks * 1e3)),
    ("P(pounding)", 12, |r| g4(r.pounding_probability)),
    (" enough at probability", 0, |r| {
        if r.sufficient_at.is_empty() {
            " none of those asked".to_string()
        } else {
            let at: Vec<String> = r.sufficient_at.iter().map(|p| num(*p)).collect();
            format!(" {}", at.join(", "))
        }
    }),
];
