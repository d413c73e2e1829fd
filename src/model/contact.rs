//! Contact laws of SPEC §4: the pounding force f_p between the two structures
//! as a function of penetration δ = x1 − x2 − Π_d and its rate δ̇ = ẋ1 − ẋ2.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// Which contact element models the collision (SPEC §4, §10).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactModel {
    /// Linear spring and dashpot: f_p = k̄ δ + 2 ζ m̄ Π_ωcon δ̇. It jumps at onset
    /// and pulls before separation (the defect the paper shows; not clipped).
    Kelvin,
    /// The paper's model: f_p = k̄ δ (1 + 3(1−e)/(2e) · δ̇/v₀).
    ImprovedKelvin,
    /// Hertz: f_p = K δ^{3/2}, elastic.
    Hertz,
    /// Muthukumar and DesRoches: f_p = K δ^{3/2} (1 + 3(1 − e²)/(4 v₀) · δ̇).
    #[serde(rename = "hertzdamp")]
    HertzDamp,
    /// Jankowski: f_p = K δ^{3/2} + c δ̇ while δ̇ > 0, K δ^{3/2} while δ̇ ≤ 0,
    /// c = 2 ζ_J √(K m̄ √δ).
    Jankowski,
    /// Hunt and Crossley: f_p = K δ^{3/2} (1 + 3(1 − e)/(2 v₀) · δ̇).
    HuntCrossley,
}

impl ContactModel {
    /// The paper's two models (SPEC §4).
    pub const PAPER: [ContactModel; 2] = [ContactModel::Kelvin, ContactModel::ImprovedKelvin];

    /// Every law (SPEC §4, §10).
    pub const ALL: [ContactModel; 6] = [
        ContactModel::Kelvin,
        ContactModel::ImprovedKelvin,
        ContactModel::Hertz,
        ContactModel::HertzDamp,
        ContactModel::Jankowski,
        ContactModel::HuntCrossley,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ContactModel::Kelvin => "kelvin",
            ContactModel::ImprovedKelvin => "improved-kelvin",
            ContactModel::Hertz => "hertz",
            ContactModel::HertzDamp => "hertzdamp",
            ContactModel::Jankowski => "jankowski",
            ContactModel::HuntCrossley => "hunt-crossley",
        }
    }

    /// The paper's two models swap (the explorer's `m` key); a Hertz-type law goes to Kelvin.
    pub fn toggled(self) -> Self {
        match self {
            ContactModel::Kelvin => ContactModel::ImprovedKelvin,
            _ => ContactModel::Kelvin,
        }
    }

    /// Whether the force is K δ^{3/2}-based (SPEC §10): not analytic at δ = 0.
    pub fn is_hertzian(self) -> bool {
        !matches!(self, ContactModel::Kelvin | ContactModel::ImprovedKelvin)
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
            "improved_kelvin" => Ok(ContactModel::ImprovedKelvin),
            "hunt_crossley" => Ok(ContactModel::HuntCrossley),
            _ => ContactModel::ALL
                .into_iter()
                .find(|m| m.name() == s)
                .ok_or(()),
        }
    }
}

/// 2∫₀¹ (1 − s^{5/2})^{−1/2} ds = 2√π Γ(7/5)/Γ(9/10): an elastic Hertz contact of reduced mass m̄
/// and approach velocity v₀ lasts t_c = [`HERTZ_DURATION`] · δ_m/v₀, with the
/// largest penetration δ_m = (5 m̄ v₀²/(4K))^{2/5} (energy: ½m̄v₀² = ⅖Kδ_m^{5/2}).
pub const HERTZ_DURATION: f64 = 2.943_275_184_3;

/// Approach velocity at which [`matched_hertz_stiffness`] matches contact
/// durations: 1, the unit a_p/ω_p of the dimensionless velocities (set 1's
/// impacts approach at 0.2 to 1.6).
pub const MATCHING_VELOCITY: f64 = 1.0;

/// The Hertz stiffness Π_K (SPEC §10) whose elastic contact at v₀ = 1 lasts
/// as long as the linear element's half period π/Π_ωcon, so that every law
/// compares like for like: δ_m = v₀ (π/Π_ωcon)/[`HERTZ_DURATION`] and
/// K = 5 m̄ v₀²/(4 δ_m^{5/2}), m̄ = Π_m/(1+Π_m).
pub fn matched_hertz_stiffness(mass_ratio: f64, contact_omega: f64) -> f64 {
    let m_bar = mass_ratio / (1.0 + mass_ratio);
    let v = MATCHING_VELOCITY;
    let delta_max = v * (std::f64::consts::PI / contact_omega) / HERTZ_DURATION;
    1.25 * m_bar * v * v / delta_max.powf(2.5)
}

/// Jankowski's damping ratio ζ_J = 9√5 (1 − e²) / (2e (e(9π − 16) + 16)) (SPEC §10).
pub fn jankowski_damping_ratio(e: f64) -> f64 {
    let pi = std::f64::consts::PI;
    9.0 * 5f64.sqrt() * (1.0 - e * e) / (2.0 * e * (e * (9.0 * pi - 16.0) + 16.0))
}

