//! `pounding records select`: the N records of a directory that best fit a
//! target spectrum, within a factor limit and at most K per earthquake
//! ([`crate::analysis::record_selection`]), scaled to the code's rule and
//! reported (and written as a suite list) as `records scale` does.

use std::path::{Path, PathBuf};

use clap::Args;

use super::design::{TargetArgs, parse_period};
use super::output::{Emit, FormatArg, printer};
use super::records_scale::{ScaleReport, list_text, verdict, write_list};
use super::{CliError, usage};
use crate::analysis::record_selection::{Candidate, Limits, select};
use crate::model::record::event;
use crate::model::suite::SuiteSpec;
use crate::output::shown;

#[derive(Debug, Clone, Default, Args)]
pub struct SelectArgs {
    /// The directory of candidate records (every record file in it).
    #[arg(long, value_name = "DIR")]
    pub from: PathBuf,
    #[command(flatten)]
    pub target: TargetArgs,
    /// T1 (s), the building's fundamental period the range is taken around.
    #[arg(long, value_name = "T1")]
    pub period: String,
    /// How many records to choose.
    #[arg(long, value_name = "N")]
    pub count: String,
    /// The largest factor M a record may take (and 1/M the smallest).
    #[arg(long, value_name = "M", default_value = "4")]
    pub max_scale: String,
    /// At most K records of one earthquake (the AT2 header's event line, K-NET's origin time).
    #[arg(long, value_name = "K")]
    pub per_event: Option<String>,
    /// Write the chosen records as a suite list here (`PATH SCALE` lines).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub output: FormatArg,
}

/// A whole number ≥ 1 given to `flag`.
fn count(flag: &str, text: &str) -> Result<usize, CliError> {
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|n| *n >= 1)
        .ok_or_else(|| {
            usage(format!(
                "{flag} {}: must be a whole number ≥ 1",
                crate::model::params::echo::text(text)
            ))
        })
}

pub fn execute(args: &SelectArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The selection of `args`, its report handed to `emit`; the list written
/// first.
pub fn report_with(
    args: &SelectArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let design = args.target.required(parse_period(&args.period)?)?;
    let wanted = count("--count", &args.count)?;
    let max_scale = args
        .max_scale
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|m| *m > 1.0 && *m <= crate::model::suite::MAX_SCALE)
        .ok_or_else(|| {
            usage(format!(
                "--max-scale {}: must be a factor in (1, {}]",
                crate::model::params::echo::text(&args.max_scale),
                crate::model::suite::MAX_SCALE
            ))
        })?;
    let per_event = args
        .per_event
        .as_deref()
        .map(|k| count("--per-event", k))
        .transpose()?;
    if !args.from.is_dir() {
        return Err(usage(format!(
            "--from {}: not a directory of records",
            shown(&args.from)
        )));
    }
    let from = shown(&args.from);
    let members = SuiteSpec::Directory(args.from.clone())
        .load()
        .map_err(|e| usage(format!("--from {e}")))?;
    let candidates: Vec<Candidate> = members
        .into_iter()
        .map(|member| Candidate {
            event: event::of_file(Path::new(&member.record.path)),
            member,
        })
        .collect();
    let limits = Limits {
        count: wanted,
        max_scale,
        per_event,
    };
    let selection = select(&design, &candidates, limits).map_err(usage)?;
    if let Some(out) = &args.out {
        let text = list_text(
            out,
            &selection.chosen,
            &selection.matching,
            &design,
            &format!(
                "pounding records select --from {from} --count {wanted} --max-scale {max_scale}{}",
                per_event
                    .map(|k| format!(" --per-event {k}"))
                    .unwrap_or_default()
            ),
        )?;
        write_list(out, &text)?;
    }
    let mut report = ScaleReport::new(&from, &design, &selection.matching, args.out.as_deref())
        .with_events(&selection.events);
    report.selection = Some(selection.excluded);
    report.candidates = Some(selection.candidates);
    emit(&report)?;
    verdict(&selection.matching.check)
}
