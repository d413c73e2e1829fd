//! The Taylor series of the motion in one configuration (SPEC §13), from a
//! state at s = 0:
//!
//! ```text
//! u_{k+1} = u̇_k/(k+1),
//! u̇_{k+1} = (−M⁻¹K u_k − M⁻¹C u̇_k + M⁻¹q [k = 0] − a_k − M⁻¹ Σ_p h_p (δδ̇)_k e_p)/(k+1),
//! ```
//!
//! with a_k the ground's coefficients (a_{k+2} = σ a_k/((k+1)(k+2)) on a
//! piece where ä_g = σ a_g) and (δδ̇)_k = Σ_j δ_j δ̇_{k−j} the improved Kelvin
//! law's product, so that a contact phase of the Kelvin family is carried
//! exactly too; a force given as a polynomial in s ([`Forcing`]) adds its
//! coefficients to ü's. The series is used on [0, radius], where its last two terms
//! are below [`TOLERANCE`] of the state's scale.

use super::system::{Product, System};

/// Highest order kept.
pub const ORDER: usize = 24;
/// Relative size of the last terms at the end of a step.
pub const TOLERANCE: f64 = 1e-17;

/// The ground's Taylor coefficients a_k from (a, ȧ, σ) at s = 0:
/// a₀ = a, a₁ = ȧ, a_{k+2} = σ a_k/((k+1)(k+2)) (ä_g = σ a_g on the piece).
pub fn ground_coefficients((a, rate, sigma): (f64, f64, f64)) -> [f64; ORDER + 1] {
    let mut g = [0.0; ORDER + 1];
    g[0] = a;
    g[1] = rate;
    for k in 0..ORDER - 1 {
        g[k + 2] = sigma * g[k] / ((k + 1) * (k + 2)) as f64;
    }
    g
}

/// A force x(s) = Σ_k x_k s^k across floors A (left) and B (right),
/// acting −x/m_A on A and +x/m_B on B, as a link's or a contact's does:
/// it adds −(x_k/m_A) at A and +(x_k/m_B) at B to the k-th coefficient
/// of ü.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forcing {
    pub left: usize,
    pub right: usize,
    /// 1/m_A and 1/m_B.
    pub left_rate: f64,
    pub right_rate: f64,
    /// x_0 … x_3 (N, N/s, N/s², N/s³).
    pub force: [f64; 4],
}

/// Coefficients of u and u̇, floor by floor (each a block of
/// [`Series::degree`] + 1, lowest order first), so that one floor's
/// polynomial is one slice.
#[derive(Debug, Clone, Default)]
pub struct Series {
    pub n: usize,
    pub u: Vec<f64>,
    pub v: Vec<f64>,
    /// The ground's coefficients a_k.
    pub ground: [f64; ORDER + 1],
    /// Where the series stays within [`TOLERANCE`].
    pub radius: f64,
    /// Highest order of u held (coefficients above it are zero):
    /// [`ORDER`] for the series, less for a polynomial written as one.
    pub degree: usize,
}

impl Series {
    /// The series from (u, u̇) with ground acceleration `a`, its rate and σ.
    /// `scale` = (displacement, velocity) of the motion, for the radius.
    pub fn new(
        system: &System,
        u0: &[f64],
        v0: &[f64],
        ground: (f64, f64, f64),
        scale: (f64, f64),
    ) -> Series {
        let mut series = Series::default();
        series.fill(system, (u0, v0), ground, scale, &[]);
        series
    }

