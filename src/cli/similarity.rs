//! `pounding similarity`: physical units in and out (SPEC §8): the spectrum
//! at several excitation levels in metres and m/s, beside the dimensionless
//! master curve they share.

use std::fmt::Write as _;
use std::time::Instant;

use clap::Args;

use super::budget::{LongArg, Work};
use super::description::Provenance;
use super::output::{FormatArg, num, render};
use super::output::{param_cells, param_columns};
use super::params::ParamArgs;
use super::spectrum::SpectrumPlan;
use super::{CliError, usage};
use crate::analysis::similarity::{Level, master_curve_spread, study};
use crate::analysis::spectrum::at_omega;
use crate::analysis::spectrum_spec::SpectrumSpec;
use crate::model::physical::{G, OMEGA_P, OMEGA_P_ALLOWED, Physical, parse_acceleration};
use crate::output::report::{Column, Report, column_cells, column_header, float_or_inf};
use serde::Serialize;

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
    // The help's `[physical]` is a preset's table, not a doc link.
    #[allow(rustdoc::broken_intra_doc_links)]
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
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub long: LongArg,
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
    let work = Work::steps(levels.len() as f64 * plan.work()?.steps);
    work.check("similarity", args.long.allow_long, true)?;
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
    let report = SimilarityReport::new(
        &plan.preset.name,
        &physical,
        mu,
        &plan.grid.to_string(),
        &result,
        spread,
        elapsed_ms,
        args.fixed_structure,
    );
    super::output::print(&render(&report, args.output.format)?)
}

/// Peak displacement and velocity of one structure in SI units.
#[derive(Debug, Serialize)]
struct PeaksSi {
    peak_displacement_m: f64,
    peak_velocity_m_s: f64,
}

impl PeaksSi {
    fn of(level: &Level, p: &crate::solver::StructurePeaks) -> PeaksSi {
        PeaksSi {
            peak_displacement_m: p.peak_displacement * level.length_scale(),
            peak_velocity_m_s: p.peak_velocity * level.velocity_scale(),
        }
    }
}

/// The physical system in SI units; infinite yield displacements or gap as `"inf"`.
#[derive(Debug, Serialize)]
struct PhysicalSi {
    m1_kg: f64,
    m2_kg: f64,
    omega1_rad_s: f64,
    omega2_rad_s: f64,
    #[serde(serialize_with = "float_or_inf")]
    yield1_m: f64,
    #[serde(serialize_with = "float_or_inf")]
    yield2_m: f64,
    #[serde(serialize_with = "float_or_inf")]
    gap_m: f64,
    damping: f64,
    alpha: f64,
    contact_omega_rad_s: f64,
    restitution: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    hertz_beta_n_m1_5: Option<f64>,
    ap_m_s2: f64,
    ap_g: f64,
    omega_p_rad_s: f64,
}

impl PhysicalSi {
    fn of(p: &Physical) -> PhysicalSi {
        PhysicalSi {
            m1_kg: p.mass[0],
            m2_kg: p.mass[1],
            omega1_rad_s: p.omega[0],
            omega2_rad_s: p.omega[1],
            yield1_m: p.yield_displacement[0],
            yield2_m: p.yield_displacement[1],
            gap_m: p.gap,
            damping: p.damping,
            alpha: p.alpha,
            contact_omega_rad_s: p.contact_omega,
            restitution: p.restitution,
            hertz_beta_n_m1_5: p.hertz_beta,
            ap_m_s2: p.ap,
            ap_g: p.ap / G,
            omega_p_rad_s: p.omega_p,
        }
    }
}

/// One spectrum point of one level, in SI units beside its Π_ω1.
#[derive(Debug, Serialize)]
struct PointSi {
    omega1: f64,
    omega1_rad_s: f64,
    period1_s: f64,
    left: PeaksSi,
    right: PeaksSi,
    free_left: PeaksSi,
    free_right: PeaksSi,
    impacts: usize,
    region: crate::analysis::spectrum::Region,
    /// The gap that prevents pounding, d_min = Π_d,min l_e (exact method only).
    min_gap_no_pounding_m: Option<f64>,
}

/// One excitation level: its scales, physical system, Π-groups and points.
#[derive(Debug, Serialize)]
struct LevelReport<'a> {
    ap_m_s2: f64,
    ap_g: f64,
    length_scale_m: f64,
    velocity_scale_m_s: f64,
    physical: PhysicalSi,
    params: &'a crate::model::Params,
    points: Vec<PointSi>,
    #[serde(skip)]
    level: &'a Level,
}

impl<'a> LevelReport<'a> {
    /// The CSV columns of the level each row is of: its a_p, ω_p, scales,
    /// masses, yield displacements and gap.
    const COLUMNS: [Column<LevelReport<'a>>; 10] = [
        ("ap_m_s2", |l| num(l.level.physical.ap)),
        ("ap_g", |l| num(l.level.physical.ap / G)),
        ("omega_p_rad_s", |l| num(l.level.physical.omega_p)),
        ("length_scale_m", |l| num(l.level.length_scale())),
        ("velocity_scale_m_s", |l| num(l.level.velocity_scale())),
        ("m1_kg", |l| num(l.level.physical.mass[0])),
        ("m2_kg", |l| num(l.level.physical.mass[1])),
        ("yield1_m", |l| num(l.level.physical.yield_displacement[0])),
        ("yield2_m", |l| num(l.level.physical.yield_displacement[1])),
        ("gap_m", |l| num(l.level.physical.gap)),
    ];

