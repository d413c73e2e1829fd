//! `pounding stress`: the numerical stress test over corner and random
//! parameter sets (see [`crate::accuracy::stress`]). Exit code 1 if any case fails.

use std::fmt::Write as _;

use clap::Args;
use serde::Serialize;

use super::CliError;
use super::output::{FormatArg, num, print, render};
use crate::accuracy::stress::{Outcome, check, corner_cases, random_cases};
use crate::output::report::{Column, Report, TableColumn, aligned, column_header, column_rows};

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
    #[command(flatten)]
    pub output: FormatArg,
}

impl Default for StressArgs {
    fn default() -> Self {
        StressArgs {
            cases: 100,
            seed: 1,
            output: FormatArg::default(),
        }
    }
}

pub fn execute(args: &StressArgs) -> Result<(), CliError> {
    let mut cases = corner_cases();
    cases.extend(random_cases(args.cases as usize, args.seed));
    let outcomes: Vec<Outcome> = cases.iter().map(check).collect();
    let report = StressReport::new(&outcomes);
    print(&render(&report, args.output.format)?)?;
    let failed = report.failed;
    if failed > 0 {
        Err(CliError::Failed(format!(
            "{failed} of {} stress cases failed",
            outcomes.len()
        )))
    } else {
        Ok(())
    }
}

/// Every case's outcome, and how many passed and failed, in every format.
#[derive(Debug, Serialize)]
pub struct StressReport<'a> {
    cases: &'a [Outcome],
    failed: usize,
    passed: usize,
}

impl<'a> StressReport<'a> {
    pub fn new(cases: &'a [Outcome]) -> Self {
        let failed = cases.iter().filter(|o| !o.passed).count();
        StressReport {
            cases,
            failed,
            passed: cases.len() - failed,
        }
    }
}

impl Report for StressReport<'_> {
    fn table(&self) -> String {
        table(self.cases)
    }

    fn csv_header(&self) -> Vec<&'static str> {
        column_header(&[], COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        column_rows(&[], COLUMNS, self.cases)
    }
}

/// The CSV columns of a case's outcome.
const COLUMNS: &[Column<Outcome>] = &[
    ("case", |o| o.name.clone()),
    ("passed", |o| o.passed.to_string()),
    ("impacts", |o| o.impacts.to_string()),
    ("steps", |o| o.steps.to_string()),
    ("step_retries", |o| o.step_retries.to_string()),
    ("energy_residual", |o| num(o.energy_residual)),
    ("min_force", |o| num(o.min_force)),
    ("ms", |o| num(o.ms)),
    ("exact_ms", |o| num(o.exact_ms)),
    ("exact_energy_residual", |o| num(o.exact_energy_residual)),
    ("newmark_vs_exact", |o| num(o.methods_differ_by)),
    ("why", why),
];

fn why(o: &Outcome) -> String {
    o.failures
        .iter()
        .chain(&o.notes)
        .cloned()
        .collect::<Vec<_>>()
        .join("; ")
}

/// The table's columns of a case's outcome.
const TABLE: &[TableColumn<Outcome>] = &[
    ("case", -44, |o| o.name.clone()),
    ("", -4, |o| {
        if o.passed { "pass" } else { "FAIL" }.to_string()
    }),
    ("impacts", 7, |o| o.impacts.to_string()),
    ("steps", 9, |o| o.steps.to_string()),
    ("retries", 7, |o| o.step_retries.to_string()),
    ("residual", 9, |o| format!("{:.1e}", o.energy_residual)),
    ("min force", 10, |o| format!("{:.3e}", o.min_force)),
    ("ms", 9, |o| format!("{:.1}", o.ms)),
    ("exact ms", 9, |o| format!("{:.3}", o.exact_ms)),
    ("N vs E", 9, |o| format!("{:.1e}", o.methods_differ_by)),
    (" why / notes", 0, |o| format!(" {}", why(o))),
];

fn table(outcomes: &[Outcome]) -> String {
    let mut s = aligned(TABLE, outcomes);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::report::{csv, json};

    #[test]
    fn a_failed_case_with_infinite_values_reads_the_same_in_json_and_csv() {
        let blown = Outcome {
            name: "blown".into(),
            passed: false,
            failures: vec!["non-finite output".into()],
            notes: vec![],
            params: String::new(),
            impacts: 0,
            steps: 10,
            step_retries: 0,
            energy_residual: f64::INFINITY,
            min_force: f64::NEG_INFINITY,
            max_force: 0.5,
            ms: 1.0,
            exact_impacts: 0,
            exact_energy_residual: 1e-15,
            exact_ms: 1.0,
            methods_differ_by: f64::INFINITY,
        };
        let cases = [blown];
        let report = StressReport::new(&cases);
        let v: serde_json::Value = serde_json::from_str(&json(&report).unwrap()).unwrap();
        assert_eq!(
            (v["passed"].as_u64(), v["failed"].as_u64()),
            (Some(0), Some(1))
        );
        let case = &v["cases"][0];
        assert_eq!(case["energy_residual"], "inf");
        assert_eq!(case["min_force"], "-inf");
        assert_eq!(case["methods_differ_by"], "inf");
        assert_eq!(case["max_force"], 0.5);
        let text = csv(&report.csv_header(), &report.csv_rows());
        let row: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
        let header = report.csv_header();
        let cell = |k: &str| row[header.iter().position(|h| *h == k).unwrap()];
        assert_eq!(cell("energy_residual"), "inf");
        assert_eq!(cell("min_force"), "-inf");
        assert_eq!(cell("newmark_vs_exact"), "inf");
        assert_eq!(cell("passed"), "false");
    }
}
