//! `pounding similarity`: physical units in and out (SPEC §8): the spectrum
//! at several excitation levels in metres and m/s, beside the dimensionless
//! master curve they share.

use std::fmt::Write as _;
use std::time::Instant;

use clap::Args;

use super::CliError;
use super::budget::Work;
use super::output::{Format, num};
use super::params::ParamArgs;
use super::spectrum::SpectrumPlan;
use crate::analysis::similarity::{Level, master_curve_spread, study};
use crate::analysis::spectrum_spec::SpectrumSpec;
use crate::model::physical::{G, OMEGA_P, OMEGA_P_ALLOWED, Physical, parse_acceleration};

#[derive(Debug, Clone, Default, Args)]
pub struct SimilarityArgs {
    #[command(flatten)]
    pub params: ParamArgs,
    /// Excitation amplitudes a_p, in m/s² or as multiples of g.
    #[arg(
        long,
        value_name = "A1,A2,...",
        default_value = "0.2g,0.5g,0.8g",
        allow_hyphen_values = true
    )]
    pub ap: String,
    /// Excitation circular frequency ω_p in rad/s [default: the preset's [physical] omega_p].
    #[arg(long = "omega-p", value_name = "W", allow_hyphen_values = true)]
    pub omega_p: Option<String>,
    /// The Π_ω1 grid START:STOP:STEP [default: the preset's, else 0.1:3.0:0.01].
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub omega1: Option<String>,
    /// Frequency ratio μ [default: the preset's, else ω2/ω1].
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub mu: Option<String>,
    /// Keep yield displacements and gap fixed in metres (Π_uy and Π_d then change with a_p,
    /// and the curves do not collapse). By default they scale with a_p, as in the paper.
    #[arg(long)]
    pub fixed_structure: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Run even when the estimated work exceeds 1e10 steps (several minutes).
    #[arg(long)]
    pub allow_long: bool,
}

fn usage(msg: impl std::fmt::Display) -> CliError {
    CliError::Usage(msg.to_string())
}

pub fn execute(args: &SimilarityArgs) -> Result<(), CliError> {
    let plan = SpectrumPlan::resolve(
        &args.params,
        args.omega1.as_deref(),
        args.mu.as_deref(),
        None,
    )?;
    let levels: Vec<f64> = args
        .ap
        .split(',')
        .map(|a| {
            parse_acceleration(a).ok_or_else(|| {
                usage(format!(
                    "--ap `{}`: must be an acceleration > 0 in m/s², or like 0.5g",
                    crate::model::params::echo::text(a.trim())
                ))
            })
        })
        .collect::<Result<_, _>>()?;
    let omega_p = match &args.omega_p {
        Some(w) => Some(
            w.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| OMEGA_P.contains(v))
                .ok_or_else(|| {
                    usage(format!(
                        "--omega-p {}: {OMEGA_P_ALLOWED}",
                        crate::model::params::echo::text(w)
                    ))
                })?,
        ),
        None => None,
    };
    let physical = match &plan.preset.physical {
        Some(t) => {
            if let Some(kv) =
                args.params.overrides.iter().find(|kv| {
                    crate::model::params::is_pi(kv.split('=').next().unwrap_or("").trim())
                })
            {
                return Err(usage(format!(
                    "--set `{kv}`: preset `{}` gives this in physical units; edit its [physical] table",
                    plan.preset.name
                )));
            }
            let mut phys =
                Physical::from_table(t).map_err(|e| usage(format!("{}: {e}", plan.preset.name)))?;
            if let Some(w) = omega_p {
                phys.omega_p = w;
            }
            phys
        }
        None => {
            let w = omega_p.ok_or_else(|| {
                usage(format!(
                    "preset `{}` has no [physical] table: give --omega-p W (rad/s)",
                    plan.preset.name
                ))
            })?;
            Physical::from_params(&plan.params, levels[0], w, 1.0)
        }
    };
    // μ: --mu, else the preset's [spectrum] mu, else ω2/ω1 of the physical system.
    let spec_mu = plan
        .preset
        .spectrum
        .as_ref()
        .and_then(|t| SpectrumSpec::from_table(t).ok())
        .and_then(|s| s.mu);
    let mu = match (&args.mu, spec_mu) {
        (None, None) => physical.omega[1] / physical.omega[0],
        _ => plan.mu,
    };
    let work = Work {
        steps: levels.len() as f64 * plan.work()?.steps,
        rows: 0.0,
    };
    work.check("similarity", args.allow_long, true)?;
    let t = Instant::now();
    let result = study(
        &physical,
        &plan.params,
        &levels,
        &plan.grid.values(),
        mu,
        !args.fixed_structure,
    )
    .map_err(|e| usage(format!("a level gives {e}")))?;
    let elapsed_ms = t.elapsed().as_secs_f64() * 1e3;
    let spread = master_curve_spread(&result);
    let text = match args.format {
        Format::Json => json(&physical, mu, &result, spread, elapsed_ms).to_string() + "\n",
        Format::Csv => csv(&result),
        Format::Table => table(
            &plan.preset.name,
            &physical,
            mu,
            &result,
            spread,
            elapsed_ms,
            args.fixed_structure,
        ),
    };
    super::output::print(&text)?;
    Ok(())
}

