//! One pair of buildings under a suite of records (SPEC §12).
//!
//! **Suites are physical.** The preset's `[physical]` table describes the
//! buildings in SI units. Record j, scaled by s_j, has its own base
//! quantities a_p,j = s_j · max|a_j| and ω_p,j (its dominant frequency,
//! SPEC §9), which turn the same buildings into that record's Π-groups
//! ([`Physical::under_record`]). Every record thus shakes the same
//! buildings, and results are compared in physical units
//! ([`super::demands::RunSi`]).
//!
//! Scaling a record by s scales every sample, so g(τ) = a(τ/ω_p)/a_p is the
//! same for every s; the scale enters through a_p alone.
//!
//! **Intensity.** With a measure IM (PGA or Sa(T), SPEC §12) and a level X
//! (in g), s_j = X / IM(record j), so every scaled record has IM = X. Without
//! a level, a record runs at the scale its suite list gives (1 otherwise).
//!
//! Each row of a suite is bit for bit the run `pounding run` makes of that
//! record with the preset and `record_amplitude = a_p,j`: both build their
//! parameters through [`Physical::under_record`] and run them through
//! [`solve`].

use super::demands::{DemandsSi, RunSi};
use super::gap::{free_run, from_max_relative};
use crate::model::excitation::RecordMotion;
use crate::model::intensity::IntensityMeasure;
use crate::model::physical::Physical;
use crate::model::suite::SuiteMember;
use crate::model::{ParamError, Params};
use crate::solver::{RunResult, solve};

/// How the records of a suite are scaled (SPEC §12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scaling {
    /// The intensity measure reported for every record.
    pub measure: IntensityMeasure,
    /// The level X (g) every record is scaled to; `None`: each record at its
    /// suite list's scale.
    pub level: Option<f64>,
    /// An IDA's levels scale the suite as a whole rather than each record
    /// to the level ([`level_scales`]): the list's scales (a suite scaled to
    /// a design spectrum by the code's rule) keep their proportions.
    pub collective: bool,
}

impl Scaling {
    /// How an IDA's levels scale the records, in words, for its reports:
    /// `None` one by one, the scaling every IDA used before a suite could be
    /// scaled to a design spectrum.
    pub fn as_a_whole(&self) -> Option<String> {
        self.collective.then(|| {
            format!(
                "the suite scaled as a whole to each level: its median {m} is the level, its \
                 records in their list's proportions (the code's factors; FEMA P-695)",
                m = self.measure
            )
        })
    }
}

/// Each member's (scale, intensity) at an IDA level X (g), from the IM of
/// its record as recorded (`raws`):
///
/// - one by one (SPEC §12): s_j = X / IM_j, so every record has IM = X;
/// - collectively (FEMA P-695 §A.8, a suite scaled as a whole): with f_j
///   the list's scales, s_j = f_j · X / median_k(f_k IM_k), so that the
///   suite's median IM is X and the records keep the proportions the list
///   gave them (the code's factors of a suite scaled to a design spectrum).
pub fn level_scales(
    members: &[SuiteMember],
    raws: &[f64],
    level: f64,
    collective: bool,
) -> Vec<(f64, f64)> {
    if !collective {
        return members
            .iter()
            .zip(raws)
            .map(|(m, &raw)| scaled(m, raw, Some(level)))
            .collect();
    }
    let mut listed: Vec<f64> = members.iter().zip(raws).map(|(m, r)| m.scale * r).collect();
    listed.sort_by(f64::total_cmp);
    let median = super::statistics::quantile(&listed, 0.5);
    members
        .iter()
        .zip(raws)
        .map(|(m, &raw)| {
            let scale = m.scale * level / median;
            (scale, raw * scale)
        })
        .collect()
}

/// A suite study: the buildings, the run settings and the scaling.
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteCase {
    /// The buildings in SI (the preset's `[physical]` table).
    pub physical: Physical,
    /// Contact law, method, free cycles after the record, Δτ, grazing floor
    /// and contact tolerance (every non-Π key of the set).
    pub settings: Params,
    pub scaling: Scaling,
}

/// Why a suite cannot be run: the record named and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SuiteRunError {
    /// A record whose intensity is 0 (all zeros) cannot be scaled or run.
    #[error(
        "record `{record}`: its {measure} is 0 (every sample is zero): it cannot be scaled or run"
    )]
    ZeroIntensity { record: String, measure: String },
    /// The record's Π-groups are out of range (a Δτ too coarse for its ω_p, …).
    #[error("record `{record}`: {error}")]
    Params { record: String, error: ParamError },
}

/// One record of a suite, run.
#[derive(Debug, Clone)]
pub struct SuiteRun {
    /// The record's name in the suite.
    pub name: String,
    /// Samples and their interval DT (s).
    pub samples: usize,
    pub dt: f64,
    /// The factor s applied to the record's accelerations.
    pub scale: f64,
    /// IM of the scaled record (g).
    pub intensity: f64,
    /// The results in SI, with the scales of the record's a_p and ω_p.
    pub si: RunSi,
    /// The record's Π-groups and settings, as `pounding run` takes them.
    pub params: Params,
    pub result: RunResult,
    /// The run without contact (gap = ∞, exact method), and its SI form.
    pub free: RunResult,
    pub free_si: RunSi,
    /// Π_d,min of SPEC §11 from the record's run without contact.
    pub min_gap: f64,
}

