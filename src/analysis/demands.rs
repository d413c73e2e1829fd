//! The demands of a run in SI (SPEC §6 "Demands for performance studies",
//! SPEC §8): a run's Π results times the scales of its a_p, ω_p and m2.
//!
//! ```text
//! X = Π_u l_e,  Ẋ = Π_v a_p/ω_p,  Ẍ_abs = A a_p,  F = Π_F m2 a_p,
//! E = Π_E m2 a_p²/ω_p²,  with l_e = a_p/ω_p².
//! ```

use serde::Serialize;

use crate::model::physical::{G, Physical};
use crate::solver::{RunResult, StructurePeaks};

/// The scales that turn a run's Π results into SI (SPEC §1, §8).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Scales {
    /// a_p (m/s²).
    pub ap: f64,
    /// ω_p (rad/s).
    pub omega_p: f64,
    /// l_e = a_p/ω_p² (m per unit of Π_u).
    pub length: f64,
    /// a_p/ω_p (m/s per unit of Π_v).
    pub velocity: f64,
    /// m2 a_p (N per unit of force).
    pub force: f64,
    /// m2 a_p²/ω_p² (J per unit of energy).
    pub energy: f64,
}

impl Scales {
    pub fn of(physical: &Physical, ap: f64, omega_p: f64) -> Scales {
        let length = ap / (omega_p * omega_p);
        Scales {
            ap,
            omega_p,
            length,
            velocity: ap / omega_p,
            force: physical.mass[1] * ap,
            energy: physical.mass[1] * ap * length,
        }
    }
}

/// One structure's demands in SI (SPEC §6 "Demands for performance studies").
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DemandsSi {
    /// Peak drift max |X| (m).
    pub peak_displacement_m: f64,
    /// Peak velocity max |Ẋ| (m/s).
    pub peak_velocity_m_s: f64,
    /// Peak absolute (floor) acceleration max |Ẍ + ü_g| (g).
    pub peak_absolute_acceleration_g: f64,
    /// μ = Π_u/Π_uy (∞ for an elastic structure).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub ductility: f64,
    /// Residual drift (1 − α)(X − Z) at the end (m, signed).
    pub residual_displacement_m: f64,
    /// Hysteretic energy E_h (kJ).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub hysteretic_energy_kj: f64,
}

impl DemandsSi {
    pub fn of(peaks: &StructurePeaks, s: &Scales) -> DemandsSi {
        DemandsSi {
            peak_displacement_m: peaks.peak_displacement * s.length,
            peak_velocity_m_s: peaks.peak_velocity * s.velocity,
            peak_absolute_acceleration_g: peaks.peak_absolute_acceleration * s.ap / G,
            ductility: peaks.ductility,
            residual_displacement_m: peaks.residual_displacement * s.length,
            hysteretic_energy_kj: peaks.hysteretic_energy * s.energy / 1e3,
        }
    }
}

/// A run's results in SI: its scales, both structures' demands, its
/// largest pounding force and the gap that prevents pounding (SPEC §11).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RunSi {
    #[serde(flatten)]
    pub scales: Scales,
    pub left: DemandsSi,
    pub right: DemandsSi,
    /// Largest pounding force (kN); 0 without contact.
    pub max_force_kn: f64,
    /// Π_d,min in m.
    pub min_gap_m: f64,
}

impl RunSi {
    /// The SI form of run `r` of the buildings `physical` at a_p = `ap`
    /// (m/s²) and ω_p = `omega_p` (rad/s), with its Π_d,min `min_gap`.
    pub fn of(physical: &Physical, ap: f64, omega_p: f64, r: &RunResult, min_gap: f64) -> RunSi {
        let scales = Scales::of(physical, ap, omega_p);
        RunSi {
            scales,
            left: DemandsSi::of(&r.left, &scales),
            right: DemandsSi::of(&r.right, &scales),
            max_force_kn: if r.impacts.is_empty() {
                0.0
            } else {
                r.max_force * scales.force / 1e3
            },
            min_gap_m: min_gap * scales.length,
        }
    }

    /// Structure `i`'s demands (0 left, 1 right).
    pub fn structure(&self, i: usize) -> &DemandsSi {
        if i == 0 { &self.left } else { &self.right }
    }
}
