//! The responses from rest of one configuration to each element's force
//! s^k (SPEC §14), made once and serving every step length, and their
//! values at one step's nodes.

use nalgebra::DMatrix;

use super::basis::basis;
use super::{Element, Law, NODES, POWERS, STAGES};
use crate::solver::buildings::poly;
use crate::solver::buildings::system::System;
use crate::solver::buildings::taylor::{Forcing, ORDER, Series};

/// The responses from rest of one configuration to each element's force
/// x_f = s^k, k = 0 … 2S − 1 (response r = k·E + f, E elements): its series,
/// and Δu_e and Δv_e of every element e as polynomials in s (row r·E + e).
/// They hold for every step length: the response to ℓ_j(s/h) is
/// Σ_k ℓ_{j,k} h^(−k) times the k-th, and to π(s/h) likewise.
#[derive(Debug, Clone)]
pub(super) struct Responses {
    pub(super) series: Vec<Series>,
    pub(super) stroke: Vec<Vec<f64>>,
    pub(super) rate: Vec<Vec<f64>>,
}

/// The responses of one step length h at its nodes: Δu and Δv of every
/// element at every node (row i·E + e) under x_f = ℓ_j (column j·E + f).
pub(super) struct AtNodes {
    pub(super) stroke: DMatrix<f64>,
    pub(super) rate: DMatrix<f64>,
}

/// The response from rest to x = s^k from the response to s^(k−1):
/// the system being linear and its coefficients constant, the response to
/// ∫₀^s x is ∫₀^s of the response to x (Duhamel), and s^k = k ∫₀^s σ^(k−1),
/// so that
///
/// ```text
/// u_k(s) = k ∫₀^s u_{k−1},   u̇_k(s) = k u_{k−1}(s),
/// ```
///
/// coefficient by coefficient; the one above the series' order is left
/// out, as the series itself leaves out its own.
pub(super) fn integrated(previous: &Series, k: usize) -> Series {
    let scale = k as f64;
    let mut response = previous.clone();
    for j in 0..=previous.degree {
        let (ru, rv) = response.order_mut(j);
        match j.checked_sub(1) {
            Some(below) => {
                for (r, &u) in ru.iter_mut().zip(previous.order(below).0) {
                    *r = scale * u / j as f64;
                }
            }
            None => ru.fill(0.0),
        }
        for (v, &u) in rv.iter_mut().zip(previous.order(j).0) {
            *v = scale * u;
        }
    }
    response
}

impl Responses {
    /// From rest in `rest` (K and C of the configuration, no load), one
    /// Taylor series per element and power of s.
    pub(super) fn make(rest: &System, elements: &[Element]) -> Responses {
        let n = rest.load.len();
        let zero = vec![0.0; n];
        let mut series = Vec::with_capacity(POWERS * elements.len());
        let (mut stroke, mut rate) = (Vec::new(), Vec::new());
        let mut buffer = Vec::new();
        for k in 0..POWERS {
            for (f, el) in elements.iter().enumerate() {
                let response = if k < 4 {
                    let mut force = [0.0; 6];
                    force[k] = 1.0;
                    let forcing = Forcing {
                        left: el.left,
                        right: el.right,
                        left_rate: el.left_rate,
                        right_rate: el.right_rate,
                        force,
                    };
                    Series::forced(
                        rest,
                        (&zero, &zero),
                        (0.0, 0.0, 0.0),
                        (1.0, 1.0),
                        &[forcing],
                    )
                } else {
                    integrated(&series[(k - 1) * elements.len() + f], k)
                };
                for other in elements {
                    let (a, b) = (other.left, other.right);
                    response.combine(&[(a, 1.0), (b, -1.0)], &[], &mut buffer);
                    stroke.push(buffer.clone());
                    response.combine(&[], &[(a, 1.0), (b, -1.0)], &mut buffer);
                    rate.push(buffer.clone());
                }
                series.push(response);
            }
        }
        Responses {
            series,
            stroke,
            rate,
        }
    }

    /// The weights w_r of the responses whose sum is the motion from rest
    /// under x_f = Σ_k p_{f,k} s^k, `power(f)` = p_f.
    pub(super) fn weights(&self, ne: usize, power: impl Fn(usize) -> [f64; POWERS]) -> Vec<f64> {
        let mut w = vec![0.0; POWERS * ne];
        for f in 0..ne {
            for (k, p) in power(f).into_iter().enumerate() {
                w[k * ne + f] = p;
            }
        }
        w
    }

