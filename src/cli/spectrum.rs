//! `pounding spectrum`: response spectra (SPEC §7): Π_u and Π_v of both
//! structures against Π_ω1, with and without pounding, one curve per family
//! value, as a table, JSON or CSV.

use std::fmt::Write as _;
use std::time::Instant;

use clap::Args;

use super::budget::{LongArg, Work, run_steps};
use super::description::{Description, Provenance};
use super::output::{Emit, FormatArg, num, printer};
use super::output::{PEAK_COLUMNS, param_cells, param_columns};
use super::params::ParamArgs;
use super::progress::Progress;
use super::{CliError, usage};
use crate::analysis::baseline::BaselineCache;
use crate::analysis::family::{Family, parse_mu};
use crate::analysis::grid::Grid;
use crate::analysis::spectrum::{RegionRange, SpectrumPoint, at_omega, region_ranges};
use crate::analysis::spectrum_spec::{SpectrumSpec, check_sweep};
use crate::analysis::sweep::{Curve, CurveSpec, curve_specs, sweep};
use crate::model::params::echo;
use crate::model::{Params, Preset};
use crate::output::report::{Report, TableColumn, aligned};
use serde::Serialize;

#[derive(Debug, Clone, Default, Args)]
pub struct SpectrumArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// The Π_ω1 grid START:STOP:STEP [default: the preset's, else 0.1:3.0:0.01].
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub omega1: Option<String>,
    /// Frequency ratio μ, Π_ω2 = μ Π_ω1 [default: the preset's, else omega2/omega1].
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub mu: Option<String>,
    /// One curve per value of a key, e.g. mass_ratio=0.1,0.5,0.9, gap=0.2,1.5,inf, mu=1.5,4,10.
    #[arg(long, value_name = "KEY=V1,V2,...", allow_hyphen_values = true)]
    pub family: Option<String>,
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub long: LongArg,
    #[command(flatten)]
    pub shard: super::shard::ShardArgs,
}

/// What to sweep, resolved from the preset's `[spectrum]` table and the flags (flags win).
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumPlan {
    pub preset: Preset,
    pub params: Params,
    pub grid: Grid,
    pub mu: f64,
    pub family: Option<Family>,
}

impl SpectrumPlan {
    pub fn resolve(
        params: &ParamArgs,
        omega1: Option<&str>,
        mu: Option<&str>,
        family: Option<&str>,
    ) -> Result<SpectrumPlan, CliError> {
        let (preset, p) = params.resolve_for_many()?;
        let spec = match &preset.spectrum {
            Some(t) => {
                SpectrumSpec::from_table(t).map_err(|e| usage(format!("{}: {e}", preset.name)))?
            }
            None => SpectrumSpec::default(),
        };
        let grid = match omega1 {
            Some(text) => text.parse().map_err(usage)?,
            None => spec.grid.unwrap_or_default(),
        };
        let mu = match (mu, spec.mu) {
            (Some(text), _) => parse_mu(text).ok_or_else(|| {
                usage(format!(
                    "--mu {}: must be a finite number > 0",
                    echo::text(text.trim())
                ))
            })?,
            (None, Some(m)) => m,
            (None, None) => parse_mu(&p.mu().to_string()).ok_or_else(|| {
                usage(format!(
                    "omega2/omega1 = {}/{}: the frequency ratio must be finite and > 0; give --mu",
                    p.omega2, p.omega1
                ))
            })?,
        };
        let family = match (family, &spec.family) {
            (Some(text), _) => Some(Family::parse(text, &p).map_err(usage)?),
            (None, Some((key, values))) => Some(
                Family::new(&preset.origin("spectrum.family"), key, values, &p).map_err(usage)?,
            ),
            (None, None) => None,
        };
        check_sweep(&p, &grid, mu, family.as_ref()).map_err(usage)?;
        Ok(SpectrumPlan {
            preset,
            params: p,
            grid,
            mu,
            family,
        })
    }

    /// The curves to compute.
    pub fn specs(&self) -> Result<Vec<CurveSpec>, CliError> {
        curve_specs(&self.params, self.mu, self.family.as_ref()).map_err(usage)
    }

