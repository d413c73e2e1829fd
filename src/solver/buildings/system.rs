//! The linear system of one configuration (SPEC §13):
//!
//! ```text
//! ü = −M⁻¹K u − M⁻¹C u̇ + M⁻¹q − 1 ü_g − M⁻¹ Σ_p h_p δ_p δ̇_p e_p.
//! ```
//!
//! - Storey i on the elastic branch: V_i = k_iΔ_i − (1−α)k_i p_i; yielding:
//!   V_i = αk_iΔ_i ± (1−α)k_iΔ_y,i. With P-Δ (SPEC §15) both lose
//!   (P_i/h_i)Δ_i, linear in the drift, so every configuration stays linear
//!   (its stiffness may be negative on a yielding branch). It acts −V_i on
//!   its upper floor and +V_i on its lower one.
//! - A closed pair p (floors A left, B right), δ = u_A − u_B − d: the law
//!   f = k̄δ + cδ̇ + hδδ̇ (SPEC §4) acts −f on A and +f on B; k̄ and c go into
//!   K and C, k̄d into q, and the improved Kelvin law's hδδ̇ stays the one
//!   nonlinear term (e_p = +1 at A, −1 at B).
//! - A link (SPEC §14) adds its spring k_l to K in every configuration, and
//!   its dashpot c_l to C when it is linear (α = 1) ([`super::link`]).

use std::sync::Arc;

use nalgebra::DMatrix;

use super::config::{Branch, Config};
use super::layout::{Layout, Storey};

mod cache;
mod columns;

pub use cache::Systems;
pub use columns::{Columns, padded};

/// The nonlinear term of one closed pair: h δ δ̇.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Product {
    pub left: usize,
    pub right: usize,
    pub gap: f64,
    /// h/m_A and h/m_B.
    pub left_rate: f64,
    pub right_rate: f64,
}

/// M⁻¹K, M⁻¹C, M⁻¹q and the nonlinear terms of one configuration.
///
/// The matrices and their two sparse forms are shared, never changed once
/// made: a configuration met again out of contact differs only in M⁻¹q
/// ([`Systems`]), so its system takes the kept matrices by reference
/// count instead of copying them at every event.
#[derive(Debug, Clone)]
pub struct System {
    pub stiffness: Arc<DMatrix<f64>>,
    pub damping: Arc<DMatrix<f64>>,
    pub load: Vec<f64>,
    pub products: Vec<Product>,
    /// The nonzero entries of M⁻¹K and M⁻¹C together, row by row: (j,
    /// (M⁻¹K)_ij, (M⁻¹C)_ij) for row i in `entries[row_start[i]..row_start[i + 1]]`,
    /// in the order of j. A floor couples only to its storeys' other floors
    /// and its contacts, so a row holds a few of the n entries.
    entries: Arc<[(usize, f64, f64)]>,
    row_start: Arc<[usize]>,
    /// M⁻¹K and M⁻¹C by columns, for the rates at a map step's ends.
    pub columns: Arc<Columns>,
}

/// Storey `i`'s stiffness k_e on its branch of `config`, less its P-Δ
/// stiffness P/h, and its constant shear V₀, with V = k_eΔ + V₀: elastic,
/// k and −(1 − α)k p; yielding, αk and ±(1 − α)kΔ_y.
fn storey_terms(s: &Storey, config: &Config, i: usize) -> (f64, f64) {
    let (ke, v0) = match config.branch[i] {
        Branch::Elastic => (
            s.stiffness,
            -(1.0 - s.alpha) * s.stiffness * config.plastic[i],
        ),
        Branch::Plus => (
            s.alpha * s.stiffness,
            (1.0 - s.alpha) * s.stiffness * s.yield_drift,
        ),
        Branch::Minus => (
            s.alpha * s.stiffness,
            -(1.0 - s.alpha) * s.stiffness * s.yield_drift,
        ),
    };
    (ke - s.geometric, v0)
}

/// M⁻¹q of `config`: each storey's −V₀ on its upper floor and +V₀ on its
/// lower one, and each closed pair's k̄d on A and −k̄d on B, divided by
/// the floor's mass.
fn load(layout: &Layout, config: &Config) -> Vec<f64> {
    let mut q = vec![0.0; layout.dofs];
    for (i, s) in layout.storeys.iter().enumerate() {
        let (_, v0) = storey_terms(s, config, i);
        q[s.upper] -= v0;
        if let Some(lo) = s.lower {
            q[lo] += v0;
        }
    }
    for (pi, (p, closed)) in layout.pairs.iter().zip(&config.contact).enumerate() {
        if let Some(closed) = closed {
            let kd = closed.law.stiffness * layout.gaps[pi];
            q[p.left_dof] += kd;
            q[p.right_dof] -= kd;
        }
    }
    for (q, m) in q.iter_mut().zip(&layout.mass) {
        *q /= m;
    }
    q
}

