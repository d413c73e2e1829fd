//! `pounding bench`: the work-precision table of issue 5 (run time against
//! error for each method, see [`crate::accuracy::work_precision`]).

use std::fmt::Write as _;

use clap::Args;

use super::CliError;
use super::output::Format;
use super::params::user_preset_dir;
use crate::accuracy::plot::{Series, render};
use crate::accuracy::work_precision::{Row, meets_target, rows};
use crate::model::{ContactModel, Preset};

#[derive(Debug, Clone, Default, Args)]
pub struct BenchArgs {
    /// Preset to measure (repeatable) [default: set1 and set2].
    #[arg(long, value_name = "NAME|PATH")]
    pub preset: Vec<String>,
    /// Contact model (repeatable) [default: both].
    #[arg(long, value_parser = ["kelvin", "improved-kelvin"])]
    pub model: Vec<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
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
}

pub fn execute(args: &BenchArgs) -> Result<(), CliError> {
    if args.spectra {
        return spectra(args);
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
                ..preset.params
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
    let text = match args.format {
        Format::Json => serde_json::json!({ "rows": all }).to_string() + "\n",
        Format::Csv => csv(&all),
        Format::Table => table(&all),
    };
    let mut text = text;
    if args.plot {
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
    let text = match args.format {
        Format::Json => {
            let list: Vec<_> = rows
                .iter()
                .map(|(a, t)| serde_json::json!({ "accuracy": a, "wall_s_ten_curves": t }))
                .collect();
            serde_json::json!({ "reference_tolerance": REFERENCE_TOLERANCE, "methods": list })
                .to_string()
                + "\n"
        }
        Format::Csv | Format::Table => {
            let mut s = format!(
                "Figures 7–10, ten curves, with and without pounding, against the reference at tol {REFERENCE_TOLERANCE:e}\n\
                 {:<8} {:>6} {:>13} {:>9} {:>10} {:>12}  worst point\n",
                "method", "runs", "max rel err", "> 1e-7", "count diff", "wall s (10)"
            );
            for (a, t) in &rows {
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
    };
    super::output::print(&text)?;
    Ok(())
}

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

fn table(rows: &[&Row]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<6} {:<16} {:<16} {:>11} {:>10} {:>13} {:>6}  target (err ≤ 1e-5, set1 ≤ 2 ms)",
        "preset", "model", "method", "dt|tol", "ms/run", "max rel err", "order"
    );
    for r in rows {
        let target = match meets_target(r) {
            Some(true) => "meets",
            Some(false) => "misses",
            None => "",
        };
        let _ = writeln!(
            s,
            "{:<6} {:<16} {:<16} {:>11} {:>10.3} {:>13.3e} {:>6}  {target}",
            r.preset,
            r.model,
            r.method,
            step_or_tolerance(r),
            r.ms_per_run,
            r.max_rel_error,
            opt(r.order, 2)
        );
    }
    let _ = writeln!(
        s,
        "errors: max over Π_u1, Π_v1, Π_u2, Π_v2 of |p − p_ref|/p_ref, reference = DOPRI5 at tol {:e}; \
         times: median of repeated runs in one process after a warm-up",
        crate::accuracy::work_precision::TRUTH_TOLERANCE
    );
    s
}

fn csv(rows: &[&Row]) -> String {
    let mut s = String::from("preset,model,method,dt,tolerance,ms_per_run,max_rel_error,order\n");
    let cell = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{}",
            r.preset,
            r.model,
            r.method,
            cell(r.dt),
            cell(r.tolerance),
            r.ms_per_run,
            r.max_rel_error,
            cell(r.order)
        );
    }
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
        render(&series, 60, 16)
    )
}
