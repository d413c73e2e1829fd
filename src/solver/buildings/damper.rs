//! Fluid viscous dampers in the exact method (SPEC §14): a link whose
//! dashpot has exponent α < 1,
//!
//! ```text
//! F_d = c_l |Δv|^α sgn Δv,   Δv = u̇_A − u̇_B,   −F_d on A, +F_d on B,
//! ```
//!
//! its spring k_l being in K of every configuration ([`super::link::add_linear`]).
//! F_d is continuous but not smooth where Δv = 0, and its slope
//! c_l α |Δv|^(α−1) has no bound there, so no configuration's linear map
//! carries it: a row with a damper never takes a map step. Away from a
//! reversal, where F_d is analytic in time, and where the damper is not
//! stiff over the step, a step is the Taylor series of the motion with F_d
//! in it ([`super::power_series`], chosen by `driver/damped.rs`); else it
//! is a step of [`super::contact_rk`], the configuration's linear motion
//! with F_d collocated at the nodes of Radau IIA
//! ([`super::damper_collocation`]), or, through a Hertz-type contact, the
//! Runge–Kutta steps with F_d in their right-hand side.
//!
//! **Reversals.** Each instant where a damper's Δv changes sign is an event
//! (g = −σΔv rising through 0, σ the sign of Δv in the current phase,
//! [`super::driver`]), found
//! on the step's polynomial and placed on the motion by Newton's method as
//! every event is, so that no step straddles the kink. Right after a
//! reversal at s = 0, with Δa = a₀,
//!
//! ```text
//! Δv ≈ a₀ s − (c_l/m̄) |a₀|^α sgn(a₀) s^(1+α)/(1+α) + …,
//! ```
//!
//! not analytic in s: a step of length h from the kink carries a local
//! error of order h^(1+α) in Δv, which the embedded error estimate sees, so
//! the adaptive steps start short and grow geometrically from there; a step
//! rejected because it reaches across the next kink is retried to where its
//! own dense output puts the kink ([`first_reversal`]).

use crate::model::buildings::LinkElement;
use crate::model::buildings::retrofit::dashpot_force;

/// One fluid viscous damper (a link with α < 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Damper {
    /// Its index among the row's links (file order).
    pub link: usize,
    /// The floors it joins, A left and B right.
    pub left: usize,
    pub right: usize,
    /// c_l (N·(s/m)^α) and α.
    pub damping: f64,
    pub exponent: f64,
    /// 1/m_A and 1/m_B.
    pub left_rate: f64,
    pub right_rate: f64,
}

impl Damper {
    /// Every damper among `links`, in their order, with the floors'
    /// masses `mass`.
    pub fn all(links: &[LinkElement], mass: &[f64]) -> Vec<Damper> {
        links
            .iter()
            .enumerate()
            .filter(|(_, l)| !l.is_linear())
            .map(|(link, l)| {
                let (a, b) = (l.pair.left_dof, l.pair.right_dof);
                Damper {
                    link,
                    left: a,
                    right: b,
                    damping: l.link.damping,
                    exponent: l.link.exponent,
                    left_rate: 1.0 / mass[a],
                    right_rate: 1.0 / mass[b],
                }
            })
            .collect()
    }

    /// Δv = u̇_A − u̇_B.
    #[inline]
    pub fn rate(&self, v: &[f64]) -> f64 {
        v[self.left] - v[self.right]
    }

    /// F_d = c_l |Δv|^α sgn Δv (N).
    #[inline]
    pub fn force(&self, rate: f64) -> f64 {
        dashpot_force(self.damping, self.exponent, rate)
    }

    /// Adds −F_d/m_A to ü_A and F_d/m_B to ü_B.
    #[inline]
    pub fn add_to(&self, v: &[f64], acc: &mut [f64]) {
        let f = self.force(self.rate(v));
        acc[self.left] -= self.left_rate * f;
        acc[self.right] += self.right_rate * f;
    }

    /// Whether the damper is stiff over a step of length h at Δv = `rate`:
    /// its relaxation time m̄/(c_l α |Δv|^(α−1)) (with 1/m̄ = 1/m_A + 1/m_B)
    /// is shorter than h. There Δv sits on its slow manifold, where the
    /// damper's force balances the force across it, and a step may carry
    /// Δv across 0 and back at the size of its own error: such crossings
    /// are not watched as events (they would chop the steps without end),
    /// and the step's error control alone holds the motion.
    pub fn stiff(&self, rate: f64, h: f64) -> bool {
        self.slope(rate) * (self.left_rate + self.right_rate) * h > 1.0
    }

    /// The relaxation time m̄/(c_l α |Δv|^(α−1)) at Δv = `rate` (s): the
    /// longest step over which the damper is not [`Damper::stiff`].
    pub fn relaxation(&self, rate: f64) -> f64 {
        1.0 / (self.slope(rate) * (self.left_rate + self.right_rate))
    }

    /// The law's slope dF/dΔv = c_l α |Δv|^(α−1) (N·s/m).
    fn slope(&self, rate: f64) -> f64 {
        self.damping * self.exponent * rate.abs().powf(self.exponent - 1.0)
    }
}

/// The sign of each damper's Δv at `v`, 0 where it is 0 (at rest: the
/// phase has no sign until Δv takes one).
pub fn signs(dampers: &[Damper], v: &[f64]) -> Vec<f64> {
    dampers.iter().map(|d| sign(d.rate(v))).collect()
}

/// The sign of a damper's Δv = `rate`, 0 where it is 0.
pub fn sign(rate: f64) -> f64 {
    match rate {
        r if r > 0.0 => 1.0,
        r if r < 0.0 => -1.0,
        _ => 0.0,
    }
}

/// Where on a step some damper's Δv first changes sign, as the fraction θ
/// of the step, located on `dense` (the state at θ ∈ [0, 1]) by bisection
/// between the start `v0` and the end `v1`; None when every damper ends
/// with the sign it started with (or started at 0), or is [`Damper::stiff`]
/// over the step's length `h`. A step rejected for its error is retried to
/// there: its error came from the kink.
pub fn first_reversal(
    dampers: &[Damper],
    h: f64,
    v0: &[f64],
    v1: &[f64],
    dense: impl Fn(f64) -> Vec<f64>,
) -> Option<f64> {
    let n = v0.len();
    let mut first: Option<f64> = None;
    for d in dampers {
        let start = d.rate(v0);
        if start == 0.0 || start * d.rate(v1) >= 0.0 || d.stiff(start, h) {
            continue;
        }
        let (mut lo, mut hi) = (0.0, first.unwrap_or(1.0));
        if start * d.rate(&dense(hi)[n..]) >= 0.0 {
            continue;
        }
        for _ in 0..50 {
            let mid = 0.5 * (lo + hi);
            if start * d.rate(&dense(mid)[n..]) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        first = Some(hi);
    }
    first
}
