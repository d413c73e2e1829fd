//! A row of shear buildings (SPEC §13), left to right, with the floors that
//! can pound.

use crate::model::ContactModel;
use crate::model::record::STANDARD_GRAVITY;

/// Floors of neighbours pair up when their elevations differ by at most this (m).
pub const ELEVATION_TOLERANCE: f64 = 1e-3;

/// One lumped-mass shear building: floor i (1 … n, bottom to top) has mass
/// m_i; storey i joins floors i−1 and i with the bilinear shear of SPEC §3 on
/// its drift Δ_i = u_i − u_{i−1}.
#[derive(Debug, Clone, PartialEq)]
pub struct Building {
    pub name: String,
    /// m_i, kg per floor, bottom to top.
    pub mass: Vec<f64>,
    /// k_i, N/m per storey.
    pub stiffness: Vec<f64>,
    /// h_i, m per storey.
    pub height: Vec<f64>,
    /// Δ_y,i, m per storey (infinite: elastic).
    pub yield_drift: Vec<f64>,
    /// Post-yield stiffness ratio α.
    pub alpha: f64,
    /// ξ of the Rayleigh damping at modes 1 and 2.
    pub damping: f64,
    /// The gravity load the storeys carry, when P-Δ is modelled (SPEC §15).
    pub p_delta: Option<PDelta>,
}

/// P-Δ of one building (SPEC §15): the weight each storey carries, and the
/// storey drift ratio at which the building collapses.
#[derive(Debug, Clone, PartialEq)]
pub struct PDelta {
    /// kg per floor, bottom to top, whose weight the storeys below carry
    /// (the floor's own mass and any leaning gravity system it holds up).
    pub gravity_mass: Vec<f64>,
    /// |Δ_i|/h_i at which the building collapses, in (0, 1).
    pub collapse_drift_ratio: f64,
}

impl Building {
    pub fn storeys(&self) -> usize {
        self.mass.len()
    }

    /// P_i = g Σ_{j ≥ i} gravity_mass_j (N): the gravity load storey `i`
    /// (0-based, bottom first) carries; 0 without P-Δ (SPEC §15).
    pub fn gravity_load(&self, storey: usize) -> f64 {
        self.p_delta.as_ref().map_or(0.0, |p| {
            STANDARD_GRAVITY * p.gravity_mass[storey..].iter().sum::<f64>()
        })
    }

    /// P_i/h_i (N/m): the geometric stiffness storey `i` loses to P-Δ. Its
    /// shear is V_i = αk_iΔ_i + (1 − α)k_i z_i − (P_i/h_i)Δ_i (SPEC §15).
    pub fn geometric_stiffness(&self, storey: usize) -> f64 {
        self.gravity_load(storey) / self.height[storey]
    }

    /// θ_i = P_i/(k_i h_i), the stability coefficient of storey `i`: 0
    /// without P-Δ; a storey with θ_i ≥ 1 cannot stand (SPEC §15).
    pub fn stability_coefficient(&self, storey: usize) -> f64 {
        self.geometric_stiffness(storey) / self.stiffness[storey]
    }

    /// The storey drift |Δ_i| (m) at which the building collapses:
    /// collapse_drift_ratio · h_i, or ∞ for a building without P-Δ, which
    /// keeps a restoring force and is not watched (SPEC §15).
    pub fn collapse_drift(&self, storey: usize) -> f64 {
        self.p_delta.as_ref().map_or(f64::INFINITY, |p| {
            p.collapse_drift_ratio * self.height[storey]
        })
    }

    /// Elevation of floor i (1-based) above the ground: Σ_{j ≤ i} h_j.
    pub fn elevation(&self, floor: usize) -> f64 {
        self.height[..floor].iter().sum()
    }
}

/// A bumper fixed to the left building's face at a joint (SPEC §14).
#[derive(Debug, Clone, PartialEq)]
pub struct Bumper {
    /// t, m: 0 < t ≤ the joint's gap.
    pub thickness: f64,
    /// k_b (N/m; β in N/m^1.5 under a Hertz-type law).
    pub stiffness: f64,
    /// e_b in [1e-3, 1].
    pub restitution: f64,
    /// The left building's floors (1-based) that carry it; None: every pair.
    pub floors: Option<Vec<usize>>,
}

/// A link across a joint (SPEC §14), in file order link1, link2, ….
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Link {
    /// Index of the joint it spans (0-based: 0 joins buildings 1 and 2).
    pub joint: usize,
    /// The left building's floor, 1-based.
    pub floor: usize,
    /// k_l ≥ 0, N/m.
    pub stiffness: f64,
    /// c_l ≥ 0, N·(s/m)^α.
    pub damping: f64,
    /// α in (0, 1].
    pub exponent: f64,
}

