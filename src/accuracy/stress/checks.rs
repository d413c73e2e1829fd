//! Running one case and checking it.

// Comparisons are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use std::time::Instant;

use serde::Serialize;

use super::cases::{AMPLITUDE_TOLERANCE, Case, Expect};
use crate::model::ContactModel;
use crate::output::report::float_or_inf;
use crate::reference::{ReferenceOptions, reference};
use crate::solver::exact::{self, ExactOptions};
use crate::solver::{RunResult, relative_peak_error, simulate};

/// Largest accepted energy residual |E_kin + E_damp + E_spring + E_contact − E_in| / max|E_in|.
/// The work terms are the exact discrete work of each Newmark step, so the
/// balance closes to the Newton tolerance and round-off.
pub const ENERGY_TOLERANCE: f64 = 1e-8;
/// Tension allowed from the improved Kelvin element for e ≥ 0.4, relative to
/// the peak force (round-off at the located separation, where δ ≈ 0).
pub const TENSION_TOLERANCE: f64 = 1e-9;
/// Restitution from which the improved Kelvin element must never pull.
pub const NO_TENSION_FROM: f64 = 0.4;
/// How closely the solver's tension must match the reference's, relative to
/// the peak force, to count as the model's own.
pub const MODEL_TENSION_AGREEMENT: f64 = 0.02;
/// Largest relative difference of the four peaks between Newmark (at its
/// default scheme) and the exact method on a case both resolve. Newmark's
/// own error reaches 3e-3 at grazing impacts; beyond this bound one of the two is wrong.
pub const METHOD_AGREEMENT: f64 = 1e-2;

/// The verdict on one case.
#[derive(Debug, Clone, Serialize)]
pub struct Outcome {
    pub name: String,
    pub passed: bool,
    /// Why it failed (empty when it passed).
    pub failures: Vec<String>,
    /// Things worth knowing that are not failures (retries, flagged coarse Δτ).
    pub notes: Vec<String>,
    pub params: String,
    pub impacts: usize,
    pub steps: usize,
    pub step_retries: usize,
    /// A failed case may hold infinite values: written `"inf"`, as in CSV.
    #[serde(serialize_with = "float_or_inf")]
    pub energy_residual: f64,
    #[serde(serialize_with = "float_or_inf")]
    pub min_force: f64,
    #[serde(serialize_with = "float_or_inf")]
    pub max_force: f64,
    pub ms: f64,
    /// The exact method on the same case: its impacts, energy residual and time.
    pub exact_impacts: usize,
    #[serde(serialize_with = "float_or_inf")]
    pub exact_energy_residual: f64,
    pub exact_ms: f64,
    /// Largest relative difference of the four peaks, Newmark against exact.
    #[serde(serialize_with = "float_or_inf")]
    pub methods_differ_by: f64,
}

