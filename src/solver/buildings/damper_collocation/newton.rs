//! The nodes' forces of one collocated step by Newton's method (SPEC §14),
//! and its first guess from the last step's forces.

use nalgebra::allocator::Allocator;
use nalgebra::{
    Const, DMatrix, DVector, DefaultAllocator, DimMin, DimName, Dyn, LU, OMatrix, OVector,
};

use super::basis::{collocated, corrected};
use super::responses::{AtNodes, Responses};
use super::{Collocation, Element, Law, NEWTON, NODES, POWERS, Row, STAGES, values};
use crate::model::buildings::retrofit::dashpot_velocity_slope;
use crate::solver::buildings::poly;
use crate::solver::buildings::taylor::{ORDER, Series};

/// The forces of the last step: its start and end, its length, and each
/// element's force (the cubic through its nodes and its defect model)
/// as a polynomial in s. A step from the same start (retried shorter, or
/// retaken) starts Newton from their values at its nodes, the next step
/// from their extrapolation past the end: O(h⁴) from the solution where
/// the force is smooth, so Newton needs fewer iterations than from the
/// force at the start held over the step, O(h) from it.
#[derive(Debug)]
pub(super) struct Forces {
    start: Vec<f64>,
    end: Vec<f64>,
    h: f64,
    polynomials: Vec<[f64; POWERS]>,
}

impl Collocation {
    /// Keeps a step's forces ([`Forces`]): from y0 to `end` over h, each
    /// element's cubic through the nodes' X plus its defect model.
    pub(super) fn remember(
        &mut self,
        y0: &[f64],
        end: &[f64],
        h: f64,
        x: &DVector<f64>,
        model: &[[f64; POWERS]],
    ) {
        let ne = self.elements.len();
        // The last step's vectors, written over.
        let forces = self.forces.get_or_insert_with(|| Forces {
            start: Vec::new(),
            end: Vec::new(),
            h,
            polynomials: Vec::new(),
        });
        forces.polynomials.clear();
        forces
            .polynomials
            .extend((0..ne).map(|e| corrected(x, ne, e, h, &model[e])));
        forces.start.clear();
        forces.start.extend_from_slice(y0);
        forces.end.clear();
        forces.end.extend_from_slice(end);
        forces.h = h;
    }

    /// Newton's first guess for a step of length h from y0 ([`Forces`]):
    /// the last step's forces at the nodes, from its start where y0 is its
    /// start, past its end where y0 is its end, with the same elements;
    /// else None (each force as at the start).
    pub(super) fn guess(&self, y0: &[f64], h: f64) -> Option<DVector<f64>> {
        let forces = self.forces.as_ref()?;
        let ne = self.elements.len();
        if forces.polynomials.len() != ne {
            return None;
        }
        let offset = if forces.end == y0 {
            forces.h
        } else if forces.start == y0 {
            0.0
        } else {
            return None;
        };
        Some(DVector::from_fn(STAGES * ne, |r, _| {
            let (i, e) = (r / ne, r % ne);
            poly::eval(&forces.polynomials[e], offset + NODES[i] * h)
        }))
    }
}

/// A solve's end (u, u̇) and its nodes' forces X; its equations
/// linearized there are the solver's ([`Newton::linearized`]).
pub(super) type Solved = (Vec<f64>, DVector<f64>);

/// The LU factors of the collocated equations' Jacobian at a solve's last
/// iterate, and each element's Δu, Δv at the nodes there (row i·E + e).
pub(super) struct Linearized {
    pub(super) jacobian: Factors,
    pub(super) stroke: DVector<f64>,
    pub(super) rate: DVector<f64>,
}

/// LU factors with partial pivoting of a Jacobian of order S·E: on the
/// stack for one to five elements (a damper and up to four contacts of
/// the improved Kelvin law closed), else on the heap. nalgebra's LU is
/// one algorithm over every size, so all give the same factors and
/// solutions to the bit. (The variants differ in size by design: boxing
/// the larger would bring back the allocation per Newton iteration that
/// the fixed sizes remove.)
#[allow(clippy::large_enum_variant)]
pub(super) enum Factors {
    One(Fixed<STAGES>),
    Two(Fixed<{ 2 * STAGES }>),
    Three(Fixed<{ 3 * STAGES }>),
    Four(Fixed<{ 4 * STAGES }>),
    Five(Fixed<{ 5 * STAGES }>),
    Any(LU<f64, Dyn, Dyn>),
}

