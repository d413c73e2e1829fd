//! The contact law of one floor pair in physical form (SPEC §13, with §4 and §10).
//!
//! With m̄ = m_A,i m_B,j/(m_A,i + m_B,j) and the joint's stiffness k̄ (β for the
//! Hertz-type laws), the law is [`ContactLaw`] of SPEC §4/§10 with
//! - Kelvin: f = k̄δ + 2ζ√(k̄m̄) δ̇, ζ = −ln e/√(π² + ln² e);
//! - improved Kelvin: f = k̄δ(1 + 3(1−e)/(2e) · δ̇/v₀);
//! - Hertz-type: f = βδ^{3/2}(1 + λδ̇) + 2ζ_J√(βm̄) δ^{1/4} δ̇⁺,
//!   so the one-storey row is the pair of SPEC §2 exactly.

use crate::model::ContactModel;
use crate::model::contact::{ContactLaw, kelvin_damping_ratio};

use super::retrofit::ContactElement;
use super::row::{FloorPair, Row};

/// m̄ of a floor pair.
pub fn reduced_mass(row: &Row, pair: &FloorPair) -> f64 {
    let ma = row.buildings[pair.left].mass[pair.left_floor - 1];
    let mb = row.buildings[pair.right].mass[pair.right_floor - 1];
    ma * mb / (ma + mb)
}

/// The law of a contact at `pair` that began with approach velocity `v0` (m/s).
pub fn pair_law(row: &Row, pair: &FloorPair, approach_velocity: f64) -> ContactLaw {
    law_of(
        row,
        pair,
        (row.joints[pair.joint].stiffness, row.restitution),
        approach_velocity,
    )
}

/// The law of a contact at `element` (a joint's own or a bumper's, SPEC §14)
/// that began with approach velocity `v0` (m/s): the row's law with the
/// element's stiffness and restitution.
pub fn element_law(row: &Row, element: &ContactElement, approach_velocity: f64) -> ContactLaw {
    law_of(
        row,
        &element.pair,
        (element.stiffness, element.restitution),
        approach_velocity,
    )
}

fn law_of(row: &Row, pair: &FloorPair, (k, e): (f64, f64), approach_velocity: f64) -> ContactLaw {
    kelvin_or_hertz(row, k, e, reduced_mass(row, pair), approach_velocity)
}

/// The row's law (`model`) with stiffness `k`, restitution `e` and reduced
/// mass `m_bar`, begun at approach velocity v0 (floored at `min_impact_velocity`).
pub fn kelvin_or_hertz(
    row: &Row,
    k: f64,
    e: f64,
    m_bar: f64,
    approach_velocity: f64,
) -> ContactLaw {
    let v0 = approach_velocity.max(row.min_impact_velocity);
    let kelvin = |linear_damping, hertz_damping| ContactLaw {
        stiffness: k,
        linear_damping,
        hertz_damping,
        hertzian: None,
    };
    match row.model {
        ContactModel::Kelvin => kelvin(2.0 * kelvin_damping_ratio(e) * (k * m_bar).sqrt(), 0.0),
        ContactModel::ImprovedKelvin => kelvin(0.0, k * 3.0 * (1.0 - e) / (2.0 * e * v0)),
        hertzian => ContactLaw::hertz_type(hertzian, k, m_bar, e, v0),
    }
}
