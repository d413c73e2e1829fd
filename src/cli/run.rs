//! `pounding run`: one simulation, its summary as a table, JSON or CSV, and
//! optionally its full history as CSV, streamed to its target as it is computed.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use serde::Serialize;

use super::CliError;
use super::budget::{LongArg, Work, run_steps, steps_per_tau};
use super::description::{Case, DIMENSIONLESS, Provenance, RecordNumbers};
use super::output::{Emit, FormatArg, num, optional, param_cells, param_columns, print};
use super::params::ParamArgs;
use super::progress::{Progress, Tracked};
use crate::accuracy::timing::median;
use crate::analysis::demands::{DemandsSi, RunSi};
use crate::model::params::echo::g4;
use crate::model::physical::Physical;
use crate::model::{Excitation, Method, Params, Preset};
use crate::output::report::{Column, Report, column_cells, column_header};
use crate::output::{Num, Target};
use crate::solver::{CsvHistory, Impact, RunResult, StructurePeaks, error_vs_exact, solve};

#[derive(Debug, Clone, Default, Args)]
pub struct RunArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub row: super::buildings::BuildingsArgs,
    /// Write the history as CSV (tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp, then the ground
    /// motion ag,vg,ug in Π form, SPEC §9), one row per step,
    /// streamed as it is computed. `-` is stdout (the summary then goes to stderr).
    #[arg(long, value_name = "FILE")]
    pub history: Option<PathBuf>,
    /// Run the same case N times in this process and report the median time.
    #[arg(long, value_name = "N", default_value_t = 1, allow_negative_numbers = true, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub repeat: u32,
    #[command(flatten)]
    pub long: LongArg,
    /// Write a history even when it is estimated at over 1 GB.
    #[arg(long)]
    pub allow_large: bool,
    /// Exit 0 and keep the history even when the result is unreliable (it is still flagged).
    #[arg(long)]
    pub allow_unreliable: bool,
}

pub fn execute(args: &RunArgs) -> Result<(), CliError> {
    let format = args.output.format;
    // With the history on stdout, stdout carries the history alone.
    let history_to_stdout = args
        .history
        .as_deref()
        .is_some_and(|h| h.as_os_str() == "-");
    report_with(args, |report| {
        let text = report.render(format)?;
        if history_to_stdout {
            let _ = std::io::stderr().write_all(text.as_bytes());
            Ok(())
        } else {
            print(&text)
        }
    })
}