/// Damping ratio of the Kelvin dashpot that returns restitution e when the
/// contact ends at δ = 0: ζ = −ln e / √(π² + ln² e) (SPEC §4).
pub fn kelvin_damping_ratio(e: f64) -> f64 {
    let l = e.ln();
    -l / (std::f64::consts::PI.powi(2) + l * l).sqrt()
}

/// The contact element with its constants folded in, for one contact phase.
///
/// With m̄ = Π_m/(1+Π_m) and k̄ = m̄ Π_ωcon² (SPEC §4), the Kelvin family is
/// written f_p = k̄ δ + c δ̇ + h δ δ̇ with
/// - Kelvin: c = 2 ζ m̄ Π_ωcon, h = 0;
/// - improved Kelvin: c = 0, h = k̄ · 3(1−e)/(2e v₀), v₀ the approach velocity
///   at the located onset, floored at `min_impact_velocity`.
///
/// The Hertz-type laws of SPEC §10 carry their own terms in `hertzian`
/// (and have k̄ = c = h = 0): their force is not analytic at δ = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// k̄, contact stiffness.
    pub stiffness: f64,
    /// c, linear dashpot coefficient (Kelvin).
    pub linear_damping: f64,
    /// h, penetration-proportional damping coefficient (improved Kelvin).
    pub hertz_damping: f64,
    /// A K δ^{3/2} law, if this is one.
    pub hertzian: Option<Hertzian>,
}

/// A Hertz-type law of SPEC §10 with its constants for one contact phase:
/// f_p = K δ^{3/2} (1 + λ δ̇) + η δ^{1/4} max(δ̇, 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertzian {
    /// K = Π_K.
    pub stiffness: f64,
    /// λ: 3(1 − e²)/(4v₀) (Muthukumar–DesRoches), 3(1 − e)/(2v₀) (Hunt–Crossley), else 0.
    pub hysteresis: f64,
    /// η = 2 ζ_J √(K m̄) (Jankowski, whose c = η δ^{1/4}), else 0.
    pub approach_damping: f64,
}

/// Force and its partial derivatives ∂f/∂δ and ∂f/∂δ̇ (the contact tangent).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    pub force: f64,
    pub d_penetration: f64,
    pub d_rate: f64,
}

/// What a contact law needs besides δ and δ̇ (SPEC §4, §10), taken from a
/// parameter set by `ContactConstants::of` (in [`super::params`], which
/// owns the parameters and names the law they use).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactConstants {
    pub model: ContactModel,
    pub mass_ratio: f64,
    pub contact_omega: f64,
    pub restitution: f64,
    /// Π_K of the Hertz-type laws.
    pub hertz_stiffness: f64,
    pub min_impact_velocity: f64,
}

impl ContactConstants {
    /// The law of a contact that began with approach velocity `approach_velocity`.
    pub fn law(&self, approach_velocity: f64) -> ContactLaw {
        let m_bar = self.mass_ratio / (1.0 + self.mass_ratio);
        let e = self.restitution;
        let v0 = approach_velocity.max(self.min_impact_velocity);
        let k = self.hertz_stiffness;
        match self.model {
            ContactModel::Kelvin | ContactModel::ImprovedKelvin => ContactLaw::new(
                self.model,
                self.mass_ratio,
                self.contact_omega,
                e,
                approach_velocity,
                self.min_impact_velocity,
            ),
            hertzian => ContactLaw::hertz_type(hertzian, k, m_bar, e, v0),
        }
    }
}

impl ContactLaw {
    /// A Hertz-type law of SPEC §10 in any consistent units: stiffness β
    /// (Π_K, or N/m^{3/2}), reduced mass m̄, restitution e and the floored
    /// approach velocity v₀. λ = 3(1 − e²)/(4v₀) (Hertz with damping),
    /// 3(1 − e)/(2v₀) (Hunt–Crossley); η = 2ζ_J√(βm̄) (Jankowski); the bare
    /// Hertz law has neither. The Kelvin family is not Hertz-type and must
    /// not be asked for: it is given the bare Hertz law.
    pub fn hertz_type(model: ContactModel, stiffness: f64, m_bar: f64, e: f64, v0: f64) -> Self {
        let (hysteresis, approach_damping) = match model {
            ContactModel::HertzDamp => (3.0 * (1.0 - e * e) / (4.0 * v0), 0.0),
            ContactModel::HuntCrossley => (3.0 * (1.0 - e) / (2.0 * v0), 0.0),
            ContactModel::Jankowski => (
                0.0,
                2.0 * jankowski_damping_ratio(e) * (stiffness * m_bar).sqrt(),
            ),
            ContactModel::Hertz | ContactModel::Kelvin | ContactModel::ImprovedKelvin => (0.0, 0.0),
        };
        ContactLaw {
            stiffness: 0.0,
            linear_damping: 0.0,
            hertz_damping: 0.0,
            hertzian: Some(Hertzian {
                stiffness,
                hysteresis,
                approach_damping,
            }),
        }
    }