fn peaks_si(level: &Level, p: &crate::solver::StructurePeaks) -> serde_json::Value {
    serde_json::json!({
        "peak_displacement_m": p.peak_displacement * level.length_scale(),
        "peak_velocity_m_s": p.peak_velocity * level.velocity_scale(),
    })
}

fn physical_json(p: &Physical) -> serde_json::Value {
    serde_json::json!({
        "m1_kg": p.mass[0], "m2_kg": p.mass[1],
        "omega1_rad_s": p.omega[0], "omega2_rad_s": p.omega[1],
        "yield1_m": num(p.yield_displacement[0]), "yield2_m": num(p.yield_displacement[1]),
        "gap_m": num(p.gap), "damping": p.damping, "alpha": p.alpha,
        "contact_omega_rad_s": p.contact_omega, "restitution": p.restitution,
        "ap_m_s2": p.ap, "ap_g": p.ap / G, "omega_p_rad_s": p.omega_p,
    })
}

fn json(
    physical: &Physical,
    mu: f64,
    levels: &[Level],
    spread: f64,
    elapsed_ms: f64,
) -> serde_json::Value {
    let level_json: Vec<serde_json::Value> = levels
        .iter()
        .map(|l| {
            let points: Vec<serde_json::Value> = l
                .curve
                .points
                .iter()
                .map(|p| {
                    serde_json::json!({
                        "omega1": p.omega1,
                        "omega1_rad_s": p.omega1 * l.physical.omega_p,
                        "period1_s": 2.0 * std::f64::consts::PI / (p.omega1 * l.physical.omega_p),
                        "left": peaks_si(l, &p.left),
                        "right": peaks_si(l, &p.right),
                        "free_left": peaks_si(l, &p.free_left),
                        "free_right": peaks_si(l, &p.free_right),
                        "impacts": p.impacts,
                        "region": p.region,
                    })
                })
                .collect();
            serde_json::json!({
                "ap_m_s2": l.physical.ap,
                "ap_g": l.physical.ap / G,
                "length_scale_m": l.length_scale(),
                "velocity_scale_m_s": l.velocity_scale(),
                "physical": physical_json(&l.physical),
                "params": super::output::params_json(&l.params),
                "points": points,
            })
        })
        .collect();
    serde_json::json!({
        "physical": physical_json(physical),
        "omega_p": physical.omega_p,
        "mu": mu,
        "levels": level_json,
        "method": levels.first().map(|l| l.params.method.name()),
        "master": levels.first().map(|l| &l.curve.points),
        "master_curve_spread": spread,
        "elapsed_ms": elapsed_ms,
    })
}

