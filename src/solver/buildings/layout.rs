//! The row's constant part (SPEC §13), laid out once per run: masses,
//! M⁻¹C of Rayleigh damping, each storey's floors and constants, the floor
//! pairs and their gaps.

use nalgebra::DMatrix;

use crate::model::buildings::matrices::RowMatrices;
use crate::model::buildings::{ContactElement, FloorPair, LinkElement, Row};

use super::damper::Damper;
use super::sparse::Sparse;

/// One storey: it joins floor `lower` (None: the ground) and floor `upper`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Storey {
    pub building: usize,
    pub lower: Option<usize>,
    pub upper: usize,
    pub stiffness: f64,
    pub alpha: f64,
    pub yield_drift: f64,
    pub height: f64,
    /// P/h (N/m), the stiffness the storey loses to P-Δ (0 without it, SPEC §15).
    pub geometric: f64,
    /// |Δ| at which its building collapses (m; ∞ without P-Δ, SPEC §15).
    pub collapse_drift: f64,
}

/// What every configuration of a run shares.
#[derive(Debug, Clone)]
pub struct Layout {
    pub dofs: usize,
    pub mass: Vec<f64>,
    /// M⁻¹C (Rayleigh, SPEC §13).
    pub damping: DMatrix<f64>,
    /// M⁻¹C's rows by their nonzeros (the columns of its transpose, each
    /// in the order of j): a shear building's Rayleigh damping is
    /// tridiagonal, so that a sum over a row's nonzeros is its dense sum,
    /// the zeros adding nothing, at a third of the products or less.
    pub damping_rows: Sparse,
    pub storeys: Vec<Storey>,
    /// The contact elements' floors and gaps: the joints' own at each floor
    /// pair first, then the bumpers' (SPEC §14, [`Row::contact_elements`]).
    pub pairs: Vec<FloorPair>,
    pub gaps: Vec<f64>,
    /// The contact elements themselves, in the order of `pairs`.
    pub elements: Vec<ContactElement>,
    /// How many of them are the joints' own (the rest are bumpers).
    pub hard: usize,
    /// The links across the joints (SPEC §14).
    pub links: Vec<LinkElement>,
    /// The links that are fluid viscous dampers (α < 1), in link order.
    pub dampers: Vec<Damper>,
    /// Floors at the same elevation whatever the gap, whose largest
    /// u_A − u_B is tracked (the gap that prevents pounding).
    pub facing: Vec<FloorPair>,
    /// Largest rate of the row out of contact (Gershgorin bound of
    /// √‖M⁻¹K₀‖ and ‖M⁻¹C‖, 1/s): sub-steps are no longer than its inverse,
    /// so that each holds less than one radian of the fastest mode.
    pub rate: f64,
}

impl Layout {
    pub fn of(row: &Row) -> Layout {
        let m = RowMatrices::of(row);
        let n = row.dofs();
        let mass: Vec<f64> = m.mass.iter().copied().collect();
        let mut damping = m.damping.clone();
        for i in 0..n {
            for j in 0..n {
                damping[(i, j)] /= mass[i];
            }
        }
        let mut storeys = Vec::new();
        for (bi, (b, &o)) in row.buildings.iter().zip(&row.offsets()).enumerate() {
            for i in 0..b.storeys() {
                storeys.push(Storey {
                    building: bi,
                    lower: (i > 0).then(|| o + i - 1),
                    upper: o + i,
                    stiffness: b.stiffness[i],
                    alpha: b.alpha,
                    yield_drift: b.yield_drift[i],
                    height: b.height[i],
                    geometric: b.geometric_stiffness(i),
                    collapse_drift: b.collapse_drift(i),
                });
            }
        }
        let elements = row.contact_elements();
        let pairs = elements.iter().map(|e| e.pair).collect();
        let gaps = elements.iter().map(|e| e.gap).collect();
        let links = row.link_elements();
        // The links' springs and linear dashpots join K₀ and C in the bound.
        let (mut k_all, mut c_all) = (m.stiffness.clone(), damping.clone());
        super::link::add_linear(&links, &mass, &mut k_all, &mut c_all);
        let stiff = (0..n)
            .map(|i| (0..n).map(|j| k_all[(i, j)].abs()).sum::<f64>() / mass[i])
            .fold(0.0, f64::max);
        let damp = (0..n)
            .map(|i| (0..n).map(|j| c_all[(i, j)].abs()).sum::<f64>())
            .fold(0.0, f64::max);
        let dampers = Damper::all(&links, &mass);
        Layout {
            facing: row.facing_floors(),
            dofs: n,
            mass,
            damping_rows: Sparse::of(&damping.transpose()),
            damping,
            storeys,
            pairs,
            gaps,
            hard: row.pairs().len(),
            elements,
            links,
            dampers,
            rate: stiff.sqrt().max(damp),
        }
    }

    /// Storey `k` of the row as (its building, its 1-based storey there).
    pub fn building_storey(&self, k: usize) -> (usize, usize) {
        let building = self.storeys[k].building;
        let below = self.storeys[..k]
            .iter()
            .filter(|s| s.building == building)
            .count();
        (building, below + 1)
    }

    /// Drift Δ = u_upper − u_lower of a storey from displacements `u`.
    #[inline]
    pub fn drift(&self, s: &Storey, u: &[f64]) -> f64 {
        u[s.upper] - s.lower.map_or(0.0, |l| u[l])
    }
}
