//! The options of `pounding figure ida|fragility|separation`: the suite,
//! its scaling and what each figure asks, parsed as `pounding suite`,
//! `ida` and `gap --suite` parse them, into a [`RiskStudy`] for
//! [`crate::figure::risk`] (the pair) or [`crate::figure::risk_row`] (a
//! row of buildings, `--buildings`).

use clap::Args;

use super::CliError;
use super::budget::LongArg;
use super::compare::same_buildings;
use super::gap_suite::DEFAULT_PROBABILITIES;
use super::limit_states::{LimitStateArgs, RowLimitArgs, limit_states};
use super::params::ParamArgs;
use super::records::members;
use super::shard::ShardArgs;
use super::subject::row::{self, RowStudyArgs};
use super::suite::{SuiteArgs, case_of, parse_level, work_of};
use crate::analysis::ida::parse_levels;
use crate::analysis::separation::parse_probabilities;
use crate::analysis::subject::runs::{plan, plan_levels};
use crate::figure::risk_compare::Variant;
use crate::figure::{FigureName, RiskStudy, RowSuiteStudy, SuiteStudy};

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
    /// fragility with --buildings: storey drift limit states and the building read.
    #[command(flatten)]
    pub row_limits: RowLimitArgs,
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
            (self.row_limits.drift.is_some(), "--drift", &[Fragility][..]),
            (
                self.row_limits.building.is_some(),
                "--building",
                &[Fragility][..],
            ),
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
/// buildings and settings of `params`, or on the row `buildings`, checked
/// and planned: a record that cannot be scaled, or work beyond the budget
/// without `--allow-long`, is refused before any run.
pub fn study(
    risk: &RiskArgs,
    params: &ParamArgs,
    buildings: Option<&str>,
    name: FigureName,
) -> Result<RiskStudy, CliError> {
    risk.check_applies(Some(name), name.name())?;
    let suite = risk.suite.clone().ok_or_else(|| {
        usage(format!(
            "figure {name}: needs --suite (a directory, a list file or synthetic:N) and a preset \
             with [physical], e.g. --preset two-buildings --suite synthetic:20, or a row, \
             --buildings block-and-frame"
        ))
    })?;
    let levels = match (name, &risk.levels) {
        (FigureName::Separation, _) => Vec::new(),
        (_, Some(text)) => parse_levels(text).map_err(usage)?,
        (_, None) => {
            return Err(usage(format!(
                "figure {name}: needs --levels START:STOP:STEP or X1,X2,… (intensities in g)"
            )));
        }
    };
    let probabilities = parse_probabilities(
        "--probability",
        risk.probability.as_deref().unwrap_or(DEFAULT_PROBABILITIES),
    )
    .map_err(|e| usage(e.to_string()))?;
    if let Some(buildings) = buildings {
        let asked = (levels, probabilities);
        return row_study(risk, params, buildings, suite, name, asked).map(RiskStudy::Row);
    }
    risk.row_limits.refuse_on_a_pair()?;
    let suite_args = SuiteArgs {
        params: params.clone(),
        suite: suite.clone(),
        im: risk.im.clone(),
        level: risk.level.clone(),
        ..SuiteArgs::default()
    };
    let states = limit_states(&risk.limits, &risk.row_limits, None)?;
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
    Ok(RiskStudy::Pair(SuiteStudy {
        preset: preset.name.clone(),
        suite,
        case,
        members,
        levels,
        states,
        probabilities,
    }))
}

/// The study of figure `name` on the row `buildings` and on each row of
/// `compare` (`--compare`, as given), to overlay: each variant's study as
/// [`study`] reads it alone, named in the legend by its file stem, with
/// the first row's buildings by number and name.
pub fn compare(
    risk: &RiskArgs,
    params: &ParamArgs,
    buildings: Option<&str>,
    compare: &[String],
    name: FigureName,
) -> Result<RiskStudy, CliError> {
    let Some(first) = buildings else {
        return Err(usage(
            "--compare: compares rows of buildings; give --buildings ROW".into(),
        ));
    };
    let mut variants: Vec<Variant> = Vec::new();
    for row in std::iter::once(first).chain(compare.iter().map(String::as_str)) {
        let RiskStudy::Row(study) = self::study(risk, params, Some(row), name)? else {
            unreachable!("--buildings chooses a row");
        };
        if let Some(head) = variants.first() {
            same_buildings(&head.study.case.row, &study.case.row, row)?;
        }
        let stem = std::path::Path::new(row)
            .file_stem()
            .map_or(row.to_string(), |s| s.to_string_lossy().into_owned());
        variants.push(Variant { name: stem, study });
    }
    Ok(RiskStudy::Compare(variants))
}

/// The study of figure `name` on the row `buildings`, as `ida --buildings`
/// and `gap --buildings --suite` read it: the row with `--set` and
/// `--model`, the scaling, the limit states (pounding first), with the
/// levels and probabilities `asked`, checked and planned before any run.
fn row_study(
    risk: &RiskArgs,
    params: &ParamArgs,
    buildings: &str,
    suite: String,
    name: FigureName,
    (levels, probabilities): (Vec<f64>, Vec<f64>),
) -> Result<RowSuiteStudy, CliError> {
    let separation = name == FigureName::Separation;
    let shard = ShardArgs::default();
    let study = RowStudyArgs {
        buildings,
        params,
        suite: &suite,
        im: risk.im.as_deref(),
        level: risk.level.as_deref().map(parse_level).transpose()?,
        allow_long: risk.long.allow_long,
        shard: &shard,
        collective: false,
    };
    let (case, members) = row::case_of(&study)?;
    let states = limit_states(&risk.limits, &risk.row_limits, Some(&case.row))?;
    if separation {
        plan(&case, &members).map_err(row::failed)?;
    } else {
        plan_levels(&case, &members, &levels).map_err(row::failed)?;
    }
    row::work_of(&case.row, &members, levels.len().max(1)).check(
        &format!("figure {name}"),
        risk.long.allow_long,
        false,
    )?;
    Ok(RowSuiteStudy {
        suite,
        case,
        members,
        levels,
        states,
        probabilities,
    })
}