/// The joint between two neighbours: gap at rest and contact stiffness.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// d, m at rest (may be infinite: no pounding).
    pub gap: f64,
    /// k̄ (N/m) of the Kelvin family; β (N/m^{3/2}) of the Hertz-type laws.
    pub stiffness: f64,
    /// A bumper in the gap (SPEC §14).
    pub bumper: Option<Bumper>,
}

/// Floor `left_floor` of building `left` and floor `right_floor` of its right
/// neighbour, at the same elevation (within [`ELEVATION_TOLERANCE`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FloorPair {
    /// Index of the joint (= index of the left building).
    pub joint: usize,
    pub left: usize,
    pub right: usize,
    /// 1-based floor numbers.
    pub left_floor: usize,
    pub right_floor: usize,
    /// Degrees of freedom of the two floors in the row's state.
    pub left_dof: usize,
    pub right_dof: usize,
}

/// The row: buildings left to right, the joints between them, the contact law.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub name: String,
    pub buildings: Vec<Building>,
    pub joints: Vec<Joint>,
    pub model: ContactModel,
    pub restitution: f64,
    /// v₀ floor of the laws that divide by it (m/s).
    pub min_impact_velocity: f64,
    /// Links across the joints (SPEC §14), in file order.
    pub links: Vec<Link>,
}

impl Row {
    /// Total number of floors: the row's degrees of freedom.
    pub fn dofs(&self) -> usize {
        self.buildings.iter().map(|b| b.storeys()).sum()
    }

    /// Index of the first floor of each building in the row's state.
    pub fn offsets(&self) -> Vec<usize> {
        let mut at = 0;
        self.buildings
            .iter()
            .map(|b| {
                let o = at;
                at += b.storeys();
                o
            })
            .collect()
    }

    /// The floors that can pound, joint by joint, bottom to top: floors of
    /// neighbours whose elevations agree within 1 mm. A joint with an infinite
    /// gap pairs nothing.
    pub fn pairs(&self) -> Vec<FloorPair> {
        self.floor_pairs(false)
    }

    /// Floors of neighbours at the same elevation, whatever the gap: where
    /// the gap that prevents pounding is measured (SPEC §13).
    pub fn facing_floors(&self) -> Vec<FloorPair> {
        self.floor_pairs(true)
    }

    fn floor_pairs(&self, with_infinite_gaps: bool) -> Vec<FloorPair> {
        let offsets = self.offsets();
        let mut out = Vec::new();
        for (j, joint) in self.joints.iter().enumerate() {
            if !(with_infinite_gaps || joint.gap.is_finite()) {
                continue;
            }
            let (a, b) = (&self.buildings[j], &self.buildings[j + 1]);
            for i in 1..=a.storeys() {
                let z = a.elevation(i);
                if let Some(k) =
                    (1..=b.storeys()).find(|&k| (b.elevation(k) - z).abs() <= ELEVATION_TOLERANCE)
                {
                    out.push(FloorPair {
                        joint: j,
                        left: j,
                        right: j + 1,
                        left_floor: i,
                        right_floor: k,
                        left_dof: offsets[j] + i - 1,
                        right_dof: offsets[j + 1] + k - 1,
                    });
                }
            }
        }
        out
    }

    /// A floor pair as the output names it: `block 3 – frame 3`.
    pub fn pair_name(&self, pair: &FloorPair) -> String {
        format!(
            "{} {} – {} {}",
            self.buildings[pair.left].name,
            pair.left_floor,
            self.buildings[pair.right].name,
            pair.right_floor
        )
    }

    /// Whether a building of the row has P-Δ and so can collapse (SPEC §15):
    /// without it every storey keeps a restoring force.
    pub fn can_collapse(&self) -> bool {
        self.buildings.iter().any(|b| b.p_delta.is_some())
    }

    /// The same buildings with every joint's gap infinite: the run without
    /// contact from which the gap that prevents pounding is measured
    /// (SPEC §11, §13), and the no-pounding baseline of every comparison.
    pub fn apart(&self) -> Row {
        let mut r = self.clone();
        for j in &mut r.joints {
            j.gap = f64::INFINITY;
        }
        r
    }

    /// The row in mirror image: buildings right to left, joints reversed
    /// (with a ground motion negated, the response is the mirror image).
    pub fn mirrored(&self) -> Row {
        let mut r = self.clone();
        r.buildings.reverse();
        r.joints.reverse();
        self.mirror_retrofits(&mut r);
        r
    }
}
