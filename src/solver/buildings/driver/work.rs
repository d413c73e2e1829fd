//! The energy balance's terms step by step (SPEC §6 summed over buildings,
//! §13; bumpers and links §14), when a run takes it
//! ([`super::RowOptions::energy`]):
//!
//! - on a series or Runge–Kutta step, the integrals of the power of each
//!   term by the Gauss–Legendre rule ([`super::super::energy`]): inside a
//!   step the motion is one analytic function, so the rule converges
//!   geometrically, to rounding with its 12 points;
//! - on a map step, in closed form ([`super::super::propagator::WorkForms`]):
//!   E_damp, E_in and each link's dashpot as quadratic forms of the state
//!   at the start, the storeys' and the links' springs as the trapezoid of
//!   a force linear in its stroke, (Δ₁ − Δ₀)(F₀ + F₁)/2; out of contact the
//!   contact and bumper terms are zero.
//!
//! So a run with its balance takes the steps of a run without it, bit for
//! bit; E_kin is taken from the state at the end ([`super::Run::finish`]).

use super::super::energy::{NODES, RowEnergy, gauss_legendre};
use super::super::layout::Storey;
use super::super::poly;
use super::super::propagator::{DAMPING, FIRST_LINK, INPUT};
use super::super::taylor::{ORDER, Series};
use super::{Run, ground_at};
use crate::model::buildings::ground::Piece;
use crate::model::buildings::retrofit::dashpot_force;

/// The sums of the balance so far, the quadrature rule, and the buffers
/// of the map steps.
#[derive(Debug, Clone)]
pub(super) struct Balance {
    pub(super) sums: RowEnergy,
    /// The Gauss–Legendre rule on [−1, 1].
    nodes: Vec<f64>,
    weights: Vec<f64>,
    /// Each link's dissipated energy over a map step.
    dissipation: Vec<f64>,
    /// A map step's state measured from its rest point, its products
    /// ([`super::super::propagator::WorkForms::on`]), and the forms' values.
    state: Vec<f64>,
    pairs: Vec<f64>,
    values: Vec<f64>,
}

impl Balance {
    /// Zero work, with the floors' kinetic energy at the start.
    pub(super) fn new(initial_kinetic: f64, links: usize) -> Balance {
        let (nodes, weights) = gauss_legendre(NODES);
        Balance {
            sums: RowEnergy {
                initial_kinetic,
                ..RowEnergy::default()
            },
            nodes,
            weights,
            dissipation: vec![0.0; links],
            state: Vec::new(),
            pairs: Vec::new(),
            values: Vec::new(),
        }
    }
}

/// The work terms of one step, J: E_in, E_damp, E_spring, E_contact,
/// E_bumper and E_link in the fields of [`RowEnergy`] (the others zero).
fn add(sums: &mut RowEnergy, step: &RowEnergy, weight: f64) {
    sums.input += weight * step.input;
    sums.damping += weight * step.damping;
    sums.spring += weight * step.spring;
    sums.contact += weight * step.contact;
    sums.bumper += weight * step.bumper;
    sums.link += weight * step.link;
}

