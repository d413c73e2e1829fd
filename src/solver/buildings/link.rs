//! Links across the joints in the exact method (SPEC §14):
//! F = k_l Δu + c_l |Δv|^α sgn Δv between floors A and B, −F on A, +F on B.
//!
//! - The spring k_l is linear always, and so is the dashpot when α = 1: both
//!   enter K and C of every configuration ([`add_linear`]), so that the
//!   cached maps and the Taylor series carry them exactly.
//! - A fluid viscous damper's dashpot (α < 1) is nonlinear, its slope
//!   without bound at Δv = 0: it stays out of K and C, and the row's
//!   Runge–Kutta steps carry it ([`super::damper`]).
//!
//! Per link a run reports peak |F|, peak |Δu| (the stroke), peak |Δv|, and
//! the energy its dashpot dissipated, E_l = ∫ c_l |Δv|^(α+1) dt; the peaks
//! inside a series step are [`super::link_peaks`]'.

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use crate::model::buildings::LinkElement;

/// Adds every link's spring to `stiffness` (K, N/m) and every linear
/// dashpot's c_l to `damping`, which holds M⁻¹C (each row divided by its
/// floor's mass `mass`).
pub fn add_linear(
    links: &[LinkElement],
    mass: &[f64],
    stiffness: &mut DMatrix<f64>,
    damping: &mut DMatrix<f64>,
) {
    for l in links {
        let (a, b) = (l.pair.left_dof, l.pair.right_dof);
        let k = l.link.stiffness;
        stiffness[(a, a)] += k;
        stiffness[(b, b)] += k;
        stiffness[(a, b)] -= k;
        stiffness[(b, a)] -= k;
        if l.is_linear() {
            let c = l.link.damping;
            damping[(a, a)] += c / mass[a];
            damping[(a, b)] -= c / mass[a];
            damping[(b, b)] += c / mass[b];
            damping[(b, a)] -= c / mass[b];
        }
    }
}

/// What a run reports of one link (SPEC §14).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LinkResult {
    /// max |F| (N).
    pub max_force: f64,
    /// max |Δu| (m), the stroke.
    pub stroke: f64,
    /// max |Δv| (m/s).
    pub max_rate: f64,
    /// E_l = ∫ c_l |Δv|^(α+1) dt (J), when the run took its energy
    /// balance (NaN otherwise).
    pub energy: f64,
}

impl LinkResult {
    pub fn new() -> LinkResult {
        LinkResult {
            energy: f64::NAN,
            ..LinkResult::default()
        }
    }
}

/// Raises each link's peaks with the state (u, u̇).
pub fn record_point(links: &[LinkElement], u: &[f64], v: &[f64], out: &mut [LinkResult]) {
    for (l, r) in links.iter().zip(out) {
        let (a, b) = (l.pair.left_dof, l.pair.right_dof);
        let (du, dv) = (u[a] - u[b], v[a] - v[b]);
        r.stroke = r.stroke.max(du.abs());
        r.max_rate = r.max_rate.max(dv.abs());
        r.max_force = r.max_force.max(l.force(du, dv).abs());
    }
}

/// Whether no link's peak can be passed on a quiet sub-step, from the
/// rigorous ranges (lo, hi) of Δu and Δv over it and whether each is
/// monotone there (then its extremes are the ends, which are recorded):
/// |Δu| and |Δv| within their peaks unless monotone, and the bound
/// k_l max|Δu| + c_l max|Δv|^α ≥ |F| within the force's peak.
pub fn quiet(
    link: &LinkElement,
    peaks: &LinkResult,
    (stroke, stroke_monotone): ((f64, f64), bool),
    (rate, rate_monotone): ((f64, f64), bool),
) -> bool {
    let su = stroke.0.abs().max(stroke.1.abs());
    let sv = rate.0.abs().max(rate.1.abs());
    let force = link.link.stiffness * su + link.link.damping * sv.powf(link.link.exponent);
    (su <= peaks.stroke || stroke_monotone)
        && (sv <= peaks.max_rate || rate_monotone)
        && force <= peaks.max_force
}
