//! The command line: a thin layer over the library. Each subcommand lives in
//! its own file and returns `Result<(), CliError>`; `main` maps the error to
//! the exit code.
//!
//! Exit codes: 0 success; 1 a check failed, a run was unreliable, or output
//! could not be written; 2 bad input (a parameter out of range, an unknown
//! preset, a malformed file, not a terminal for the explorer, a request
//! beyond the work or size bound without its confirming flag). Clap's own
//! usage errors are 2 too. A pipe closed by its reader (`| head`) ends the
//! command quietly with 0, as the reader asked for no more. SIGINT, SIGTERM
//! and SIGHUP remove temporary files, then end the process by the signal.

pub mod bench;
pub mod budget;
pub mod buildings;
pub mod compare;
pub mod description;
pub mod design;
pub mod design_suite;
pub mod figure;
pub mod figure_risk;
pub mod gap;
pub mod gap_suite;
pub mod ida;
pub mod limit_states;
pub mod map;
pub mod map_suite;
#[cfg(feature = "app")]
pub mod merge;
pub mod output;
pub mod params;
pub mod progress;
pub mod records;
pub mod records_scale;
pub mod records_select;
pub mod run;
pub mod shard;
pub mod similarity;
pub mod spectrum;
pub mod spelling;
pub mod stress;
pub mod study_tables;
pub mod subject;
pub mod suite;
#[cfg(feature = "app")]
pub mod tui;

#[cfg(feature = "app")]
use clap::{Parser, Subcommand};

/// A command's failure, with the exit code it maps to.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input: exit code 2.
    #[error("{0}")]
    Usage(String),
    /// A failed check or an I/O error: exit code 1.
    #[error("{0}")]
    Failed(String),
    /// Stdout's reader went away (`| head`): stop quietly, exit code 0.
    #[error("broken pipe")]
    BrokenPipe,
}

/// Bad input (exit code 2), its message `message`.
pub fn usage(message: impl std::fmt::Display) -> CliError {
    CliError::Usage(message.to_string())
}

impl CliError {
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Usage(_) => 2,
            CliError::Failed(_) => 1,
            CliError::BrokenPipe => 0,
        }
    }
}

impl From<crate::model::ParamError> for CliError {
    fn from(e: crate::model::ParamError) -> Self {
        CliError::Usage(e.to_string())
    }
}

impl From<crate::output::OutputError> for CliError {
    fn from(e: crate::output::OutputError) -> Self {
        match e {
            crate::output::OutputError::BrokenPipe => CliError::BrokenPipe,
            e => CliError::Failed(e.to_string()),
        }
    }
}

impl From<crate::model::PresetError> for CliError {
    fn from(e: crate::model::PresetError) -> Self {
        CliError::Usage(e.to_string())
    }
}

#[cfg(feature = "app")]
#[derive(Debug, Parser)]
#[command(
    name = "pounding",
    version,
    about = "Pounding of adjacent buildings in earthquakes: a pair of inelastic SDOF structures \
             in Buckingham-Π form, rows of multi-storey buildings, suites of records, and the \
             risk of pounding",
    long_about = "Pounding of adjacent buildings in earthquakes: a pair of inelastic SDOF \
                  structures with bilinear hysteresis in Buckingham-Π form, rows of shear \
                  buildings that pound at their floors (--buildings), and suites of records \
                  with fragility and the risk of pounding (suite, ida). Ground motion: a sine, the cycloidal pulses A, B, C1 \
                  and C2, or a recorded accelerogram (PEER .AT2 or plain time-acceleration \
                  columns). Contact laws: kelvin, improved-kelvin, hertz, hertzdamp, jankowski, \
                  hunt-crossley. Methods: Newmark-β (average acceleration) or the exact \
                  event-driven one. Without a command it opens the terminal explorer."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// The explorer's flags, also without the `tui` command.
    #[command(flatten)]
    pub tui: tui::TuiArgs,
}

