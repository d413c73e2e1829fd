//! Contact laws of SPEC §4: the pounding force f_p between the two structures
//! as a function of penetration δ = x1 − x2 − Π_d and its rate δ̇ = ẋ1 − ẋ2.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// Which contact element models the collision (SPEC §4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactModel {
    /// Linear spring and dashpot: f_p = k̄ δ + 2 ζ m̄ Π_ωcon δ̇. It jumps at onset
    /// and pulls before separation (the defect the paper shows; not clipped).
    Kelvin,
    /// The paper's model: f_p = k̄ δ (1 + 3(1−e)/(2e) · δ̇/v₀).
    ImprovedKelvin,
}

impl ContactModel {
    pub const ALL: [ContactModel; 2] = [ContactModel::Kelvin, ContactModel::ImprovedKelvin];

    pub fn name(self) -> &'static str {
        match self {
            ContactModel::Kelvin => "kelvin",
            ContactModel::ImprovedKelvin => "improved-kelvin",
        }
    }

    /// The other model (the explorer's `m` key).
    pub fn toggled(self) -> Self {
        match self {
            ContactModel::Kelvin => ContactModel::ImprovedKelvin,
            ContactModel::ImprovedKelvin => ContactModel::Kelvin,
        }
    }
}

impl fmt::Display for ContactModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ContactModel {
    type Err = ();
    fn from_str(s: &str) -> Result<Self, ()> {
        match s {
            "kelvin" => Ok(ContactModel::Kelvin),
            "improved-kelvin" | "improved_kelvin" => Ok(ContactModel::ImprovedKelvin),
            _ => Err(()),
        }
    }
}

/// Damping ratio of the Kelvin dashpot that returns restitution e when the
/// contact ends at δ = 0: ζ = −ln e / √(π² + ln² e) (SPEC §4).
pub fn kelvin_damping_ratio(e: f64) -> f64 {
    let l = e.ln();
    -l / (std::f64::consts::PI.powi(2) + l * l).sqrt()
}

/// The contact element with its constants folded in, for one contact phase.
///
/// With m̄ = Π_m/(1+Π_m) and k̄ = m̄ Π_ωcon² (SPEC §4), the force is written
/// f_p = k̄ δ + c δ̇ + h δ δ̇ with
/// - Kelvin: c = 2 ζ m̄ Π_ωcon, h = 0;
/// - improved Kelvin: c = 0, h = k̄ · 3(1−e)/(2e v₀), v₀ the approach velocity
///   at the located onset, floored at `min_impact_velocity`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// k̄, contact stiffness.
    pub stiffness: f64,
    /// c, linear dashpot coefficient (Kelvin).
    pub linear_damping: f64,
    /// h, penetration-proportional damping coefficient (improved Kelvin).
    pub hertz_damping: f64,
}

/// Force and its partial derivatives ∂f/∂δ and ∂f/∂δ̇ (the contact tangent).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    pub force: f64,
    pub d_penetration: f64,
    pub d_rate: f64,
}

impl ContactLaw {
    /// The law for a contact that began with approach velocity `approach_velocity` (δ̇ at onset).
    pub fn new(
        model: ContactModel,
        mass_ratio: f64,
        contact_omega: f64,
        restitution: f64,
        approach_velocity: f64,
        min_impact_velocity: f64,
    ) -> Self {
        let m_bar = mass_ratio / (1.0 + mass_ratio);
        let stiffness = m_bar * contact_omega * contact_omega;
        match model {
            ContactModel::Kelvin => ContactLaw {
                stiffness,
                linear_damping: 2.0 * kelvin_damping_ratio(restitution) * m_bar * contact_omega,
                hertz_damping: 0.0,
            },
            ContactModel::ImprovedKelvin => {
                let v0 = approach_velocity.max(min_impact_velocity);
                ContactLaw {
                    stiffness,
                    linear_damping: 0.0,
                    hertz_damping: stiffness * 3.0 * (1.0 - restitution) / (2.0 * restitution * v0),
                }
            }
        }
    }

    /// f_p(δ, δ̇) and its tangent, for δ > 0 (in contact).
    #[inline]
    pub fn force(&self, penetration: f64, rate: f64) -> ContactForce {
        let k = self.stiffness;
        let c = self.linear_damping;
        let h = self.hertz_damping;
        ContactForce {
            force: k * penetration + c * rate + h * penetration * rate,
            d_penetration: k + h * rate,
            d_rate: c + h * penetration,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kelvin_zeta_limits() {
        assert!(kelvin_damping_ratio(1.0).abs() < 1e-15);
        // e = 0.4: ln e = -0.916291, ζ = 0.916291/√(9.869604+0.839589) = 0.2799978
        assert!((kelvin_damping_ratio(0.4) - 0.2799978).abs() < 1e-6);
    }

    #[test]
    fn improved_kelvin_is_spring_at_e_1() {
        let law = ContactLaw::new(ContactModel::ImprovedKelvin, 0.5, 50.0, 1.0, 1.0, 1e-3);
        let f = law.force(0.01, 3.0);
        assert!((f.force - 0.5 / 1.5 * 2500.0 * 0.01).abs() < 1e-12);
    }
}
