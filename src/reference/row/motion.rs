//! The equations of SPEC §13 written again for the reference, as a
//! first-order system in y = (u, u̇), with each storey's shear and each
//! closed pair's force computed directly from the law:
//!
//! ```text
//! m_i ü_i = −(C u̇)_i − V_i + V_{i+1} ∓ Σ f_p − m_i ü_g(t),
//! V_i = αk_iΔ_i + (1 − α)k_i z_i − (P_i/h_i)Δ_i,
//! ```
//!
//! the last term P-Δ's (SPEC §15, 0 without it), with z_i fixed by the
//! storey's mode (Δ − p elastic, ±Δ_y yielding).
//!
//! The retrofits of SPEC §14 are written out here again from the preset's
//! values: each bumper is one more contact element at its joint's floor
//! pairs, with gap d − t and its own stiffness and restitution; each link
//! adds F = k_l Δu + c_l |Δv|^α sgn Δv, −F on its left floor and +F on its
//! right one, and the state carries each link's dissipated energy
//! E_l = ∫ c_l |Δv|^(α+1) dt as one more component, integrated with the motion.

use nalgebra::DMatrix;

use crate::model::ContactLaw;
use crate::model::buildings::matrices::RowMatrices;
use crate::model::buildings::{FloorPair, Ground, Row};
use crate::model::record::STANDARD_GRAVITY;

/// Mode of the whole row between events.
#[derive(Debug, Clone)]
pub struct Mode {
    /// 0 elastic, +1 / −1 yielding at z = ±Δ_y.
    pub branch: Vec<i8>,
    pub plastic: Vec<f64>,
    pub laws: Vec<Option<ContactLaw>>,
    /// Each fluid viscous damper's sign of Δv in this phase (0: none yet,
    /// or a linear link).
    pub turn: Vec<f64>,
}

/// A storey: its floors (lower None: the ground), k, α, Δ_y.
#[derive(Debug, Clone, Copy)]
pub struct StoreyData {
    pub lower: Option<usize>,
    pub upper: usize,
    pub k: f64,
    pub alpha: f64,
    pub yield_drift: f64,
    /// P_i/h_i (N/m), 0 without P-Δ.
    pub p_over_h: f64,
    /// |Δ| of collapse (m), ∞ without P-Δ.
    pub collapse_drift: f64,
    /// The building, and the storey in it (1-based).
    pub building: usize,
    pub storey: usize,
}

/// A link: its floors, k_l, c_l and α.
#[derive(Debug, Clone, Copy)]
pub struct LinkData {
    pub left: usize,
    pub right: usize,
    pub k: f64,
    pub c: f64,
    pub exponent: f64,
}

impl LinkData {
    pub fn force(&self, du: f64, dv: f64) -> f64 {
        self.k * du + self.c * dv.abs().powf(self.exponent) * dv.signum()
    }
}

pub struct Motion<'a> {
    pub ground: &'a Ground,
    pub n: usize,
    pub mass: Vec<f64>,
    pub damping: DMatrix<f64>,
    pub storeys: Vec<StoreyData>,
    /// Contact elements: the joints' own at every floor pair, then the bumpers'.
    pub pairs: Vec<FloorPair>,
    pub gaps: Vec<f64>,
    /// (stiffness, restitution) of each element's law.
    pub laws: Vec<(f64, f64)>,
    /// How many elements are the joints' own.
    pub hard: usize,
    pub links: Vec<LinkData>,
}

