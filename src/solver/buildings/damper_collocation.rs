//! The step of a row with fluid viscous dampers (SPEC §14) by exponential
//! collocation: the linear motion of the configuration carried exactly, and
//! only the nonlinear forces across floor pairs collocated, each as a
//! polynomial in time.
//!
//! Out of Hertz-type contact the row is linear but for its dampers' forces
//! F_d = c_l |Δv_d|^α sgn Δv_d and, in a contact of the improved Kelvin law,
//! the term h δ_p δ̇_p (SPEC §4). Over a step of length h each such force
//! x_e(s) is the quadratic through its values X_{e,j} at the nodes c_j h of
//! Radau IIA (c = (4 − √6)/10, (4 + √6)/10, 1),
//!
//! ```text
//! x_e(s) = Σ_j X_{e,j} ℓ_j(s/h),   ℓ_j the Lagrange basis on c,
//! ```
//!
//! and the motion under it is the linear system's, exactly (to round-off)
//! by superposition of its Taylor series ([`super::taylor`]): the free
//! motion from the start under the ground, plus the response from rest to
//! each x_e = ℓ_j, which depends only on the configuration's K and C and
//! on h, and is cached by them ([`Collocation`]). Δu_e and Δv_e at the
//! nodes are then linear in the 3 × (elements) unknowns X, which solve
//!
//! ```text
//! damper:   ψ(X_{d,i}) = Δv_d(c_i h),   ψ(F) = sgn F (|F|/c_l)^(1/α),
//! product:  X_{p,i} = h_p δ_p(c_i h) δ̇_p(c_i h),
//! ```
//!
//! by Newton's method: the damper's law written the other way round, as
//! Newmark's mixed step and [`super::damper_radau`] write it, smooth with
//! a bounded slope where F = 0. For a damper much stiffer than the step
//! (its relaxation time m̄/(c_l α |Δv|^(α−1)) ≪ h) the equations are Radau
//! IIA's on Δv (∫₀^{c_i} ℓ_j = a_ij), so the step is L-stable there; the
//! last node is the end, so the end satisfies the damper's law.
//!
//! **Order.** The quadratic through the Radau nodes misses x by
//! x[c₁, c₂, c₃, s] π(s), π(s) = Π(s − c_i h), and π is orthogonal on
//! [0, h] to polynomials of degree ≤ 1 (the 3-point Radau rule is exact to
//! degree 4): the end carries a local error O(h⁶) as Radau IIA's does, the
//! nodes O(h⁴). The local error is estimated by step doubling,
//! (y_h − y_{h/2,h/2})/(2⁵ − 1), and the step returns y_{h/2,h/2}.
//!
//! Step lengths are powers of 2^(1/4), or the rest of the sub-step, so that the
//! responses are made once per configuration and length and reused: a step
//! then costs two Taylor series of the free motion and a Newton solve on
//! 3 × (elements) unknowns instead of 3 × (n + elements).

use std::collections::HashMap;

use nalgebra::{DMatrix, DVector};

use super::damper::Damper;
use super::system::System;
use super::taylor::{Forcing, Series};
use crate::model::buildings::retrofit::{dashpot_force, dashpot_velocity, dashpot_velocity_slope};

/// The nodes c_j of Radau IIA, 3 stages: (4 − √6)/10, (4 + √6)/10, 1.
pub const NODES: [f64; 3] = super::damper_radau::C;

/// Newton iterations at most on one step.
const NEWTON: usize = 50;

/// Response sets kept at most; past it the cache starts afresh (the rests
/// of sub-steps after events add one set each).
const CAPACITY: usize = 512;

/// What an element's force obeys.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Law {
    /// ψ(X) = Δv: a fluid viscous damper's force (N).
    Damper { damping: f64, exponent: f64 },
    /// X = h δ δ̇, δ = Δu − gap: the improved Kelvin law's product (N).
    Product { gap: f64, coefficient: f64 },
}

/// One nonlinear force across floors A and B: −X/m_A on A, +X/m_B on B.
/// The rates are the floors' alone, so that the responses of a contact's
/// product serve every contact of the pair whatever its h (v₀).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Element {
    left: usize,
    right: usize,
    left_rate: f64,
    right_rate: f64,
    law: Law,
}

