//! `pounding run`: one simulation, its summary as a table, JSON or CSV, and
//! optionally its full history as CSV.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;

use super::CliError;
use super::output::{Format, num, params_json};
use super::params::ParamArgs;
use crate::accuracy::timing::median;
use crate::model::{Params, preset::write_atomic};
use crate::solver::{FullHistory, RunResult, SolverOptions, simulate};

#[derive(Debug, Clone, Default, Args)]
pub struct RunArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// Output format of the summary.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Write the history as CSV (tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp), one row per step.
    #[arg(long, value_name = "FILE")]
    pub history: Option<PathBuf>,
    /// Run the same case N times in this process and report the median time.
    #[arg(long, value_name = "N", default_value_t = 1, allow_negative_numbers = true, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub repeat: u32,
}

pub fn execute(args: &RunArgs) -> Result<(), CliError> {
    let (preset, p) = args.params.resolve()?;
    let options = SolverOptions::default();
    let mut times = Vec::with_capacity(args.repeat as usize);
    let mut result = RunResult::default();
    for _ in 0..args.repeat {
        let t = Instant::now();
        result = simulate(&p, &options, &mut ());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    let elapsed_ms = median(times);
    if let Some(path) = &args.history {
        let steps = (p.tau_end() / p.dt) as usize + 64;
        let mut history = FullHistory::with_capacity(steps.min(50_000_000));
        simulate(&p, &options, &mut history);
        write_atomic(path, history.to_csv().as_bytes()).map_err(|e| {
            CliError::Failed(format!("cannot write history to {}: {e}", path.display()))
        })?;
    }
    let text = match args.format {
        Format::Table => table(&preset.name, &p, &result, elapsed_ms, args.repeat),
        Format::Json => json(&p, &result, elapsed_ms).to_string() + "\n",
        Format::Csv => csv(&result, elapsed_ms),
    };
    print!("{text}");
    Ok(())
}

/// The run summary as the JSON object of the issue (SPEC §6).
pub fn json(p: &Params, r: &RunResult, elapsed_ms: f64) -> serde_json::Value {
    serde_json::json!({
        "params": params_json(p),
        "model": p.model.name(),
        "dt": p.dt,
        "tau_end": r.tau_end,
        "steps": r.steps,
        "left": r.left,
        "right": r.right,
        "impacts": r.impacts.len(),
        "max_force": r.max_force,
        "min_force": r.min_force,
        "energy_residual": r.energy.residual,
        "energy": r.energy,
        "impact_list": r.impacts,
        "step_retries": r.step_retries,
        "unconverged_steps": r.unconverged_steps,
        "elapsed_ms": elapsed_ms,
    })
}

fn csv(r: &RunResult, elapsed_ms: f64) -> String {
    let header = "left_peak_displacement,left_peak_velocity,left_yielded,right_peak_displacement,\
                  right_peak_velocity,right_yielded,impacts,max_force,min_force,energy_residual,steps,elapsed_ms";
    format!(
        "{header}\n{},{},{},{},{},{},{},{},{},{},{},{}\n",
        r.left.peak_displacement,
        r.left.peak_velocity,
        r.left.yielded,
        r.right.peak_displacement,
        r.right.peak_velocity,
        r.right.yielded,
        r.impacts.len(),
        r.max_force,
        r.min_force,
        r.energy.residual,
        r.steps,
        elapsed_ms
    )
}

fn table(name: &str, p: &Params, r: &RunResult, elapsed_ms: f64, repeat: u32) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{name}: {} contact, Δτ = {}, {} cycles (τ_end = {:.3}), Π_d = {}",
        p.model,
        p.dt,
        p.cycles,
        r.tau_end,
        num(p.gap)
    );
    let _ = writeln!(
        s,
        "{:<12} {:>12} {:>12}  yielded",
        "structure", "Π_u", "Π_v"
    );
    for (label, peaks) in [("left (1)", &r.left), ("right (2)", &r.right)] {
        let _ = writeln!(
            s,
            "{label:<12} {:>12.6} {:>12.6}  {}",
            peaks.peak_displacement,
            peaks.peak_velocity,
            if peaks.yielded { "yes" } else { "no" }
        );
    }
    let tension = if r.min_force < 0.0 { " (tension)" } else { "" };
    let _ = writeln!(
        s,
        "impacts {}   max force {:.4}   min force {:.4}{tension}   energy residual {:.1e}",
        r.impacts.len(),
        r.max_force,
        r.min_force,
        r.energy.residual
    );
    let timing = if repeat > 1 {
        format!("median of {repeat}: ")
    } else {
        String::new()
    };
    let _ = writeln!(s, "steps {}   {timing}{elapsed_ms:.3} ms", r.steps);
    if r.step_retries + r.unconverged_steps > 0 {
        let _ = writeln!(
            s,
            "warning: {} steps retried smaller, {} accepted unconverged",
            r.step_retries, r.unconverged_steps
        );
    }
    if !r.impacts.is_empty() {
        let _ = writeln!(
            s,
            "\n{:>3} {:>9} {:>9} {:>9} {:>9} {:>7} {:>10} {:>11}",
            "#", "start", "end", "v_approach", "v_sep", "e", "peak force", "penetration"
        );
        for (i, imp) in r.impacts.iter().enumerate() {
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