impl SuiteRun {
    /// Structure `i`'s demands in SI (0 left, 1 right).
    pub fn demands(&self, i: usize) -> DemandsSi {
        *self.si.structure(i)
    }

    /// Largest pounding force (kN); 0 without contact.
    pub fn max_force_kn(&self) -> f64 {
        self.si.max_force_kn
    }

    /// Π_d,min in m.
    pub fn min_gap_m(&self) -> f64 {
        self.si.min_gap_m
    }

    pub fn pounded(&self) -> bool {
        !self.result.impacts.is_empty()
    }
}

/// The scale and intensity of a member under `scaling` (SPEC §12): s = X/IM
/// at a level X, else the list's scale.
pub fn scale_of(member: &SuiteMember, scaling: &Scaling) -> Result<(f64, f64), SuiteRunError> {
    let raw = raw_intensity(member, &scaling.measure)?;
    Ok(scaled(member, raw, scaling.level))
}

/// The intensity measure of a member's record as recorded (scale 1), in g;
/// an error naming the record when it is not finite and > 0 (nothing could
/// scale it to a level).
pub fn raw_intensity(
    member: &SuiteMember,
    measure: &IntensityMeasure,
) -> Result<f64, SuiteRunError> {
    let raw = measure.measure(&member.record);
    if !(raw > 0.0 && raw.is_finite()) || member.record.peak <= 0.0 {
        return Err(SuiteRunError::ZeroIntensity {
            record: member.name.clone(),
            measure: measure.to_string(),
        });
    }
    Ok(raw)
}

/// The (scale, intensity) of a member whose record measures `raw`: s = X/IM
/// at a level X, else the list's scale; the intensity is then IM·s. A
/// study at many levels measures each record once and calls this per level.
pub fn scaled(member: &SuiteMember, raw: f64, level: Option<f64>) -> (f64, f64) {
    let scale = match level {
        Some(level) => level / raw,
        None => member.scale,
    };
    (scale, raw * scale)
}

/// The parameters of one member: the buildings under the record at its
/// scale, with a_p = s·max|a| and ω_p its dominant frequency.
pub fn member_params(
    case: &SuiteCase,
    member: &SuiteMember,
    scale: f64,
) -> Result<Params, SuiteRunError> {
    let motion = RecordMotion {
        scale,
        amplitude: scale * member.record.peak,
        ..RecordMotion::new(member.record.clone())
    };
    case.physical
        .under_record(&case.settings, motion)
        .map_err(|error| SuiteRunError::Params {
            record: member.name.clone(),
            error,
        })
}

/// What one member will run: its scale, the IM of the scaled record (g)
/// and its parameters.
#[derive(Debug, Clone)]
pub struct MemberPlan {
    pub scale: f64,
    pub intensity: f64,
    pub params: Params,
}

/// Each member's (scale, intensity) under `scaling`: they depend on the
/// records only, so a study of many buildings measures each record once.
pub fn scales(
    members: &[SuiteMember],
    scaling: &Scaling,
) -> Result<Vec<(f64, f64)>, SuiteRunError> {
    members.iter().map(|m| scale_of(m, scaling)).collect()
}

/// Runs one planned member: its pounding run, and its run without contact
/// for Π_d,min ([`runs_of`]).
pub fn run_member(case: &SuiteCase, member: &SuiteMember, plan: &MemberPlan) -> SuiteRun {
    let (result, free) = runs_of(&plan.params);
    member_run(case, member, plan, result, free)
}

/// The pounding run of `params`, and its run without contact unless the
/// pounding run had no impact (then it is its own).
pub fn runs_of(params: &Params) -> (RunResult, RunResult) {
    let result = solve(params, &mut ());
    // The same buildings without contact (gap = ∞), by the exact method:
    // their demands are the no-pounding baseline of every comparison, their
    // separate peaks what the code rules combine (SPEC §11), and their
    // largest x1 − x2 is Π_d,min unless the pounding run had no impact
    // (then it is its own no-pounding run).
    let free = if params.pounding() {
        free_run(params)
    } else {
        result.clone()
    };
    (result, free)
}

/// A member's row from its two runs (see [`run_member`]): the runs of a
/// shard, read back from its part, give the row the unsharded suite has.
pub fn member_run(
    case: &SuiteCase,
    member: &SuiteMember,
    plan: &MemberPlan,
    result: RunResult,
    free: RunResult,
) -> SuiteRun {
    let params = &plan.params;
    let min_gap = from_max_relative(
        result
            .max_relative_displacement
            .or(free.max_relative_displacement)
            .unwrap_or(f64::NAN),
    );
    // [`Physical::under_record`] names a_p and ω_p in the set.
    let (ap, omega_p) = (params.record_amplitude, params.record_omega);
    let si = RunSi::of(&case.physical, ap, omega_p, &result, min_gap);
    let free_si = RunSi::of(&case.physical, ap, omega_p, &free, min_gap);
    SuiteRun {
        name: member.name.clone(),
        samples: member.record.acceleration.len(),
        dt: member.record.dt,
        scale: plan.scale,
        intensity: plan.intensity,
        si,
        params: params.clone(),
        result,
        free,
        free_si,
        min_gap,
    }
}