/// The responses from rest to x_e = ℓ_j for every unknown q = j·E + e
/// (E elements): Δu and Δv of every element at every node (row i·E + e),
/// (u, u̇) at the end, each response's series, and each element's series
/// under x_e = π (the dense output's cubic term).
#[derive(Debug, Clone)]
struct Responses {
    stroke: DMatrix<f64>,
    rate: DMatrix<f64>,
    end: DMatrix<f64>,
    series: Vec<Series>,
    cubic: Vec<Series>,
}

/// The cached responses, by (K, C, elements, h), and what the steps cost.
#[derive(Debug, Default)]
pub struct Collocation {
    responses: HashMap<Vec<u64>, Responses>,
    /// Solves of one step's nodes (three per doubled step).
    pub solves: usize,
    /// Newton iterations over them.
    pub newton: usize,
    /// Response sets made.
    pub made: usize,
    /// The series of the last step's motion, its dense output: the free
    /// motion's plus each response's times its unknown (None when the last
    /// step failed).
    pub last: Option<Series>,
    /// Steps accepted and rejected for their error ([`super::contact_rk`]'s
    /// control of the step length).
    pub accepted: usize,
    pub rejected: usize,
}

/// ℓ_j(θ), the Lagrange basis on the nodes.
fn lagrange(j: usize, theta: f64) -> f64 {
    (0..3)
        .filter(|&k| k != j)
        .map(|k| (theta - NODES[k]) / (NODES[j] - NODES[k]))
        .product()
}

/// The quadratic ℓ_j(s/h) in powers of s.
fn basis(j: usize, h: f64) -> [f64; 4] {
    let (a, b) = match j {
        0 => (NODES[1], NODES[2]),
        1 => (NODES[0], NODES[2]),
        _ => (NODES[0], NODES[1]),
    };
    let w = 1.0 / ((NODES[j] - a) * (NODES[j] - b));
    // (θ − a)(θ − b) w, θ = s/h.
    [a * b * w, -(a + b) * w / h, w / (h * h), 0.0]
}

/// The node polynomial π(θ) = (θ − c₁)(θ − c₂)(θ − 1), θ = s/h, in powers
/// of s: zero at every node.
fn node_polynomial(h: f64) -> [f64; 4] {
    let [a, b, _] = NODES;
    [
        -a * b,
        (a * b + a + b) / h,
        -(a + b + 1.0) / (h * h),
        1.0 / (h * h * h),
    ]
}

/// Each element's force (or product) at the state (u, u̇).
fn values(elements: &[Element], u: &[f64], v: &[f64]) -> Vec<f64> {
    elements
        .iter()
        .map(|el| {
            let (du, dv) = measure(el, u, v);
            match el.law {
                Law::Damper { damping, exponent } => dashpot_force(damping, exponent, dv),
                Law::Product { gap, coefficient } => coefficient * (du - gap) * dv,
            }
        })
        .collect()
}

fn elements(dampers: &[Damper], system: &System, mass: &[f64]) -> Vec<Element> {
    let mut out: Vec<Element> = dampers
        .iter()
        .map(|d| Element {
            left: d.left,
            right: d.right,
            left_rate: d.left_rate,
            right_rate: d.right_rate,
            law: Law::Damper {
                damping: d.damping,
                exponent: d.exponent,
            },
        })
        .collect();
    // The system's product rates are h/m_A and h/m_B.
    out.extend(system.products.iter().map(|p| Element {
        left: p.left,
        right: p.right,
        left_rate: 1.0 / mass[p.left],
        right_rate: 1.0 / mass[p.right],
        law: Law::Product {
            gap: p.gap,
            coefficient: p.left_rate * mass[p.left],
        },
    }));
    out
}

/// The cache key: K and C's nonzero entries, the elements, h.
fn key(system: &System, elements: &[Element], h: f64) -> Vec<u64> {
    let n = system.load.len();
    let mut key = Vec::new();
    for i in 0..n {
        for &(j, k, c) in system.row(i) {
            key.extend([j as u64, k.to_bits(), c.to_bits()]);
        }
        key.push(u64::MAX);
    }
    for e in elements {
        key.extend([
            e.left as u64,
            e.right as u64,
            e.left_rate.to_bits(),
            e.right_rate.to_bits(),
        ]);
    }
    key.push(h.to_bits());
    key
}

