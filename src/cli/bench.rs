//! `pounding bench`: the work-precision table (run time against
//! error for each method, see [`crate::accuracy::work_precision`]).

use std::fmt::Write as _;

use clap::Args;

use super::CliError;
use super::output::{Format, FormatArg, num, optional, render};
use super::params::user_preset_dir;
use crate::accuracy::figure_spectra::SpectraAccuracy;
use crate::accuracy::plot::{Series, render as plot_render};
use crate::accuracy::record_speed::RecordRow;
use crate::accuracy::work_precision::{Row, TRUTH_TOLERANCE, meets_target, rows};
use crate::model::{ContactModel, Preset};
use crate::output::report::{Column, Report, TableColumn, aligned, column_header, column_rows};
use serde::Serialize;

#[derive(Debug, Clone, Default, Args)]
pub struct BenchArgs {
    /// Preset to measure (repeatable) [default: set1 and set2].
    #[arg(long, value_name = "NAME|PATH")]
    pub preset: Vec<String>,
    /// Contact law (repeatable) [default: the paper's two, kelvin and improved-kelvin;
    /// with --buildings, the row's own]. Any of kelvin, improved-kelvin, hertz,
    /// hertzdamp, jankowski, hunt-crossley.
    #[arg(long, value_parser = ["kelvin", "improved-kelvin", "hertz", "hertzdamp", "jankowski", "hunt-crossley"])]
    pub model: Vec<String>,
    #[command(flatten)]
    pub output: FormatArg,
    /// Also draw error against time on log–log axes (Braille), one plot per preset and model.
    #[arg(long)]
    pub plot: bool,
    /// Instead of the table: every point of the ten curves of Figures 7–10
    /// (5,820 runs) with each method against the reference, and the wall time
    /// of the ten curves as `pounding spectrum` computes them. Takes a minute.
    #[arg(long)]
    pub spectra: bool,
    /// Only this method's rows (newmark: its three schemes; exact) [default: every method].
    #[arg(long, value_parser = ["newmark", "exact"])]
    pub method: Option<String>,
    /// Instead of the table: the exact method under this record against the
    /// plain Nigam–Jennings pass over its samples (the floor), side by side,
    /// for the first preset [default: set1] elastic apart, inelastic apart and
    /// pounding. `record:PATH`, or `synthetic:N` for one simulated record of
    /// N samples at DT = 0.005 s (seed 1, as `records synth`).
    #[arg(long, value_name = "record:PATH|synthetic:N")]
    pub excitation: Option<String>,
    /// A row of buildings (SPEC §13) instead of the pair: its work-precision rows.
    #[command(flatten)]
    pub row: super::buildings::BuildingsArgs,
    #[command(flatten)]
    pub long: super::budget::LongArg,
}

pub fn execute(args: &BenchArgs) -> Result<(), CliError> {
    if args.row.buildings.is_some() {
        let model = args.model.first().map(String::as_str);
        let long = args.long.allow_long;
        return super::buildings::bench(
            &args.row,
            args.excitation.as_deref(),
            model,
            &args.output,
            long,
        );
    }
    if args.spectra {
        return spectra(args);
    }
    if let Some(excitation) = &args.excitation {
        return record_speed(args, excitation);
    }
    let names = if args.preset.is_empty() {
        vec!["set1".to_string(), "set2".to_string()]
    } else {
        args.preset.clone()
    };
    let models: Vec<ContactModel> = if args.model.is_empty() {
        ContactModel::PAPER.to_vec()
    } else {
        args.model.iter().filter_map(|m| m.parse().ok()).collect()
    };
    let dirs: Vec<_> = user_preset_dir(None).into_iter().collect();
    let presets = names
        .iter()
        .map(|n| Preset::find(n, &dirs))
        .collect::<Result<Vec<_>, _>>()?;
    let mut groups = Vec::new();
    for preset in &presets {
        preset.params.validate()?;
        for &model in &models {
            let p = crate::model::Params {
                model,
                ..preset.params.clone()
            };
            groups.push(rows(&preset.name, &p));
        }
    }
    if let Some(m) = &args.method {
        // The reference rows stay: they are the error axis.
        let keep = |r: &Row| r.method == "reference" || r.method.starts_with(m.as_str());
        for g in &mut groups {
            g.retain(|r| keep(r));
        }
    }
    let all: Vec<&Row> = groups.iter().flatten().collect();
    let report = BenchReport {
        version: env!("CARGO_PKG_VERSION"),
        units: "ms_per_run in milliseconds of wall time; dt, tolerance, max_rel_error and order dimensionless",
        truth_tolerance: TRUTH_TOLERANCE,
        rows: all,
    };
    let mut text = render(&report, args.output.format)?;
    if args.plot && args.output.format == Format::Table {
        for group in &groups {
            text += &plot(group);
        }
    }
    super::output::print(&text)?;
    Ok(())
}

