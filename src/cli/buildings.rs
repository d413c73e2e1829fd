//! `--buildings PRESET`: the row commands of SPEC §13 (`run`), parsing and
//! printing only; the model, the methods and the report live in the library.

use std::time::Instant;

use clap::Args;

use super::budget::{SECONDS_PER_STEP, Work};
use super::output::{Emit, FormatArg, print, render};
use super::params::ParamArgs;
use super::{CliError, usage};
use crate::accuracy::timing::median;
use crate::analysis::buildings_report::RowReport;
use crate::analysis::work;
use crate::model::buildings::matrices::default_tail;
use crate::model::buildings::{Ground, Row, load_with};
use crate::model::excitation::Excitation;
use crate::model::physical::parse_acceleration;
use crate::solver::buildings::{RowOptions, default_step, max_step, run_newmark, run_row};

/// The options of a row of buildings.
#[derive(Debug, Clone, Default, Args)]
pub struct BuildingsArgs {
    /// A row of shear buildings (SPEC §13): a built-in row (two-buildings,
    /// block-and-frame, three-in-series, block-and-frame-pdelta,
    /// block-and-frame-retrofit) or a path to a row preset. `--set
    /// NAME.KEY=V` edits one building, `--set jointN.KEY=V` one joint
    /// (`jointN.bumper.KEY=V` its bumper), `--set linkN.KEY=V` one link.
    #[arg(long, value_name = "NAME|PATH")]
    pub buildings: Option<String>,
    /// Scale factor on the ground motion (rows).
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub scale: Option<f64>,
    /// Free vibration after the motion ends, in seconds [default: four times the longest fundamental period] (rows).
    #[arg(long, value_name = "SECONDS")]
    pub tail: Option<f64>,
    /// Amplitude of a sine or pulse, in m/s² or with a `g` suffix [default: 0.3g] (rows).
    #[arg(long, value_name = "A")]
    pub amplitude: Option<String>,
    /// Period of a sine or pulse in seconds [default: 1] (rows).
    #[arg(long, value_name = "SECONDS")]
    pub period: Option<f64>,
}

impl BuildingsArgs {
    /// The options of a row's ground motion (`--scale`, `--tail`,
    /// `--amplitude`, `--period`) that were given.
    pub fn motion_flags(&self) -> Vec<&'static str> {
        [
            ("--scale", self.scale.is_some()),
            ("--tail", self.tail.is_some()),
            ("--amplitude", self.amplitude.is_some()),
            ("--period", self.period.is_some()),
        ]
        .into_iter()
        .filter(|(_, given)| *given)
        .map(|(flag, _)| flag)
        .collect()
    }

    /// The row, with `--set` and `--model` applied.
    pub fn row(&self, overrides: &[String], model: Option<&str>) -> Result<Row, CliError> {
        let name = self.buildings.as_deref().unwrap_or("block-and-frame");
        let mut sets = overrides.to_vec();
        if let Some(m) = model {
            sets.push(format!("model=\"{m}\""));
        }
        load_with(name, &sets).map_err(usage)
    }

    /// The first of `--amplitude` and `--period` given, as (key, value):
    /// the shape of a sine or a pulse.
    fn shape(&self) -> Option<(&'static str, String)> {
        match (&self.amplitude, self.period) {
            (Some(a), _) => Some(("--amplitude", a.clone())),
            (None, Some(p)) => Some(("--period", p.to_string())),
            (None, None) => None,
        }
    }

    /// `synthetic:N` or `record:PATH`, scaled by `scale`.
    fn record(&self, spec: &str, scale: f64) -> Result<Ground, CliError> {
        let record = match spec.strip_prefix("record:") {
            Some(path) => crate::model::record::read(path).map_err(usage)?,
            None => synthetic(spec)?,
        };
        Ok(Ground::from_record(&record, scale))
    }

    /// The ground motion and its name, and the run's length.
    pub fn ground(
        &self,
        excitation: Option<&str>,
        cycles: Option<&str>,
        row: &Row,
    ) -> Result<(Ground, String, f64), CliError> {
        let scale = self.scale.unwrap_or(1.0);
        if !scale.is_finite() {
            return Err(usage(format!("--scale {scale}: must be a finite number")));
        }
        let amplitude = match &self.amplitude {
            None => 0.3 * crate::model::record::STANDARD_GRAVITY,
            Some(a) => parse_acceleration(a).ok_or_else(|| {
                usage(format!(
                    "--amplitude `{a}`: must be a number > 0 in m/s², or with a g suffix (0.3g)"
                ))
            })?,
        } * scale;
        let period = self.period.unwrap_or(1.0);
        if !(period > 0.0 && period.is_finite()) {
            return Err(usage(format!(
                "--period {period}: must be a finite number > 0 (s)"
            )));
        }
        let omega = 2.0 * std::f64::consts::PI / period;
        let name = excitation.unwrap_or("sine");
        let ground = match name {
            "sine" => {
                let cycles = match cycles {
                    None => 8.0,
                    Some(c) => c
                        .parse::<f64>()
                        .ok()
                        .filter(|c| *c > 0.0 && c.is_finite())
                        .ok_or_else(|| {
                            usage(format!("--cycles `{c}`: must be a finite number > 0"))
                        })?,
                };
                Ground::sine(amplitude, omega, cycles * period)
            }
            _ if cycles.is_some() => {
                return Err(usage(format!(
                    "--cycles `{}`: only a sine on a row takes cycles; a row under {name} runs for the motion and then --tail seconds",
                    cycles.unwrap_or_default()
                )));
            }
            spec if spec.starts_with("synthetic:") || spec.starts_with("record:") => {
                if let Some((key, value)) = self.shape() {
                    return Err(usage(format!(
                        "{key} `{value}`: a record on a row is used in its own units; only a sine or a pulse takes --amplitude and --period (scale a record with --scale)"
                    )));
                }
                self.record(spec, scale)?
            }
            other => match Excitation::parse(other) {
                Ok(Excitation::Pulse(pulse)) => Ground::from_pulse(pulse, amplitude, omega),
                _ => {
                    return Err(usage(format!(
                        "--excitation `{other}`: rows take sine, pulse-a, pulse-b, pulse-c1, pulse-c2, synthetic:N or record:PATH"
                    )));
                }
            },
        };
        let tail = self.tail.unwrap_or_else(|| default_tail(row));
        if !(tail >= 0.0 && tail.is_finite()) {
            return Err(usage(format!(
                "--tail {tail}: must be a finite number ≥ 0 (s)"
            )));
        }
        Ok((ground.clone(), name.to_string(), ground.end() + tail))
    }
}

