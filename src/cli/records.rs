//! `pounding records`: ground-motion records for suites (SPEC §12).
//! `records scale` and `records select` ([`super::records_scale`],
//! [`super::records_select`]) scale and choose records for a target
//! spectrum. `records synth` writes simulated records ([`crate::model::simulated`]) as
//! `.AT2` files and a suite list naming them, through [`crate::output`]; the
//! files read back bit for bit as the suite `synthetic:N@SEED` holds them.

use std::path::PathBuf;

use clap::{Args, Subcommand, ValueEnum};

use super::output::{print, refuse_non_file};
use super::{CliError, usage};
use crate::model::simulated::{self, Filter, MAX_COUNT, Simulation, SimulationError};
use crate::model::suite::{LIST_FILE, SuiteMember};
use crate::output::{shown, write_file};

#[derive(Debug, Clone, Args)]
pub struct RecordsArgs {
    #[command(subcommand)]
    pub command: RecordsCommand,
}

#[derive(Debug, Clone, Subcommand)]
pub enum RecordsCommand {
    /// Write N simulated records (filtered white noise, SPEC §12) as .AT2 files and a suite list.
    Synth(SynthArgs),
    /// Scale a suite's records to a target spectrum by a code's rule (EC8, ASCE 7) and write the list.
    Scale(super::records_scale::ScaleArgs),
    /// Choose the N records of a directory that best fit a target spectrum, and scale them.
    Select(super::records_select::SelectArgs),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FilterArg {
    /// One ground oscillator (ω_g, ζ_g).
    KanaiTajimi,
    /// Kanai–Tajimi, then a high-pass oscillator (ω_f, ζ_f).
    CloughPenzien,
}

#[derive(Debug, Clone, Args)]
pub struct SynthArgs {
    /// Number of records.
    #[arg(long, value_name = "N")]
    pub count: usize,
    /// Seed; record j of seed S is the same whatever N.
    #[arg(long, value_name = "S", default_value_t = simulated::DEFAULT_SEED)]
    pub seed: u64,
    /// Existing directory to write synthetic-001.at2 … and suite.txt into.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Duration of each record (s).
    #[arg(
        long,
        value_name = "S",
        default_value_t = 20.0,
        allow_hyphen_values = true
    )]
    pub duration: f64,
    /// Sample interval (s).
    #[arg(
        long,
        value_name = "S",
        default_value_t = 0.01,
        allow_hyphen_values = true
    )]
    pub dt: f64,
    /// Peak ground acceleration of each record (g).
    #[arg(
        long,
        value_name = "G",
        default_value_t = 0.3,
        allow_hyphen_values = true
    )]
    pub pga: f64,
    /// Ground filter.
    #[arg(long, value_enum, default_value_t = FilterArg::KanaiTajimi)]
    pub filter: FilterArg,
    /// Ground filter frequency ω_g (rad/s) [default: 5π].
    #[arg(long, value_name = "RAD_S", default_value_t = simulated::DEFAULT_OMEGA_G, allow_hyphen_values = true)]
    pub omega_g: f64,
    /// Ground filter damping ratio ζ_g.
    #[arg(long, value_name = "X", default_value_t = simulated::DEFAULT_ZETA_G, allow_hyphen_values = true)]
    pub zeta_g: f64,
    /// Clough–Penzien high-pass frequency ω_f (rad/s) [default: π/2].
    #[arg(long, value_name = "RAD_S", default_value_t = simulated::DEFAULT_OMEGA_F, allow_hyphen_values = true)]
    pub omega_f: f64,
    /// Clough–Penzien high-pass damping ratio ζ_f.
    #[arg(long, value_name = "X", default_value_t = simulated::DEFAULT_ZETA_F, allow_hyphen_values = true)]
    pub zeta_f: f64,
}

pub fn execute(args: &RecordsArgs) -> Result<(), CliError> {
    match &args.command {
        RecordsCommand::Synth(synth) => execute_synth(synth),
        RecordsCommand::Scale(scale) => super::records_scale::execute(scale),
        RecordsCommand::Select(select) => super::records_select::execute(select),
    }
}