impl Run<'_> {
    /// Storey `k`'s shear at drift Δ in the configuration in force:
    /// V = αkΔ + (1 − α)k z − (P/h)Δ (SPEC §13, §15).
    pub(super) fn shear(&self, k: usize, s: &Storey, drift: f64) -> f64 {
        let z = self.config.z(k, drift, s.yield_drift);
        s.alpha * s.stiffness * drift + (1.0 - s.alpha) * s.stiffness * z - s.geometric * drift
    }

    /// The power of each term of the balance at (u, u̇) under ground
    /// acceleration `ag` (W, in [`RowEnergy`]'s fields), and each link's
    /// dissipated power into `dissipation`: F_d Δv, with each fluid
    /// viscous damper's force F_d from `dashpots` (damper by damper) where
    /// the step carries it, else c_l|Δv|^α sgn Δv (SPEC §14).
    pub(super) fn power(
        &self,
        (u, v): (&[f64], &[f64]),
        ag: f64,
        dashpots: Option<&[f64]>,
        dissipation: &mut [f64],
    ) -> RowEnergy {
        let layout = &self.layout;
        let n = layout.dofs;
        let mut p = RowEnergy::default();
        for i in 0..n {
            let row = layout.damping_rows.column(i);
            let cv: f64 = row.iter().map(|&(j, c)| c * v[j]).sum();
            p.damping += layout.mass[i] * v[i] * cv;
            p.input -= layout.mass[i] * v[i] * ag;
        }
        for (k, st) in layout.storeys.iter().enumerate() {
            let d = layout.drift(st, u);
            p.spring += self.shear(k, st, d) * layout.drift(st, v);
        }
        // The joints' own elements, then the bumpers' (SPEC §14).
        for (pi, pair) in layout.pairs.iter().enumerate() {
            if let Some(closed) = &self.config.contact[pi] {
                let delta = u[pair.left_dof] - u[pair.right_dof] - layout.gaps[pi];
                let rate = v[pair.left_dof] - v[pair.right_dof];
                let work = closed.law.force(delta, rate).force * rate;
                if pi < layout.hard {
                    p.contact += work;
                } else {
                    p.bumper += work;
                }
            }
        }
        // The dampers are the links that are not linear, in link order.
        let mut damper = 0;
        for (l, out) in layout.links.iter().zip(dissipation) {
            let (a, b) = (l.pair.left_dof, l.pair.right_dof);
            let rate = v[a] - v[b];
            let (dashpot, dissipated) = match dashpots {
                Some(forces) if !l.is_linear() => {
                    damper += 1;
                    (forces[damper - 1], forces[damper - 1] * rate)
                }
                _ => (
                    dashpot_force(l.link.damping, l.link.exponent, rate),
                    l.dissipation(rate),
                ),
            };
            p.link += (l.link.stiffness * (u[a] - u[b]) + dashpot) * rate;
            *out = dissipated;
        }
        p
    }

    /// The work terms on [0, end] of a Taylor or Runge–Kutta step, by the
    /// Gauss–Legendre rule.
    pub(super) fn work_on(&mut self, series: &Series, end: f64) {
        let Some(mut b) = self.energy.take() else {
            return;
        };
        let mut dissipated = vec![0.0; self.layout.links.len()];
        let rule = (&b.nodes[..], &b.weights[..]);
        self.quadrature(series, end, rule, &mut b.sums, &mut dissipated);
        for (r, d) in self.links.iter_mut().zip(&dissipated) {
            r.energy = r.energy.max(0.0) + d;
        }
        b.sums.max_input = b.sums.max_input.max(b.sums.input.abs());
        self.energy = Some(b);
    }

    /// The work terms on [0, end] of `series` by the Gauss–Legendre rule
    /// (nodes, weights) on [−1, 1], added to `sums`, and each link's
    /// dissipated energy to `dissipated`: a fluid viscous damper's work
    /// with the force the series carries where it carries one (a
    /// collocated step's force polynomial, a damped series' own), to
    /// which its motion is the exact answer, so that the work closes the
    /// balance with the motion's other terms. The law at the series' Δv
    /// does not: where the damper all but locks, Δv's interior error (of
    /// the order of its own size) then counts in c|Δv|^(α+1) as
    /// dissipation, always positive. With α = 0.2 and c = 1e7 under
    /// synthetic:2000 the balance stood 2e-7 open with the law, 4e-12
    /// with the carried force.
    pub(super) fn quadrature(
        &self,
        series: &Series,
        end: f64,
        (nodes, weights): (&[f64], &[f64]),
        sums: &mut RowEnergy,
        dissipated: &mut [f64],
    ) {
        let n = self.layout.dofs;
        let (mut u, mut v) = (vec![0.0; n], vec![0.0; n]);
        let mut power = vec![0.0; dissipated.len()];
        let dampers = self.layout.dampers.len();
        let carried: Option<Vec<&[f64]>> = (0..dampers).map(|d| series.damper_force(d)).collect();
        let mut forces = vec![0.0; dampers];
        for (xi, wi) in nodes.iter().zip(weights) {
            let s = 0.5 * end * (1.0 + xi);
            let weight = 0.5 * end * wi;
            series.state(s, &mut u, &mut v);
            let ag = series.ground[..=ORDER]
                .iter()
                .rev()
                .fold(0.0, |acc, &c| acc * s + c);
            if let Some(carried) = &carried {
                for (f, c) in forces.iter_mut().zip(carried) {
                    *f = poly::eval(c, s);
                }
            }
            let dashpots = carried.as_ref().map(|_| &forces[..]);
            let p = self.power((&u, &v), ag, dashpots, &mut power);
            add(sums, &p, weight);
            for (d, p) in dissipated.iter_mut().zip(&power) {
                *d += weight * p;
            }
        }
    }

    /// The work terms of the map step of length h on `piece` from the
    /// current state to displacements u₁, in closed form: the map asked
    /// for last is this step's
    /// ([`super::super::propagator::Propagator::last_work_forms`]). The end's
    /// velocities enter only E_kin, taken at the run's end.
    // Out of line, so that a profile shows the balance's cost on a map step
    // apart from the step's own (one call per map step).
    #[inline(never)]
    pub(super) fn work_on_map(&mut self, piece: &Piece, h: f64, u1: &[f64]) {
        let Some(mut b) = self.energy.take() else {
            return;
        };
        let step = self.map_work(ground_at(piece, self.t), u1, &mut b);
        #[cfg(test)]
        if super::work_check::checking() {
            self.check_work(piece, h, &step, &b.dissipation);
        }
        // The step's length serves the check alone.
        #[cfg(not(test))]
        let _ = h;
        add(&mut b.sums, &step, 1.0);
        for (r, d) in self.links.iter_mut().zip(&b.dissipation) {
            r.energy = r.energy.max(0.0) + d;
        }
        b.sums.max_input = b.sums.max_input.max(b.sums.input.abs());
        self.energy = Some(b);
    }

    /// The terms of [`Run::work_on_map`] (J), and each link's dissipated
    /// energy into `b.dissipation`.
    pub(super) fn map_work(
        &mut self,
        ground: (f64, f64),
        u1: &[f64],
        b: &mut Balance,
    ) -> RowEnergy {
        let forms = self.propagator.last_work_forms(&self.system, &self.layout);
        b.values.resize(forms.len(), 0.0);
        forms.on(
            (&self.u, &self.v),
            ground,
            (&self.system.load, u1),
            (&self.key, &mut self.rest),
            (&mut b.state, &mut b.pairs),
            &mut b.values,
        );
        let mut step = RowEnergy {
            damping: b.values[DAMPING],
            input: b.values[INPUT],
            ..RowEnergy::default()
        };
        let (u0, layout) = (&self.u, &self.layout);
        for (k, st) in layout.storeys.iter().enumerate() {
            let (d0, d1) = (layout.drift(st, u0), layout.drift(st, u1));
            step.spring += 0.5 * (d1 - d0) * (self.shear(k, st, d0) + self.shear(k, st, d1));
        }
        for (k, (l, out)) in layout.links.iter().zip(&mut b.dissipation).enumerate() {
            let (i, j) = (l.pair.left_dof, l.pair.right_dof);
            let (s0, s1) = (u0[i] - u0[j], u1[i] - u1[j]);
            *out = b.values[FIRST_LINK + k];
            step.link += 0.5 * (s1 - s0) * l.link.stiffness * (s0 + s1) + *out;
        }
        step
    }
}