/// `synthetic:N`: one simulated record of N samples at DT = 0.005 s, PGA 0.3 g.
fn synthetic(spec: &str) -> Result<crate::model::record::Record, CliError> {
    let n = &spec["synthetic:".len()..];
    super::records::synthetic_record(&format!("synthetic:{n}"), n)
}

/// `pounding bench --buildings`: work-precision rows of both methods
/// against the reference.
pub fn bench(
    args: &BuildingsArgs,
    excitation: Option<&str>,
    model: Option<&str>,
    output: &FormatArg,
    allow_long: bool,
) -> Result<(), CliError> {
    let row = args.row(&[], model)?;
    let (ground, name, duration) =
        args.ground(Some(excitation.unwrap_or("synthetic:2000")), None, &row)?;
    // The reference costs about twenty exact runs; Newmark runs at the
    // default step and at two, four and eight times it.
    let exact = work::row_seconds(&row, duration, None);
    let newmark = work::row_seconds(&row, duration, Some(default_step(&row, duration, &ground)));
    bounded(
        "bench --buildings",
        21.0 * exact + 1.875 * newmark,
        allow_long,
    )?;
    let rows = crate::accuracy::row_bench::row_bench(&row, &ground, duration).map_err(usage)?;
    let report = crate::analysis::buildings_report::RowBenchReport {
        row: row.name.clone(),
        excitation: name,
        duration,
        rows,
    };
    print(&render(&report, output.format)?)
}

/// `--dt` in seconds for rows, by default [`default_step`] of the run's
/// length; at most [`max_step`].
fn newmark_step(
    params: &ParamArgs,
    duration: f64,
    row: &Row,
    ground: &Ground,
) -> Result<f64, CliError> {
    let (most, why) = max_step(row, ground);
    let Some(text) = &params.dt else {
        return Ok(default_step(row, duration, ground).min(most));
    };
    let dt = text
        .parse::<f64>()
        .ok()
        .filter(|d| *d > 0.0 && d.is_finite())
        .ok_or_else(|| {
            usage(format!(
                "--dt `{text}`: rows take a step in seconds, a finite number > 0"
            ))
        })?;
    if dt > most {
        return Err(usage(format!(
            "--dt `{text}`: must be <= {} s on this row ({why})",
            crate::model::params::echo::g4(most)
        )));
    }
    Ok(dt)
}