/// LU factors of the fixed order M on the stack.
type Fixed<const M: usize> = LU<f64, Const<M>, Const<M>>;

/// The factors of the Jacobian at `rows` ([`fill`]) of the fixed order D.
fn fixed<D>(nodes: &AtNodes, rows: &Rows) -> LU<f64, D, D>
where
    D: DimName + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    let mut jacobian = OMatrix::<f64, D, D>::zeros();
    fill(nodes, rows, jacobian.as_mut_slice());
    jacobian.lu()
}

/// b ← J⁻¹ b by the factors `lu` of the fixed order D; false where J is
/// singular.
fn solve_fixed<D>(lu: &LU<f64, D, D>, b: &mut DVector<f64>) -> bool
where
    D: DimName + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    let mut fixed = OVector::<f64, D>::from_column_slice(b.as_slice());
    let solved = lu.solve_mut(&mut fixed);
    b.copy_from(&fixed);
    solved
}

impl Factors {
    /// The factors of the Jacobian at the linearized rows `rows`
    /// ([`fill`]).
    fn of(nodes: &AtNodes, rows: &Rows) -> Factors {
        match rows.diagonal.len() / STAGES {
            1 => Factors::One(fixed(nodes, rows)),
            2 => Factors::Two(fixed(nodes, rows)),
            3 => Factors::Three(fixed(nodes, rows)),
            4 => Factors::Four(fixed(nodes, rows)),
            5 => Factors::Five(fixed(nodes, rows)),
            _ => {
                let m = rows.diagonal.len();
                let mut jacobian = DMatrix::zeros(m, m);
                fill(nodes, rows, jacobian.as_mut_slice());
                Factors::Any(jacobian.lu())
            }
        }
    }

    /// b ← J⁻¹ b; false where J is singular.
    pub(super) fn solve_mut(&self, b: &mut DVector<f64>) -> bool {
        match self {
            Factors::One(lu) => solve_fixed(lu, b),
            Factors::Two(lu) => solve_fixed(lu, b),
            Factors::Three(lu) => solve_fixed(lu, b),
            Factors::Four(lu) => solve_fixed(lu, b),
            Factors::Five(lu) => solve_fixed(lu, b),
            Factors::Any(lu) => lu.solve_mut(b),
        }
    }
}

/// The collocated equations linearized at an iterate, row by row
/// (r = i·E + e): the diagonal term, a damper's ψ'(X_r) or a product's 1,
/// and a product's (h, δ̇_r, δ_r). The elements are the dampers first
/// ([`super::elements_into`]), so that each node's block of E rows is
/// `dampers` damper rows and then product rows, and [`fill`] writes each
/// kind's entries in a loop of its own, with no branch per entry.
#[derive(Debug, Default)]
struct Rows {
    dampers: usize,
    elements: usize,
    diagonal: Vec<f64>,
    coefficient: Vec<f64>,
    rate: Vec<f64>,
    stretch: Vec<f64>,
}

impl Rows {
    /// Rows for the elements `elements` at the nodes, their values zero.
    fn reset(&mut self, elements: &[Element]) {
        let ne = elements.len();
        self.elements = ne;
        self.dampers = elements
            .iter()
            .take_while(|el| matches!(el.law, Law::Damper { .. }))
            .count();
        debug_assert!(
            elements[self.dampers..]
                .iter()
                .all(|el| matches!(el.law, Law::Product { .. })),
            "the dampers come first"
        );
        for v in [
            &mut self.diagonal,
            &mut self.coefficient,
            &mut self.rate,
            &mut self.stretch,
        ] {
            v.clear();
            v.resize(STAGES * ne, 0.0);
        }
    }
}