/// The accuracy and the wall time of the paper's ten spectrum curves, per method.
fn spectra(args: &BenchArgs) -> Result<(), CliError> {
    use crate::accuracy::figure_spectra::{REFERENCE_TOLERANCE, measure, time_all_curves};
    use crate::model::Method;
    let methods: Vec<Method> = match &args.method {
        Some(m) => vec![m.parse().map_err(CliError::Usage)?],
        None => Method::ALL.to_vec(),
    };
    let mut rows = Vec::new();
    for method in methods {
        // Median of three timings; the accuracy pass once.
        let mut times: Vec<f64> = (0..3).map(|_| time_all_curves(method)).collect();
        times.sort_by(f64::total_cmp);
        let accuracy = measure(method);
        rows.push((accuracy, times[1]));
    }
    let report = SpectraReport {
        version: env!("CARGO_PKG_VERSION"),
        units: "wall_s_ten_curves in seconds (median of three); errors dimensionless",
        reference_tolerance: REFERENCE_TOLERANCE,
        methods: rows
            .into_iter()
            .map(|(accuracy, wall_s_ten_curves)| SpectraRow {
                accuracy,
                wall_s_ten_curves,
            })
            .collect(),
    };
    super::output::print(&render(&report, args.output.format)?)
}

/// `bench --excitation`: the exact method under a record against the floor.
fn record_speed(args: &BenchArgs, spec: &str) -> Result<(), CliError> {
    use crate::accuracy::record_speed::rows;
    use crate::model::{Excitation, RecordMotion};
    let excitation = match spec.trim().strip_prefix("synthetic:") {
        Some(n) => {
            let record = super::records::synthetic_record(spec, n)?;
            Excitation::Record(RecordMotion::new(crate::model::record::intern(record)))
        }
        None => Excitation::parse(spec)
            .map_err(|e| CliError::Usage(format!("--excitation {spec}: {e}")))?,
    };
    let dirs: Vec<_> = user_preset_dir(None).into_iter().collect();
    let name = args.preset.first().map_or("set1", String::as_str);
    let preset = Preset::find(name, &dirs)?;
    let p = crate::model::Params {
        excitation,
        ..preset.params
    };
    p.validate()?;
    let rows = rows(&p).ok_or_else(|| {
        CliError::Usage(format!(
            "--excitation {spec}: not a record (record:PATH or synthetic:N)"
        ))
    })?;
    let report = RecordSpeedReport {
        version: env!("CARGO_PKG_VERSION"),
        preset: preset.name.clone(),
        excitation: spec.to_string(),
        units: "ms of wall time per run (median after a warm-up); ns per sample interval (record and free tail); ratio = ms / floor_ms",
        rows,
    };
    super::output::print(&render(&report, args.output.format)?)
}

/// `bench --excitation` in every format.
#[derive(Debug, Serialize)]
struct RecordSpeedReport {
    version: &'static str,
    preset: String,
    excitation: String,
    units: &'static str,
    rows: Vec<RecordRow>,
}