/// Refuses a request on `row` estimated beyond the commands' work bound
/// (`cli::budget`) without `--allow-long`: `seconds` of runs estimated by
/// [`work::row_seconds`], so that a long tail or a tiny Newmark step
/// is a clear error rather than a wait without end.
fn bounded(what: &str, seconds: f64, allow_long: bool) -> Result<(), CliError> {
    Work::steps(seconds / SECONDS_PER_STEP).check(what, allow_long, true)
}

/// `pounding run --buildings`.
pub fn run(
    args: &BuildingsArgs,
    params: &ParamArgs,
    repeat: u32,
    allow_long: bool,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let method = params.method.as_deref().unwrap_or("exact");
    let mut row = args.row(&params.overrides, params.model.as_deref())?;
    if params.no_pounding {
        // The no-pounding baseline: every joint open for good.
        for joint in &mut row.joints {
            joint.gap = f64::INFINITY;
        }
    }
    let (ground, name, duration) =
        args.ground(params.excitation.as_deref(), params.cycles.as_deref(), &row)?;
    let step = match method {
        "newmark" => Some(newmark_step(params, duration, &row, &ground)?),
        _ => None,
    };
    let seconds = f64::from(repeat.max(1)) * work::row_seconds(&row, duration, step);
    bounded("run --buildings", seconds, allow_long)?;
    // The exact method takes its energy balance on the run's own steps
    // (closed forms on the maps, quadrature on the series): the time per
    // run includes it.
    let options = RowOptions {
        energy: true,
        ..RowOptions::lasting(duration)
    };
    let mut times = Vec::new();
    let mut result = None;
    for _ in 0..repeat.max(1) {
        let t = Instant::now();
        let run = match step {
            Some(dt) => run_newmark(&row, &ground, duration, dt),
            None => run_row(&row, &ground, &options),
        };
        result = Some(run.map_err(|e| CliError::Failed(e.to_string()))?);
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    let result = result.expect("at least one run");
    let report = RowReport::new(&row, &result, (&ground, &name), method, median(times));
    emit(&report)
}

/// `pounding gap --buildings`: per joint, the gap that prevents pounding
/// beside the code rules.
pub fn gap(
    args: &BuildingsArgs,
    params: &ParamArgs,
    allow_long: bool,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    refuse_no_pounding(
        "gap",
        params,
        "the gap is found from the runs without contact",
    )?;
    let row = args.row(&params.overrides, params.model.as_deref())?;
    let (ground, name, duration) =
        args.ground(params.excitation.as_deref(), params.cycles.as_deref(), &row)?;
    let seconds = 2.0 * work::row_seconds(&row, duration, None);
    bounded("gap --buildings", seconds, allow_long)?;
    let report = crate::analysis::gap::row_gap(&row, &ground, duration, &name)
        .map_err(|e| CliError::Failed(e.to_string()))?;
    emit(&report)
}

/// `--no-pounding` where a row command draws or finds the run without
/// contact itself: one line saying why.
fn refuse_no_pounding(command: &str, params: &ParamArgs, why: &str) -> Result<(), CliError> {
    if params.no_pounding {
        return Err(usage(format!(
            "--no-pounding: not with {command} --buildings ({why}); drop --no-pounding"
        )));
    }
    Ok(())
}

/// `pounding figure buildings --out F.svg|png`: envelopes with and without
/// pounding, and the impact forces.
pub fn figure(
    args: &BuildingsArgs,
    params: &ParamArgs,
    out: Option<&std::path::Path>,
    allow_long: bool,
) -> Result<(), CliError> {
    use crate::figure::{Format, encode};
    refuse_no_pounding(
        "figure",
        params,
        "it draws the row with and without pounding",
    )?;
    let out = out.ok_or_else(|| usage("figure buildings needs --out F.svg or F.png"))?;
    let format = match out.extension().and_then(|e| e.to_str()) {
        Some("svg") => Format::Svg,
        Some("png") => Format::Png,
        _ => {
            return Err(usage(format!(
                "--out {}: must end in .svg or .png",
                out.display()
            )));
        }
    };
    let row = args.row(&params.overrides, params.model.as_deref())?;
    let (ground, name, duration) =
        args.ground(params.excitation.as_deref(), params.cycles.as_deref(), &row)?;
    let seconds = 2.0 * work::row_seconds(&row, duration, None);
    bounded("figure buildings", seconds, allow_long)?;
    let fig = crate::figure::buildings::row_figure_of(&row, &ground, &name, duration)
        .map_err(|e| CliError::Failed(e.to_string()))?;
    let bytes = encode(&fig, format, crate::figure::buildings::ROW_FIGURE_SIZE)
        .map_err(|e| CliError::Failed(e.to_string()))?;
    crate::output::write_file(out, &bytes)?;
    Ok(())
}
