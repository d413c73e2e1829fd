//! The limit-state flags of `ida` and `figure fragility`, read for the
//! study's subject (SPEC §12, §13, §15; [`crate::analysis::limit_state`]):
//! `--ductility` for the pair, `--drift`, `--building` and `--collapse` for
//! a row, `--acceleration` and `--force` for both.

use clap::Args;

use super::{CliError, usage};
use crate::analysis::limit_state::{LimitParser, LimitState, LimitStateError, ROW_ONLY};
use crate::model::buildings::Row;

/// The limit states beside pounding (SPEC §12), as `ida` and `figure
/// fragility` take them.
#[derive(Debug, Clone, Default, Args)]
pub struct LimitStateArgs {
    /// Ductility limit states, e.g. 2,4 or left:2,right:4 (either structure by default).
    #[arg(long, value_name = "[SIDE:]MU,…")]
    pub ductility: Option<String>,
    /// Peak absolute acceleration limit states, e.g. 0.5g,1g (a bare number is m/s²);
    /// with `ida --buildings` an item may name its building, frame:1g.
    #[arg(long, value_name = "[SIDE:]A,…")]
    pub acceleration: Option<String>,
    /// Peak impact force limit states in kN, e.g. 500; with `ida --buildings`
    /// an item may name its building, frame:500.
    #[arg(long, value_name = "KN,…")]
    pub force: Option<String>,
}

/// The limit states of a row of buildings beside `--acceleration`,
/// `--force` and pounding (SPEC §12, §13).
#[derive(Debug, Clone, Default, Args)]
pub struct RowLimitArgs {
    /// With --buildings: storey drift ratio limit states, each in (0, 1),
    /// e.g. 0.005,0.01,0.02 (FEMA's IO, LS, CP for frames) or frame:0.01.
    #[arg(long, value_name = "[NAME:]RATIO,…")]
    pub drift: Option<String>,
    /// With --buildings: the building the limit states read when an item
    /// names none, and the pounding limit state's: a building of the row
    /// or `any` [default: any]. `--acceleration`, `--force` and `--drift`
    /// items may name their own (`frame:0.5g`).
    #[arg(long, value_name = "NAME|any")]
    pub building: Option<String>,
    /// With --buildings: the collapse limit state of every building with
    /// P-Δ (SPEC §15), whose fragility's median is the collapse intensity
    /// Ŝ_CT; a collapsed building exceeds every other limit state of its own.
    #[arg(long)]
    pub collapse: bool,
}

impl RowLimitArgs {
    /// Refuses `--drift`, `--building` and `--collapse` where the study is
    /// of the pair.
    pub fn refuse_on_a_pair(&self) -> Result<(), CliError> {
        for (flag, given) in [
            ("--drift", self.drift.is_some()),
            ("--building", self.building.is_some()),
            ("--collapse", self.collapse),
        ] {
            if given {
                return Err(CliError::Usage(ROW_ONLY.replace("{flag}", flag)));
            }
        }
        Ok(())
    }
}

/// The limit states the flags ask of the pair (`row` none) or of `row`:
/// pounding first (of `--building` on a row), then with `--collapse` each
/// P-Δ building's collapse, then `--ductility` or `--drift`,
/// `--acceleration` and `--force`. A flag that does not apply to the
/// subject is refused in one line.
pub fn limit_states(
    limits: &LimitStateArgs,
    row_limits: &RowLimitArgs,
    row: Option<&Row>,
) -> Result<Vec<LimitState>, CliError> {
    let parser = match row {
        None => {
            row_limits.refuse_on_a_pair()?;
            LimitParser::pair()
        }
        Some(row) => LimitParser::row(row),
    };
    let ductility = limits.ductility.as_deref().map(|t| parser.ductility(t));
    let ductility = ductility.transpose().map_err(usage)?;
    let parser = parser
        .with_building(row_limits.building.as_deref())
        .map_err(usage)?;
    let mut states = vec![parser.pounding()];
    if let (Some(row), true) = (row, row_limits.collapse) {
        let collapses = parser.collapses(row);
        if collapses.is_empty() {
            return Err(usage(format!(
                "--collapse: no building of `{}` has P-Δ (`p_delta = true`): a building without it \
                 keeps a restoring force after yielding (α ≥ 0) and cannot collapse",
                row.name
            )));
        }
        states.extend(collapses);
    }
    states.extend(ductility.into_iter().flatten());
    type Parse = fn(&LimitParser, &str) -> Result<Vec<LimitState>, LimitStateError>;
    let flags: [(&Option<String>, Parse); 3] = [
        (&row_limits.drift, LimitParser::drift),
        (&limits.acceleration, LimitParser::acceleration),
        (&limits.force, LimitParser::force),
    ];
    for (text, parse) in flags {
        if let Some(t) = text {
            states.extend(parse(&parser, t).map_err(usage)?);
        }
    }
    Ok(states)
}
