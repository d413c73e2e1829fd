//! `pounding gap`: the smallest gap that prevents pounding (SPEC §11), exact
//! from one no-pounding run of the exact method, beside the code rules ABS,
//! SRSS and DDC and their ratio to it; with `--x KEY=START:STOP:STEP`, the
//! same along one parameter (a gap spectrum over Π_ω1, or any Π key or μ).

use std::fmt::Write as _;
use std::time::Instant;

use clap::Args;
use serde::Serialize;

use super::budget::{LongArg, Work, run_steps};
use super::description::{DIMENSIONLESS, Provenance, RecordNumbers};
use super::map::{AxisReport, resolve_mu};
use super::output::{Emit, FormatArg, num, optional, printer};
use super::output::{param_cells, param_columns};
use super::params::ParamArgs;
use super::progress::Progress;
use super::{CliError, usage};
use crate::analysis::gap::{MinimumGap, free_params, minimum_gap, minimum_gaps};
use crate::analysis::map::{Axis, line};
use crate::model::{Method, Params};
use crate::output::report::{Column, Report, column_cells, column_header};

#[derive(Debug, Clone, Default, Args)]
pub struct GapArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// Sweep one parameter, e.g. omega1=0.1:3.0:0.01 (Π_ω2 follows at the preset's μ) or mu=1:10:0.5.
    #[arg(long, value_name = "KEY=START:STOP:STEP", allow_hyphen_values = true)]
    pub x: Option<String>,
    /// Frequency ratio μ, Π_ω2 = μ Π_ω1 on an omega1 axis [default: the preset's, else omega2/omega1].
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub mu: Option<String>,
    /// A suite of records instead of one set: each record's minimum gap, the
    /// gap at each --probability and the code rules (SPEC §12).
    #[command(flatten)]
    pub records: super::suite::SuiteOptions,
    /// With --suite: probabilities of not pounding, each in (0, 1) [default: 0.5,0.84,0.9].
    #[arg(long, value_name = "P,…", allow_hyphen_values = true)]
    pub probability: Option<String>,
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub long: LongArg,
    #[command(flatten)]
    pub shard: super::shard::ShardArgs,
    #[command(flatten)]
    pub row: super::buildings::BuildingsArgs,
    /// With --buildings and --suite: run the same study on each of these
    /// rows too (a retrofit, say), each with the first row's buildings by
    /// name, and report them side by side.
    #[arg(long, value_name = "NAME|PATH", num_args = 1.., value_delimiter = ',')]
    pub compare: Vec<String>,
}

pub fn execute(args: &GapArgs) -> Result<(), CliError> {
    report_with(args, printer(args.output.format))
}

/// The minimum gap of `args` (of a suite's records with `--suite`), its
/// typed report handed to `emit`.
pub fn report_with(
    args: &GapArgs,
    emit: impl FnOnce(&dyn Emit) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let others = [
        ("--probability", args.probability.is_some()),
        ("--compare", !args.compare.is_empty()),
    ];
    if args.row.buildings.is_some() {
        let Some(mut suite_args) =
            args.records
                .request(&args.params, args.output, args.long, &others)?
        else {
            return super::buildings::gap(&args.row, &args.params, args.long.allow_long, emit);
        };
        if let Some((flag, _)) = [
            ("--x", args.x.is_some()),
            ("--mu", args.mu.is_some()),
            ("--scale", args.row.scale.is_some()),
            ("--tail", args.row.tail.is_some()),
            ("--amplitude", args.row.amplitude.is_some()),
            (
                "--period",
                args.row.period.is_some() && args.records.design.target.is_none(),
            ),
        ]
        .into_iter()
        .find(|(_, given)| *given)
        {
            return Err(usage(format!(
                "{flag}: not with --buildings and --suite (each record is scaled by --level \
                 or its list, and runs four fundamental periods past its end); drop {flag}"
            )));
        }
        suite_args.buildings = args.row.buildings.clone();
        suite_args.compare = args.compare.clone();
        suite_args.shard = args.shard.clone();
        suite_args.period = args.row.period.map(|t| t.to_string());
        let suite_args = suite_args.at_design_level()?;
        return super::gap_suite::report_with(&suite_args, args.probability.as_deref(), emit);
    }
    if let Some(suite_args) = args
        .records
        .request(&args.params, args.output, args.long, &others)?
    {
        if args.x.is_some() {
            return Err(CliError::Usage(
                "--x: a suite's separation is for the preset's buildings; drop --x or --suite"
                    .into(),
            ));
        }
        let suite_args = super::suite::SuiteArgs {
            shard: args.shard.clone(),
            compare: args.compare.clone(),
            period: args.row.period.map(|t| t.to_string()),
            ..suite_args
        }
        .at_design_level()?;
        return super::gap_suite::report_with(&suite_args, args.probability.as_deref(), emit);
    }
    let (preset, mut p) = args.params.resolve()?;
    // Π_d,min is taken on the exact method's own series, whatever --method says.
    p.method = free_params(&p).method;
    let axis = args
        .x
        .as_deref()
        .map(|t| Axis::parse("--x", t))
        .transpose()
        .map_err(usage)?;
    let mu = match &axis {
        Some(_) => Some(resolve_mu(&preset, &p, args.mu.as_deref())?),
        None => None,
    };
    let points: Vec<(f64, Params)> = match (&axis, mu) {
        (Some(a), Some(mu)) => line(&p, mu, a).map_err(usage)?,
        _ => vec![(f64::NAN, p.clone())],
    };
    let work = Work::steps(points.len() as f64 * run_steps(&p));
    work.check("gap", args.long.allow_long, true)?;
    let progress = Progress::start(&work);
    let t = Instant::now();
    let whole = || match &axis {
        Some(_) => minimum_gaps(&points.iter().map(|(_, q)| q.clone()).collect::<Vec<_>>()),
        None => vec![minimum_gap(&p)],
    };
    let Some((gaps, merged_ms)) =
        super::shard::gap::run(&args.shard, &preset.name, &points, axis.is_some(), whole)?
    else {
        return Ok(());
    };
    let elapsed_ms = merged_ms.unwrap_or(t.elapsed().as_secs_f64() * 1e3);
    drop(progress);
    let mut report = GapReport::new(&preset.name, &p, axis.as_ref(), &points, &gaps, elapsed_ms);
    report.mu = mu;
    emit(&report)?;
    match gaps.iter().find(|g| !g.completed) {
        Some(g) => Err(CliError::Failed(format!(
            "the no-pounding run at omega1 = {}, omega2 = {} stopped before τ_end; \
             its minimum gap covers only the part that was run",
            num(g.omega1),
            num(g.omega2)
        ))),
        None => Ok(()),
    }
}

