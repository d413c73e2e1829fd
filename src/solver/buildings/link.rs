//! Links across the joints in the exact method (SPEC §14):
//! F = k_l Δu + c_l |Δv|^α sgn Δv between floors A and B, −F on A, +F on B.
//!
//! - The spring k_l is linear always, and so is the dashpot when α = 1: both
//!   enter K and C of every configuration ([`add_linear`]), so that the
//!   cached maps and the Taylor series carry them exactly.
//! - A fluid viscous damper (α < 1) is the one nonlinear element that is
//!   always on: its force c_l|Δv|^α sgn Δv is added to the motion by the
//!   Runge–Kutta steps of [`super::contact_rk`], and the instants where Δv
//!   changes sign, where it is not smooth, are events.
//!
//! Per link a run reports peak |F|, peak |Δu| (the stroke), peak |Δv|, and
//! the energy its dashpot dissipated, E_l = ∫ c_l |Δv|^(α+1) dt.

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use crate::model::buildings::LinkElement;
use crate::solver::exact::contact_rk::equispaced_quintic;

use super::poly;
use super::taylor::Series;

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

/// Whether any link is a fluid viscous damper (α < 1).
pub fn any_damper(links: &[LinkElement]) -> bool {
    links.iter().any(|l| !l.is_linear())
}

/// Adds the fluid viscous dampers' forces (α < 1) to the accelerations
/// `acc` at (u, u̇): −F/m_A on A, +F/m_B on B, F = c_l|Δv|^α sgn Δv.
pub fn add_damper_forces(links: &[LinkElement], mass: &[f64], v: &[f64], acc: &mut [f64]) {
    for l in links.iter().filter(|l| !l.is_linear()) {
        let (a, b) = (l.pair.left_dof, l.pair.right_dof);
        let dv = v[a] - v[b];
        let f = l.link.damping * dv.abs().powf(l.link.exponent) * dv.signum();
        acc[a] -= f / mass[a];
        acc[b] += f / mass[b];
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

/// Raises each link's peaks over [0, end] of a step written as `series`:
/// |Δu| and |Δv| on their polynomials; |F| on its polynomial for a linear
/// link, and on the quintic through six equally spaced values of F for a
/// damper (α < 1), as the Hertz-type contact forces are taken.
pub fn peaks_on(
    links: &[LinkElement],
    series: &Series,
    end: f64,
    out: &mut [LinkResult],
    (du, dv): (&mut Vec<f64>, &mut Vec<f64>),
) {
    for (l, r) in links.iter().zip(out) {
        let (a, b) = (l.pair.left_dof, l.pair.right_dof);
        series.combine(&[(a, 1.0), (b, -1.0)], &[], du);
        series.combine(&[], &[(a, 1.0), (b, -1.0)], dv);
        if poly::magnitude_bound(du, end) > r.stroke {
            r.stroke = r.stroke.max(poly::max_abs(du, end));
        }
        if poly::magnitude_bound(dv, end) > r.max_rate {
            r.max_rate = r.max_rate.max(poly::max_abs(dv, end));
        }
        let force: Vec<f64> = if l.is_linear() {
            du.iter()
                .zip(dv.iter())
                .map(|(x, y)| l.link.stiffness * x + l.link.damping * y)
                .collect()
        } else {
            let values = std::array::from_fn(|j| {
                let s = end * j as f64 / 5.0;
                l.force(poly::eval(du, s), poly::eval(dv, s))
            });
            equispaced_quintic(&values, end).c[..=5].to_vec()
        };
        if poly::magnitude_bound(&force, end) > r.max_force {
            r.max_force = r.max_force.max(poly::max_abs(&force, end));
        }
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
