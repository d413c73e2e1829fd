//! `pounding records scale`: a suite's records scaled to a target spectrum
//! by the code's rule ([`crate::analysis::record_scaling`]), with each
//! record's factor, ln-misfit and ratio at T1, the suite's worst ratio and
//! the verdict; optionally written as a suite list of `PATH SCALE` lines
//! that `suite`, `ida`, `gap --suite` and `map --suite` read as they are.
//! `--check` applies the rule to the list's own scales instead.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::Args;
use serde::Serialize;

use super::design::{TargetArgs, parse_period};
use super::design_suite::load as members;
use super::output::{Emit, FormatArg, num, printer, refuse_non_file};
use super::study_tables::{clip, name_width};
use super::{CliError, usage};
use crate::analysis::record_scaling::{
    Binding, Design, FACTOR_BAND, FRACTION, Matching, PeriodRange, RecordMatch, RuleCheck, check,
    scale,
};
use crate::model::params::echo::g4;
use crate::model::suite::{MAX_SCALE, SuiteMember, SuiteSpec};
use crate::output::report::Report;
use crate::output::shown;

#[derive(Debug, Clone, Default, Args)]
pub struct ScaleArgs {
    // The help's `[@SEED]` is an optional part, not a doc link.
    #[allow(rustdoc::broken_intra_doc_links)]
    /// The records: a directory, a list file of `PATH [SCALE]` lines, or synthetic:N[@SEED].
    #[arg(long, value_name = "SUITE")]
    pub suite: String,
    #[command(flatten)]
    pub target: TargetArgs,
    /// T1 (s), the building's fundamental period the range is taken around.
    #[arg(long, value_name = "T1")]
    pub period: String,
    /// Write the scaled suite list here (`PATH SCALE` lines, a `#` header).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Apply the rule to the list's own scales, without scaling.
    #[arg(long)]
    pub check: bool,
    #[command(flatten)]
    pub output: FormatArg,
}