    fn of(l: &'a Level) -> LevelReport<'a> {
        let points = l
            .curve
            .points
            .iter()
            .map(|p| PointSi {
                omega1: p.omega1,
                omega1_rad_s: p.omega1 * l.physical.omega_p,
                period1_s: 2.0 * std::f64::consts::PI / (p.omega1 * l.physical.omega_p),
                left: PeaksSi::of(l, &p.left),
                right: PeaksSi::of(l, &p.right),
                free_left: PeaksSi::of(l, &p.free_left),
                free_right: PeaksSi::of(l, &p.free_right),
                impacts: p.impacts,
                region: p.region,
                min_gap_no_pounding_m: p.min_gap_no_pounding.map(|g| g * l.length_scale()),
            })
            .collect();
        LevelReport {
            ap_m_s2: l.physical.ap,
            ap_g: l.physical.ap / G,
            length_scale_m: l.length_scale(),
            velocity_scale_m_s: l.velocity_scale(),
            physical: PhysicalSi::of(&l.physical),
            params: &l.params,
            points,
            level: l,
        }
    }
}

/// SI for the physical runs, Π-groups for the rest.
const UNITS: &str = "SI (m, m/s, rad/s, s, kg, m/s²) for the physical runs; \
                     omega1, params and master are dimensionless Π-groups (SPEC §1, §8)";

/// The similarity study in every format: physical runs in SI units, the
/// master curve in Π-groups.
#[derive(Debug, Serialize)]
pub struct SimilarityReport<'a> {
    #[serde(flatten)]
    provenance: Provenance<'a>,
    physical: PhysicalSi,
    omega_p: f64,
    mu: f64,
    omega1_grid: String,
    /// How yield displacements and gap follow a_p.
    structure: &'static str,
    method: Option<&'static str>,
    levels: Vec<LevelReport<'a>>,
    /// The dimensionless spectrum of the first level.
    master: Option<&'a [crate::analysis::spectrum::SpectrumPoint]>,
    master_curve_spread: f64,
    elapsed_ms: f64,
    #[serde(skip)]
    source: &'a Physical,
    #[serde(skip)]
    fixed: bool,
}

impl<'a> SimilarityReport<'a> {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        preset: &'a str,
        physical: &'a Physical,
        mu: f64,
        grid: &str,
        levels: &'a [Level],
        spread: f64,
        elapsed_ms: f64,
        fixed: bool,
    ) -> Self {
        SimilarityReport {
            provenance: Provenance::new(preset, UNITS),
            physical: PhysicalSi::of(physical),
            omega_p: physical.omega_p,
            mu,
            omega1_grid: grid.to_string(),
            structure: if fixed {
                "yield displacements and gap fixed in metres"
            } else {
                "yield displacements and gap scale with a_p"
            },
            method: levels.first().map(|l| l.params.method.name()),
            levels: levels.iter().map(LevelReport::of).collect(),
            master: levels.first().map(|l| l.curve.points.as_slice()),
            master_curve_spread: spread,
            elapsed_ms,
            source: physical,
            fixed,
        }
    }
}

impl Report for SimilarityReport<'_> {
    /// Every row is self-contained: the level (a_p, ω_p, scales, yield
    /// displacements and gap in metres), the Π_ω1 grid, the point's whole
    /// dimensionless parameter set (model and method among them), then its
    /// peaks in SI units and as Π-groups.
    fn csv_header(&self) -> Vec<&'static str> {
        let mut h = column_header(&[], &LevelReport::COLUMNS);
        h.push("omega1_grid");
        h.extend(param_columns());
        h.extend([
            "omega1_rad_s",
            "period1_s",
            "left_peak_displacement_m",
            "left_peak_velocity_m_s",
            "right_peak_displacement_m",
            "right_peak_velocity_m_s",
            "free_left_peak_displacement_m",
            "free_left_peak_velocity_m_s",
            "free_right_peak_displacement_m",
            "free_right_peak_velocity_m_s",
            "left_pi_u",
            "left_pi_v",
            "right_pi_u",
            "right_pi_v",
            "free_left_pi_u",
            "free_left_pi_v",
            "free_right_pi_u",
            "free_right_pi_v",
            "impacts",
            "region",
            "min_gap_no_pounding_m",
        ]);
        h
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let mut rows = Vec::new();
        for lr in &self.levels {
            let l = lr.level;
            let (lx, lv) = (l.length_scale(), l.velocity_scale());
            for (p, si) in l.curve.points.iter().zip(&lr.points) {
                let mut row: Vec<String> = column_cells(&LevelReport::COLUMNS, lr).collect();
                row.push(self.omega1_grid.clone());
                row.extend(param_cells(&at_omega(&l.params, p.omega1, self.mu)));
                row.extend([si.omega1_rad_s, si.period1_s].map(num));
                let pi = p.peaks();
                row.extend(
                    pi.iter()
                        .enumerate()
                        .map(|(i, v)| num(v * if i % 2 == 0 { lx } else { lv })),
                );
                row.extend(pi.map(num));
                row.push(p.impacts.to_string());
                row.push(p.region.name().to_string());
                row.push(si.min_gap_no_pounding_m.map(num).unwrap_or_default());
                rows.push(row);
            }
        }
        rows
    }

    fn table(&self) -> String {
        let levels: Vec<&Level> = self.levels.iter().map(|l| l.level).collect();
        table(
            self.provenance.preset,
            self.source,
            self.mu,
            &levels,
            self.master_curve_spread,
            self.elapsed_ms,
            self.fixed,
        )
    }
}

fn table(
    name: &str,
    physical: &Physical,
    mu: f64,
    levels: &[&Level],
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
