//! The collocated step's error estimate (SPEC §14): the defect of the
//! collocated force modelled as (κ + λθ + μθ²)π(θ), and the forces' own
//! answer to the motion it moves.

use nalgebra::DVector;

use super::basis::{lagrange, quadratic};
use super::newton::Linearized;
use super::{Collocation, Element, Law, NODES, POWERS, values};
use crate::model::buildings::retrofit::dashpot_force;
use crate::solver::buildings::poly;
use crate::solver::buildings::taylor::{ORDER, Series};

/// κ_e = (x_e(0) − Σ_j X_{e,j} ℓ_j(0))/π(0) of each element: the start's
/// force against the quadratic's there, over the node polynomial's.
pub(super) fn kappa(elements: &[Element], y0: &[f64], x: &DVector<f64>) -> Vec<f64> {
    let n = y0.len() / 2;
    let ne = elements.len();
    let start = values(elements, &y0[..n], &y0[n..]);
    let [a, b, _] = NODES;
    (0..ne)
        .map(|e| {
            let at_zero: f64 = (0..3).map(|j| x[j * ne + e] * lagrange(j, 0.0)).sum();
            (start[e] - at_zero) / (-a * b)
        })
        .collect()
}

impl Collocation {
    /// The forces' own answer to the defect model: the quadratic through
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
    /// alone; where it is soft, P is small. None where J is singular.
    pub(super) fn feedback(
        &self,
        set: usize,
        h: f64,
        model: &[[f64; POWERS]],
        linearized: &Linearized,
    ) -> Option<DVector<f64>> {
        let responses = &self.sets[set];
        let ne = self.elements.len();
        let w = responses.weights(ne, |e| model[e]);
        let mut b = DVector::zeros(3 * ne);
        let mut p = [0.0; ORDER + 1];
        for (i, &c) in NODES.iter().enumerate() {
            poly::powers(c * h, &mut p);
            for (e, el) in self.elements.iter().enumerate() {
                let (mut du, mut dv) = (0.0, 0.0);
                for (r, &wr) in w.iter().enumerate() {
                    if wr != 0.0 {
                        dv += wr * poly::dot(&responses.rate[r * ne + e], &p);
                        if let Law::Product { .. } = el.law {
                            du += wr * poly::dot(&responses.stroke[r * ne + e], &p);
                        }
                    }
                }
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
        linearized.jacobian.solve(&b)
    }

    /// Each element's (λ_e, μ_e) of the defect model d_e(θh) ≈
    /// −(κ_e + λ_e θ + μ_e θ²)π(θ), or None where a damper's defect does not
    /// follow it. For each damper, d(θh) = Σ_j X_j ℓ_j(θ) − F(Δv(θh)) on
    /// the collocated motion: λ and μ from d at θ = 1/2 and 7/8, and the
    /// model checked at θ = 1/4, to within a tenth of it (or to 1e-12 of
    /// the damper's force at the motion's speed): the force's divided
    /// difference x[c₁, c₂, c₃, θh] is then nearly quadratic over the step, as where F
    /// is analytic over a disc some steps wide; near a reversal of Δv
    /// (F ∝ |s − s₀|^α) it is not, at any h. A contact's product, a
    /// polynomial in the motion, keeps λ = μ = 0.
    pub(super) fn defect_model(
        &self,
        set: usize,
        free: &Series,
        h: f64,
        x: &DVector<f64>,
        kappa: &[f64],
        speed: f64,
    ) -> Option<Vec<[f64; 2]>> {
        let responses = &self.sets[set];
        let ne = self.elements.len();
        let w = responses.weights(ne, |f| quadratic(x, ne, f, h));
        let pi = |theta: f64| {
            let [a, b, _] = NODES;
            (theta - a) * (theta - b) * (theta - 1.0)
        };
        self.elements
            .iter()
            .enumerate()
            .map(|(e, el)| {
                let Law::Damper { damping, exponent } = el.law else {
                    return Some([0.0; 2]);
                };
                let defect = |theta: f64| {
                    let s = theta * h;
                    let (vl, vr) = (free.velocity(el.left), free.velocity(el.right));
                    let mut rate = poly::eval(vl, s) - poly::eval(vr, s);
                    for (r, &wr) in w.iter().enumerate() {
                        if wr != 0.0 {
                            rate += wr * poly::eval(&responses.rate[r * ne + e], s);
                        }
                    }
                    let force: f64 = (0..3).map(|j| x[j * ne + e] * lagrange(j, theta)).sum();
                    force - dashpot_force(damping, exponent, rate)
                };
                // g(θ) = −d(θh)/π(θ) = κ + λθ + μθ² through θ = 0, 1/2, 7/8.
                let (a, b) = (0.5, 0.875);
                let (ga, gb) = (-defect(a) / pi(a) - kappa[e], -defect(b) / pi(b) - kappa[e]);
                let mu = (gb / b - ga / a) / (b - a);
                let lambda = ga / a - mu * a;
                let floor = 1e-12 * damping * speed.powf(exponent);
                let theta = 0.25;
                let model = -(kappa[e] + (lambda + mu * theta) * theta) * pi(theta);
                ((defect(theta) - model).abs() <= 0.1 * model.abs() + floor).then_some([lambda, mu])
            })
            .collect()
    }
}