/// Δu_e and Δv_e of element e at (u, u̇).
fn measure(e: &Element, u: &[f64], v: &[f64]) -> (f64, f64) {
    (u[e.left] - u[e.right], v[e.left] - v[e.right])
}

impl Responses {
    /// From rest in `linear` (K and C of the configuration, no load), one
    /// Taylor series per unknown.
    fn make(linear: &System, elements: &[Element], h: f64) -> Responses {
        let n = linear.load.len();
        let ne = elements.len();
        let m = 3 * ne;
        let zero = vec![0.0; n];
        let mut stroke = DMatrix::zeros(m, m);
        let mut rate = DMatrix::zeros(m, m);
        let mut end = DMatrix::zeros(2 * n, m);
        let mut all = Vec::with_capacity(m);
        let (mut u, mut v) = (vec![0.0; n], vec![0.0; n]);
        let response = |el: &Element, force: [f64; 4]| {
            let forcing = Forcing {
                left: el.left,
                right: el.right,
                left_rate: el.left_rate,
                right_rate: el.right_rate,
                force,
            };
            Series::forced(
                linear,
                (&zero, &zero),
                (0.0, 0.0, 0.0),
                (1.0, 1.0),
                &[forcing],
            )
        };
        for j in 0..3 {
            let force = basis(j, h);
            for (f, el) in elements.iter().enumerate() {
                let q = j * ne + f;
                let series = response(el, force);
                for (i, &c) in NODES.iter().enumerate() {
                    series.state(c * h, &mut u, &mut v);
                    for (e, other) in elements.iter().enumerate() {
                        let (du, dv) = measure(other, &u, &v);
                        stroke[(i * ne + e, q)] = du;
                        rate[(i * ne + e, q)] = dv;
                    }
                }
                for r in 0..n {
                    end[(r, q)] = u[r];
                    end[(n + r, q)] = v[r];
                }
                all.push(series);
            }
        }
        let cubic = elements
            .iter()
            .map(|el| response(el, node_polynomial(h)))
            .collect();
        Responses {
            stroke,
            rate,
            end,
            series: all,
            cubic,
        }
    }
}

/// What one step needs of the row beyond its state.
pub struct Row<'a> {
    /// The configuration's system (its products are elements here).
    pub system: &'a System,
    pub dampers: &'a [Damper],
    /// The floors' masses (kg).
    pub mass: &'a [f64],
    /// (a_g, ȧ_g, σ) at offset s from the step's start.
    pub ground: &'a dyn Fn(f64) -> (f64, f64, f64),
    /// The motion's scales (largest |u|, largest |u̇|).
    pub scale: (f64, f64),
}

impl Collocation {
    /// The responses of `linear` for `elements` over h, made when missing.
    fn responses(&mut self, linear: &System, elements: &[Element], h: f64) -> &Responses {
        let key = key(linear, elements, h);
        if !self.responses.contains_key(&key) {
            if self.responses.len() >= CAPACITY {
                self.responses.clear();
            }
            self.made += 1;
            let mut rest = linear.clone();
            rest.load.fill(0.0);
            let made = Responses::make(&rest, elements, h);
            self.responses.insert(key.clone(), made);
        }
        &self.responses[&key]
    }

    /// The end of one solve of length h on `free` (from y0) and the nodes'
    /// forces X, from the first guess `guess` (X's values at the nodes when
    /// given, else each force as at the start), counted.
    fn solve(
        &mut self,
        row: &Row,
        (linear, elements): (&System, &[Element]),
        (free, y0): (&Series, &[f64]),
        h: f64,
        guess: Option<DVector<f64>>,
    ) -> Option<Solved> {
        let responses = self.responses(linear, elements, h);
        let (end, iterations) = solve(row, elements, responses, (free, y0), h, guess);
        self.solves += 1;
        self.newton += iterations;
        end
    }

