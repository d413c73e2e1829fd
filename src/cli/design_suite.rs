//! Where a `--suite` string becomes suite members, and the studies'
//! shorthand `--target TARGET [--period T1]`: the records scaled to the
//! target by the code's rule ([`crate::analysis::record_scaling`]) before
//! any study runs them, for the pair and for the row alike.
//!
//! The shorthand writes the scaling into the suite's own name, a form
//! every command reads and every report prints as its suite:
//!
//! ```text
//! SUITE scaled to TARGET by CODE at T1=0.5 s over 0.2:2 T1 (the left building's T1)
//! ```
//!
//! (the note in parentheses says where T1 came from; it is not read back).
//! Loading that name loads SUITE, scales its records as `records scale`
//! does, and runs each at its factor, as a list of `PATH SCALE` would: so
//! the output says how the records were scaled, and the name given back as
//! `--suite` runs the same study (a merge of shards, another command).
//!
//! T1 is `--period`, or else the pair's left T1 (a preset's `[physical]`
//! table) or the row's longest first-mode period, and the name says which.

use super::design::{PeriodSource, TargetArgs, parse_period};
use super::params::ParamArgs;
use super::{CliError, usage};
use crate::analysis::record_scaling::{Design, scale};
use crate::model::buildings::Row;
use crate::model::buildings::matrices::periods;
use crate::model::suite::{SuiteMember, SuiteSpec};

/// The words between a suite and its target in a scaled suite's name.
const SCALED_TO: &str = " scaled to ";

/// A suite scaled to a target, as its name reads.
#[derive(Debug, Clone, PartialEq)]
struct ScaledSuite {
    base: String,
    target: String,
    code: String,
    period: String,
    range: String,
}

impl ScaledSuite {
    /// The name of `base` scaled by `design`, with a note on T1.
    fn name(base: &str, design: &Design, source: &PeriodSource) -> String {
        let note = match source {
            PeriodSource::Given => String::new(),
            PeriodSource::Buildings(words) => format!(" ({words})"),
        };
        format!(
            "{base}{SCALED_TO}{} by {} at T1={} s over {}:{} T1{note}",
            design.target.label(),
            design.code.name(),
            design.period,
            design.range.low,
            design.range.high
        )
    }

    /// The parts of a scaled suite's name, or `None` for any other suite.
    fn parse(text: &str) -> Option<ScaledSuite> {
        let (base, rest) = text.split_once(SCALED_TO)?;
        let (target, rest) = rest.rsplit_once(" by ")?;
        let (code, rest) = rest.split_once(" at T1=")?;
        let (period, rest) = rest.split_once(" s over ")?;
        let range = rest.split_once(" T1").map_or(rest, |(r, _)| r);
        Some(ScaledSuite {
            base: base.to_string(),
            target: target.to_string(),
            code: code.to_string(),
            period: period.to_string(),
            range: range.to_string(),
        })
    }

    /// The design the name states, checked as the flags would be.
    fn design(&self) -> Result<Design, CliError> {
        let period = parse_period(&self.period)?;
        TargetArgs {
            target: Some(self.target.clone()),
            code: Some(self.code.clone()),
            range: Some(self.range.clone()),
        }
        .required(period)
    }
}

/// The records of `SUITE`: a directory, a list file, `synthetic:N@S`, or
/// a scaled suite's name (module doc); or the one-line error naming the
/// file and line.
pub fn load(suite: &str) -> Result<Vec<SuiteMember>, CliError> {
    let Some(scaled) = ScaledSuite::parse(suite) else {
        return SuiteSpec::parse(suite)
            .and_then(|s| s.load())
            .map_err(usage);
    };
    let design = scaled.design()?;
    let members = load(&scaled.base)?;
    let matching = scale(&design, &members).map_err(usage)?;
    if !matching.check.holds {
        // The study runs, as asked; what the rule misses is said once.
        eprintln!(
            "note: the suite scaled to {} does not meet {}: {}",
            design.target.label(),
            matching.check.clause,
            matching.check.failures.join("; ")
        );
    }
    Ok(members
        .into_iter()
        .zip(&matching.records)
        .map(|(m, r)| SuiteMember {
            scale: r.factor,
            ..m
        })
        .collect())
}