/// The run of `args`, its typed report handed to `emit` (before an
/// unreliable result fails, as the command line prints it first).
pub fn report_with(
    args: &RunArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    if args.row.buildings.is_some() {
        if let Some(path) = &args.history {
            // A row's motion is drawn by `figure buildings` and the explorer;
            // the history's columns are the pair's (SPEC §9).
            return Err(super::usage(format!(
                "--history {}: not with run --buildings (the history's columns are the \
                 pair's, SPEC §9); draw a row's motion with `pounding figure buildings`",
                path.display()
            )));
        }
        let long = args.long.allow_long;
        return super::buildings::run(&args.row, &args.params, args.repeat, long, emit);
    }
    let (preset, p) = args.params.resolve()?;
    let steps = run_steps(&p);
    let history_runs = f64::from(u8::from(args.history.is_some()));
    let work = Work {
        steps: steps * (f64::from(args.repeat) + history_runs),
        rows: steps * history_runs,
    };
    let what = if args.history.is_some() {
        "run with --history"
    } else {
        "run"
    };
    work.check(what, args.long.allow_long, args.allow_large)?;
    // Open the history target before any work, so a bad path fails at once.
    let history = args.history.as_deref().map(Target::open).transpose()?;
    let progress = Progress::start(&work);

    let mut times = Vec::with_capacity(args.repeat as usize);
    let mut result = RunResult::default();
    for i in 0..args.repeat {
        let t = Instant::now();
        let mut tracked = Tracked::new((), &progress, steps * f64::from(i), steps_per_tau(&p));
        result = solve(&p, &mut tracked);
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    let elapsed_ms = median(times);
    let reason = result.unreliable();
    let accepted = reason.is_none() || args.allow_unreliable;

    let mut discarded = None;
    if let Some(target) = history {
        let offset = steps * f64::from(args.repeat);
        let csv = CsvHistory::with_ground(target, p.ground());
        let mut csv = Tracked::new(csv, &progress, offset, steps_per_tau(&p));
        solve(&p, &mut csv);
        let target = match csv.inner.finish() {
            Ok((target, _rows)) => target,
            Err((target, e)) => return Err(target.error(&e).into()),
        };
        if accepted {
            target.commit()?;
        } else {
            discarded = Some(target.name().to_string());
        }
    }
    drop(progress);

    // Newmark's actual error, from an exact run of the same parameters (a few per cent of its cost).
    let error = (p.method == Method::Newmark).then(|| error_vs_exact(&p, &result));
    // Π_d,min (SPEC §11): an exact run without impact already tracked it;
    // otherwise one exact run without contact.
    let min_gap = match result.max_relative_displacement {
        Some(top) => crate::analysis::gap::from_max_relative(top),
        None => crate::analysis::gap::minimum_gap(&p).exact,
    };
    let mut report = RunReport::new(&preset.name, &p, &result, elapsed_ms, args.repeat, min_gap);
    report.error_vs_exact = error;
    report.si = si_of(&preset, &p, &result, min_gap);
    emit(&report)?;
    match reason {
        Some(why) if !args.allow_unreliable => {
            let kept = discarded.map_or(String::new(), |name| format!("; {name} was not written"));
            Err(CliError::Failed(format!(
                "unreliable result: {why}{kept}; pass --allow-unreliable to accept it"
            )))
        }
        _ => Ok(()),
    }
}

/// The run's demands in SI for a preset with a `[physical]` table: m2 from
/// the table, a_p and ω_p the run's (a record's own under a record, else
/// the table's), so that Π results times these scales are the buildings'.
fn si_of(preset: &Preset, p: &Params, r: &RunResult, min_gap: f64) -> Option<RunSi> {
    let physical = Physical::from_table(preset.physical.as_ref()?).ok()?;
    let (ap, omega_p) = match p.ground() {
        Excitation::Record(m) => (m.amplitude, m.omega),
        _ => (physical.ap, physical.omega_p),
    };
    Some(RunSi::of(&physical, ap, omega_p, r, min_gap))
}

/// The summary of one run, in every format (SPEC §6).
#[derive(Debug, Serialize)]
pub struct RunReport<'a> {
    /// `version`, `preset` and `units` (Π-groups: a run is dimensionless).
    #[serde(flatten)]
    provenance: Provenance<'a>,
    #[serde(skip)]
    repeat: u32,
    /// The parameters, their contact law, excitation (SPEC §9, with what
    /// must be said beside it) and the method that ran.
    #[serde(flatten)]
    case: Case<'a>,
    dt: f64,
    tau_end: f64,
    steps: usize,
    left: StructurePeaks,
    right: StructurePeaks,
    impacts: usize,
    max_force: f64,
    min_force: f64,
    energy_residual: f64,
    energy: crate::solver::EnergyBalance,
    impact_list: &'a [Impact],
    step_retries: usize,
    unconverged_steps: usize,
    /// Largest relative error of the four peaks against the exact method
    /// (Newmark runs only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_vs_exact: Option<f64>,
    /// Π_d,min of SPEC §11: the smallest gap at which these structures
    /// would never touch, from an exact run without contact.
    pub min_gap_no_pounding: f64,
    /// With a preset's `[physical]` table (SPEC §8): the demands in SI, at
    /// the a_p and ω_p of the run (a record's own under a record, SPEC §12).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub si: Option<RunSi>,
    /// False when the result should not be trusted; `unreliable_reason` says why.
    reliable: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    unreliable_reason: Option<String>,
    elapsed_ms: f64,
}