    /// [`Series::new`] with polynomial forces across floor pairs
    /// ([`Forcing`]) added to the right-hand side.
    pub fn forced(
        system: &System,
        (u0, v0): (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        forcing: &[Forcing],
    ) -> Series {
        let mut series = Series::default();
        series.fill(system, (u0, v0), ground, scale, forcing);
        series
    }

    /// [`Series::forced`] written over this series, its coefficients'
    /// vectors reused (a run takes thousands of steps).
    pub fn fill(
        &mut self,
        system: &System,
        start: (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        forcing: &[Forcing],
    ) {
        self.fill_with(system, &system.products, start, ground, scale, forcing);
    }

    /// [`Series::fill`] of the configuration's linear motion alone: K, C
    /// and q, its products h δ δ̇ left out (a collocated step carries them
    /// as forces, [`super::damper_collocation`]).
    pub fn fill_linear(
        &mut self,
        system: &System,
        start: (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
    ) {
        self.fill_with(system, &[], start, ground, scale, &[]);
    }

    /// The series with the products `products` in place of the system's.
    fn fill_with(
        &mut self,
        system: &System,
        products: &[Product],
        (u0, v0): (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        forcing: &[Forcing],
    ) {
        const W: usize = ORDER + 1;
        let n = u0.len();
        let mut u = std::mem::take(&mut self.u);
        let mut v = std::mem::take(&mut self.v);
        u.clear();
        u.resize(W * n, 0.0);
        v.clear();
        v.resize(W * n, 0.0);
        for i in 0..n {
            u[i * W] = u0[i];
            v[i * W] = v0[i];
        }
        let g = ground_coefficients(ground);
        let np = products.len();
        let mut delta = vec![0.0; np * W];
        let mut rate_d = vec![0.0; np * W];
        let mut acc = vec![0.0; n];
        for k in 0..ORDER {
            for (i, acc) in acc.iter_mut().enumerate() {
                let mut s = -g[k];
                if k == 0 {
                    s += system.load[i];
                }
                for &(j, kij, cij) in system.row(i) {
                    s -= kij * u[j * W + k] + cij * v[j * W + k];
                }
                *acc = s;
            }
            for (pi, p) in products.iter().enumerate() {
                let row = pi * W;
                let (l, r) = (p.left * W + k, p.right * W + k);
                delta[row + k] = u[l] - u[r] - if k == 0 { p.gap } else { 0.0 };
                rate_d[row + k] = v[l] - v[r];
                let conv: f64 = (0..=k).map(|j| delta[row + j] * rate_d[row + k - j]).sum();
                acc[p.left] -= p.left_rate * conv;
                acc[p.right] += p.right_rate * conv;
            }
            for f in forcing {
                if let Some(&x) = f.force.get(k) {
                    acc[f.left] -= f.left_rate * x;
                    acc[f.right] += f.right_rate * x;
                }
            }
            let inv = 1.0 / (k + 1) as f64;
            for i in 0..n {
                u[i * W + k + 1] = v[i * W + k] * inv;
                v[i * W + k + 1] = acc[i] * inv;
            }
        }
        let norm = |k: usize| {
            let nu = (0..n).fold(0.0f64, |m, i| m.max(u[i * W + k].abs())) / scale.0;
            let nv = (0..n).fold(0.0f64, |m, i| m.max(v[i * W + k].abs())) / scale.1;
            nu.max(nv)
        };
        let radius = [ORDER - 1, ORDER]
            .iter()
            .map(|&k| {
                let nk = norm(k);
                if nk > 0.0 {
                    (TOLERANCE / nk).powf(1.0 / k as f64)
                } else {
                    f64::INFINITY
                }
            })
            .fold(f64::INFINITY, f64::min);
        *self = Series {
            n,
            u,
            v,
            ground: g,
            radius,
            degree: ORDER,
        };
    }

    /// The coefficients of u_i, orders 0 to [`Series::degree`].
    #[inline]
    pub fn displacement(&self, i: usize) -> &[f64] {
        &self.u[i * (self.degree + 1)..(i + 1) * (self.degree + 1)]
    }

    /// The coefficients of u̇_i, orders 0 to [`Series::degree`].
    #[inline]
    pub fn velocity(&self, i: usize) -> &[f64] {
        &self.v[i * (self.degree + 1)..(i + 1) * (self.degree + 1)]
    }

    /// (u, u̇) at s.
    pub fn state(&self, s: f64, u: &mut [f64], v: &mut [f64]) {
        for i in 0..self.n {
            let (cu, cv) = (self.displacement(i), self.velocity(i));
            let mut a = 0.0;
            let mut b = 0.0;
            for k in (0..=self.degree).rev() {
                a = a * s + cu[k];
                b = b * s + cv[k];
            }
            u[i] = a;
            v[i] = b;
        }
    }

    /// Coefficients of Σ_i (wu_i u_i + wv_i u̇_i) over the given (dof, weight) terms.
    pub fn combine(&self, du: &[(usize, f64)], dv: &[(usize, f64)], out: &mut Vec<f64>) {
        out.clear();
        out.resize(self.degree + 1, 0.0);
        for &(i, w) in du {
            for (o, &x) in out.iter_mut().zip(self.displacement(i)) {
                *o += w * x;
            }
        }
        for &(i, w) in dv {
            for (o, &x) in out.iter_mut().zip(self.velocity(i)) {
                *o += w * x;
            }
        }
    }

    /// Coefficients of the absolute acceleration ü_i + ü_g (one order fewer).
    pub fn absolute_acceleration(&self, i: usize, out: &mut Vec<f64>) {
        out.clear();
        let v = self.velocity(i);
        out.extend((0..ORDER).map(|k| {
            let rate = if k < self.degree {
                (k + 1) as f64 * v[k + 1]
            } else {
                0.0
            };
            rate + self.ground[k]
        }));
    }
}