/// The Jacobian of the collocated equations, column by column:
///
/// ```text
/// damper:   J_rq = −Δv_r[ℓ_q] + ψ'(X_r) [r = q],
/// product:  J_rq = −h(δ̇_r Δu_r[ℓ_q] + δ_r Δv_r[ℓ_q]) + [r = q],
/// ```
///
/// Δu_r[ℓ_q], Δv_r[ℓ_q] the responses at the nodes ([`AtNodes`]), into
/// `jacobian` (m × m, column-major): in each node's block of rows the
/// dampers' entries, then the products', then the diagonal.
fn fill(nodes: &AtNodes, rows: &Rows, jacobian: &mut [f64]) {
    let m = rows.diagonal.len();
    let (ne, nd) = (rows.elements, rows.dampers);
    let columns = jacobian.chunks_exact_mut(m);
    let strokes = nodes.stroke.as_slice().chunks_exact(m);
    let rates = nodes.rate.as_slice().chunks_exact(m);
    for (q, ((column, stroke), rate)) in columns.zip(strokes).zip(rates).enumerate() {
        let blocks = column
            .chunks_exact_mut(ne)
            .zip(stroke.chunks_exact(ne))
            .zip(rate.chunks_exact(ne));
        let linear = rows
            .coefficient
            .chunks_exact(ne)
            .zip(rows.rate.chunks_exact(ne))
            .zip(rows.stretch.chunks_exact(ne));
        for (((block, stroke), rate), ((coefficient, speed), stretch)) in blocks.zip(linear) {
            let (dampers, products) = block.split_at_mut(nd);
            for (j, v) in dampers.iter_mut().zip(rate) {
                *j = -v;
            }
            let product = stroke[nd..]
                .iter()
                .zip(&rate[nd..])
                .zip(&coefficient[nd..])
                .zip(&speed[nd..])
                .zip(&stretch[nd..]);
            for (j, ((((s, v), c), r), d)) in products.iter_mut().zip(product) {
                *j = -c * (r * s + d * v);
            }
        }
        column[q] += rows.diagonal[q];
    }
}

/// `v` of length m, its values left as they are where it has that
/// length already (they are written over before they are read).
fn sized(v: &mut DVector<f64>, m: usize) {
    if v.len() != m {
        *v = DVector::zeros(m);
    }
}

/// The buffers of the Newton solves of a run's collocated steps, reused
/// from solve to solve, and the last solve's linearization.
#[derive(Default)]
pub(super) struct Newton {
    /// The responses at the step's nodes.
    nodes: AtNodes,
    /// The free motion's Δu, Δv at the nodes.
    free_stroke: DVector<f64>,
    free_rate: DVector<f64>,
    /// The free motion's u and u̇ of an element's two floors, as
    /// polynomials: left u, right u, left u̇, right u̇.
    floors: [Vec<f64>; 4],
    /// Each damper's bound on Newton's update (zero for a product).
    bounds: Vec<f64>,
    /// The residual, then the update.
    delta: DVector<f64>,
    rows: Rows,
    /// The equations linearized at the last converged solve's iterate.
    last: Option<Linearized>,
}

impl Newton {
    /// The equations linearized at the last solve's converged iterate
    /// (None where it failed).
    pub(super) fn linearized(&self) -> Option<&Linearized> {
        self.last.as_ref()
    }