pub fn execute(args: &ScaleArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The scaling of `args`, its report handed to `emit` (the list written
/// first); exit 1 when the rule does not hold.
pub fn report_with(
    args: &ScaleArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    verdict(&scaled(args, emit)?)
}

/// [`report_with`] without the verdict's exit: the rule's check, whatever
/// it says (the Python module returns it in the report).
pub fn scaled(
    args: &ScaleArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<RuleCheck, CliError> {
    let design = args.target.required(parse_period(&args.period)?)?;
    if args.check && args.out.is_some() {
        return Err(usage(
            "--out: --check writes nothing (the list is checked as it is); drop --out",
        ));
    }
    let spec = SuiteSpec::parse(&args.suite).map_err(usage)?;
    if let (Some(out), SuiteSpec::Synthetic { count, seed }) = (&args.out, &spec) {
        return Err(usage(format!(
            "--out {}: the records of synthetic:{count}@{seed} are made in memory, a list cannot \
             name them; write them with `pounding records synth --count {count} --seed {seed} \
             --out DIR`, then scale DIR",
            shown(out)
        )));
    }
    let members = members(&args.suite)?;
    let matching = if args.check {
        check(&design, &members)
    } else {
        scale(&design, &members)
    }
    .map_err(usage)?;
    if let Some(out) = &args.out {
        let text = list_text(
            out,
            &members,
            &matching,
            &design,
            &format!(
                "pounding records scale --suite {}",
                crate::output::escape_controls(args.suite.chars())
            ),
        )?;
        write_list(out, &text)?;
    }
    emit(&ScaleReport::new(
        &args.suite,
        &design,
        &matching,
        args.out.as_deref(),
    ))?;
    Ok(matching.check)
}

/// Writes a suite list atomically, never over a file that is not regular.
pub fn write_list(out: &Path, text: &str) -> Result<(), CliError> {
    refuse_non_file(out)?;
    Ok(crate::output::write_file(out, text.as_bytes())?)
}

/// Exit 1, naming why, when the rule does not hold.
pub fn verdict(check: &RuleCheck) -> Result<(), CliError> {
    if check.holds {
        return Ok(());
    }
    Err(CliError::Failed(format!(
        "the suite does not meet {}: {}",
        check.clause,
        check.failures.join("; ")
    )))
}

/// A record's path as a list at `out` names it: relative to the list's
/// directory when the record is under it, else absolute.
fn list_path(out: &Path, record: &str) -> Result<String, CliError> {
    let dir = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let fail = |what: &Path, e: std::io::Error| {
        CliError::Failed(format!("{}: {}", shown(what), crate::output::reason(&e)))
    };
    let dir = dir.canonicalize().map_err(|e| {
        CliError::Failed(format!(
            "cannot write {}: its directory {}",
            shown(out),
            crate::output::reason(&e)
        ))
    })?;
    let path = Path::new(record)
        .canonicalize()
        .map_err(|e| fail(Path::new(record), e))?;
    let named = path.strip_prefix(&dir).unwrap_or(&path);
    let text = named
        .to_str()
        .ok_or_else(|| CliError::Failed(format!("the path {} is not UTF-8", shown(named))))?;
    if text.chars().any(char::is_whitespace) {
        return Err(CliError::Failed(format!(
            "the path {} holds white space, which a `PATH SCALE` list cannot",
            shown(named)
        )));
    }
    Ok(text.to_string())
}

/// The suite list of a scaling: a `#` header naming the target, the range
/// and the rule, then `PATH SCALE` a line, each scale written exactly.
pub fn list_text(
    out: &Path,
    members: &[SuiteMember],
    matching: &Matching,
    design: &Design,
    command: &str,
) -> Result<String, CliError> {
    let check = &matching.check;
    let mut text = format!(
        "# {command} --target {} --code {} --period {} --range {}:{}\n\
         # target: {} ({})\n\
         # rule: {}\n\
         # over {}–{} s; common factor {}; {}\n\
         # one record a line: PATH SCALE\n",
        design.target.label(),
        design.code.name(),
        design.period,
        design.range.low,
        design.range.high,
        design.target.label(),
        design.target.clause(),
        design.code.rule(),
        design.range.low * design.period,
        design.range.high * design.period,
        matching.common_factor,
        if check.holds {
            "the rule holds".to_string()
        } else {
            format!("the rule does not hold: {}", check.failures.join("; "))
        }
    );
    for (m, r) in members.iter().zip(&matching.records) {
        if !(r.factor > 0.0 && r.factor <= MAX_SCALE) {
            return Err(CliError::Failed(format!(
                "record `{}` needs the factor {}, outside the (0, {MAX_SCALE}] a list may hold",
                m.name,
                g4(r.factor)
            )));
        }
        let _ = writeln!(text, "{} {}", list_path(out, &m.record.path)?, r.factor);
    }
    Ok(text)
}

/// The period range, in multiples of T1 and in seconds.
#[derive(Debug, Serialize)]
struct RangeReport {
    #[serde(flatten)]
    multiples: PeriodRange,
    low_s: f64,
    high_s: f64,
}

/// `records scale` and `records select` in every format.
#[derive(Debug, Serialize)]
pub struct ScaleReport<'a> {
    version: &'static str,
    suite: &'a str,
    target_spectrum: String,
    target_clause: &'static str,
    rule: String,
    period_s: f64,
    range: RangeReport,
    common_factor: f64,
    binding: Binding,
    /// The grid (s), the target on it (g), the suite's mean and percentiles (g).
    periods: &'a [f64],
    target: &'a [f64],
    mean: &'a [f64],
    p16: &'a [f64],
    p84: &'a [f64],
    records: Vec<RecordRow<'a>>,
    check: &'a RuleCheck,
    #[serde(skip_serializing_if = "Option::is_none")]
    list: Option<String>,
    /// `records select`: how many candidates, and why the others were left out.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub selection: Option<crate::analysis::record_selection::Exclusions>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub candidates: Option<usize>,
}

/// One record: its match, and the event it comes from (`records select`).
#[derive(Debug, Serialize)]
struct RecordRow<'a> {
    #[serde(flatten)]
    matched: &'a RecordMatch,
    #[serde(skip_serializing_if = "Option::is_none")]
    event: Option<String>,
}

impl<'a> ScaleReport<'a> {
    pub fn new(
        suite: &'a str,
        design: &Design,
        matching: &'a Matching,
        list: Option<&Path>,
    ) -> ScaleReport<'a> {
        ScaleReport {
            version: env!("CARGO_PKG_VERSION"),
            suite,
            target_spectrum: design.target.label(),
            target_clause: design.target.clause(),
            rule: design.code.rule(),
            period_s: design.period,
            range: RangeReport {
                multiples: design.range,
                low_s: design.range.low * design.period,
                high_s: design.range.high * design.period,
            },
            common_factor: matching.common_factor,
            binding: matching.binding,
            periods: &matching.periods,
            target: &matching.target,
            mean: &matching.mean,
            p16: &matching.p16,
            p84: &matching.p84,
            records: matching
                .records
                .iter()
                .map(|matched| RecordRow {
                    matched,
                    event: None,
                })
                .collect(),
            check: &matching.check,
            list: list.map(shown),
            selection: None,
            candidates: None,
        }
    }

    /// Each record's event, in order (`records select`).
    pub fn with_events(mut self, events: &[Option<String>]) -> Self {
        for (row, event) in self.records.iter_mut().zip(events) {
            row.event = event.clone();
        }
        self
    }
}