    /// Σ_r w_r (u, u̇)_r(s), added to (u, v), to the degree `degree` of
    /// the free motion of the step, which carries it to the series'
    /// tolerance (the responses' terms past it are as small as its own):
    /// Σ_k s^k Σ_r w_r c_{r,k} by Horner's rule, order by order on the
    /// responses' columns (each order's 2n coefficients one run of
    /// memory, [`Series::held`]), rather than a dot product per floor and
    /// response: one pass over the same coefficients, in runs of 2n.
    pub(super) fn add_state(
        &self,
        w: &[f64],
        (s, degree): (f64, usize),
        (u, v): (&mut [f64], &mut [f64]),
    ) {
        let n = u.len();
        let mut sum = vec![0.0; 2 * n];
        for k in (0..=degree.min(ORDER)).rev() {
            for x in &mut sum {
                *x *= s;
            }
            for (series, &wr) in self.series.iter().zip(w) {
                if wr == 0.0 || k > series.degree {
                    continue;
                }
                let column = &series.held()[2 * n * k..2 * n * (k + 1)];
                for (x, c) in sum.iter_mut().zip(column) {
                    *x += wr * c;
                }
            }
        }
        for (x, y) in u.iter_mut().chain(v.iter_mut()).zip(&sum) {
            *x += y;
        }
    }
}

/// Σ_r w_r p_{r,e}: element e's Δu (`polynomials` the responses'
/// `stroke`) or Δv (their `rate`) under the weights w, to `width`
/// coefficients, added to `out` (which holds at least `width`): one
/// polynomial to evaluate at a step's points instead of one per response.
pub(super) fn weighted(
    polynomials: &[Vec<f64>],
    w: &[f64],
    (ne, e): (usize, usize),
    width: usize,
    out: &mut [f64],
) {
    for (r, &wr) in w.iter().enumerate() {
        if wr != 0.0 {
            for (o, c) in out[..width].iter_mut().zip(&polynomials[r * ne + e]) {
                *o += wr * c;
            }
        }
    }
}

impl Default for AtNodes {
    fn default() -> AtNodes {
        AtNodes {
            stroke: DMatrix::zeros(0, 0),
            rate: DMatrix::zeros(0, 0),
        }
    }
}

impl AtNodes {
    /// The responses to x_f = ℓ_j(s/h) at the nodes c_i h, from the
    /// responses to s^k: ℓ_j(s/h) = Σ_k ℓ_{j,k} s^k ([`basis`]), written
    /// over the last step's. Δu is made for the contacts' products alone
    /// (a damper's law reads Δv only; its rows of `stroke` are left zero).
    /// The responses are summed to the degree `degree` of the step's free
    /// motion, as in [`Responses::add_state`].
    pub(super) fn refill(
        &mut self,
        responses: &Responses,
        elements: &[Element],
        (h, degree): (f64, usize),
    ) {
        let ne = elements.len();
        let m = STAGES * ne;
        let (stroke, rate) = (&mut self.stroke, &mut self.rate);
        for matrix in [&mut *stroke, &mut *rate] {
            if matrix.shape() == (m, m) {
                matrix.fill(0.0);
            } else {
                *matrix = DMatrix::zeros(m, m);
            }
        }
        let bases: [[f64; STAGES]; STAGES] = std::array::from_fn(|j| basis(j, h));
        let (strokes, rates) = (stroke.as_mut_slice(), rate.as_mut_slice());
        let mut p = [0.0; ORDER + 1];
        let p = &mut p[..=degree.min(ORDER)];
        for (i, &c) in NODES.iter().enumerate() {
            poly::powers(c * h, p);
            for k in 0..STAGES {
                for f in 0..ne {
                    for (e, el) in elements.iter().enumerate() {
                        let row = (k * ne + f) * ne + e;
                        let du = match el.law {
                            Law::Damper { .. } => 0.0,
                            Law::Product { .. } => poly::dot(&responses.stroke[row][..p.len()], p),
                        };
                        let dv = poly::dot(&responses.rate[row][..p.len()], p);
                        // Entry (i·E + e, j·E + f), column-major.
                        for (j, b) in bases.iter().enumerate() {
                            let at = (j * ne + f) * m + i * ne + e;
                            strokes[at] += b[k] * du;
                            rates[at] += b[k] * dv;
                        }
                    }
                }
            }
        }
    }
}