impl System {
    pub fn of(layout: &Layout, config: &Config) -> System {
        let n = layout.dofs;
        let mut k = DMatrix::<f64>::zeros(n, n);
        let mut c = layout.damping.clone();
        for (i, s) in layout.storeys.iter().enumerate() {
            let (ke, _) = storey_terms(s, config, i);
            let up = s.upper;
            k[(up, up)] += ke;
            if let Some(lo) = s.lower {
                k[(lo, lo)] += ke;
                k[(up, lo)] -= ke;
                k[(lo, up)] -= ke;
            }
        }
        let mut products = Vec::new();
        for (pi, (p, closed)) in layout.pairs.iter().zip(&config.contact).enumerate() {
            let Some(closed) = closed else { continue };
            let (a, b) = (p.left_dof, p.right_dof);
            let d = layout.gaps[pi];
            let law = &closed.law;
            let (kk, cc) = (law.stiffness, law.linear_damping);
            k[(a, a)] += kk;
            k[(b, b)] += kk;
            k[(a, b)] -= kk;
            k[(b, a)] -= kk;
            // `c` is M⁻¹C already: the dashpot enters divided by each floor's mass.
            let (ma, mb) = (layout.mass[a], layout.mass[b]);
            c[(a, a)] += cc / ma;
            c[(a, b)] -= cc / ma;
            c[(b, b)] += cc / mb;
            c[(b, a)] -= cc / mb;
            if law.hertz_damping != 0.0 {
                products.push(Product {
                    left: a,
                    right: b,
                    gap: d,
                    left_rate: law.hertz_damping / ma,
                    right_rate: law.hertz_damping / mb,
                });
            }
        }
        super::link::add_linear(&layout.links, &layout.mass, &mut k, &mut c);
        for i in 0..n {
            let m = layout.mass[i];
            for j in 0..n {
                k[(i, j)] /= m;
            }
        }
        let mut entries = Vec::new();
        let mut row_start = vec![0];
        for i in 0..n {
            for j in 0..n {
                let (kij, cij) = (k[(i, j)], c[(i, j)]);
                if kij != 0.0 || cij != 0.0 {
                    entries.push((j, kij, cij));
                }
            }
            row_start.push(entries.len());
        }
        System {
            columns: Arc::new(Columns::of(&k, &c)),
            stiffness: Arc::new(k),
            damping: Arc::new(c),
            load: load(layout, config),
            products,
            entries: entries.into(),
            row_start: row_start.into(),
        }
    }

    /// This system with the load M⁻¹q of `config` in place of its own: the
    /// system of `config` when it has this one's branches and contacts
    /// (the plastic offsets enter M⁻¹q alone), bit for bit.
    pub fn with_load_of(&self, layout: &Layout, config: &Config) -> System {
        System {
            stiffness: Arc::clone(&self.stiffness),
            damping: Arc::clone(&self.damping),
            load: load(layout, config),
            products: self.products.clone(),
            entries: Arc::clone(&self.entries),
            row_start: Arc::clone(&self.row_start),
            columns: Arc::clone(&self.columns),
        }
    }

    /// Row i of (M⁻¹K, M⁻¹C): its nonzero (j, (M⁻¹K)_ij, (M⁻¹C)_ij).
    #[inline]
    pub fn row(&self, i: usize) -> &[(usize, f64, f64)] {
        &self.entries[self.row_start[i]..self.row_start[i + 1]]
    }

    /// ü at (u, u̇) under ground acceleration a (the equation above).
    pub fn acceleration(&self, u: &[f64], v: &[f64], a: f64, out: &mut [f64]) {
        for (i, out) in out.iter_mut().enumerate() {
            let mut s = self.load[i] - a;
            for &(j, kij, cij) in self.row(i) {
                s -= kij * u[j] + cij * v[j];
            }
            *out = s;
        }
        for p in &self.products {
            let f = (u[p.left] - u[p.right] - p.gap) * (v[p.left] - v[p.right]);
            out[p.left] -= p.left_rate * f;
            out[p.right] += p.right_rate * f;
        }
    }
}