#[cfg(feature = "app")]
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run one simulation and print its peaks, impacts and energy balance.
    Run(run::RunArgs),
    /// Response spectra: peak response against Π_ω1 with and without pounding (SPEC §7).
    Spectrum(spectrum::SpectrumArgs),
    /// Region map of the left structure over two parameters (any Π key or mu), SPEC §7.
    Map(map::MapArgs),
    /// The smallest gap that prevents pounding, beside the code rules ABS, SRSS, DDC (SPEC §11).
    Gap(gap::GapArgs),
    /// Physical units in and out, and the self-similarity of SPEC §8.
    Similarity(similarity::SimilarityArgs),
    /// One physical pair of buildings, or a row of them (--buildings), under a
    /// suite of records scaled to an intensity: the demands of every record and
    /// their statistics (SPEC §12, §13).
    Suite(suite::SuiteArgs),
    /// Incremental dynamic analysis: a suite at every intensity level, and the
    /// lognormal fragility of each limit state with and without pounding, for a
    /// pair or a row of buildings (SPEC §12, §13).
    Ida(ida::IdaArgs),
    /// Open the terminal explorer (the default without a command).
    Tui(tui::TuiArgs),
    /// Work-precision table: run time against error for each method (Newmark-β schemes, exact).
    Bench(bench::BenchArgs),
    /// Numerical stress test over corner and random parameter sets (Kelvin and improved Kelvin).
    Stress(stress::StressArgs),
    /// The paper's figures and the scenes as SVG or PNG files.
    Figure(Box<figure::FigureArgs>),
    /// Ground-motion records for suites: `records synth` writes simulated ones, `records scale`
    /// and `records select` scale and choose them for a target spectrum (SPEC §12).
    Records(records::RecordsArgs),
    /// The parts of a sharded sweep (`--shard K/N`) into the output the
    /// unsharded command writes.
    Merge(merge::MergeArgs),
}

#[cfg(feature = "app")]
/// Parses the command line and runs the chosen command.
pub fn main_with_args(args: impl IntoIterator<Item = std::ffi::OsString>) -> i32 {
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        // Help and version print in full; a usage error is its first line
        // only (it names the flag and the value), like every other bad input.
        Err(e) if !e.use_stderr() => {
            let _ = e.print();
            return e.exit_code();
        }
        Err(e) => {
            let text = e.render().to_string();
            eprintln!("{}", text.lines().next().unwrap_or("error: bad arguments"));
            return e.exit_code();
        }
    };
    let explorer = matches!(cli.command, None | Some(Command::Tui(_)));
    if !explorer {
        // The explorer handles these signals itself, and cleans up on its way out.
        let _ = crate::output::temp::cleanup_then_die_on_signals();
    }
    let outcome = match cli.command {
        Some(Command::Run(args)) => run::execute(&args),
        Some(Command::Spectrum(args)) => spectrum::execute(&args),
        Some(Command::Map(args)) => map::execute(&args),
        Some(Command::Gap(args)) => gap::execute(&args),
        Some(Command::Similarity(args)) => similarity::execute(&args),
        Some(Command::Suite(args)) => suite::execute(&args),
        Some(Command::Ida(args)) => ida::execute(&args),
        Some(Command::Tui(args)) => tui::execute(&args),
        Some(Command::Bench(args)) => bench::execute(&args),
        Some(Command::Stress(args)) => stress::execute(&args),
        Some(Command::Figure(args)) => figure::execute(&args),
        Some(Command::Records(args)) => records::execute(&args),
        Some(Command::Merge(args)) => merge::execute(&args),
        None => tui::execute(&cli.tui),
    };
    crate::output::temp::remove_live();
    match outcome {
        Ok(()) | Err(CliError::BrokenPipe) => 0,
        Err(e) => {
            // One line whatever a message quotes; stderr may be unwritable too.
            use std::io::Write as _;
            let _ = writeln!(
                std::io::stderr(),
                "error: {}",
                e.to_string().replace(['\n', '\r'], " ")
            );
            e.exit_code()
        }
    }
}