impl<'a> RunReport<'a> {
    pub fn new(
        preset: &'a str,
        p: &'a Params,
        r: &'a RunResult,
        elapsed_ms: f64,
        repeat: u32,
        min_gap_no_pounding: f64,
    ) -> Self {
        let unreliable_reason = r.unreliable();
        RunReport {
            provenance: Provenance::new(preset, DIMENSIONLESS),
            repeat,
            case: Case {
                method: r.method,
                ..Case::of(p, None)
            },
            dt: p.dt,
            tau_end: r.tau_end,
            steps: r.steps,
            left: r.left,
            right: r.right,
            impacts: r.impacts.len(),
            max_force: r.max_force,
            min_force: r.min_force,
            energy_residual: r.energy.residual,
            energy: r.energy,
            impact_list: &r.impacts,
            step_retries: r.step_retries,
            unconverged_steps: r.unconverged_steps,
            error_vs_exact: None,
            min_gap_no_pounding,
            si: None,
            reliable: unreliable_reason.is_none(),
            unreliable_reason,
            elapsed_ms,
        }
    }
}

/// The CSV columns of each structure's peaks and demands (SPEC §6), in the
/// order of [`structure_cells`].
const LEFT_COLUMNS: [&str; 7] = [
    "left_peak_displacement",
    "left_peak_velocity",
    "left_peak_absolute_acceleration",
    "left_ductility",
    "left_residual_displacement",
    "left_hysteretic_energy",
    "left_yielded",
];
const RIGHT_COLUMNS: [&str; 7] = [
    "right_peak_displacement",
    "right_peak_velocity",
    "right_peak_absolute_acceleration",
    "right_ductility",
    "right_residual_displacement",
    "right_hysteretic_energy",
    "right_yielded",
];

/// One structure's cells under [`LEFT_COLUMNS`] or [`RIGHT_COLUMNS`].
fn structure_cells(p: &StructurePeaks) -> [String; 7] {
    [
        num(p.peak_displacement),
        num(p.peak_velocity),
        num(p.peak_absolute_acceleration),
        num(p.ductility),
        num(p.residual_displacement),
        num(p.hysteretic_energy),
        p.yielded.to_string(),
    ]
}

impl<'a> RunReport<'a> {
    /// The CSV columns after the demands in SI.
    const RESULT_COLUMNS: [Column<RunReport<'a>>; 10] = [
        ("impacts", |r| r.impacts.to_string()),
        ("max_force", |r| num(r.max_force)),
        ("min_force", |r| num(r.min_force)),
        ("energy_residual", |r| num(r.energy_residual)),
        ("steps", |r| r.steps.to_string()),
        ("elapsed_ms", |r| num(r.elapsed_ms)),
        ("error_vs_exact", |r| optional(r.error_vs_exact)),
        ("min_gap_no_pounding", |r| num(r.min_gap_no_pounding)),
        ("reliable", |r| r.reliable.to_string()),
        ("unreliable_reason", |r| {
            r.unreliable_reason.clone().unwrap_or_default()
        }),
    ];

    /// The table's lines of each structure's peaks and demands (SPEC §6), in
    /// Π units: Π_u, Π_v, A = max |ẍ + g| (in a_p), μ = Π_u/Π_uy, r the
    /// residual displacement, E_h the hysteretic energy.
    fn structure_table(&self, s: &mut String) {
        let _ = writeln!(
            s,
            "{:<10} {:>10} {:>10} {:>10} {:>8} {:>10} {:>10}  yielded",
            "structure", "Π_u", "Π_v", "A", "μ", "r", "E_h"
        );
        for (label, peaks) in [("left (1)", &self.left), ("right (2)", &self.right)] {
            let _ = writeln!(
                s,
                "{label:<10} {:>10.6} {:>10.6} {:>10.4} {:>8} {:>10.6} {:>10.4}  {}",
                peaks.peak_displacement,
                peaks.peak_velocity,
                peaks.peak_absolute_acceleration,
                fixed(peaks.ductility, 3),
                peaks.residual_displacement,
                peaks.hysteretic_energy,
                if peaks.yielded { "yes" } else { "no" }
            );
        }
        let _ = writeln!(
            s,
            "A = max |ẍ + g| (in a_p), μ = Π_u/Π_uy, r = residual displacement, E_h = hysteretic energy (SPEC §6)"
        );
        if let Some(si) = &self.si {
            let sc = &si.scales;
            let _ = writeln!(
                s,
                "in SI, at a_p = {} m/s² ({} g), ω_p = {} rad/s, l_e = {} mm:",
                g4(sc.ap),
                g4(sc.ap / crate::model::physical::G),
                g4(sc.omega_p),
                g4(sc.length * 1e3)
            );
            let _ = writeln!(
                s,
                "{:<10} {:>10} {:>10} {:>10} {:>8} {:>10} {:>10}",
                "structure", "u mm", "v m/s", "A g", "μ", "r mm", "E_h kJ"
            );
            for (label, d) in [("left (1)", &si.left), ("right (2)", &si.right)] {
                let _ = writeln!(
                    s,
                    "{label:<10} {:>10} {:>10} {:>10} {:>8} {:>10} {:>10}",
                    g4(d.peak_displacement_m * 1e3),
                    g4(d.peak_velocity_m_s),
                    g4(d.peak_absolute_acceleration_g),
                    fixed(d.ductility, 3),
                    g4(d.residual_displacement_m * 1e3),
                    g4(d.hysteretic_energy_kj)
                );
            }
            let _ = writeln!(
                s,
                "max force {} kN; gap that prevents pounding {} mm",
                g4(si.max_force_kn),
                g4(si.min_gap_m * 1e3)
            );
        }
    }
}