impl SynthArgs {
    /// The simulation the flags ask for, validated.
    pub fn simulation(&self) -> Result<Simulation, CliError> {
        let filter = match self.filter {
            FilterArg::KanaiTajimi => Filter::KanaiTajimi,
            FilterArg::CloughPenzien => Filter::CloughPenzien {
                omega_f: self.omega_f,
                zeta_f: self.zeta_f,
            },
        };
        let simulation = Simulation {
            duration: self.duration,
            dt: self.dt,
            pga: self.pga,
            filter,
            omega_g: self.omega_g,
            zeta_g: self.zeta_g,
        };
        simulation.validate().map_err(flag_error)?;
        Ok(simulation)
    }
}

/// `synthetic:N` of `--excitation`: one simulated record of N ≥ 11 samples
/// at DT = 0.005 s (seed 1, as `records synth`), named `name`.
pub fn synthetic_record(name: &str, n: &str) -> Result<crate::model::record::Record, CliError> {
    let samples: usize = n
        .parse()
        .ok()
        .filter(|&n| n >= 11)
        .ok_or_else(|| usage(format!("synthetic:N needs N ≥ 11, not `{n}`")))?;
    Simulation::synthetic(name, samples).map_err(usage)
}

/// A parameter out of range, named by its flag: `--zeta-g -1: must be in (0, 5]`.
fn flag_error(e: SimulationError) -> CliError {
    usage(format!(
        "--{} {}: must be {}",
        e.key.replace('_', "-"),
        e.value,
        e.allowed
    ))
}

fn execute_synth(args: &SynthArgs) -> Result<(), CliError> {
    if !(1..=MAX_COUNT).contains(&args.count) {
        return Err(usage(format!(
            "--count {}: must be in [1, {MAX_COUNT}]",
            args.count
        )));
    }
    let simulation = args.simulation()?;
    let dir = &args.out;
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => {
            return Err(usage(format!("--out {}: not a directory", shown(dir))));
        }
        Err(e) => {
            return Err(usage(format!(
                "--out {}: {} (the directory must exist)",
                shown(dir),
                crate::output::reason(&e)
            )));
        }
    }
    let names: Vec<String> = (1..=args.count).map(simulated::file_name).collect();
    // Refuse before writing anything if a target is there and is not a file.
    for name in names.iter().map(String::as_str).chain([LIST_FILE]) {
        refuse_non_file(&dir.join(name))?;
    }
    for (j, name) in names.iter().enumerate() {
        let text = simulation.at2_text(args.seed, j + 1);
        write_file(&dir.join(name), text.as_bytes())?;
    }
    write_file(
        &dir.join(LIST_FILE),
        list_text(args, &simulation, &names).as_bytes(),
    )?;
    print(&format!(
        "wrote {} records ({}, seed {}, {} s at DT = {} s, PGA {} g) and {} to {}\n",
        args.count,
        simulation.filter.name(),
        args.seed,
        simulation.duration,
        simulation.dt,
        simulation.pga,
        LIST_FILE,
        shown(dir)
    ))
}

/// The suite list: a comment stating how the records were made, then one
/// file name a line (scale 1).
fn list_text(args: &SynthArgs, simulation: &Simulation, names: &[String]) -> String {
    let mut text = format!(
        "# pounding records synth --count {} --seed {}, {} filter, {} s at DT = {} s, PGA {} g\n",
        args.count,
        args.seed,
        simulation.filter.name(),
        simulation.duration,
        simulation.dt,
        simulation.pga
    );
    if *simulation == Simulation::default() {
        text.push_str(&format!(
            "# the same records as the suite synthetic:{}@{}\n",
            args.count, args.seed
        ));
    }
    text.push_str("# one record a line: PATH [SCALE]\n");
    for name in names {
        text.push_str(name);
        text.push('\n');
    }
    text
}

/// The records of `SUITE` (a directory, a list file, `synthetic:N@S`, or
/// a suite scaled to a target: [`super::design_suite`]), or the one-line
/// error naming the file and line.
pub fn members(suite: &str) -> Result<Vec<SuiteMember>, CliError> {
    super::design_suite::load(suite)
}
