//! The equations of motion of SPEC §2–4 written as a first-order system
//! y = (x1, ẋ1, x2, ẋ2), smooth between events.
//!
//! Between events each spring is on one branch of the bilinear law (SPEC §3):
//! - elastic, anchored at (x_a, z_a): z = z_a + (x − x_a);
//! - yielded with sign σ: z = σ Π_uy;
//!
//! so f_s = Π_α k x + (1 − Π_α) k z is affine in x, and the contact is either
//! open (f_p = 0) or closed with the law fixed at onset (SPEC §4). Everything
//! is recomputed here from [`Params`]; nothing is taken from `solver`.

use crate::model::{ContactModel, Excitation, Params};

use super::dopri5::Vector;

/// One spring's branch between events (SPEC §3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Branch {
    /// z = z_anchor + (x − x_anchor), |z| < Π_uy.
    Elastic { x_anchor: f64, z_anchor: f64 },
    /// z = sign · Π_uy while sign · ẋ > 0.
    Yielded { sign: f64 },
}

/// The pounding force law of one contact phase (SPEC §4, §10), every law as
/// one sum whose unused terms are zero:
///
/// f_p = k̄δ + cδ̇ + hδδ̇ + K δ^{3/2} + K λ δ^{3/2} δ̇ + c_J δ^{1/4} max(δ̇, 0).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Contact {
    pub stiffness: f64,
    pub dashpot: f64,
    pub penetration_dashpot: f64,
    /// K of the Hertz-type laws.
    pub hertz: f64,
    /// K λ: the δ^{3/2} δ̇ term (Muthukumar–DesRoches, Hunt–Crossley).
    pub hertz_dashpot: f64,
    /// 2 ζ_J √(K m̄): Jankowski's approach-only damping, c = this · δ^{1/4}.
    pub approach_dashpot: f64,
}

/// Which pieces are active between two events.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    pub springs: [Branch; 2],
    pub contact: Option<Contact>,
}

/// The constant coefficients, recomputed from the Π-groups.
#[derive(Debug, Clone)]
pub struct Structures {
    /// Masses (Π_m, 1).
    pub mass: [f64; 2],
    /// Dashpots 2Π_ξΠ_mΠ_ω1 and 2Π_ξΠ_ω2 (SPEC §2).
    pub damping: [f64; 2],
    /// Elastic stiffness k1 = Π_m Π_ω1², k2 = Π_ω2² (SPEC §3).
    pub stiffness: [f64; 2],
    pub yield_displacement: [f64; 2],
    pub alpha: f64,
    pub gap: f64,
    pub excitation: Excitation,
    params: Params,
}

impl Structures {
    pub fn new(p: &Params, excitation: Excitation) -> Self {
        Structures {
            mass: [p.mass_ratio, 1.0],
            damping: [
                2.0 * p.damping * p.mass_ratio * p.omega1,
                2.0 * p.damping * p.omega2,
            ],
            stiffness: [p.mass_ratio * p.omega1.powi(2), p.omega2.powi(2)],
            yield_displacement: [p.yield1, p.yield2],
            alpha: p.alpha,
            gap: p.gap,
            excitation,
            params: p.clone(),
        }
    }

    /// δ = x1 − x2 − Π_d (SPEC §4).
    #[inline]
    pub fn penetration(&self, y: &Vector) -> f64 {
        y[0] - y[2] - self.gap
    }

    /// δ̇ = ẋ1 − ẋ2.
    #[inline]
    pub fn penetration_rate(&self, y: &Vector) -> f64 {
        y[1] - y[3]
    }

    /// The elastic part z of spring `i` at displacement `x` on `branch`.
    #[inline]
    pub fn elastic_part(&self, i: usize, branch: Branch, x: f64) -> f64 {
        match branch {
            Branch::Elastic { x_anchor, z_anchor } => z_anchor + (x - x_anchor),
            Branch::Yielded { sign } => sign * self.yield_displacement[i],
        }
    }

    /// f_s = Π_α k x + (1 − Π_α) k z (SPEC §3).
    #[inline]
    pub fn spring_force(&self, i: usize, branch: Branch, x: f64) -> f64 {
        let k = self.stiffness[i];
        self.alpha * k * x + (1.0 - self.alpha) * k * self.elastic_part(i, branch, x)
    }

