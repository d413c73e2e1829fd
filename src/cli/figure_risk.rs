//! The options of `pounding figure ida|fragility|separation`: the suite,
//! its scaling and what each figure asks, parsed as `pounding suite`,
//! `ida` and `gap --suite` parse them, into a [`SuiteStudy`] for
//! [`crate::figure::risk`].

use clap::Args;

use super::CliError;
use super::budget::LongArg;
use super::gap_suite::DEFAULT_PROBABILITIES;
use super::ida::LimitStateArgs;
use super::params::ParamArgs;
use super::records::members;
use super::suite::{SuiteArgs, case_of, work_of};
use crate::analysis::ida::{parse_levels, plan_levels};
use crate::analysis::separation::parse_probabilities;
use crate::analysis::suite::plan;
use crate::figure::{FigureName, SuiteStudy};

#[derive(Debug, Clone, Default, Args)]
pub struct RiskArgs {
    /// ida, fragility, separation: the records, as `pounding suite --suite`.
    #[arg(long, value_name = "SUITE")]
    pub suite: Option<String>,
    /// ida, fragility, separation: intensity measure `pga` or `sa:T` [default: pga].
    #[arg(long, value_name = "pga|sa:T")]
    pub im: Option<String>,
    /// ida, fragility: intensity levels in g, START:STOP:STEP or X1,X2,…
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub levels: Option<String>,
    /// separation: scale each record to this IM in g [default: the list's scales].
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub level: Option<String>,
    /// separation: probabilities of no pounding, e.g. 0.5,0.84,0.9 [default: 0.5,0.84,0.9].
    #[arg(long, value_name = "P,…")]
    pub probability: Option<String>,
    /// fragility: the limit states beside pounding.
    #[command(flatten)]
    pub limits: LimitStateArgs,
    #[command(flatten)]
    pub long: LongArg,
}

fn usage(message: String) -> CliError {
    CliError::Usage(message)
}

impl RiskArgs {
    /// The options given, each with the figures it applies to.
    fn given(&self) -> Vec<(&'static str, &'static [FigureName])> {
        use FigureName::{Fragility, Ida, Separation};
        let all: &'static [FigureName] = &[Ida, Fragility, Separation];
        [
            (self.suite.is_some(), "--suite", all),
            (self.im.is_some(), "--im", all),
            (self.long.allow_long, "--allow-long", all),
            (self.levels.is_some(), "--levels", &[Ida, Fragility][..]),
            (self.level.is_some(), "--level", &[Separation][..]),
            (
                self.probability.is_some(),
                "--probability",
                &[Separation][..],
            ),
            (
                self.limits.ductility.is_some(),
                "--ductility",
                &[Fragility][..],
            ),
            (
                self.limits.acceleration.is_some(),
                "--acceleration",
                &[Fragility][..],
            ),
            (self.limits.force.is_some(), "--force", &[Fragility][..]),
        ]
        .into_iter()
        .filter(|(given, ..)| *given)
        .map(|(_, flag, names)| (flag, names))
        .collect()
    }

    /// Refuses an option that figure `name` (`None`: `all`) does not take.
    pub fn check_applies(&self, name: Option<FigureName>, shown: &str) -> Result<(), CliError> {
        for (flag, names) in self.given() {
            if !name.is_some_and(|n| names.contains(&n)) {
                let list: Vec<&str> = names.iter().map(|n| n.name()).collect();
                return Err(usage(format!(
                    "{flag} applies to figure {}, not {shown}",
                    list.join(", ")
                )));
            }
        }
        Ok(())
    }
}

/// The suite study of figure `name` (ida, fragility or separation) on the
/// buildings and settings of `params`, checked and planned: a record
/// that cannot be scaled, or work beyond the budget without `--allow-long`,
/// is refused before any run.
pub fn study(
    risk: &RiskArgs,
    params: &ParamArgs,
    name: FigureName,
) -> Result<SuiteStudy, CliError> {
    risk.check_applies(Some(name), name.name())?;
    let suite = risk.suite.clone().ok_or_else(|| {
        usage(format!(
            "figure {name}: needs --suite (a directory, a list file or synthetic:N) and a preset \
             with [physical], e.g. --preset two-buildings --suite synthetic:20"
        ))
    })?;
    let suite_args = SuiteArgs {
        params: params.clone(),
        suite: suite.clone(),
        im: risk.im.clone(),
        level: risk.level.clone(),
        ..SuiteArgs::default()
    };
    let levels = match (name, &risk.levels) {
        (FigureName::Separation, _) => Vec::new(),
        (_, Some(text)) => parse_levels(text).map_err(usage)?,
        (_, None) => {
            return Err(usage(format!(
                "figure {name}: needs --levels START:STOP:STEP or X1,X2,… (intensities in g)"
            )));
        }
    };
    let states = risk.limits.parse()?;
    let probabilities = parse_probabilities(
        "--probability",
        risk.probability.as_deref().unwrap_or(DEFAULT_PROBABILITIES),
    )
    .map_err(|e| usage(e.to_string()))?;
    let (preset, case) = case_of(&suite_args)?;
    let members = members(&suite)?;
    let plans = match name {
        FigureName::Separation => plan(&case, &members).map(|p| vec![p]),
        _ => plan_levels(&case, &members, &levels),
    }
    .map_err(|e| usage(e.to_string()))?;
    work_of(plans.iter().flatten()).check(
        &format!("figure {name}"),
        risk.long.allow_long,
        false,
    )?;
    Ok(SuiteStudy {
        preset: preset.name.clone(),
        suite,
        case,
        members,
        levels,
        states,
        probabilities,
    })
}