/// One point: the axis value (absent without `--x`), the minimum gap and
/// each rule's ratio to it.
#[derive(Debug, Serialize)]
struct GapPoint {
    #[serde(skip_serializing_if = "Option::is_none")]
    x: Option<f64>,
    #[serde(flatten)]
    gap: MinimumGap,
    /// ABS, SRSS, DDC over the exact gap (above 1: conservative); null where it is 0.
    ratio_absolute_sum: Option<f64>,
    ratio_srss: Option<f64>,
    ratio_double_difference: Option<f64>,
    /// Whether the parameter set's own Π_d is below the exact minimum (it pounds).
    pounds_at_set_gap: bool,
    #[serde(skip)]
    params: Params,
}

/// The minimum gaps, in every format.
#[derive(Debug, Serialize)]
pub struct GapReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    /// The parameters (the axis key is set per point); their gap is the set's own.
    params: &'a Params,
    /// The no-pounding runs are always made by the exact method.
    method: Method,
    /// A record's samples, DT, scale, a_p and ω_p, as numbers.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    record: Option<RecordNumbers>,
    #[serde(skip_serializing_if = "Option::is_none")]
    x: Option<AxisReport>,
    /// μ of a sweep: Π_ω2 = μ Π_ω1 where Π_ω1 is the axis.
    #[serde(skip_serializing_if = "Option::is_none")]
    mu: Option<f64>,
    points: Vec<GapPoint>,
    elapsed_ms: f64,
}

impl<'a> GapReport<'a> {
    fn new(
        preset: &'a str,
        p: &'a Params,
        axis: Option<&Axis>,
        points: &[(f64, Params)],
        gaps: &[MinimumGap],
        elapsed_ms: f64,
    ) -> Self {
        let points = points
            .iter()
            .zip(gaps)
            .map(|((x, q), g)| {
                let [abs, srss, ddc] = g.ratios();
                GapPoint {
                    x: axis.map(|_| *x),
                    gap: *g,
                    ratio_absolute_sum: abs,
                    ratio_srss: srss,
                    ratio_double_difference: ddc,
                    pounds_at_set_gap: q.gap < g.exact,
                    params: q.clone(),
                }
            })
            .collect();
        GapReport {
            provenance: Provenance::new(preset, DIMENSIONLESS),
            params: p,
            method: free_params(p).method,
            record: RecordNumbers::of(p),
            x: axis.map(AxisReport::of),
            mu: None,
            points,
            elapsed_ms,
        }
    }