/// The CSV columns of the demands in SI, empty without `[physical]`.
const SI_COLUMNS: [&str; 12] = [
    "left_peak_displacement_m",
    "left_peak_velocity_m_s",
    "left_peak_absolute_acceleration_g",
    "left_residual_displacement_m",
    "left_hysteretic_energy_kj",
    "right_peak_displacement_m",
    "right_peak_velocity_m_s",
    "right_peak_absolute_acceleration_g",
    "right_residual_displacement_m",
    "right_hysteretic_energy_kj",
    "max_force_kn",
    "min_gap_m",
];

/// The cells of [`SI_COLUMNS`].
fn si_cells(si: Option<&RunSi>) -> Vec<String> {
    let Some(si) = si else {
        return vec![String::new(); SI_COLUMNS.len()];
    };
    let side = |d: &DemandsSi| {
        [
            d.peak_displacement_m,
            d.peak_velocity_m_s,
            d.peak_absolute_acceleration_g,
            d.residual_displacement_m,
            d.hysteretic_energy_kj,
        ]
    };
    let mut cells: Vec<String> = side(&si.left)
        .into_iter()
        .chain(side(&si.right))
        .map(num)
        .collect();
    cells.extend([num(si.max_force_kn), num(si.min_gap_m)]);
    cells
}

/// `v` to `digits` decimals, or `inf`/`nan` as [`Num`] writes them.
fn fixed(v: f64, digits: usize) -> String {
    if v.is_finite() {
        format!("{v:.digits$}")
    } else {
        Num(v).to_string()
    }
}

