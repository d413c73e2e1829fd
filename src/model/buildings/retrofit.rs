//! Retrofits of a row (SPEC §14): bumpers in a joint's gap and links across it.
//!
//! - A **bumper** of thickness t at a joint is a second contact element in
//!   parallel with the joint's own at each of its floor pairs (or only at
//!   the left building's floors it lists): gap d − t, stiffness k_b,
//!   restitution e_b, under the row's contact law with the pair's m̄ and its
//!   own onset velocity. Its compression is c = u_A − u_B − (d − t); it
//!   bottoms out where c > t, and the joint's own element then closes too.
//! - A **link** joins floor i of building A and the floor of its right
//!   neighbour B at the same elevation, in tension and compression always:
//!   F = k_l Δu + c_l |Δv|^α sgn Δv, Δu = u_A − u_B, acting −F on A and +F
//!   on B, as a contact force does. α = 1 is a linear dashpot; α < 1 a fluid
//!   viscous damper, whose force is not smooth where Δv = 0.
//!
//! The solvers see both through [`Row::contact_elements`] and [`Row::link_elements`]:
//! one list of contact elements (hard pairs first, in [`Row::pairs`]' order,
//! then bumpers), one list of links with their degrees of freedom.

pub use super::row::{Bumper, Link};
use super::row::{FloorPair, Row};

/// One contact element between two floors: a joint's own, or a bumper's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactElement {
    pub pair: FloorPair,
    /// Gap at rest, m: d for the joint's own element, d − t for a bumper.
    pub gap: f64,
    /// k̄ (or β) and e of its law.
    pub stiffness: f64,
    pub restitution: f64,
    /// The bumper's thickness t, or None for the joint's own element.
    pub thickness: Option<f64>,
}

/// A dashpot's force at the velocity Δv (SPEC §14):
/// F = c_l |Δv|^α sgn Δv (N), linear for α = 1, a fluid viscous damper's
/// for α < 1.
#[inline]
pub fn dashpot_force(damping: f64, exponent: f64, dv: f64) -> f64 {
    damping * dv.abs().powf(exponent) * dv.signum()
}

/// A dashpot's law written the other way round (SPEC §14): the velocity
/// Δv = ψ(F) = sgn F (|F|/c_l)^(1/α) at which it carries the force F.
/// Bounded in slope where F = 0 (1/α ≥ 1), where c_l|Δv|^α has none: the
/// implicit steps of both methods take the force as their unknown.
#[inline]
pub fn dashpot_velocity(damping: f64, exponent: f64, force: f64) -> f64 {
    (force / damping).abs().powf(1.0 / exponent) * force.signum()
}

/// ψ'(F) = (|F|/c_l)^(1/α − 1)/(c_l α) ≥ 0, the slope of
/// [`dashpot_velocity`].
#[inline]
pub fn dashpot_velocity_slope(damping: f64, exponent: f64, force: f64) -> f64 {
    (force / damping).abs().powf(1.0 / exponent - 1.0) / (damping * exponent)
}

/// A link with the floors it joins.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkElement {
    pub link: Link,
    pub pair: FloorPair,
}

impl LinkElement {
    /// F = k_l Δu + c_l |Δv|^α sgn Δv (N), acting −F on the left floor.
    #[inline]
    pub fn force(&self, du: f64, dv: f64) -> f64 {
        self.link.stiffness * du + dashpot_force(self.link.damping, self.link.exponent, dv)
    }

    /// Whether the force is linear in (Δu, Δv): α = 1.
    pub fn is_linear(&self) -> bool {
        self.link.exponent == 1.0
    }

    /// The power the dashpot dissipates, c_l |Δv|^(α+1) (W).
    #[inline]
    pub fn dissipation(&self, dv: f64) -> f64 {
        self.link.damping * dv.abs().powf(self.link.exponent + 1.0)
    }
}

impl Row {
    /// Every contact element of the row: the joints' own at each floor pair
    /// ([`Row::pairs`], in its order), then each joint's bumper at the pairs
    /// it covers, joint by joint, bottom to top.
    pub fn contact_elements(&self) -> Vec<ContactElement> {
        let pairs = self.pairs();
        let own = pairs.iter().map(|p| ContactElement {
            pair: *p,
            gap: self.joints[p.joint].gap,
            stiffness: self.joints[p.joint].stiffness,
            restitution: self.restitution,
            thickness: None,
        });
        let bumpers = pairs.iter().filter_map(|p| {
            let joint = &self.joints[p.joint];
            let b = joint.bumper.as_ref()?;
            let covered = b
                .floors
                .as_ref()
                .is_none_or(|floors| floors.contains(&p.left_floor));
            covered.then_some(ContactElement {
                pair: *p,
                gap: joint.gap - b.thickness,
                stiffness: b.stiffness,
                restitution: b.restitution,
                thickness: Some(b.thickness),
            })
        });
        own.chain(bumpers).collect()
    }

    /// The bumper elements alone ([`Row::contact_elements`] after the pairs).
    pub fn bumper_elements(&self) -> Vec<ContactElement> {
        self.contact_elements().split_off(self.pairs().len())
    }

    /// The floors each link joins, in file order. A link's floors are
    /// checked when the preset is read, so each has its partner.
    pub fn link_elements(&self) -> Vec<LinkElement> {
        let facing = self.facing_floors();
        self.links
            .iter()
            .filter_map(|l| {
                let pair = *facing
                    .iter()
                    .find(|p| p.joint == l.joint && p.left_floor == l.floor)?;
                Some(LinkElement { link: *l, pair })
            })
            .collect()
    }

    /// Whether the row has any retrofit: a bumper or a link.
    pub fn is_retrofitted(&self) -> bool {
        !self.links.is_empty() || self.joints.iter().any(|j| j.bumper.is_some())
    }

    /// Whether a link is a fluid viscous damper, α < 1 (SPEC §14): its
    /// force is not linear in Δv, so no matrix map carries the row.
    pub fn has_fluid_damper(&self) -> bool {
        self.links.iter().any(|l| l.exponent < 1.0)
    }

    /// The same row without its retrofits: no bumper, no link.
    pub fn bare(&self) -> Row {
        let mut r = self.clone();
        r.links.clear();
        for j in &mut r.joints {
            j.bumper = None;
        }
        r
    }

    /// A bumper's `floors` and a link's joint and floor in the mirror image
    /// ([`Row::mirrored`]): the joint from the other end, and the partner
    /// floor of each named floor, which is the left building's now.
    pub(super) fn mirror_retrofits(&self, mirrored: &mut Row) {
        let facing = self.facing_floors();
        let last = self.joints.len().saturating_sub(1);
        let partner = |joint: usize, floor: usize| {
            facing
                .iter()
                .find(|p| p.joint == joint && p.left_floor == floor)
                .map_or(floor, |p| p.right_floor)
        };
        for (j, joint) in self.joints.iter().enumerate() {
            if let Some(floors) = joint.bumper.as_ref().and_then(|b| b.floors.as_ref()) {
                let bumper = mirrored.joints[last - j].bumper.as_mut().expect("mirrored");
                bumper.floors = Some(floors.iter().map(|&f| partner(j, f)).collect());
            }
        }
        for (l, m) in self.links.iter().zip(&mut mirrored.links) {
            m.joint = last - l.joint;
            m.floor = partner(l.joint, l.floor);
        }
    }
}
