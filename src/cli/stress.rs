//! `pounding stress`: the numerical stress test over corner and random
//! parameter sets (see [`crate::accuracy::stress`]). Exit code 1 if any case fails.

use std::fmt::Write as _;

use clap::Args;

use super::CliError;
use super::output::{Format, num};
use crate::accuracy::stress::{Outcome, check, corner_cases, random_cases};

#[derive(Debug, Clone, Args)]
pub struct StressArgs {
    /// Number of random parameter sets after the corner cases.
    #[arg(long, value_name = "N", default_value_t = 100, allow_negative_numbers = true, value_parser = clap::value_parser!(u32).range(0..=100_000))]
    pub cases: u32,
    /// Seed of the random parameter sets (same seed, same cases).
    #[arg(
        long,
        value_name = "S",
        default_value_t = 1,
        allow_negative_numbers = true
    )]
    pub seed: u64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

impl Default for StressArgs {
    fn default() -> Self {
        StressArgs {
            cases: 100,
            seed: 1,
            format: Format::Table,
        }
    }
}

pub fn execute(args: &StressArgs) -> Result<(), CliError> {
    let mut cases = corner_cases();
    cases.extend(random_cases(args.cases as usize, args.seed));
    let outcomes: Vec<Outcome> = cases.iter().map(check).collect();
    let failed = outcomes.iter().filter(|o| !o.passed).count();
    let text = match args.format {
        Format::Json => {
            serde_json::json!({
                "cases": outcomes,
                "passed": outcomes.len() - failed,
                "failed": failed,
            })
            .to_string()
                + "\n"
        }
        Format::Csv => csv(&outcomes),
        Format::Table => table(&outcomes),
    };
    super::output::print(&text)?;
    if failed > 0 {
        Err(CliError::Failed(format!(
            "{failed} of {} stress cases failed",
            outcomes.len()
        )))
    } else {
        Ok(())
    }
}

fn why(o: &Outcome) -> String {
    o.failures
        .iter()
        .chain(&o.notes)
        .cloned()
        .collect::<Vec<_>>()
        .join("; ")
}

fn table(outcomes: &[Outcome]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<44} {:<4} {:>7} {:>9} {:>7} {:>9} {:>10} {:>9} {:>9} {:>9}  why / notes",
        "case",
        "",
        "impacts",
        "steps",
        "retries",
        "residual",
        "min force",
        "ms",
        "exact ms",
        "N vs E"
    );
    for o in outcomes {
        let _ = writeln!(
            s,
            "{:<44} {:<4} {:>7} {:>9} {:>7} {:>9.1e} {:>10.3e} {:>9.1} {:>9.3} {:>9.1e}  {}",
            o.name,
            if o.passed { "pass" } else { "FAIL" },
            o.impacts,
            o.steps,
            o.step_retries,
            o.energy_residual,
            o.min_force,
            o.ms,
            o.exact_ms,
            o.methods_differ_by,
            why(o)
        );
    }
    let failed = outcomes.iter().filter(|o| !o.passed).count();
    let _ = writeln!(
        s,
        "{} cases, {} passed, {failed} failed",
        outcomes.len(),
        outcomes.len() - failed
    );
    for o in outcomes.iter().filter(|o| !o.passed) {
        let _ = writeln!(s, "failed: {}: {}", o.name, o.params);
    }
    s
}

fn csv(outcomes: &[Outcome]) -> String {
    let header = [
        "case",
        "passed",
        "impacts",
        "steps",
        "step_retries",
        "energy_residual",
        "min_force",
        "ms",
        "exact_ms",
        "exact_energy_residual",
        "newmark_vs_exact",
        "why",
    ];
    let rows: Vec<Vec<String>> = outcomes
        .iter()
        .map(|o| {
            vec![
                o.name.clone(),
                o.passed.to_string(),
                o.impacts.to_string(),
                o.steps.to_string(),
                o.step_retries.to_string(),
                num(o.energy_residual),
                num(o.min_force),
                num(o.ms),
                num(o.exact_ms),
                num(o.exact_energy_residual),
                num(o.methods_differ_by),
                why(o),
            ]
        })
        .collect();
    crate::output::report::csv(&header, &rows)
}
