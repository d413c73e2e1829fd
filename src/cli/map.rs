//! `pounding map`: the left structure's spectral regions (SPEC §7) over two
//! parameters, `--x KEY=START:STOP:STEP --y KEY=START:STOP:STEP`, each any
//! Π key or `mu`, with every cell's peaks, amplification ratios, impacts,
//! forces and minimum gap, as a table, JSON or CSV.

use std::fmt::Write as _;
use std::time::Instant;

use clap::Args;
use serde::Serialize;

use super::budget::{LongArg, Work, run_steps};
use super::description::{Description, Provenance};
use super::output::{
    Emit, FormatArg, PEAK_COLUMNS, num, optional, param_cells, param_columns, printer,
};
use super::params::ParamArgs;
use super::progress::Progress;
use super::{CliError, usage};
use crate::analysis::map::{Axis, MapCache, MapCell, MapPlan, compute_rows, row_regions};
use crate::analysis::spectrum::{REGION_THRESHOLD, Region};
use crate::analysis::spectrum_spec::{SpectrumSpec, mu_from_text};
use crate::model::params::echo;
use crate::model::{Params, Preset};
use crate::output::report::{Column, Report, column_cells, column_header};

#[derive(Debug, Clone, Default, Args)]
pub struct MapArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// The horizontal axis: a Π key or mu over a grid, e.g. omega1=0.1:3.0:0.02.
    #[arg(long, value_name = "KEY=START:STOP:STEP", allow_hyphen_values = true)]
    pub x: String,
    /// The vertical axis, e.g. mu=1:10:0.1 or gap=0.1:2:0.05.
    #[arg(long, value_name = "KEY=START:STOP:STEP", allow_hyphen_values = true)]
    pub y: String,
    /// Frequency ratio μ, Π_ω2 = μ Π_ω1 on an omega1 axis [default: the preset's, else omega2/omega1].
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub mu: Option<String>,
    // The help's `[physical]` is a preset's table, not a doc link.
    #[allow(rustdoc::broken_intra_doc_links)]
    /// A suite of records instead of one set: --x and --y are then physical
    /// quantities of the preset's [physical] table (m1, m2, period1, period2,
    /// yield1, yield2, gap, damping, alpha, contact_omega, restitution), and
    /// each cell gives P(pounding) and the median amplification of the left
    /// building's drift (SPEC §12).
    #[command(flatten)]
    pub records: super::suite::SuiteOptions,
    /// With --suite: a row of shear buildings (SPEC §13) instead of the
    /// preset's pair, a built-in row (block-and-frame-retrofit, …) or a path:
    /// --x and --y are then any two keys --set takes (joint1.gap,
    /// link1.damping, joint1.bumper.thickness, frame.damping, …), and each
    /// cell gives P(pounding) per joint, the median peak drift ratio and
    /// floor acceleration per building and the median peak force per link
    /// (SPEC §14): what a retrofit buys.
    #[arg(long, value_name = "NAME|PATH")]
    pub buildings: Option<String>,
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub long: LongArg,
    #[command(flatten)]
    pub shard: super::shard::ShardArgs,
}