    /// The estimated work: a pounding run and a baseline run per point of every curve.
    pub fn work(&self) -> Result<Work, CliError> {
        let points = self.grid.len() as f64;
        let steps = self
            .specs()?
            .iter()
            .map(|s| 2.0 * points * run_steps(&s.params))
            .sum();
        Ok(Work::steps(steps))
    }

    /// Computes every curve with a fresh baseline cache; returns the curves,
    /// the cache (for its counters) and the wall time in ms.
    pub fn compute(&self) -> Result<(Vec<Curve>, BaselineCache, f64), CliError> {
        self.compute_with(&Progress::start(&Work::default()))
    }

    /// [`SpectrumPlan::compute`], telling `progress` as it goes. With a bar
    /// shown, the grid is swept in slices; every point depends on its own
    /// Π_ω1 only, so the curves are the same either way.
    pub fn compute_with(
        &self,
        progress: &Progress,
    ) -> Result<(Vec<Curve>, BaselineCache, f64), CliError> {
        let specs = self.specs()?;
        let grid = self.grid.values();
        let mut cache = BaselineCache::new();
        let t = Instant::now();
        let slice = if progress.is_shown() {
            (grid.len() / 100).max(4 * rayon::current_num_threads())
        } else {
            grid.len().max(1)
        };
        let steps_per_point: f64 = specs.iter().map(|s| 2.0 * run_steps(&s.params)).sum();
        let mut curves: Vec<Curve> = Vec::new();
        for part in grid.chunks(slice) {
            let swept = sweep(&specs, part, &mut cache);
            if curves.is_empty() {
                curves = swept;
            } else {
                for (curve, more) in curves.iter_mut().zip(swept) {
                    curve.points.extend(more.points);
                }
            }
            progress.add(steps_per_point * part.len() as f64);
        }
        if curves.is_empty() {
            curves = sweep(&specs, &grid, &mut cache);
        }
        Ok((curves, cache, t.elapsed().as_secs_f64() * 1e3))
    }
}

pub fn execute(args: &SpectrumArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The spectrum of `args`, its typed report handed to `emit`.
pub fn report_with(
    args: &SpectrumArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let plan = SpectrumPlan::resolve(
        &args.params,
        args.omega1.as_deref(),
        args.mu.as_deref(),
        args.family.as_deref(),
    )?;
    let work = plan.work()?;
    work.check("spectrum", args.long.allow_long, true)?;
    let Some((curves, cache, elapsed_ms)) = super::shard::spectrum::run(
        &args.shard,
        &plan.preset,
        &plan.specs()?,
        &plan.grid,
        || plan.compute_with(&Progress::start(&work)),
    )?
    else {
        return Ok(());
    };
    let report = SpectrumReport::new(&plan, &curves, &cache, elapsed_ms);
    emit(&report)
}

/// The Π_ω1 grid as reported.
#[derive(Debug, Serialize)]
struct GridReport {
    start: f64,
    stop: f64,
    step: f64,
    points: usize,
}

/// One curve: its family member (`{}` without a family), μ, its points and
/// the left structure's regions along it.
#[derive(Debug, Serialize)]
struct CurveReport<'a> {
    family: serde_json::Map<String, serde_json::Value>,
    mu: f64,
    points: &'a [SpectrumPoint],
    regions: Vec<RegionRange>,
    #[serde(skip)]
    curve: &'a Curve,
}

/// A spectrum in every format. All quantities are Π-groups (dimensionless).
#[derive(Debug, Serialize)]
pub struct SpectrumReport<'a> {
    /// The fixed parameters (Π_ω1, Π_ω2 and the family key are set per point).
    #[serde(flatten)]
    description: Description<'a>,
    omega1_grid: String,
    grid: GridReport,
    curves: Vec<CurveReport<'a>>,
    baseline_runs: usize,
    baselines_from_pounding_runs: usize,
    elapsed_ms: f64,
}

impl<'a> SpectrumReport<'a> {
    pub fn new(
        plan: &'a SpectrumPlan,
        curves: &'a [Curve],
        cache: &BaselineCache,
        elapsed_ms: f64,
    ) -> Self {
        SpectrumReport {
            description: Description::spectral(&plan.preset.name, &plan.params, plan.mu),
            omega1_grid: plan.grid.to_string(),
            grid: GridReport {
                start: plan.grid.start,
                stop: plan.grid.stop,
                step: plan.grid.step,
                points: plan.grid.len(),
            },
            curves: curves
                .iter()
                .map(|c| {
                    let mut family = serde_json::Map::new();
                    if let Some(m) = &c.spec.member {
                        family.insert(m.key.clone(), m.json_value());
                    }
                    CurveReport {
                        family,
                        mu: c.spec.mu,
                        points: &c.points,
                        regions: region_ranges(&c.points),
                        curve: c,
                    }
                })
                .collect(),
            baseline_runs: cache.runs,
            baselines_from_pounding_runs: cache.from_pounding,
            elapsed_ms,
        }
    }
}