    /// The Kelvin-family law for a contact that began with approach velocity
    /// `approach_velocity` (δ̇ at onset). The Hertz-type laws need Π_K:
    /// [`ContactConstants::law`].
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
            ContactModel::ImprovedKelvin => {
                let v0 = approach_velocity.max(min_impact_velocity);
                ContactLaw {
                    stiffness,
                    linear_damping: 0.0,
                    hertz_damping: stiffness * 3.0 * (1.0 - restitution) / (2.0 * restitution * v0),
                    hertzian: None,
                }
            }
            ContactModel::Kelvin => ContactLaw {
                stiffness,
                linear_damping: 2.0 * kelvin_damping_ratio(restitution) * m_bar * contact_omega,
                hertz_damping: 0.0,
                hertzian: None,
            },
            hertzian => ContactConstants {
                model: hertzian,
                mass_ratio,
                contact_omega,
                restitution,
                hertz_stiffness: matched_hertz_stiffness(mass_ratio, contact_omega),
                min_impact_velocity,
            }
            .law(approach_velocity),
        }
    }

    /// Whether the force is a polynomial in (δ, δ̇), so that the motion in
    /// contact is analytic (the Kelvin family), or a K δ^{3/2} law.
    #[inline]
    pub fn is_analytic(&self) -> bool {
        self.hertzian.is_none()
    }

    /// f_p(δ, δ̇) and its tangent, for δ > 0 (in contact). A Hertz-type law
    /// takes δ⁺ = max(δ, 0), so a trial state just outside contact gives 0.
    #[inline]
    pub fn force(&self, penetration: f64, rate: f64) -> ContactForce {
        if let Some(h) = &self.hertzian {
            return h.force(penetration, rate);
        }
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

impl Hertzian {
    /// f = K δ^{3/2}(1 + λ δ̇) + η δ^{1/4} δ̇⁺ with ∂f/∂δ = 3/2 K δ^{1/2}(1 + λδ̇)
    /// + ¼ η δ^{−3/4} δ̇⁺ and ∂f/∂δ̇ = K λ δ^{3/2} + η δ^{1/4} [δ̇ > 0].
    #[inline]
    pub fn force(&self, penetration: f64, rate: f64) -> ContactForce {
        let d = penetration.max(0.0);
        let root = d.sqrt();
        let d32 = d * root;
        let k = self.stiffness;
        let factor = 1.0 + self.hysteresis * rate;
        let mut out = ContactForce {
            force: k * d32 * factor,
            d_penetration: 1.5 * k * root * factor,
            d_rate: k * self.hysteresis * d32,
        };
        if self.approach_damping > 0.0 && rate > 0.0 && d > 0.0 {
            let quarter = root.sqrt();
            let c = self.approach_damping * quarter;
            out.force += c * rate;
            out.d_rate += c;
            out.d_penetration += 0.25 * c * rate / d;
        }
        out
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
    fn matched_hertz_contact_lasts_the_linear_half_period() {
        // 2∫₀¹ (1 − s^{5/2})^{−1/2} ds by the substitution s = 1 − u², midpoint rule.
        let n = 200_000;
        let mut sum = 0.0;
        for i in 0..n {
            let u = (i as f64 + 0.5) / n as f64;
            let s: f64 = 1.0 - u * u;
            sum += 2.0 * u / (1.0 - s.powf(2.5)).sqrt() / n as f64;
        }
        assert!((2.0 * sum - HERTZ_DURATION).abs() < 1e-5, "{}", 2.0 * sum);
        // Set 1: m̄ = 1/3, Π_ωcon = 50.
        let k = matched_hertz_stiffness(0.5, 50.0);
        let delta_max = (5.0 / 3.0 / (4.0 * k)).powf(0.4);
        let t = HERTZ_DURATION * delta_max;
        assert!((t - std::f64::consts::PI / 50.0).abs() < 1e-12, "{t}");
    }

    #[test]
    fn jankowski_zeta_formula() {
        // e = 0.65: 9√5 · 0.5775 / (1.3 · (0.65 · 12.2743 + 16)) = 11.6220/31.1716 = 0.37284.
        assert!((jankowski_damping_ratio(0.65) - 0.372_836).abs() < 1e-6);
        assert_eq!(jankowski_damping_ratio(1.0), 0.0);
    }

    #[test]
    fn improved_kelvin_is_spring_at_e_1() {
        let law = ContactLaw::new(ContactModel::ImprovedKelvin, 0.5, 50.0, 1.0, 1.0, 1e-3);
        let f = law.force(0.01, 3.0);
        assert!((f.force - 0.5 / 1.5 * 2500.0 * 0.01).abs() < 1e-12);
    }
}