    /// The dense output of a step of length h from y0: the motion under
    /// each force's cubic through its value at the start and at the nodes,
    /// x_e = Σ_j X_{e,j} ℓ_j + κ_e π with κ_e = (x_e(0) − Σ_j X_{e,j} ℓ_j(0))/π(0),
    /// so that its interior misses the force by O(h⁴) where the quadratic
    /// alone misses it by O(h³): `free` plus each response's series times
    /// its coefficient. Its end differs from the step's by the cubic
    /// term's, which π's orthogonality keeps within the step's error.
    fn motion(
        &mut self,
        (linear, elements): (&System, &[Element]),
        (free, y0): (&Series, &[f64]),
        h: f64,
        x: &DVector<f64>,
    ) -> Series {
        let n = y0.len() / 2;
        let ne = elements.len();
        let start = values(elements, &y0[..n], &y0[n..]);
        let [a, b, _] = NODES;
        let kappa: Vec<f64> = (0..ne)
            .map(|e| {
                let at_zero: f64 = (0..3).map(|j| x[j * ne + e] * lagrange(j, 0.0)).sum();
                (start[e] - at_zero) / (-a * b)
            })
            .collect();
        let responses = self.responses(linear, elements, h);
        let mut motion = free.clone();
        let terms = responses.series.iter().zip(x.iter());
        for (series, &xq) in terms.chain(responses.cubic.iter().zip(&kappa)) {
            for (m, r) in motion.u.iter_mut().zip(&series.u) {
                *m += xq * r;
            }
            for (m, r) in motion.v.iter_mut().zip(&series.v) {
                *m += xq * r;
            }
        }
        motion.radius = h;
        motion
    }

    /// One step of length h from y0 = (u, u̇): the end y_h and the error
    /// estimate by step doubling, (y_h − y_{h/2,h/2})/31, its series in
    /// [`Collocation::last`]; or None when Newton's method does not
    /// converge or h passes the reach of the free motion's series.
    pub fn step(&mut self, row: &Row, y0: &[f64], h: f64) -> Option<(Vec<f64>, Vec<f64>)> {
        self.last = None;
        let n = y0.len() / 2;
        let mut linear = row.system.clone();
        linear.products.clear();
        let elements = elements(row.dampers, row.system, row.mass);
        let system = (&linear, &elements[..]);
        let free = Series::new(&linear, &y0[..n], &y0[n..], (row.ground)(0.0), row.scale);
        if h > free.radius {
            return None;
        }
        let (whole, x) = self.solve(row, system, (&free, y0), h, None)?;
        // The halves start from the whole step's forces, interpolated.
        let ne = elements.len();
        let guess = |offset: f64| {
            DVector::from_fn(3 * ne, |r, _| {
                let (i, e) = (r / ne, r % ne);
                let theta = offset + 0.5 * NODES[i];
                (0..3).map(|j| x[j * ne + e] * lagrange(j, theta)).sum()
            })
        };
        let (half, _) = self.solve(row, system, (&free, y0), 0.5 * h, Some(guess(0.0)))?;
        let (u, v) = half.split_at(n);
        let middle = Series::new(&linear, u, v, (row.ground)(0.5 * h), row.scale);
        let (twice, _) = self.solve(row, system, (&middle, &half), 0.5 * h, Some(guess(0.5)))?;
        let error = whole
            .iter()
            .zip(&twice)
            .map(|(a, b)| (a - b) / 31.0)
            .collect();
        // With a contact's product the quintic through the ends is the
        // better dense output (the product's cubic term is not the force's
        // own); without, the whole step's motion, whose end is within the
        // step's error of y_{h/2,h/2}.
        if row.system.products.is_empty() {
            self.last = Some(self.motion(system, (&free, y0), h, &x));
        }
        Some((twice, error))
    }
}

/// A solve's end (u, u̇) and its nodes' forces X.
type Solved = (Vec<f64>, DVector<f64>);