pub fn execute(args: &MapArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The map of `args` (of a suite's records with `--suite`), its typed
/// report handed to `emit`.
pub fn report_with(
    args: &MapArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let others = [("--buildings", args.buildings.is_some())];
    if let Some(mut suite_args) =
        args.records
            .request(&args.params, args.output, args.long, &others)?
    {
        suite_args.shard = args.shard.clone();
        suite_args.buildings = args.buildings.clone();
        let suite_args = suite_args.at_design_level()?;
        return match suite_args.buildings {
            Some(_) => super::map_suite::row::report_with(&suite_args, &args.x, &args.y, emit),
            None => super::map_suite::pair::report_with(&suite_args, &args.x, &args.y, emit),
        };
    }
    let (preset, p) = args.params.resolve_for_many()?;
    let x = Axis::parse("--x", &args.x).map_err(usage)?;
    let y = Axis::parse("--y", &args.y).map_err(usage)?;
    let mu = resolve_mu(&preset, &p, args.mu.as_deref())?;
    let plan = MapPlan::new(p.clone(), mu, x, y).map_err(usage)?;
    let work = Work::steps(2.0 * plan.cells() as f64 * run_steps(&p));
    work.check("map", args.long.allow_long, true)?;
    let progress = Progress::start(&work);
    let t = Instant::now();
    let Some(((cells, cache), merged_ms)) =
        super::shard::map::run(&args.shard, &preset.name, &plan, || {
            compute_with(&plan, &progress)
        })?
    else {
        return Ok(());
    };
    let elapsed_ms = merged_ms.unwrap_or(t.elapsed().as_secs_f64() * 1e3);
    drop(progress);
    let report = MapReport::new(&preset.name, &plan, &cells, &cache, elapsed_ms);
    emit(&report)
}

/// μ as a spectrum takes it: `--mu`, else the preset's `[spectrum]` μ,
/// else Π_ω2/Π_ω1 of the parameters.
pub(super) fn resolve_mu(preset: &Preset, p: &Params, text: Option<&str>) -> Result<f64, CliError> {
    if let Some(text) = text {
        return mu_from_text(text).map_err(|e| CliError::Usage(format!("--mu: {e}")));
    }
    let spec = match &preset.spectrum {
        Some(t) => SpectrumSpec::from_table(t)
            .map_err(|e| CliError::Usage(format!("{}: {e}", preset.name)))?,
        None => SpectrumSpec::default(),
    };
    Ok(spec.mu.unwrap_or(p.mu()))
}

/// The map, row slice after row slice when a bar is shown (each cell
/// depends on its own parameters only, so the cells are the same either way).
fn compute_with(plan: &MapPlan, progress: &Progress) -> (Vec<MapCell>, MapCache) {
    let ys = plan.y.values();
    let row_steps = 2.0 * plan.x.len() as f64 * run_steps(&plan.base);
    let rows_per_slice = if progress.is_shown() {
        // About a hundred slices, each with enough cells to keep every thread busy.
        (ys.len() / 100)
            .max((8 * rayon::current_num_threads()).div_ceil(plan.x.len()))
            .max(1)
    } else {
        ys.len()
    };
    let mut cache = MapCache::default();
    let mut cells = Vec::with_capacity(plan.cells());
    for slice in ys.chunks(rows_per_slice) {
        cells.extend(compute_rows(plan, slice, &mut cache));
        progress.add(row_steps * slice.len() as f64);
    }
    (cells, cache)
}

/// One axis as reported.
#[derive(Debug, Serialize)]
pub(super) struct AxisReport {
    pub key: &'static str,
    pub symbol: &'static str,
    pub grid: String,
    start: f64,
    stop: f64,
    step: f64,
    pub points: usize,
}

impl AxisReport {
    pub fn of(a: &Axis) -> AxisReport {
        AxisReport {
            key: a.key,
            symbol: a.symbol(),
            grid: a.grid.to_string(),
            start: a.grid.start,
            stop: a.grid.stop,
            step: a.grid.step,
            points: a.len(),
        }
    }
}

/// A map in every format.
#[derive(Debug, Serialize)]
pub struct MapReport<'a> {
    /// The fixed parameters (the axis keys are set per cell) and μ of the
    /// cells unless `mu` or `omega2` is an axis.
    #[serde(flatten)]
    description: Description<'a>,
    x: AxisReport,
    y: AxisReport,
    layout: &'static str,
    cells: &'a [MapCell],
    baseline_runs: usize,
    baselines_from_pounding_runs: usize,
    incomplete_cells: usize,
    elapsed_ms: f64,
    #[serde(skip)]
    plan: &'a MapPlan,
}

impl<'a> MapReport<'a> {
    pub fn new(
        preset: &'a str,
        plan: &'a MapPlan,
        cells: &'a [MapCell],
        cache: &MapCache,
        elapsed_ms: f64,
    ) -> Self {
        MapReport {
            description: Description::spectral(preset, &plan.base, plan.mu),
            x: AxisReport::of(&plan.x),
            y: AxisReport::of(&plan.y),
            layout: "row-major: cells[j * x.points + i] is (x value i, y value j)",
            cells,
            baseline_runs: cache.baselines.runs,
            baselines_from_pounding_runs: cache.baselines.from_pounding,
            incomplete_cells: cells.iter().filter(|c| !c.completed).count(),
            elapsed_ms,
            plan,
        }
    }

    /// The cells row by row (one y value each).
    fn rows(&self) -> std::slice::Chunks<'a, MapCell> {
        self.cells.chunks(self.plan.x.len().max(1))
    }
}

/// A cell's mark in the table: `+` amplification, `−` suppression, `·` none, `?` stopped early.
fn mark(c: &MapCell) -> char {
    match (c.completed, c.region) {
        (false, _) => '?',
        (true, Region::Amplification) => '+',
        (true, Region::Suppression) => '−',
        (true, Region::None) => '·',
    }
}