impl Report for RecordSpeedReport {
    fn table(&self) -> String {
        let s = format!(
            "{} under {} ({} intervals): exact method against the Nigam–Jennings floor ({} ms)\n",
            self.preset,
            self.excitation,
            self.rows.first().map_or(0, |r| r.intervals),
            self.rows
                .first()
                .map_or(String::new(), |r| format!("{:.4}", r.floor_ms)),
        );
        s + &aligned(RECORD_TABLE, &self.rows)
    }

    fn csv_header(&self) -> Vec<&'static str> {
        column_header(&["preset", "excitation"], RECORD_COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let head = [self.preset.clone(), self.excitation.clone()];
        column_rows(&head, RECORD_COLUMNS, &self.rows)
    }
}

/// The table's columns of a case of `bench --excitation`.
const RECORD_TABLE: &[TableColumn<RecordRow>] = &[
    ("case", -24, |r| r.case.to_string()),
    ("run", -6, |r| r.run.to_string()),
    ("series ms", 10, |r| format!("{:.4}", r.series_ms)),
    ("ms", 10, |r| format!("{:.4}", r.ms)),
    ("ns/intvl", 9, |r| format!("{:.1}", r.ns_per_interval)),
    ("×floor", 7, |r| format!("{:.2}", r.ratio)),
    ("impacts", 8, |r| r.impacts.to_string()),
    ("Δpeaks", 11, |r| format!("{:.1e}", r.peak_difference)),
];

/// The CSV columns of a case of `bench --excitation`, after the preset and
/// the excitation.
const RECORD_COLUMNS: &[Column<RecordRow>] = &[
    ("case", |r| r.case.to_string()),
    ("run", |r| r.run.to_string()),
    ("intervals", |r| r.intervals.to_string()),
    ("series_ms", |r| num(r.series_ms)),
    ("ms", |r| num(r.ms)),
    ("ns_per_interval", |r| num(r.ns_per_interval)),
    ("floor_ms", |r| num(r.floor_ms)),
    ("ratio", |r| num(r.ratio)),
    ("impacts", |r| r.impacts.to_string()),
    ("peak_difference", |r| num(r.peak_difference)),
];

/// The work-precision table in every format.
#[derive(Debug, Serialize)]
struct BenchReport<'a> {
    version: &'static str,
    units: &'static str,
    /// Tolerance of the DOPRI5 reference every error is measured against.
    truth_tolerance: f64,
    rows: Vec<&'a Row>,
}

impl Report for BenchReport<'_> {
    fn table(&self) -> String {
        table(&self.rows)
    }

    fn csv_header(&self) -> Vec<&'static str> {
        column_header(&[], BENCH_COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        column_rows(&[], BENCH_COLUMNS, self.rows.iter().copied())
    }
}

/// The CSV columns of a work-precision row.
const BENCH_COLUMNS: &[Column<Row>] = &[
    ("preset", |r| r.preset.clone()),
    ("model", |r| r.model.clone()),
    ("method", |r| r.method.to_string()),
    ("dt", |r| optional(r.dt)),
    ("tolerance", |r| optional(r.tolerance)),
    ("ms_per_run", |r| num(r.ms_per_run)),
    ("max_rel_error", |r| num(r.max_rel_error)),
    ("order", |r| optional(r.order)),
    ("truth_tolerance", |_| num(TRUTH_TOLERANCE)),
];

/// One method's accuracy over the ten curves, and their wall time.
#[derive(Debug, Serialize)]
struct SpectraRow {
    accuracy: SpectraAccuracy,
    wall_s_ten_curves: f64,
}

/// `bench --spectra` in every format.
#[derive(Debug, Serialize)]
struct SpectraReport {
    version: &'static str,
    units: &'static str,
    reference_tolerance: f64,
    methods: Vec<SpectraRow>,
}

