//! The collocated step's error estimate (SPEC §14): the defect of the
//! collocated force modelled as (κ + a₁θ + a₂θ² + a₃θ³)π(θ), and the
//! forces' own answer to the motion it moves.

use nalgebra::{DVector, SMatrix, SVector};

use super::basis::{collocated, lagrange_at, node_value};
use super::newton::Linearized;
use super::responses::weighted;
use super::{Collocation, Element, Law, MODEL, NODES, POWERS, STAGES, values};
use crate::model::buildings::retrofit::dashpot_force;
use crate::solver::buildings::poly;
use crate::solver::buildings::taylor::{ORDER, Series};

/// Where the defect model is fitted (the first S − 1 points) and
/// checked (the last), as fractions θ of the step: the middle of each gap
/// between consecutive nodes, where π is not small, and θ = 1/2.
const FIT: [f64; MODEL + 1] = {
    let mut points = [0.5; MODEL + 1];
    let mut k = 0;
    while k < MODEL {
        points[k] = 0.5 * (NODES[k] + NODES[k + 1]);
        k += 1;
    }
    points
};

/// ℓ_j at the start, θ = 0.
const AT_START: [[f64; STAGES]; 1] = lagrange_at([0.0]);

/// ℓ_j at the points of [`FIT`] (row k).
const AT_FIT: [[f64; STAGES]; MODEL + 1] = lagrange_at(FIT);

/// π at the points of [`FIT`].
const NODE_AT_FIT: [f64; MODEL + 1] = {
    let mut values = [0.0; MODEL + 1];
    let mut k = 0;
    while k <= MODEL {
        values[k] = node_value(FIT[k]);
        k += 1;
    }
    values
};

/// κ_e = (x_e(0) − Σ_j X_{e,j} ℓ_j(0))/π(0) of each element: the start's
/// force against the collocated cubic's there, over the node polynomial's.
pub(super) fn kappa(elements: &[Element], y0: &[f64], x: &DVector<f64>) -> Vec<f64> {
    let n = y0.len() / 2;
    let ne = elements.len();
    let start = values(elements, &y0[..n], &y0[n..]);
    (0..ne)
        .map(|e| {
            let at_zero: f64 = (0..STAGES).map(|j| x[j * ne + e] * AT_START[0][j]).sum();
            (start[e] - at_zero) / node_value(0.0)
        })
        .collect()
}

impl Collocation {
    /// The forces' own answer to the defect model: the cubic through
    /// P at the nodes by which each element's force follows the motion the
    /// model moves, its law linearized there,
    ///
    /// ```text
    /// damper:   ψ'(X_i) P_i = Δv_i[model + P],
    /// product:  P_i = h (δ̇_i Δu_i[model + P] + δ_i Δv_i[model + P]),
    /// ```
    ///
    /// Δu[·], Δv[·] the responses at the nodes: J P = b with J the
    /// collocated equations' Jacobian and b the model's own Δv (for a
    /// product, h(δ̇ Δu + δ Δv)) at the nodes. Where a damper is stiff
    /// over the step (ψ' small) it holds Δv at the nodes, as Radau IIA's
    /// stages do, and the end's error is far below the model's response
    /// alone; where it is soft, P is small. None where J is singular. The
    /// responses are summed to the free motion's degree `degree`, as the
    /// step's own are ([`super::responses::AtNodes::of`]).
    pub(super) fn feedback(
        &self,
        set: usize,
        (h, degree): (f64, usize),
        model: &[[f64; POWERS]],
        linearized: &Linearized,
    ) -> Option<DVector<f64>> {
        let responses = &self.sets[set];
        let ne = self.elements.len();
        let w = responses.weights(ne, |e| model[e]);
        let mut b = DVector::zeros(STAGES * ne);
        let width = degree.min(ORDER) + 1;
        let powers: [[f64; ORDER + 1]; STAGES] = std::array::from_fn(|i| {
            let mut p = [0.0; ORDER + 1];
            poly::powers(NODES[i] * h, &mut p[..width]);
            p
        });
        for (e, el) in self.elements.iter().enumerate() {
            // The model's Δv (and a product's Δu) as one polynomial.
            let (mut du, mut dv) = ([0.0; ORDER + 1], [0.0; ORDER + 1]);
            weighted(&responses.rate, &w, (ne, e), width, &mut dv);
            if let Law::Product { .. } = el.law {
                weighted(&responses.stroke, &w, (ne, e), width, &mut du);
            }
            for (i, p) in powers.iter().enumerate() {
                let (du, dv) = (poly::dot(&du[..width], p), poly::dot(&dv[..width], p));
                let row = i * ne + e;
                b[row] = match el.law {
                    Law::Damper { .. } => dv,
                    Law::Product { gap, coefficient } => {
                        let delta = linearized.stroke[row] - gap;
                        coefficient * (linearized.rate[row] * du + delta * dv)
                    }
                };
            }
        }
        linearized.jacobian.solve_mut(&mut b).then_some(b)
    }