/// The columns of a cell's results, after its parameter set and the eight
/// peaks ([`PEAK_COLUMNS`]).
const CELL_COLUMNS: &[Column<MapCell>] = &[
    ("left_amplification", |c| num(c.left_amplification)),
    ("right_amplification", |c| num(c.right_amplification)),
    ("region", |c| c.region.name().to_string()),
    ("impacts", |c| c.impacts.to_string()),
    ("max_force", |c| num(c.max_force)),
    ("min_force", |c| num(c.min_force)),
    ("min_gap", |c| optional(c.min_gap)),
    ("left_yielded", |c| c.left.yielded.to_string()),
    ("right_yielded", |c| c.right.yielded.to_string()),
    ("completed", |c| c.completed.to_string()),
];

impl Report for MapReport<'_> {
    /// Every row carries the cell's whole parameter set, μ and its results.
    fn csv_header(&self) -> Vec<&'static str> {
        let head = [
            &Provenance::CSV_COLUMNS[..],
            &param_columns(),
            &PEAK_COLUMNS,
        ]
        .concat();
        column_header(&head, CELL_COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let row = |c: &MapCell| {
            let mut row = self.description.provenance.csv_cells();
            row.extend(param_cells(&self.plan.at(c.x, c.y)));
            row.extend(c.peaks().map(num));
            row.extend(column_cells(CELL_COLUMNS, c));
            row
        };
        self.cells.iter().map(row).collect()
    }

    fn table(&self) -> String {
        let (p, x, y) = (&self.plan.base, &self.plan.x, &self.plan.y);
        let case = &self.description.case;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: left-structure regions over x = {} ({}, {} points) and y = {} ({}, {} points)",
            self.description.provenance.preset,
            x.symbol(),
            x.grid,
            x.len(),
            y.symbol(),
            y.grid,
            y.len()
        );
        // The fixed values people look for first; the axes' own keys vary.
        let fixed: Vec<String> = [
            ("mass_ratio", "Π_m", p.mass_ratio),
            ("gap", "Π_d", p.gap),
            ("mu", "μ", self.plan.mu),
        ]
        .iter()
        .filter(|(key, _, _)| {
            let varies = |k: &str| [x.key, y.key].contains(&k);
            let mu_varies = *key == "mu" && varies("omega2");
            !(varies(key) || mu_varies)
        })
        .map(|(_, symbol, v)| format!("{symbol} = {}", echo::g4(*v)))
        .collect();
        let _ = writeln!(
            s,
            "{} method, {} excitation, {} contact, {}; + amplification, − suppression \
             (Π_u1 beyond ±{} % of no pounding), · no influence{}",
            case.method,
            case.excitation,
            p.model,
            fixed.join(", "),
            num(REGION_THRESHOLD * 100.0),
            if self.incomplete_cells > 0 {
                ", ? a run stopped early"
            } else {
                ""
            }
        );
        let labels: Vec<String> = y.values().iter().map(|v| num(*v)).collect();
        let width = labels.iter().map(String::len).max().unwrap_or(1);
        s.push('\n');
        for (label, row) in labels.iter().zip(self.rows()).rev() {
            let marks: String = row.iter().map(mark).collect();
            let _ = writeln!(s, "{label:>width$} |{marks}");
        }
        let _ = writeln!(
            s,
            "{:>width$}  {} … {}  ({})",
            y.symbol(),
            num(x.grid.start),
            num(x.grid.stop),
            x.symbol()
        );
        let count = |r: Region| self.cells.iter().filter(|c| c.region == r).count();
        let _ = writeln!(
            s,
            "\ncells: {} amplification, {} suppression, {} no influence; {} with impacts",
            count(Region::Amplification),
            count(Region::Suppression),
            count(Region::None),
            self.cells.iter().filter(|c| c.impacts > 0).count()
        );
        let _ = writeln!(s, "\nregions along {} per row:", x.symbol());
        for (label, row) in labels.iter().zip(self.rows()) {
            let bands: Vec<String> = row_regions(row)
                .iter()
                .map(|r| match r.points {
                    1 => format!("{} {}", r.region.name(), num(r.from)),
                    _ => format!("{} {}–{}", r.region.name(), num(r.from), num(r.to)),
                })
                .collect();
            let _ = writeln!(s, "{} = {label}: {}", y.symbol(), bands.join(", "));
        }
        let _ = writeln!(
            s,
            "\n{} cells, {} baseline runs ({} baselines taken from impact-free pounding runs){}, {:.0} ms",
            self.cells.len(),
            self.baseline_runs,
            self.baselines_from_pounding_runs,
            if self.incomplete_cells > 0 {
                format!(", {} cells with a run stopped early", self.incomplete_cells)
            } else {
                String::new()
            },
            self.elapsed_ms
        );
        s
    }
}