/// The scaled suite's name (module doc) that `--target` asks of `suite`,
/// with T1 from `--period` or else `default_period` (its value and, in
/// words, where it comes from); `None` without `--target`, when `--code`,
/// `--range` and `--period` are refused. `--level` is refused beside it.
pub fn scaled_name(
    suite: &str,
    design: &TargetArgs,
    period: Option<&str>,
    level: Option<&str>,
    default_period: impl FnOnce() -> Result<(f64, String), CliError>,
) -> Result<Option<String>, CliError> {
    if design.target.is_none() {
        if let Some(flag) = design.without_target() {
            return Err(usage(format!("{flag}: applies with --target TARGET")));
        }
        if period.is_some() {
            return Err(usage(
                "--period: applies with --target TARGET (the records' T1)",
            ));
        }
        return Ok(None);
    }
    if let Some(level) = level {
        return Err(usage(format!(
            "--level {}: not with --target (the records are scaled to the target by the \
             code's rule); drop one",
            crate::model::params::echo::text(level)
        )));
    }
    let (period, source) = match period {
        Some(text) => (parse_period(text)?, PeriodSource::Given),
        None => {
            let (t1, words) = default_period()?;
            (t1, PeriodSource::Buildings(words))
        }
    };
    let design = design.required(period)?;
    Ok(Some(ScaledSuite::name(suite, &design, &source)))
}

/// A period rounded to four significant digits, as `--im sa` on a row.
fn rounded(t: f64) -> f64 {
    format!("{t:.3e}").parse::<f64>().unwrap_or(t)
}

/// T1 of a row when `--period` is not given: its longest first-mode
/// period, and which building's it is.
pub fn row_period(row: &Row) -> Result<(f64, String), CliError> {
    let (name, t1) = row
        .buildings
        .iter()
        .map(|b| (b.name.clone(), periods(b)[0]))
        .fold(
            (String::new(), 0.0),
            |best, (n, t)| {
                if t > best.1 { (n, t) } else { best }
            },
        );
    Ok((
        rounded(t1),
        format!("the row's longest T1, building {name}"),
    ))
}

/// T1 of the pair when `--period` is not given: the left building's, from
/// the preset's `[physical]` table.
pub fn pair_period(params: &ParamArgs) -> Result<(f64, String), CliError> {
    let (preset, _) = params.resolve_for_many()?;
    let physical = params.physical(&preset)?.ok_or_else(|| {
        usage(format!(
            "--target: give --period T1 (preset `{}` has no [physical] table to take the \
             left building's T1 from)",
            preset.name
        ))
    })?;
    Ok((
        rounded(std::f64::consts::TAU / physical.omega[0]),
        "the left building's T1".into(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::record_scaling::{Code, PeriodRange};
    use crate::model::target_spectrum::TargetSpectrum;

    #[test]
    fn a_scaled_suite_name_reads_back() {
        let design = Design::new(
            TargetSpectrum::parse("ec8:ag=0.3,ground=B,type=1").unwrap(),
            Code::Ec8,
            0.5,
            PeriodRange::default(),
        )
        .unwrap();
        let name = ScaledSuite::name(
            "synthetic:20",
            &design,
            &PeriodSource::Buildings("the left building's T1".into()),
        );
        assert_eq!(
            name,
            "synthetic:20 scaled to ec8:ag=0.3,ground=B,type=1,importance=1 by ec8 at T1=0.5 s \
             over 0.2:2 T1 (the left building's T1)"
        );
        let parsed = ScaledSuite::parse(&name).unwrap();
        assert_eq!(parsed.base, "synthetic:20");
        assert_eq!(parsed.design().unwrap(), design);
        assert_eq!(ScaledSuite::parse("synthetic:20"), None);
    }
}