fn csv(levels: &[Level]) -> String {
    let mut s = String::from(
        "ap_m_s2,omega1,omega1_rad_s,left_peak_displacement_m,left_peak_velocity_m_s,right_peak_displacement_m,\
         right_peak_velocity_m_s,free_left_peak_displacement_m,free_left_peak_velocity_m_s,\
         free_right_peak_displacement_m,free_right_peak_velocity_m_s,left_pi_u,left_pi_v,right_pi_u,right_pi_v,\
         free_left_pi_u,free_left_pi_v,free_right_pi_u,free_right_pi_v,impacts,region,method\n",
    );
    for l in levels {
        let (lx, lv) = (l.length_scale(), l.velocity_scale());
        for p in &l.curve.points {
            let pi = p.peaks();
            let _ = write!(
                s,
                "{},{},{}",
                l.physical.ap,
                p.omega1,
                p.omega1 * l.physical.omega_p
            );
            for (i, v) in pi.iter().enumerate() {
                let _ = write!(s, ",{}", v * if i % 2 == 0 { lx } else { lv });
            }
            for v in pi {
                let _ = write!(s, ",{v}");
            }
            let _ = writeln!(s, ",{},{},{}", p.impacts, p.region.name(), l.params.method);
        }
    }
    s
}

fn table(
    name: &str,
    physical: &Physical,
    mu: f64,
    levels: &[Level],
    spread: f64,
    elapsed_ms: f64,
    fixed: bool,
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{name}: m1 = {} kg, m2 = {} kg, T1 = {:.3} s, T2 = {:.3} s, ω_p = {:.4} rad/s, μ = {mu:.4}, {} method",
        physical.mass[0],
        physical.mass[1],
        2.0 * std::f64::consts::PI / physical.omega[0],
        2.0 * std::f64::consts::PI / physical.omega[1],
        physical.omega_p,
        levels.first().map_or("-", |l| l.params.method.name())
    );
    let _ = writeln!(
        s,
        "{}",
        if fixed {
            "yield displacements and gap fixed in metres: Π_uy and Π_d change with a_p"
        } else {
            "yield displacements and gap scale with a_p: every Π-group is the same at every level"
        }
    );
    for l in levels {
        let _ = writeln!(
            s,
            "a_p = {:.3} g: u_y = {:.4} / {:.4} m, d = {} m, l_e = {:.5} m, Π_uy = {:.4} / {:.4}, Π_d = {}",
            l.physical.ap / G,
            l.physical.yield_displacement[0],
            l.physical.yield_displacement[1],
            num(l.physical.gap),
            l.length_scale(),
            l.params.yield1,
            l.params.yield2,
            num(l.params.gap)
        );
    }
    let _ = write!(s, "\n{:>6} {:>8}", "Π_ω1", "ω1 rad/s");
    for l in levels {
        let _ = write!(
            s,
            " {:>9} {:>9}",
            format!("X1@{:.2}g", l.physical.ap / G),
            "free"
        );
    }
    let _ = writeln!(s, " | {:>8} {:>8} {:>8}  region", "Π_u1", "free", "Π_u2");
    let Some(master) = levels.first() else {
        return s;
    };
    for (i, p) in master.curve.points.iter().enumerate() {
        let _ = write!(s, "{:>6.3} {:>8.3}", p.omega1, p.omega1 * physical.omega_p);
        for l in levels {
            let q = &l.curve.points[i];
            let _ = write!(
                s,
                " {:>9.4} {:>9.4}",
                q.left.peak_displacement * l.length_scale(),
                q.free_left.peak_displacement * l.length_scale()
            );
        }
        let _ = writeln!(
            s,
            " | {:>8.4} {:>8.4} {:>8.4}  {}",
            p.left.peak_displacement,
            p.free_left.peak_displacement,
            p.right.peak_displacement,
            p.region.name()
        );
    }
    let _ = writeln!(
        s,
        "\nlargest relative difference of a dimensionless peak between levels: {spread:.1e}   {elapsed_ms:.0} ms"
    );
    s
}