    /// The nodes' forces over a step of length h on the free motion
    /// `free` (from y0), by Newton's method: the end (u, u̇) when it
    /// converged (to 1e-15 of each damper's force at the motion's speed,
    /// 1e-14 of each product, the last update or what its contraction
    /// leaves), and the iterations taken.
    pub(super) fn solve(
        &mut self,
        row: &Row,
        elements: &[Element],
        responses: &Responses,
        (free, y0): (&Series, &[f64]),
        h: f64,
        guess: Option<DVector<f64>>,
    ) -> (Option<Solved>, usize) {
        let n = y0.len() / 2;
        let ne = elements.len();
        let m = STAGES * ne;
        let nodes = &mut self.nodes;
        nodes.refill(responses, elements, (h, free.degree));
        // The free motion's Δu, Δv at the nodes.
        let (free_stroke, free_rate) = (&mut self.free_stroke, &mut self.free_rate);
        sized(free_stroke, m);
        sized(free_rate, m);
        // The free motion's Δu, Δv at the nodes: each floor's polynomial
        // read off the series' columns (no floor-by-floor copy of a series
        // made afresh each step), left less right.
        let mut p = [0.0; ORDER + 1];
        let [ul, ur, vl, vr] = &mut self.floors;
        for (e, el) in elements.iter().enumerate() {
            free.displacement_into(el.left, ul);
            free.displacement_into(el.right, ur);
            free.velocity_into(el.left, vl);
            free.velocity_into(el.right, vr);
            for (i, &c) in NODES.iter().enumerate() {
                poly::powers(c * h, &mut p);
                free_stroke[i * ne + e] = poly::dot(ul, &p) - poly::dot(ur, &p);
                free_rate[i * ne + e] = poly::dot(vl, &p) - poly::dot(vr, &p);
            }
        }
        // First guess: each force as at the start.
        let (u0, v0) = y0.split_at(n);
        let mut x = guess.unwrap_or_else(|| {
            let start = values(elements, u0, v0);
            DVector::from_fn(m, |r, _| start[r % ne])
        });
        // Each damper's bound on Newton's update: 1e-15 of its force at the
        // motion's speed, and never below the smallest normal number. A
        // vanishing damper (c = 1e-300) would otherwise ask for updates
        // among the subnormals, whose precision falls with their size, so
        // that whether Newton converges would rest on rounding; a force
        // that small moves no floor.
        self.bounds.clear();
        self.bounds.extend(elements.iter().map(|el| match el.law {
            Law::Damper { damping, exponent } => {
                (1e-15 * damping * row.scale.1.powf(exponent)).max(f64::MIN_POSITIVE)
            }
            Law::Product { .. } => 0.0,
        }));
        let delta = &mut self.delta;
        sized(delta, m);
        // The last solve's buffers, written over.
        let (mut stroke, mut rate) = match self.last.take() {
            Some(last) => (last.stroke, last.rate),
            None => (DVector::zeros(m), DVector::zeros(m)),
        };
        sized(&mut stroke, m);
        sized(&mut rate, m);
        // Each row's law linearized at the iterate: a damper's ψ'(X) on
        // the diagonal, a product's (h, δ̇, δ) and 1 there.
        let rows = &mut self.rows;
        rows.reset(elements);
        // The last update's size against its bound (none before the
        // first, so that the first is held to the bound itself).
        let mut previous = f64::NAN;
        for iteration in 1..=NEWTON {
            nodes.stroke.mul_to(&x, &mut stroke);
            stroke += &*free_stroke;
            nodes.rate.mul_to(&x, &mut rate);
            rate += &*free_rate;
            for i in 0..STAGES {
                for (e, el) in elements.iter().enumerate() {
                    let r = i * ne + e;
                    match el.law {
                        Law::Damper { damping, exponent } => {
                            // ψ(F) = α F ψ'(F): one power for both.
                            let slope = dashpot_velocity_slope(damping, exponent, x[r]);
                            delta[r] = exponent * x[r] * slope - rate[r];
                            rows.diagonal[r] = slope;
                        }
                        Law::Product { gap, coefficient } => {
                            let stretch = stroke[r] - gap;
                            delta[r] = x[r] - coefficient * stretch * rate[r];
                            rows.diagonal[r] = 1.0;
                            rows.coefficient[r] = coefficient;
                            rows.rate[r] = rate[r];
                            rows.stretch[r] = stretch;
                        }
                    }
                }
            }
            let factors = Factors::of(nodes, rows);
            // The update, the residual solved in place.
            if !factors.solve_mut(delta) {
                return (None, iteration);
            }
            x -= &*delta;
            let bounds = &self.bounds;
            // The update against its bound, the largest over the rows (NaN
            // where one is: such an update never converges).
            let mut size = 0.0f64;
            for i in 0..STAGES {
                for (e, el) in elements.iter().enumerate() {
                    let r = i * ne + e;
                    let bound = match el.law {
                        Law::Damper { .. } => bounds[e],
                        Law::Product { .. } => 1e-14 * x[r].abs().max(1e-300),
                    };
                    let ratio = delta[r].abs() / bound;
                    if ratio.is_nan() || ratio > size {
                        size = ratio;
                    }
                }
            }
            // Converged where the update is within its bound, or where the
            // updates contract at a rate θ < 1/2 that bounds what is left
            // by θ/(1 − θ) times the last update (Hairer and Wanner,
            // Solving ODEs II, §IV.8): the iteration that would only
            // confirm it is not taken. On block-and-frame-retrofit at
            // α = 0.35 under synthetic:2000 the solves take 2.3 iterations
            // where they took 3.0, and the run a twentieth less time.
            let theta = size / previous;
            previous = size;
            let converged = size <= 1.0 || (theta < 0.5 && theta / (1.0 - theta) * size <= 1.0);
            if converged {
                // (u, u̇) side by side.
                let mut u = vec![0.0; 2 * n];
                let (eu, ev) = u.split_at_mut(n);
                free.state(h, eu, ev);
                let w = responses.weights(ne, |e| collocated(&x, ne, e, h));
                responses.add_state(&w, (h, free.degree), (eu, ev));
                self.last = Some(Linearized {
                    jacobian: factors,
                    stroke,
                    rate,
                });
                return (Some((u, x)), iteration);
            }
        }
        (None, NEWTON)
    }
}

impl std::fmt::Debug for Newton {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Newton")
            .field("converged", &self.last.is_some())
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests;