/// Resident set size of this process in bytes (Linux; None elsewhere).
fn resident_bytes() -> Option<usize> {
    let text = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: usize = text.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

/// Runs `case` and checks every invariant.
pub fn check(case: &Case) -> Outcome {
    let p = &case.params;
    let rss_before = resident_bytes();
    let start = Instant::now();
    let r = simulate(p, &case.options, &mut ());
    let ms = start.elapsed().as_secs_f64() * 1e3;
    let rss_after = resident_bytes();
    let mut failures = invariants(case, &r);
    // The same case with the exact method: its own invariants, then agreement.
    let start = Instant::now();
    let x = exact::simulate(p, &ExactOptions::matching(p, &case.options), &mut ());
    let exact_ms = start.elapsed().as_secs_f64() * 1e3;
    let exact_case = Case {
        name: case.name.clone(),
        params: p.clone(),
        options: case.options.clone(),
        expect: case.expect,
    };
    failures.extend(
        invariants(&exact_case, &x)
            .into_iter()
            .map(|f| format!("exact: {f}")),
    );
    let methods_differ_by = relative_peak_error(&r.peaks(), &x.peaks());
    let mut notes = Vec::new();
    if let Some(tension) = tension(case, &r) {
        match model_tension(case) {
            _ if case.expect == Expect::UnderResolved => {
                notes.push(format!("degraded: {tension}, {} impacts", r.impacts.len()))
            }
            Some(own)
                if (r.min_force - own).abs() <= MODEL_TENSION_AGREEMENT * r.max_force.max(1.0) =>
            {
                notes.push(format!(
                    "tension {:.3e} is the model's own (reference {own:.3e}): contact not isolated",
                    r.min_force
                ))
            }
            own => failures.push(format!(
                "{tension} (reference: {})",
                own.map_or("no tension".into(), |f| format!("{f:.3e}"))
            )),
        }
    }
    if r.step_retries > 0 {
        notes.push(format!("{} steps retried smaller", r.step_retries));
    }
    // Newmark's period error is (ωΔτ)²/12: a Δτ beyond a tenth of a radian of
    // the fastest structure is a deliberately coarse corner, compared but not judged.
    let coarse = p.dt * p.omega1.max(p.omega2).max(1.0) > 0.1;
    if case.expect == Expect::UnderResolved || p.coarse_dt_warning().is_some() || coarse {
        notes.push(format!(
            "Newmark differs from exact by {methods_differ_by:.1e}"
        ));
    } else if !(methods_differ_by <= METHOD_AGREEMENT) {
        failures.push(format!(
            "Newmark and exact differ by {methods_differ_by:.2e} > {METHOD_AGREEMENT:e}"
        ));
    }
    if p.coarse_dt_warning().is_some() {
        let substeps = case.options.substeps(p);
        notes.push(if substeps > 1 {
            format!("coarse dt flagged; {substeps} sub-steps per dt in contact")
        } else {
            format!(
                "flagged under-resolved: {:.2} steps per contact period",
                p.steps_per_contact_period()
            )
        });
    }
    match case.expect {
        Expect::Invariants | Expect::UnderResolved => {}
        Expect::AmplitudeBound(bound) => {
            for (i, (peak, b)) in [r.left.peak_displacement, r.right.peak_displacement]
                .into_iter()
                .zip(bound)
                .enumerate()
            {
                if !(peak <= b * (1.0 + AMPLITUDE_TOLERANCE)) {
                    failures.push(format!("Π_u{} = {peak} exceeds the amplitude {b}", i + 1));
                }
            }
        }
        Expect::MemoryBound(limit) => match (rss_before, rss_after) {
            (Some(a), Some(b)) => {
                let growth = b.saturating_sub(a);
                if growth > limit {
                    failures.push(format!(
                        "resident memory grew by {growth} bytes over {} steps",
                        r.steps
                    ));
                } else {
                    notes.push(format!(
                        "memory growth {} kB over {} steps",
                        growth / 1024,
                        r.steps
                    ));
                }
            }
            _ => notes.push("memory not measured (no /proc/self/statm)".into()),
        },
    }
    Outcome {
        name: case.name.clone(),
        passed: failures.is_empty(),
        failures,
        notes,
        params: p.to_string(),
        impacts: r.impacts.len(),
        steps: r.steps,
        step_retries: r.step_retries,
        energy_residual: r.energy.residual,
        min_force: r.min_force,
        max_force: r.max_force,
        ms,
        exact_impacts: x.impacts.len(),
        exact_energy_residual: x.energy.residual,
        exact_ms,
        methods_differ_by,
    }
}

/// The invariants every run keeps; returns what broke.
pub fn invariants(case: &Case, r: &RunResult) -> Vec<String> {
    let p = &case.params;
    let mut failures = Vec::new();
    let impacts_finite = r.impacts.iter().all(|i| {
        [
            i.start,
            i.end,
            i.approach_velocity,
            i.separation_velocity,
            i.peak_force,
            i.max_penetration,
        ]
        .iter()
        .all(|v| v.is_finite())
    });
    if !r.is_finite() || !impacts_finite {
        failures.push(format!("non-finite output: peaks {:?}", r.peaks()));
    }
    if !r.completed || (r.tau_end - p.tau_end()).abs() > 1e-9 * p.tau_end() {
        failures.push(format!("stopped at τ = {} of {}", r.tau_end, p.tau_end()));
    }
    if !(r.energy.residual <= ENERGY_TOLERANCE) {
        failures.push(format!(
            "energy residual {:.2e} > {ENERGY_TOLERANCE:e}",
            r.energy.residual
        ));
    }
    if r.unconverged_steps > 0 {
        failures.push(format!(
            "{} steps accepted with Newton unconverged",
            r.unconverged_steps
        ));
    }
    failures
}

/// Tension from the improved Kelvin element at e ≥ 0.4, if any.
///
/// For an isolated impact (contact much stiffer than the structures) the
/// separation velocity is ≈ e v₀ and the force k̄δ(1 + 3(1−e)/(2e) δ̇/v₀) stays
/// ≥ 0 for e ≥ 0.4. When the springs or the excitation pull the structures
/// apart faster than that (a soft contact, a very stiff structure), the model
/// itself pulls; [`model_tension`] tells the two apart.
pub fn tension(case: &Case, r: &RunResult) -> Option<String> {
    let p = &case.params;
    (p.model == ContactModel::ImprovedKelvin
        && p.restitution >= NO_TENSION_FROM
        && r.min_force < -TENSION_TOLERANCE * r.max_force.max(1.0))
    .then(|| {
        format!(
            "tension {:.3e} from improved Kelvin at e = {}",
            r.min_force, p.restitution
        )
    })
}

/// The smallest pounding force of the independent reference for this case,
/// if it pulls too (then the tension is the model's, not the solver's).
pub fn model_tension(case: &Case) -> Option<f64> {
    let o = &case.options;
    let truth = reference(
        &case.params,
        &ReferenceOptions {
            tolerance: 1e-10,
            excitation: o.excitation.clone(),
            initial_displacement: o.initial_displacement,
            initial_velocity: o.initial_velocity,
            ..ReferenceOptions::default()
        },
    );
    (truth.completed && truth.min_force < -TENSION_TOLERANCE * truth.max_force.max(1.0))
        .then_some(truth.min_force)
}