impl Report for RunReport<'_> {
    /// The preset and every parameter (with the contact law, the ground
    /// motion and the method), then the results.
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = vec!["preset"];
        h.extend(param_columns());
        h.extend(["excitation_note"]);
        h.extend(RecordNumbers::COLUMNS);
        h.extend(LEFT_COLUMNS);
        h.extend(RIGHT_COLUMNS);
        h.extend(SI_COLUMNS);
        h.extend(column_header(&[], &Self::RESULT_COLUMNS));
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let (l, r) = (&self.left, &self.right);
        let mut row = vec![self.provenance.preset.to_string()];
        row.extend(param_cells(&Params {
            method: self.case.method,
            ..self.case.params.clone()
        }));
        row.extend([self.case.excitation_note.clone().unwrap_or_default()]);
        row.extend(RecordNumbers::cells(self.case.params));
        row.extend(structure_cells(l));
        row.extend(structure_cells(r));
        row.extend(si_cells(self.si.as_ref()));
        row.extend(column_cells(&Self::RESULT_COLUMNS, self));
        vec![row]
    }

    fn table(&self) -> String {
        let (p, case) = (self.case.params, &self.case);
        let mut s = String::new();
        // The exact method's one knob beside its name; Newmark's is Δτ.
        let tolerance = match p.method {
            crate::model::Method::Exact => {
                format!(" (contact tolerance {})", Num(p.contact_tolerance))
            }
            crate::model::Method::Newmark => String::new(),
        };
        let _ = writeln!(
            s,
            "{}: {} excitation, {} contact, {} method{tolerance}, Δτ = {}, {} cycles (τ_end = {:.3}), Π_d = {}",
            self.provenance.preset,
            case.excitation,
            case.model,
            case.method,
            Num(p.dt),
            p.cycles,
            self.tau_end,
            Num(p.gap)
        );
        if let Some(note) = &case.excitation_note {
            let _ = writeln!(s, "{}: {note}", case.excitation);
        }
        self.structure_table(&mut s);
        let tension = if self.min_force < 0.0 {
            " (tension)"
        } else {
            ""
        };
        let _ = writeln!(
            s,
            "impacts {}   max force {:.4}   min force {:.4}{tension}   energy residual {:.1e}",
            self.impacts, self.max_force, self.min_force, self.energy_residual
        );
        let timing = if self.repeat > 1 {
            format!("median of {}: ", self.repeat)
        } else {
            String::new()
        };
        let _ = writeln!(
            s,
            "steps {}   {timing}{:.3} ms",
            self.steps, self.elapsed_ms
        );
        let _ = writeln!(
            s,
            "gap that prevents pounding Π_d,min = {:.6} (SPEC §11; this set's Π_d = {})",
            self.min_gap_no_pounding,
            Num(p.gap)
        );
        if let Some(e) = self.error_vs_exact {
            let _ = writeln!(s, "error vs exact {e:.1e} (max relative, four peaks)");
        }
        if self.step_retries + self.unconverged_steps > 0 {
            let _ = writeln!(
                s,
                "warning: {} steps retried smaller, {} accepted unconverged",
                self.step_retries, self.unconverged_steps
            );
        }
        if let Some(why) = &self.unreliable_reason {
            let _ = writeln!(s, "UNRELIABLE: {why}");
        }
        if !self.impact_list.is_empty() {
            let _ = writeln!(
                s,
                "\n{:>3} {:>9} {:>9} {:>9} {:>9} {:>7} {:>10} {:>11}",
                "#", "start", "end", "v_approach", "v_sep", "e", "peak force", "penetration"
            );
            for (i, imp) in self.impact_list.iter().enumerate() {
                let _ = writeln!(
                    s,
                    "{:>3} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>7.4} {:>10.4} {:>11.6}{}",
                    i + 1,
                    imp.start,
                    imp.end,
                    imp.approach_velocity,
                    imp.separation_velocity,
                    imp.restitution,
                    imp.peak_force,
                    imp.max_penetration,
                    if imp.ended {
                        ""
                    } else {
                        "  (in contact at end)"
                    }
                );
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::report::{csv, json};

    #[test]
    fn unreliable_result_is_flagged_in_every_format() {
        let p = crate::model::SET1;
        let mut r = RunResult::default();
        r.energy.residual = 0.5;
        let report = RunReport::new("set1", &p, &r, 1.0, 1, 2.5736);
        let v: serde_json::Value = serde_json::from_str(&json(&report).unwrap()).unwrap();
        assert_eq!(v["reliable"], false);
        assert_eq!(
            v["unreliable_reason"],
            "energy residual 5.000e-1 exceeds 1e-4"
        );
        assert_eq!(v["method"], "newmark");
        let text = csv(&report.csv_header(), &report.csv_rows());
        let last = text.lines().nth(1).unwrap();
        assert!(
            last.starts_with("set1,") && last.contains(",sine,"),
            "{last}"
        );
        assert!(
            last.contains(",newmark,") // no error_vs_exact on a report built by hand
                && last.ends_with(",,2.5736,false,energy residual 5.000e-1 exceeds 1e-4"),
            "{last}"
        );
        assert!(
            report
                .table()
                .contains("UNRELIABLE: energy residual 5.000e-1 exceeds 1e-4")
        );
        r.energy.residual = 1e-12;
        let report = RunReport::new("set1", &p, &r, 1.0, 1, 2.5736);
        let v: serde_json::Value = serde_json::from_str(&json(&report).unwrap()).unwrap();
        assert_eq!(v["reliable"], true);
        assert!(!report.table().contains("UNRELIABLE"));
    }
}