/// What set the common factor, in words.
fn binding_words(binding: Binding) -> String {
    match binding {
        Binding::Fit => "1: the fitted mean meets the rule".into(),
        Binding::Spectrum { period_s } => format!(
            "set where the mean sits at {} % of the target, T = {} s",
            FRACTION * 100.0,
            g4(period_s)
        ),
        Binding::ZeroPeriod => "set by the mean PGA at a_g·S".into(),
        Binding::List => "none: the list's scales, checked as they are".into(),
    }
}

impl Report for ScaleReport<'_> {
    fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "suite {} ({} records) scaled to {} ({})",
            self.suite,
            self.records.len(),
            self.target_spectrum,
            self.target_clause
        );
        let _ = writeln!(s, "rule: {}", self.rule);
        let _ = writeln!(
            s,
            "T1 = {} s, range {}–{} s ({}–{} T1, {} periods); common factor {} ({})",
            g4(self.period_s),
            g4(self.range.low_s),
            g4(self.range.high_s),
            self.range.multiples.low,
            self.range.multiples.high,
            self.periods.len(),
            g4(self.common_factor),
            binding_words(self.binding)
        );
        if let (Some(n), Some(e)) = (self.candidates, &self.selection) {
            let _ = writeln!(
                s,
                "chosen from {n} records: {} with a factor outside the limit, {} beyond the \
                 per-event cap, {} past the limit after the common factor, {} silent",
                e.factor, e.per_event, e.after_common_factor, e.silent
            );
        }
        let _ = writeln!(s);
        let width = name_width(self.records.iter().map(|r| r.matched.record.as_str()));
        let events = self.records.iter().any(|r| r.event.is_some());
        let _ = writeln!(
            s,
            "{:<width$} {:>9} {:>10} {:>10} {:>16}{}",
            "record",
            "factor",
            "LS factor",
            "ln-misfit",
            "Sa/target at T1",
            if events { "  event" } else { "" }
        );
        for r in &self.records {
            let m = r.matched;
            let _ = writeln!(
                s,
                "{:<width$} {:>9} {:>10} {:>10} {:>16}{}{}",
                clip(&m.record, width),
                g4(m.factor),
                g4(m.least_squares_factor),
                g4(m.ln_misfit),
                g4(m.ratio_at_period),
                if m.outside_band { " *" } else { "" },
                r.event
                    .as_deref()
                    .map(|e| format!("  {e}"))
                    .unwrap_or_default()
            );
        }
        if self.records.iter().any(|r| r.matched.outside_band) {
            let _ = writeln!(s, "* factor outside [{}, {}]", FACTOR_BAND.0, FACTOR_BAND.1);
        }
        let c = self.check;
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "mean/target over the range: min {} at T = {} s (margin {:+.2} % over {} %)",
            format_args!("{:.4}", c.min_ratio),
            g4(c.at_period_s),
            // A suite scaled to sit at 90 % is there to rounding: no `-0.00`.
            if c.margin.abs() < 1e-9 {
                0.0
            } else {
                c.margin * 100.0
            },
            FRACTION * 100.0
        );
        if let (Some(pga), Some(anchor)) = (c.mean_pga_g, c.zero_period_target_g) {
            let _ = writeln!(
                s,
                "mean PGA {} g against a_g·S = {} g (ratio {:.4})",
                g4(pga),
                g4(anchor),
                pga / anchor
            );
        }
        let _ = writeln!(
            s,
            "{} records (at least {}): {}",
            c.records,
            c.min_records,
            c.verdict()
        );
        if let Some(list) = &self.list {
            let _ = writeln!(s, "list: {list}");
        }
        s
    }

    fn csv_header(&self) -> Vec<&'static str> {
        vec![
            "period_s",
            "target_g",
            "threshold_g",
            "mean_g",
            "p16_g",
            "p84_g",
            "mean_over_target",
        ]
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        (0..self.periods.len())
            .map(|k| {
                vec![
                    num(self.periods[k]),
                    num(self.target[k]),
                    num(FRACTION * self.target[k]),
                    num(self.mean[k]),
                    num(self.p16[k]),
                    num(self.p84[k]),
                    num(self.mean[k] / self.target[k]),
                ]
            })
            .collect()
    }
}
