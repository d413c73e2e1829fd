//! The equations of SPEC §13 written again for the reference, as a
//! first-order system in y = (u, u̇), with each storey's shear and each
//! closed pair's force computed directly from the law:
//!
//! ```text
//! m_i ü_i = −(C u̇)_i − V_i + V_{i+1} ∓ Σ f_p − m_i ü_g(t),
//! V_i = αk_iΔ_i + (1 − α)k_i z_i,
//! ```
//!
//! with z_i fixed by the storey's mode (Δ − p elastic, ±Δ_y yielding).

use nalgebra::DMatrix;

use crate::model::ContactLaw;
use crate::model::buildings::matrices::RowMatrices;
use crate::model::buildings::{FloorPair, Ground, Row};

/// Mode of the whole row between events.
#[derive(Debug, Clone)]
pub struct Mode {
    /// 0 elastic, +1 / −1 yielding at z = ±Δ_y.
    pub branch: Vec<i8>,
    pub plastic: Vec<f64>,
    pub laws: Vec<Option<ContactLaw>>,
}

/// A storey: its floors (lower None: the ground), k, α, Δ_y.
#[derive(Debug, Clone, Copy)]
pub struct StoreyData {
    pub lower: Option<usize>,
    pub upper: usize,
    pub k: f64,
    pub alpha: f64,
    pub yield_drift: f64,
}

pub struct Motion<'a> {
    pub ground: &'a Ground,
    pub n: usize,
    pub mass: Vec<f64>,
    pub damping: DMatrix<f64>,
    pub storeys: Vec<StoreyData>,
    pub pairs: Vec<FloorPair>,
    pub gaps: Vec<f64>,
}

impl<'a> Motion<'a> {
    pub fn new(row: &Row, ground: &'a Ground) -> Motion<'a> {
        let m = RowMatrices::of(row);
        let mut storeys = Vec::new();
        for (b, &o) in row.buildings.iter().zip(&row.offsets()) {
            for i in 0..b.storeys() {
                storeys.push(StoreyData {
                    lower: if i == 0 { None } else { Some(o + i - 1) },
                    upper: o + i,
                    k: b.stiffness[i],
                    alpha: b.alpha,
                    yield_drift: b.yield_drift[i],
                });
            }
        }
        let pairs = row.pairs();
        let gaps = pairs.iter().map(|p| row.joints[p.joint].gap).collect();
        Motion {
            ground,
            n: row.dofs(),
            mass: m.mass.iter().copied().collect(),
            damping: m.damping,
            storeys,
            pairs,
            gaps,
        }
    }

    pub fn drift(&self, s: &StoreyData, x: &[f64]) -> f64 {
        x[s.upper] - s.lower.map_or(0.0, |l| x[l])
    }

    pub fn z(&self, mode: &Mode, i: usize, drift: f64) -> f64 {
        match mode.branch[i] {
            0 => drift - mode.plastic[i],
            b => f64::from(b) * self.storeys[i].yield_drift,
        }
    }

    /// ẏ = f(t, y) in `mode`.
    pub fn rhs(&self, mode: &Mode, t: f64, y: &[f64], out: &mut [f64]) {
        let n = self.n;
        let (u, v) = y.split_at(n);
        let mut force: Vec<f64> = (0..n)
            .map(|i| {
                -v.iter()
                    .enumerate()
                    .map(|(j, &vj)| self.damping[(i, j)] * vj)
                    .sum::<f64>()
            })
            .collect();
        for (i, s) in self.storeys.iter().enumerate() {
            let d = self.drift(s, u);
            let shear = s.alpha * s.k * d + (1.0 - s.alpha) * s.k * self.z(mode, i, d);
            force[s.upper] -= shear;
            if let Some(l) = s.lower {
                force[l] += shear;
            }
        }
        for ((p, law), &gap) in self.pairs.iter().zip(&mode.laws).zip(&self.gaps) {
            if let Some(law) = law {
                let (a, b) = (p.left_dof, p.right_dof);
                let f = law.force(u[a] - u[b] - gap, v[a] - v[b]).force;
                force[a] -= f;
                force[b] += f;
            }
        }
        let ag = self.ground.at(t);
        out[..n].copy_from_slice(v);
        for i in 0..n {
            out[n + i] = force[i] / self.mass[i] - ag;
        }
    }
}