    /// The contact law for an onset with approach velocity `approach` (SPEC §4):
    /// m̄ = Π_m/(1+Π_m), k̄ = m̄ Π_ωcon²; Kelvin c = 2ζm̄Π_ωcon with
    /// ζ = −ln e/√(π² + ln² e); improved Kelvin h = k̄ · 3(1−e)/(2e v₀),
    /// v₀ = max(approach, min_impact_velocity).
    pub fn contact_at_onset(&self, approach: f64) -> Contact {
        let p = &self.params;
        let m_bar = p.mass_ratio / (1.0 + p.mass_ratio);
        let stiffness = m_bar * p.contact_omega * p.contact_omega;
        let e = p.restitution;
        let v0 = approach.max(p.min_impact_velocity);
        let k = p.hertz_stiffness();
        match p.model {
            ContactModel::Kelvin => {
                let log_e = e.ln();
                let zeta = -log_e / (std::f64::consts::PI.powi(2) + log_e * log_e).sqrt();
                Contact {
                    stiffness,
                    dashpot: 2.0 * zeta * m_bar * p.contact_omega,
                    ..Contact::default()
                }
            }
            ContactModel::ImprovedKelvin => Contact {
                stiffness,
                penetration_dashpot: stiffness * 1.5 * (1.0 - e) / (e * v0),
                ..Contact::default()
            },
            // SPEC §10: K δ^{3/2}.
            ContactModel::Hertz => Contact {
                hertz: k,
                ..Contact::default()
            },
            // K δ^{3/2} (1 + 3(1 − e²)/(4 v₀) δ̇).
            ContactModel::HertzDamp => Contact {
                hertz: k,
                hertz_dashpot: k * 0.75 * (1.0 - e * e) / v0,
                ..Contact::default()
            },
            // K δ^{3/2} (1 + 3(1 − e)/(2 v₀) δ̇).
            ContactModel::HuntCrossley => Contact {
                hertz: k,
                hertz_dashpot: k * 1.5 * (1.0 - e) / v0,
                ..Contact::default()
            },
            // K δ^{3/2} + 2ζ_J √(K m̄ √δ) δ̇ while δ̇ > 0,
            // ζ_J = 9√5 (1 − e²) / (2e (e(9π − 16) + 16)).
            ContactModel::Jankowski => {
                let pi = std::f64::consts::PI;
                let zeta =
                    9.0 * 5f64.sqrt() * (1.0 - e * e) / (2.0 * e * (e * (9.0 * pi - 16.0) + 16.0));
                Contact {
                    hertz: k,
                    approach_dashpot: 2.0 * zeta * (k * m_bar).sqrt(),
                    ..Contact::default()
                }
            }
        }
    }

    /// f_p in a mode (0 when open).
    #[inline]
    pub fn pounding_force(&self, mode: &Mode, y: &Vector) -> f64 {
        match mode.contact {
            None => 0.0,
            Some(c) => {
                let d = self.penetration(y);
                let r = self.penetration_rate(y);
                let linear = c.stiffness * d + c.dashpot * r + c.penetration_dashpot * d * r;
                if c.hertz == 0.0 {
                    return linear;
                }
                let dp = d.max(0.0);
                let d32 = dp * dp.sqrt();
                let approach = if r > 0.0 {
                    c.approach_dashpot * dp.sqrt().sqrt() * r
                } else {
                    0.0
                };
                linear + c.hertz * d32 + c.hertz_dashpot * d32 * r + approach
            }
        }
    }

    /// The absolute accelerations (ẍ1 + g, ẍ2 + g) in a mode (SPEC §2, §6):
    ///   Π_m (ẍ1 + g) = −2Π_ξΠ_mΠ_ω1 ẋ1 − f_s1 − f_p,
    ///        ẍ2 + g  = −2Π_ξΠ_ω2 ẋ2 − f_s2 + f_p.
    #[inline]
    pub fn absolute_acceleration(&self, mode: &Mode, y: &Vector) -> [f64; 2] {
        let fp = self.pounding_force(mode, y);
        let fs1 = self.spring_force(0, mode.springs[0], y[0]);
        let fs2 = self.spring_force(1, mode.springs[1], y[2]);
        [
            (-self.damping[0] * y[1] - fs1 - fp) / self.mass[0],
            (-self.damping[1] * y[3] - fs2 + fp) / self.mass[1],
        ]
    }

    /// ẏ = (ẋ1, ẍ1, ẋ2, ẍ2) with (SPEC §2)
    ///   Π_m ẍ1 = −2Π_ξΠ_mΠ_ω1 ẋ1 − f_s1 − f_p − Π_m g(τ),
    ///       ẍ2 = −2Π_ξΠ_ω2 ẋ2 − f_s2 + f_p − g(τ).
    #[inline]
    pub fn derivative(&self, mode: &Mode, tau: f64, y: &Vector) -> Vector {
        let g = self.excitation.at(tau);
        let fp = self.pounding_force(mode, y);
        let fs1 = self.spring_force(0, mode.springs[0], y[0]);
        let fs2 = self.spring_force(1, mode.springs[1], y[2]);
        [
            y[1],
            (-self.damping[0] * y[1] - fs1 - fp) / self.mass[0] - g,
            y[3],
            (-self.damping[1] * y[3] - fs2 + fp) / self.mass[1] - g,
        ]
    }
}