/// The nodes' forces over a step of length h on the free motion `free`
/// (from y0), by Newton's method: the end (u, u̇) when it converged (to
/// 1e-15 of each damper's force at the motion's speed, 1e-14 of each
/// product), and the iterations taken.
fn solve(
    row: &Row,
    elements: &[Element],
    responses: &Responses,
    (free, y0): (&Series, &[f64]),
    h: f64,
    guess: Option<DVector<f64>>,
) -> (Option<Solved>, usize) {
    let n = y0.len() / 2;
    let ne = elements.len();
    let m = 3 * ne;
    // The free motion's Δu, Δv at the nodes.
    let (mut u, mut v) = (vec![0.0; n], vec![0.0; n]);
    let mut free_stroke = DVector::zeros(m);
    let mut free_rate = DVector::zeros(m);
    for (i, &c) in NODES.iter().enumerate() {
        free.state(c * h, &mut u, &mut v);
        for (e, el) in elements.iter().enumerate() {
            let (du, dv) = measure(el, &u, &v);
            free_stroke[i * ne + e] = du;
            free_rate[i * ne + e] = dv;
        }
    }
    // First guess: each force as at the start.
    let (u0, v0) = y0.split_at(n);
    let x = guess.unwrap_or_else(|| {
        let start = values(elements, u0, v0);
        DVector::from_fn(m, |r, _| start[r % ne])
    });
    let mut x = x;
    let speed = row.scale.1;
    let mut residual = DVector::zeros(m);
    let mut jacobian = DMatrix::zeros(m, m);
    for iteration in 1..=NEWTON {
        let stroke = &free_stroke + &responses.stroke * &x;
        let rate = &free_rate + &responses.rate * &x;
        for r in 0..m {
            match elements[r % ne].law {
                Law::Damper { damping, exponent } => {
                    residual[r] = dashpot_velocity(damping, exponent, x[r]) - rate[r];
                    for q in 0..m {
                        jacobian[(r, q)] = -responses.rate[(r, q)];
                    }
                    jacobian[(r, r)] += dashpot_velocity_slope(damping, exponent, x[r]);
                }
                Law::Product { gap, coefficient } => {
                    let delta = stroke[r] - gap;
                    residual[r] = x[r] - coefficient * delta * rate[r];
                    for q in 0..m {
                        jacobian[(r, q)] = -coefficient
                            * (rate[r] * responses.stroke[(r, q)] + delta * responses.rate[(r, q)]);
                    }
                    jacobian[(r, r)] += 1.0;
                }
            }
        }
        let Some(delta) = jacobian.clone().lu().solve(&residual) else {
            return (None, iteration);
        };
        x -= &delta;
        let converged = (0..m).all(|r| {
            let bound = match elements[r % ne].law {
                Law::Damper { damping, exponent } => 1e-15 * damping * speed.powf(exponent),
                Law::Product { .. } => 1e-14 * x[r].abs().max(1e-300),
            };
            delta[r].abs() <= bound
        });
        if converged {
            free.state(h, &mut u, &mut v);
            let forced = &responses.end * &x;
            let mut y1 = vec![0.0; 2 * n];
            for r in 0..n {
                y1[r] = u[r] + forced[r];
                y1[n + r] = v[r] + forced[n + r];
            }
            return (Some((y1, x)), iteration);
        }
    }
    (None, NEWTON)
}

#[cfg(test)]
mod tests {
    use super::super::damper_radau::A;
    use super::{NODES, basis, lagrange, node_polynomial};

    /// ∫₀^{c_i} ℓ_j = a_ij, Radau IIA's matrix (Hairer & Wanner, Table
    /// IV.5.6): where the damper is far stiffer than the step the
    /// collocated equations on Δv are Radau IIA's; and ℓ_j(c_i) = δ_ij,
    /// π(c_i) = 0, each to 1e-15.
    #[test]
    fn the_basis_integrates_to_radau_iia() {
        let pi = node_polynomial(1.0);
        for (&c, row) in NODES.iter().zip(&A) {
            let at = pi.iter().rev().fold(0.0, |acc, x| acc * c + x);
            assert!(at.abs() < 1e-15, "π({c}) = {at}");
            for (j, &a) in row.iter().enumerate() {
                let p = basis(j, 1.0);
                let integral: f64 = (0..4)
                    .map(|k| p[k] * c.powi(k as i32 + 1) / (k + 1) as f64)
                    .sum();
                assert!(
                    (integral - a).abs() < 1e-15,
                    "a_{j}: {integral} against {a}"
                );
                let value = lagrange(j, c);
                let expected = if c == NODES[j] { 1.0 } else { 0.0 };
                assert!((value - expected).abs() < 1e-15, "ℓ_{j}({c}) = {value}");
            }
        }
    }
}