/// The table's columns of a point: Π_ω1, each peak with pounding beside
/// the same without (free), the impacts and the left structure's region.
const POINT_TABLE: &[TableColumn<SpectrumPoint>] = &[
    ("Π_ω1", 7, |pt| format!("{:.3}", pt.omega1)),
    ("Π_u1", 9, |pt| format!("{:.4}", pt.left.peak_displacement)),
    ("free", 9, |pt| {
        format!("{:.4}", pt.free_left.peak_displacement)
    }),
    ("Π_v1", 9, |pt| format!("{:.4}", pt.left.peak_velocity)),
    ("free", 9, |pt| format!("{:.4}", pt.free_left.peak_velocity)),
    ("Π_u2", 9, |pt| {
        format!("{:.4}", pt.right.peak_displacement)
    }),
    ("free", 9, |pt| {
        format!("{:.4}", pt.free_right.peak_displacement)
    }),
    ("Π_v2", 9, |pt| format!("{:.4}", pt.right.peak_velocity)),
    ("free", 9, |pt| {
        format!("{:.4}", pt.free_right.peak_velocity)
    }),
    ("impacts", 7, |pt| pt.impacts.to_string()),
    (" region", 0, |pt| format!(" {}", pt.region.name())),
];

impl Report for SpectrumReport<'_> {
    /// Every row is self-contained: the curve's family member (`key=value`,
    /// empty without a family), the Π_ω1 grid, μ and the point's whole
    /// parameter set (model, excitation and method among them), then its
    /// dimensionless results.
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = Provenance::CSV_COLUMNS.to_vec();
        h.extend(["family", "omega1_grid"]);
        h.extend(param_columns());
        h.extend(PEAK_COLUMNS);
        h.extend(["impacts", "region", "min_gap_no_pounding"]);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for c in &self.curves {
            let spec = &c.curve.spec;
            let family = spec
                .member
                .as_ref()
                .map_or(String::new(), |m| format!("{}={}", m.key, m.text.trim()));
            for pt in c.points {
                let mut row = self.description.provenance.csv_cells();
                row.extend([family.clone(), self.omega1_grid.clone()]);
                row.extend(param_cells(&at_omega(&spec.params, pt.omega1, spec.mu)));
                row.extend(pt.peaks().map(num));
                row.push(pt.impacts.to_string());
                row.push(pt.region.name().to_string());
                row.push(pt.min_gap_no_pounding.map(num).unwrap_or_default());
                rows.push(row);
            }
        }
        rows
    }

    fn table(&self) -> String {
        let (head, case) = (&self.description.provenance, &self.description.case);
        let p = case.params;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: spectrum over Π_ω1 = {} ({} points), {} excitation, {} contact, {} method, Π_m = {}, Π_d = {}",
            head.preset,
            self.omega1_grid,
            self.grid.points,
            case.excitation,
            case.model,
            case.method,
            num(p.mass_ratio),
            num(p.gap)
        );
        for c in &self.curves {
            let label = c
                .curve
                .spec
                .member
                .as_ref()
                .map_or_else(String::new, |m| format!("{m}, "));
            let _ = writeln!(s, "\n{label}μ = {}   (free = no pounding)", num(c.mu));
            s.push_str(&aligned(POINT_TABLE, c.points));
            let ranges: Vec<String> = c
                .regions
                .iter()
                .map(|r| format!("{} {}–{}", r.region.name(), num(r.from), num(r.to)))
                .collect();
            let _ = writeln!(s, "left-structure regions: {}", ranges.join(", "));
        }
        let _ = writeln!(
            s,
            "\n{} baseline runs ({} baselines taken from impact-free pounding runs), {:.0} ms",
            self.baseline_runs, self.baselines_from_pounding_runs, self.elapsed_ms
        );
        s
    }
}
