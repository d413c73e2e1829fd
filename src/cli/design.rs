//! `--target`, `--code`, `--range` and `--period`: a target spectrum and
//! the code's record rule ([`crate::analysis::record_scaling`]), as
//! `records scale`, `records select`, `figure match` and the studies'
//! shorthand take them. Parsed here once; every refusal is one line naming
//! the flag, the value and what is allowed.

use clap::Args;

use super::{CliError, usage};
use crate::analysis::record_scaling::{Code, Design, PeriodRange};
use crate::model::target_spectrum::TargetSpectrum;

/// The target and its rule (T1 is the command's own `--period`).
#[derive(Debug, Clone, Default, Args)]
pub struct TargetArgs {
    /// The site's target spectrum (5 % damped, g): asce7:SDS=…,SD1=…,TL=…
    /// (ASCE 7-16 §11.4.6), asce7-mce:… (1.5 × it), ec8:ag=…,ground=A|B|C|D|E,type=1|2[,importance=…]
    /// (EN 1998-1 §3.2.2.2), or file:PATH (two columns T s, Sa g; log-log).
    #[arg(long, value_name = "TARGET")]
    pub target: Option<String>,
    /// With --target: the record rule, ec8 (EN 1998-1 §3.2.3.1.2) or asce7
    /// (ASCE 7-16 §16.2.3) [default: the target's code; asce7 for a file].
    #[arg(long, value_name = "ec8|asce7")]
    pub code: Option<String>,
    /// With --target: the rule's periods as multiples of T1 [default: 0.2:2.0].
    #[arg(long, value_name = "LO:HI", allow_hyphen_values = true)]
    pub range: Option<String>,
}

/// `--period T1`: a period in (0, 10] s.
pub fn parse_period(text: &str) -> Result<f64, CliError> {
    let max = crate::model::intensity::MAX_PERIOD;
    text.trim()
        .strip_suffix('s')
        .unwrap_or(text.trim())
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|t| *t > 0.0 && *t <= max)
        .ok_or_else(|| {
            usage(format!(
                "--period {}: T1 must be a period in (0, {max}] s",
                crate::model::params::echo::text(text)
            ))
        })
}

/// Where T1 came from, said beside the scaling.
#[derive(Debug, Clone, PartialEq)]
pub enum PeriodSource {
    /// `--period`.
    Given,
    /// A default from the buildings, in words (`the left building's T1`).
    Buildings(String),
}

impl TargetArgs {
    /// The flags of a rule given without `--target`, by their flag.
    pub fn without_target(&self) -> Option<&'static str> {
        if self.target.is_some() {
            return None;
        }
        [
            ("--code", self.code.is_some()),
            ("--range", self.range.is_some()),
        ]
        .into_iter()
        .find(|(_, given)| *given)
        .map(|(flag, _)| flag)
    }

    /// The design of `--target` at T1 = `period`, checked; `None` without
    /// `--target` (then `--code` and `--range` are refused).
    pub fn design(&self, period: f64) -> Result<Option<Design>, CliError> {
        let Some(text) = &self.target else {
            if let Some(flag) = self.without_target() {
                return Err(usage(format!("{flag}: applies with --target TARGET")));
            }
            return Ok(None);
        };
        let target = parse_target(text)?;
        let code = match &self.code {
            None => Code::of(&target),
            Some(c) => Code::parse(c).ok_or_else(|| {
                usage(format!(
                    "--code {}: unknown code; must be one of {}",
                    crate::model::params::echo::text(c),
                    Code::NAMES
                ))
            })?,
        };
        let range = match &self.range {
            None => PeriodRange::default(),
            Some(r) => PeriodRange::parse(r).map_err(usage)?,
        };
        Design::new(target, code, period, range)
            .map(Some)
            .map_err(usage)
    }

    /// [`TargetArgs::design`] with `--target` required.
    pub fn required(&self, period: f64) -> Result<Design, CliError> {
        self.design(period)?.ok_or_else(|| {
            usage(format!(
                "--target: required; give {}",
                TargetSpectrum::FORMS
            ))
        })
    }
}

/// `--target TEXT`, or the one-line refusal naming it.
pub fn parse_target(text: &str) -> Result<TargetSpectrum, CliError> {
    TargetSpectrum::parse(text).map_err(|e| usage(format!("--target {e}")))
}