    /// Each element's (a_{e,1}, a_{e,2}, a_{e,3}) of the defect model
    /// d_e(θh) ≈ −(κ_e + a_{e,1}θ + a_{e,2}θ² + a_{e,3}θ³)π(θ), or None
    /// where an element's defect does not follow it. For each element,
    /// d(θh) = Σ_j X_j ℓ_j(θ) − x(θh), x the law's value on the collocated
    /// motion (the damper's F(Δv), the product's h δ δ̇): the a_q from d
    /// midway between consecutive nodes ([`FIT`]), and the model checked
    /// at θ = 1/2, to
    /// within a tenth of it (or to 1e-12 of the damper's force at the
    /// motion's speed, of the product's largest node value): the force's
    /// divided difference x[c₁, …, c₄, θh] is then nearly a cubic over the
    /// step, as where x is analytic over a disc some steps wide; near a
    /// reversal of Δv (F ∝ |s − s₀|^α) it is not, at any h. π being
    /// orthogonal on [0, 1] to 1, θ and θ² only, the cubic term carries
    /// the end's error: a product's defect is fitted as a damper's is.
    pub(super) fn defect_model(
        &self,
        set: usize,
        free: &Series,
        h: f64,
        x: &DVector<f64>,
        kappa: &[f64],
        speed: f64,
    ) -> Option<Vec<[f64; MODEL]>> {
        let responses = &self.sets[set];
        let ne = self.elements.len();
        let w = responses.weights(ne, |f| collocated(x, ne, f, h));
        // The responses to the free motion's degree, as the step's own.
        let width = (free.degree + 1).min(ORDER + 1);
        // g(θ) − κ = Σ_q a_q θ^q at the fitting points.
        let powers = SMatrix::<f64, MODEL, MODEL>::from_fn(|k, q| FIT[k].powi(q as i32 + 1));
        let powers = powers.lu();
        self.elements
            .iter()
            .enumerate()
            .map(|(e, el)| {
                // The element's Δu or Δv at s on the collocated motion: the
                // free motion's (left less right, each floor's by Horner's
                // rule down the series' columns) and the forces' responses.
                let along = |free: f64, response: &[Vec<f64>], s: f64| {
                    let mut x = free;
                    for (r, &wr) in w.iter().enumerate() {
                        if wr != 0.0 {
                            x += wr * poly::eval(&response[r * ne + e][..width], s);
                        }
                    }
                    x
                };
                // d at the point FIT[k].
                let defect = |k: usize| {
                    let s = FIT[k] * h;
                    let velocities = free.velocity_at(el.left, s) - free.velocity_at(el.right, s);
                    let rate = along(velocities, &responses.rate, s);
                    let force: f64 = (0..STAGES).map(|j| x[j * ne + e] * AT_FIT[k][j]).sum();
                    let law = match el.law {
                        Law::Damper { damping, exponent } => dashpot_force(damping, exponent, rate),
                        Law::Product { gap, coefficient } => {
                            let displacements = free.displacement_at(el.left, s)
                                - free.displacement_at(el.right, s);
                            let stroke = along(displacements, &responses.stroke, s);
                            coefficient * (stroke - gap) * rate
                        }
                    };
                    force - law
                };
                let g =
                    SVector::<f64, MODEL>::from_fn(|k, _| -defect(k) / NODE_AT_FIT[k] - kappa[e]);
                let a = powers.solve(&g)?;
                let floor = match el.law {
                    Law::Damper { damping, exponent } => 1e-12 * damping * speed.powf(exponent),
                    Law::Product { .. } => {
                        1e-12 * (0..STAGES).fold(0.0f64, |m, j| m.max(x[j * ne + e].abs()))
                    }
                };
                let theta = FIT[MODEL];
                let fitted = a.iter().rev().fold(0.0, |acc, q| (acc + q) * theta);
                let model = -(kappa[e] + fitted) * NODE_AT_FIT[MODEL];
                ((defect(MODEL) - model).abs() <= 0.1 * model.abs() + floor)
                    .then(|| std::array::from_fn(|q| a[q]))
            })
            .collect()
    }
}