impl Report for SpectraReport {
    fn table(&self) -> String {
        let mut s = format!(
            "Figures 7–10, ten curves, with and without pounding, against the reference at tol {:e}\n\
             {:<8} {:>6} {:>13} {:>9} {:>10} {:>12}  worst point\n",
            self.reference_tolerance,
            "method",
            "runs",
            "max rel err",
            "> 1e-7",
            "count diff",
            "wall s (10)"
        );
        for SpectraRow {
            accuracy: a,
            wall_s_ten_curves: t,
        } in &self.methods
        {
            let _ = writeln!(
                s,
                "{:<8} {:>6} {:>13.3e} {:>9} {:>10} {:>12.3}  {}",
                a.method,
                a.runs,
                a.max_rel_error,
                a.above_1e_7,
                a.impact_count_mismatches,
                t,
                a.worst
            );
        }
        s
    }

    fn csv_header(&self) -> Vec<&'static str> {
        column_header(&[], SPECTRA_COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        column_rows(&[], SPECTRA_COLUMNS, &self.methods)
    }
}

/// The CSV columns of a method of `bench --spectra`.
const SPECTRA_COLUMNS: &[Column<SpectraRow>] = &[
    ("method", |r| r.accuracy.method.name().to_string()),
    ("runs", |r| r.accuracy.runs.to_string()),
    ("max_rel_error", |r| num(r.accuracy.max_rel_error)),
    ("above_1e_7", |r| r.accuracy.above_1e_7.to_string()),
    ("impact_count_mismatches", |r| {
        r.accuracy.impact_count_mismatches.to_string()
    }),
    ("wall_s_ten_curves", |r| num(r.wall_s_ten_curves)),
    ("reference_tolerance", |_| {
        num(crate::accuracy::figure_spectra::REFERENCE_TOLERANCE)
    }),
    ("worst", |r| r.accuracy.worst.clone()),
];

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or("-".into(), |v| format!("{v:.digits$}"))
}

fn step_or_tolerance(r: &Row) -> String {
    match (r.dt, r.tolerance) {
        (Some(dt), _) => format!("dt={dt}"),
        (None, Some(t)) => format!("tol={t:e}"),
        _ => "-".into(),
    }
}

/// The work-precision table's columns of a row, and whether it meets the
/// target.
const TABLE: &[TableColumn<Row>] = &[
    ("preset", -6, |r| r.preset.clone()),
    ("model", -16, |r| r.model.clone()),
    ("method", -16, |r| r.method.to_string()),
    ("dt|tol", 11, step_or_tolerance),
    ("ms/run", 10, |r| format!("{:.3}", r.ms_per_run)),
    ("max rel err", 13, |r| format!("{:.3e}", r.max_rel_error)),
    ("order", 6, |r| opt(r.order, 2)),
    (
        " target (err ≤ 1e-5, set1 ≤ 2 ms)",
        0,
        |r| match meets_target(r) {
            Some(true) => " meets".into(),
            Some(false) => " misses".into(),
            None => " ".into(),
        },
    ),
];

fn table(rows: &[&Row]) -> String {
    let mut s = aligned(TABLE, rows.iter().copied());
    let _ = writeln!(
        s,
        "errors: max over Π_u1, Π_v1, Π_u2, Π_v2 of |p − p_ref|/p_ref, reference = DOPRI5 at tol {:e}; \
         times: median of repeated runs in one process after a warm-up; \
         each run finds the four peaks and the impacts (exact: no energy integrals, no force or penetration extremes)",
        TRUTH_TOLERANCE
    );
    s
}

fn plot(group: &[Row]) -> String {
    let Some(first) = group.first() else {
        return String::new();
    };
    let markers = ['P', 'L', 'S', 'E', 'R'];
    let methods = [
        "newmark-plain",
        "newmark-located",
        "newmark-substep",
        "exact",
        "reference",
    ];
    let series: Vec<Series> = methods
        .iter()
        .zip(markers)
        .map(|(m, marker)| Series {
            marker,
            label: (*m).to_string(),
            points: group
                .iter()
                .filter(|r| r.method == *m)
                .map(|r| (r.ms_per_run, r.max_rel_error))
                .collect(),
        })
        .collect();
    format!(
        "\n{} {}:\n{}",
        first.preset,
        first.model,
        plot_render(&series, 60, 16)
    )
}