impl<'a> Motion<'a> {
    pub fn new(row: &Row, ground: &'a Ground) -> Motion<'a> {
        let m = RowMatrices::of(row);
        let mut storeys = Vec::new();
        for (bi, (b, &o)) in row.buildings.iter().zip(&row.offsets()).enumerate() {
            for i in 0..b.storeys() {
                let (p_over_h, collapse_drift) = match &b.p_delta {
                    Some(p) => {
                        let load: f64 = p.gravity_mass[i..].iter().sum::<f64>() * STANDARD_GRAVITY;
                        (load / b.height[i], p.collapse_drift_ratio * b.height[i])
                    }
                    None => (0.0, f64::INFINITY),
                };
                storeys.push(StoreyData {
                    lower: if i == 0 { None } else { Some(o + i - 1) },
                    upper: o + i,
                    k: b.stiffness[i],
                    alpha: b.alpha,
                    yield_drift: b.yield_drift[i],
                    p_over_h,
                    collapse_drift,
                    building: bi,
                    storey: i + 1,
                });
            }
        }
        let mut pairs = row.pairs();
        let hard = pairs.len();
        let mut gaps: Vec<f64> = pairs.iter().map(|p| row.joints[p.joint].gap).collect();
        let mut laws: Vec<(f64, f64)> = pairs
            .iter()
            .map(|p| (row.joints[p.joint].stiffness, row.restitution))
            .collect();
        let bumpers: Vec<_> = pairs
            .iter()
            .filter_map(|p| {
                let joint = &row.joints[p.joint];
                let b = joint.bumper.as_ref()?;
                let covered = b.floors.as_ref().is_none_or(|f| f.contains(&p.left_floor));
                covered.then_some((*p, joint.gap - b.thickness, (b.stiffness, b.restitution)))
            })
            .collect();
        for (p, gap, law) in bumpers {
            pairs.push(p);
            gaps.push(gap);
            laws.push(law);
        }
        let offsets = row.offsets();
        let links = row
            .links
            .iter()
            .map(|l| {
                let (a, b) = (&row.buildings[l.joint], &row.buildings[l.joint + 1]);
                let z = a.elevation(l.floor);
                let right = (1..=b.storeys())
                    .find(|&k| (b.elevation(k) - z).abs() <= 1e-3)
                    .expect("a link's floor has a partner");
                LinkData {
                    left: offsets[l.joint] + l.floor - 1,
                    right: offsets[l.joint + 1] + right - 1,
                    k: l.stiffness,
                    c: l.damping,
                    exponent: l.exponent,
                }
            })
            .collect();
        Motion {
            ground,
            n: row.dofs(),
            mass: m.mass.iter().copied().collect(),
            damping: m.damping,
            storeys,
            pairs,
            gaps,
            laws,
            hard,
            links,
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

    /// The floors' forces F = −C u̇ − (V_i − V_{i+1}) ∓ Σ f_p in `mode`, so
    /// that m_i ü_i = F_i − m_i ü_g and F_i/m_i = ü_i + ü_g is floor i's
    /// absolute acceleration (SPEC §13).
    pub fn forces(&self, mode: &Mode, y: &[f64]) -> Vec<f64> {
        let n = self.n;
        let (u, v) = (&y[..n], &y[n..2 * n]);
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
            let shear =
                s.alpha * s.k * d + (1.0 - s.alpha) * s.k * self.z(mode, i, d) - s.p_over_h * d;
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
        for l in &self.links {
            let f = l.force(u[l.left] - u[l.right], v[l.left] - v[l.right]);
            force[l.left] -= f;
            force[l.right] += f;
        }
        force
    }

    /// ẏ = f(t, y) in `mode`.
    pub fn rhs(&self, mode: &Mode, t: f64, y: &[f64], out: &mut [f64]) {
        let n = self.n;
        let force = self.forces(mode, y);
        let ag = self.ground.at(t);
        out[..n].copy_from_slice(&y[n..2 * n]);
        for i in 0..n {
            out[n + i] = force[i] / self.mass[i] - ag;
        }
        for (k, l) in self.links.iter().enumerate() {
            let dv = y[n + l.left] - y[n + l.right];
            out[2 * n + k] = l.c * dv.abs().powf(l.exponent + 1.0);
        }
    }

    /// dF/dt of link `l` along the motion: k_l Δv + c_l α |Δv|^(α−1) Δa.
    pub fn link_rate(&self, l: &LinkData, y: &[f64], rate: &[f64]) -> f64 {
        let n = self.n;
        let dv = y[n + l.left] - y[n + l.right];
        let da = rate[n + l.left] - rate[n + l.right];
        l.k * dv + l.c * l.exponent * dv.abs().powf(l.exponent - 1.0) * da
    }

    /// d/dt (F_i/m_i), the rate of floor i's absolute acceleration, at y with
    /// ẏ = f(t, y): each term of [`Motion::forces`] differentiated along the
    /// motion,
    ///
    /// ```text
    /// dF/dt = −C ü − Σ k_t,j Δ̇_j (storeys) ∓ Σ (∂f/∂δ δ̇ + ∂f/∂δ̇ δ̈) (pairs),
    /// ```
    ///
    /// with k_t = k on the elastic branch and αk while yielding (SPEC §3),
    /// less P/h with P-Δ (SPEC §15).
    pub fn jerk(&self, mode: &Mode, i: usize, y: &[f64], rate: &[f64]) -> f64 {
        let n = self.n;
        let (u, v) = (&y[..n], &y[n..2 * n]);
        let acc = &rate[n..2 * n];
        let mut d = -(0..n).map(|j| self.damping[(i, j)] * acc[j]).sum::<f64>();
        for (k, s) in self.storeys.iter().enumerate() {
            let sign = if s.upper == i {
                -1.0
            } else if s.lower == Some(i) {
                1.0
            } else {
                continue;
            };
            let tangent = if mode.branch[k] == 0 {
                s.k
            } else {
                s.alpha * s.k
            } - s.p_over_h;
            d += sign * tangent * self.drift(s, v);
        }
        for ((p, law), &gap) in self.pairs.iter().zip(&mode.laws).zip(&self.gaps) {
            let Some(law) = law else { continue };
            let (a, b) = (p.left_dof, p.right_dof);
            let sign = if a == i {
                -1.0
            } else if b == i {
                1.0
            } else {
                continue;
            };
            let c = law.force(u[a] - u[b] - gap, v[a] - v[b]);
            d += sign * (c.d_penetration * (v[a] - v[b]) + c.d_rate * (acc[a] - acc[b]));
        }
        for l in &self.links {
            let sign = if l.left == i {
                -1.0
            } else if l.right == i {
                1.0
            } else {
                continue;
            };
            d += sign * self.link_rate(l, y, rate);
        }
        d / self.mass[i]
    }
}