    fn table_one(&self, s: &mut String, pt: &GapPoint) {
        let g = &pt.gap;
        let p = self.params;
        let _ = writeln!(
            s,
            "{}: the gap that prevents pounding (SPEC §11), from one no-pounding run \
             ({} method, {} cycles)",
            self.provenance.preset, self.method, p.cycles
        );
        let _ = writeln!(
            s,
            "Π_ω1 = {}, Π_ω2 = {}: Π_u1 = {:.4}, Π_u2 = {:.4} without pounding\n",
            num(g.omega1),
            num(g.omega2),
            g.free_left.peak_displacement,
            g.free_right.peak_displacement
        );
        let _ = writeln!(s, "{:<34} {:>8} {:>9}", "rule", "Π_d", "/ exact");
        let _ = writeln!(
            s,
            "{:<34} {:>8.4} {:>9}",
            "exact: max over τ of x1 − x2", g.exact, "1"
        );
        let labels = [
            "ABS: Π_u1 + Π_u2".to_string(),
            "SRSS: √(Π_u1² + Π_u2²)".to_string(),
            format!("DDC: ρ = {:.4}", g.rules.correlation),
        ];
        for ((label, (_, v)), ratio) in labels.iter().zip(g.rules.named()).zip(g.ratios()) {
            let verdict = match ratio {
                Some(r) if r >= 1.0 => "  conservative",
                Some(_) => "  too small: the structures would pound",
                None => "",
            };
            let ratio = ratio.map_or("-".to_string(), |r| format!("{r:.4}"));
            let _ = writeln!(s, "{label:<34} {v:>8.4} {ratio:>9}{verdict}");
        }
        let _ = writeln!(
            s,
            "\nthe set's own gap Π_d = {} {}",
            num(p.gap),
            if pt.pounds_at_set_gap {
                "is below the minimum: they pound"
            } else {
                "clears the minimum: no pounding"
            }
        );
    }

    fn table_sweep(&self, s: &mut String, axis: &AxisReport) {
        let _ = writeln!(
            s,
            "{}: the gap that prevents pounding over {} = {} ({} points; exact method, \
             no-pounding runs){}",
            self.provenance.preset,
            axis.symbol,
            axis.grid,
            axis.points,
            match (axis.key, self.mu) {
                ("omega1", Some(mu)) => format!(", Π_ω2 = μ Π_ω1 with μ = {}", num(mu)),
                _ => String::new(),
            }
        );
        let _ = writeln!(
            s,
            "{:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>7} {:>7} {:>7}",
            axis.symbol,
            "Π_u1",
            "Π_u2",
            "exact",
            "ABS",
            "SRSS",
            "DDC",
            "ABS/ex",
            "SRSS/ex",
            "DDC/ex"
        );
        for pt in &self.points {
            let g = &pt.gap;
            let ratios = g
                .ratios()
                .map(|r| r.map_or("-".to_string(), |r| format!("{r:.3}")));
            let _ = writeln!(
                s,
                "{:>9} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>7} {:>7} {:>7}",
                num(pt.x.unwrap_or(f64::NAN)),
                g.free_left.peak_displacement,
                g.free_right.peak_displacement,
                g.exact,
                g.rules.absolute_sum,
                g.rules.srss,
                g.rules.double_difference,
                ratios[0],
                ratios[1],
                ratios[2]
            );
        }
        for (k, name) in ["ABS", "SRSS", "DDC"].iter().enumerate() {
            let short = self
                .points
                .iter()
                .filter(|pt| pt.gap.ratios()[k].is_some_and(|r| r < 1.0))
                .count();
            let _ = writeln!(
                s,
                "{name}: below the exact gap (would pound) at {short} of {} points",
                self.points.len()
            );
        }
    }
}

impl Report for GapReport<'_> {
    fn csv_header(&self) -> Vec<&'static str> {
        let head = [&Provenance::CSV_COLUMNS[..], &param_columns()].concat();
        column_header(&head, POINT_COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let row = |pt: &GapPoint| {
            let mut row = self.provenance.csv_cells();
            row.extend(param_cells(&pt.params));
            row.extend(column_cells(POINT_COLUMNS, pt));
            row
        };
        self.points.iter().map(row).collect()
    }

    fn table(&self) -> String {
        let mut s = String::new();
        match &self.x {
            Some(axis) => self.table_sweep(&mut s, axis),
            None => {
                if let Some(pt) = self.points.first() {
                    self.table_one(&mut s, pt);
                }
            }
        }
        s
    }
}

/// The CSV columns of a point, after its parameter set.
const POINT_COLUMNS: &[Column<GapPoint>] = &[
    ("free_left_peak_displacement", |pt| {
        num(pt.gap.free_left.peak_displacement)
    }),
    ("free_right_peak_displacement", |pt| {
        num(pt.gap.free_right.peak_displacement)
    }),
    ("min_gap", |pt| num(pt.gap.exact)),
    ("absolute_sum", |pt| num(pt.gap.rules.absolute_sum)),
    ("srss", |pt| num(pt.gap.rules.srss)),
    ("double_difference", |pt| {
        num(pt.gap.rules.double_difference)
    }),
    ("correlation", |pt| num(pt.gap.rules.correlation)),
    ("ratio_absolute_sum", |pt| optional(pt.ratio_absolute_sum)),
    ("ratio_srss", |pt| optional(pt.ratio_srss)),
    ("ratio_double_difference", |pt| {
        optional(pt.ratio_double_difference)
    }),
    ("pounds_at_set_gap", |pt| pt.pounds_at_set_gap.to_string()),
    ("completed", |pt| pt.gap.completed.to_string()),
];
