//! The step of a row with fluid viscous dampers (SPEC §14) by exponential
//! collocation: the linear motion of the configuration carried exactly, and
//! only the nonlinear forces across floor pairs collocated, each as a
//! polynomial in time: the step near a damper's reversal and where a
//! damper is stiff over the step; elsewhere the Taylor series carries the
//! dampers' forces itself ([`super::power_series`], `driver/damped.rs`).
//!
//! Out of Hertz-type contact the row is linear but for its dampers' forces
//! F_d = c_l |Δv_d|^α sgn Δv_d and, in a contact of the improved Kelvin law,
//! the term h δ_p δ̇_p (SPEC §4). Over a step of length h each such force
//! x_e(s) is the cubic through its values X_{e,j} at the S = 4 nodes c_j h
//! of Radau IIA (c the roots of d³/dθ³[θ³(θ − 1)⁴]: 0.0886, 0.4095, 0.7877
//! and 1),
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
//! nodes are then linear in the 4 × (elements) unknowns X, which solve
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
//! **Order.** The cubic through the Radau nodes misses x by
//! x[c₁, …, c₄, s] π(s), π(s) = Π(s − c_i h), and π is orthogonal on
//! [0, h] to polynomials of degree ≤ 2 (the 4-point Radau rule is exact to
//! degree 6): the end carries a local error O(h⁸) as Radau IIA's does, the
//! nodes O(h⁵). The local error is the response to the defect of the
//! collocated force, d = −x[c₁, …, c₄, s] π(s), in the row with each
//! force's law linearized about the step: its divided difference is fitted
//! as a cubic in s where the force is smooth, the forces' own answer
//! to the motion it moves added (which, where a damper is stiff over the
//! step, is the larger part: the linear row's response alone can miss
//! the true local error by a decade or two), and by step doubling near a
//! damper's reversal, where the force is not smooth ([`Collocation::step`]).
//!
//! **Why four stages.** The force c_l|Δv|^α is analytic in time only as
//! far as the nearest (complex) zero of Δv, at a distance ρ of the order
//! of Δv/Δv̇; its derivatives grow as k!/ρ^k, so a step of local error
//! O(h^(2S)) held to 1e-12 is some ρ·1e-12^(1/(2S)) long. Three stages
//! (O(h⁶)) took 25,705 steps on block-and-frame-retrofit with its damper
//! at α = 0.35 under synthetic:2000, nearly all of 0.3 to 1 ms and held by
//! their error, not by events; four (O(h⁸)) take 9,100 for the same
//! tolerance, each a cubic's solve instead of a quadratic's.
//!
//! **Why not more.** S is one constant, [`STAGES`]: the nodes are tabled
//! for 4, 5 and 6 stages (`damper_collocation/nodes.rs`), and every table (the basis, π, the
//! halves' nodes, the estimate's points, the powers kept, the Newton
//! step's sizes on the stack) follows it. By the model above five stages
//! would take half the steps of four; they take six times more (56,759
//! accepted and 32,796 rejected on the run above): the estimate, not the
//! motion, holds them. The cause is not rounding but truncation: each
//! response is summed only to the free motion's degree D (8 on short
//! steps), and the response to θ^k = (s/h)^k starts at order k + 1 in u̇
//! (k + 2 in u) while it is of the size of h at s = h for every k, so
//! that the defect model's top powers (degree 2S − 1, nine at five
//! stages) lose their leading terms whatever h, and the estimate stays
//! near the tolerance as the steps shrink: on the first 2 s of
//! presets/synthetic.at2 at c = 4e6, 83,035 accepted steps of a median
//! 0.5 µs, their estimate a median 350 times their uncorrected end's true
//! error. Summed to D + k + 2, with the responses carried to order 40,
//! the model holds: the same run takes 842 steps (four stages: 1,564),
//! their estimate honest (true error over the tolerance: median 0.03,
//! 90th percentile 0.33, largest 0.96), and under synthetic:2000 five
//! stages take 5,059 accepted steps (four: 9,134; six: 3,893). They do
//! not pay yet: the wider sums and dense output cost as much as the steps
//! saved (149 ms against four stages' 133 ms, side by side), and at
//! c = 1e5 one step of 1.4 ms in a closed stiff contact (the damper and
//! three products of the improved Kelvin law, h at 0.8 of the free
//! motion's radius) misses its end by 27 times the tolerance with an
//! estimate of 0.3, though the defect model meets the defect to 1e-7 at
//! every twentieth of the step: the peaks then stand 4.3e-9 from the
//! independent reference, past its limit of 1e-9. At four stages the
//! truncation costs nothing measurable (the same true errors to three
//! digits, 9,108 accepted steps against 9,134), so the sums stop at D.
//!
//! **Tolerance.** The estimate is held to [`super::contact_rk::TOLERANCE`]
//! (1e-12 of the motion's scales), as the Hertz-type contact phases' steps
//! are. It is honest there: on block-and-frame-retrofit with its damper at
//! α = 0.35 under the first 2 s of presets/synthetic.at2, accepted steps'
//! end errors against sixteen collocated sub-steps are a median 0.14 of
//! the tolerance at c = 4e6 (90th percentile 0.42, largest 1.2) and 0.002
//! at c = 1e5 (0.07, 4.1, the largest at a reversal). The run's error is the sum of its steps'
//! errors, so the tolerance is not looser: with three stages, ten times
//! looser put the peaks 2.1e-9 from the independent reference at c = 1e5,
//! past its limit of 1e-9.
//!
//! **Where the steps are, and why they are short.** On
//! block-and-frame-retrofit at α = 0.35 under synthetic:2000 (14.6 s with
//! the free tail) the collocated steps carry 5.05 s in 3,630 steps (a
//! median 1.5 ms) and the damped series the other 9.5 s in 3,219. Of the
//! collocated steps 97 % are many relaxation times long (h/τ a median
//! 38) with the damper all but locked (|Δv| a median 3.3e-6 m/s): there
//! Δv = ψ(F) ≈ 0 is nearly a constraint on the floors' velocities, with F
//! its multiplier, the stiff limit of a problem of index 2, where Radau
//! IIA's order falls towards its stage order S (Hairer and Wanner, Solving
//! ODEs II, §VII.4). The error estimate shows it: over 457
//! rejected steps retried shorter, it fell with h at a median power of
//! 3.8 (quartiles 2.3 and 5.3), not 2S = 8. The step controller's
//! exponent is therefore not the lever it seems: shrinking a rejected
//! step by err^(−1/4) or err^(−1/3) instead of err^(−1/8), a safety
//! factor of 0.95, or growth by err^(−1/6), each alone or together,
//! moved the run by 0 to −3 % (4,053 to 4,174 attempted steps against
//! 4,136). Fewer steps there take another method for the locked
//! damper, such as the constrained row's own linear map with the creep
//! ψ(F) as its forcing.
//!
//! **Why the estimate counts Δv's error as it stands.** Where the damper
//! locks, an accepted step's estimate lies almost all in Δv (the rest a
//! median 1e-3 of it, 6e-2 at the 90th percentile), and an error ε there
//! is not carried on as it stands: the damper relaxes it within its
//! relaxation time τ, leaving ετ in the stroke and the floors' momentum
//! as it was (measured on the motion itself, the module's test
//! `a_stiff_damper_relaxes_an_error_in_its_rate`: 13τ on, 4e-5 of ε is
//! left and the stroke has moved by ετ to 0.4 %). Counting ε by what it
//! leaves (with τ at |Δv| + |ε|, the law's slope falling as |Δv| grows)
//! took the run above from 3,630 collocated steps to 2,085 and from 11
//! to 8.4 times the bare row, each step's true local error still within
//! the tolerance so counted (the largest 2.6 of it). It was not kept:
//! the rest of the error, 1e-3 of the tolerance before, then sits at the
//! tolerance on every step, and over strong motion with yielding it adds
//! up. Against runs at a hundredth of the tolerance, on 31 variants of
//! block-and-frame-retrofit (Kelvin, improved Kelvin and Hertz contact,
//! α = 0.2, 0.35 and 0.6, c = 1e6 to 1e7, synthetic:2000 at one to three
//! times, sines of 20 and 57 cycles), the worst peak moved by up to 5e-9
//! where this estimate keeps it within 1.4e-10. Capping the discount at
//! 10 or 30 times did not hold 1e-9 either (2.2e-9, 2.5e-9); at 3 it
//! did, for a tenth fewer steps; and counting the rest at a tenth of the
//! tolerance left the run only a tenth shorter. Part of that 5e-9 was a
//! step retaken to place an event and taken as it came, now held to the
//! tolerance ([`super::contact_rk::Contact::retake`]), which had also
//! set the runs at this estimate with α = 0.2 and c = 1e7 1.4e-8 from
//! the run at a hundredth of the tolerance. With retakes held, the 31
//! variants stand within 1.0e-10 (peak accelerations 1.3e-10) of those
//! runs, and the relaxed count still moves the motion's peaks by up to
//! 1.4e-9 (improved Kelvin, α = 0.2, c = 1e6, the 57-cycle sine) and the
//! damper's floors' peak accelerations by up to 1.7e-8 (improved Kelvin,
//! α = 0.2, c = 1e7, synthetic:2000), the force's error ε/ψ'(F) reaching
//! them: it stays out.
//!
//! **Cost.** A step's free motion is filled to the order that carries it
//! over the step (not the fixed order's radius), and kept for the steps
//! that start from the same state again (one rejected for its error, one
//! retaken to place an event); Newton's method starts from the last step's
//! forces extrapolated over the new step (`Forces`), and stops where the
//! updates' contraction bounds what is left within its tolerance, not
//! after an iteration that would only confirm it (2.3 iterations a solve
//! where it took 3.0). (A simplified Newton's method, the Jacobian's
//! factors kept while the updates shrink fast, lost the vanishing
//! damper's run: its inverse law's slope changes by orders of magnitude
//! over an update. Kept only for the confirming iteration, where the
//! force moved by less than 1e-3 of itself, it moved the error estimate,
//! which rests on the factors, enough to take 1 % more steps.)
//!
//! The end's state sums the responses' coefficients under their weights
//! order by order before Horner's rule (one pass over runs of memory, not
//! a dot product per floor and response), the forces' answer to the
//! defect model sums each element's responses into one polynomial before
//! reading it at the nodes, and the free motion's floors are read off the
//! series' columns, not copied out floor by floor for a series made
//! afresh each step. The law at the estimate's points is not read so: there
//! Δv is the free motion's and each response's values summed as before,
//! because where a damper all but locks the estimate follows Δv's
//! rounding. Summing the coefficients first there, or only the free
//! motion's two floors', took 41 to 50 % more steps on
//! block-and-frame-retrofit in Kelvin contact with α = 0.2 and
//! c_l = 1e7 under synthetic:2000 (24,552 and 26,133 against 17,408),
//! and set the link's peak stroke 1.6e-9 and 3.4e-9 from the run at a
//! hundredth of the tolerance (6.6e-10 before).
//!
//! The responses to x_e = s^k (k = 0 … 7) from rest depend only on the
//! configuration's K and C and the elements, and are made once per
//! configuration and reused for every step length h, the response to
//! ℓ_j(s/h) being Σ_k ℓ_{j,k} h^(−k) times the k-th (those to s⁴ … s⁷
//! by integrating the one before, `integrated`): a step then costs one
//! Taylor series of the free motion and a Newton solve on 4 × (elements)
//! unknowns instead of 4 × (n + elements).

mod basis;
mod estimate;
mod newton;
mod nodes;
mod responses;
#[cfg(test)]
pub(super) mod tests;

use std::collections::HashMap;

use nalgebra::DVector;

use super::damper::Damper;
use super::system::System;
use super::taylor::{ORDER, Series};
use crate::model::buildings::retrofit::dashpot_force;
use basis::{corrected, defect_polynomial, lagrange_at};
use estimate::kappa;
use newton::{Forces, Newton, Solved};
use responses::Responses;

/// Stages S of the collocation: 4, 5 or 6 (the tabled nodes); four, for
/// the reason in the module's doc ("Why not more").
pub const STAGES: usize = 4;

/// The nodes c_j of Radau IIA, the roots of
/// d^(S−1)/dθ^(S−1) [θ^(S−1) (θ − 1)^S], the last 1 (tabled in `damper_collocation/nodes.rs`).
pub const NODES: [f64; STAGES] = nodes::radau();

/// The nodes of a half of a step, θ = `offset` + c_i/2.
const fn halved(offset: f64) -> [f64; STAGES] {
    let mut points = [0.0; STAGES];
    let mut i = 0;
    while i < STAGES {
        points[i] = offset + 0.5 * NODES[i];
        i += 1;
    }
    points
}

/// ℓ_j at the nodes of the first half of a step and of the second,
/// θ = c_i/2 and 1/2 + c_i/2 (row i): the halves' first guess.
const AT_HALVES: [[[f64; STAGES]; STAGES]; 2] =
    [lagrange_at(halved(0.0)), lagrange_at(halved(0.5))];

/// Coefficients a_1 … a_{S−1} of the defect model past κ ([`basis::defect_polynomial`]).
const MODEL: usize = STAGES - 1;

/// Newton iterations at most on one step.
const NEWTON: usize = 50;

/// Powers of s whose responses are kept: s⁰ … s^(2S−1), the collocated
/// polynomial's (degree S − 1) and the defect model's
/// (κ + a₁θ + … + a_{S−1}θ^(S−1))π(θ), of degree 2S − 1.
const POWERS: usize = 2 * STAGES;

/// The step-doubling estimate's divisor 2^p − 1 for the elements: a step
/// is doubled where the defect model fails, next to a damper's reversal
/// at s₀, where F ∝ |s − s₀|^α puts an error O(h^(1+α)) into Δv, not the
/// O(h^(2S)) of a smooth force; so p = 1 + α of the smallest exponent
/// (the error of the two halves is then the difference over 2^(1+α) − 1,
/// between 1.4 and 3 times smaller than the difference itself).
fn doubling(elements: &[Element]) -> f64 {
    let order = elements
        .iter()
        .filter_map(|el| match el.law {
            Law::Damper { exponent, .. } => Some(1.0 + exponent),
            Law::Product { .. } => None,
        })
        .fold((2 * STAGES - 1) as f64, f64::min);
    order.exp2() - 1.0
}

/// Response sets kept at most; past it the cache starts afresh (one set
/// per configuration met).
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

/// The cached responses, by configuration (K, C, elements), and what the
/// steps cost.
#[derive(Debug, Default)]
pub struct Collocation {
    /// Each set's place in `sets`, by its key ([`key`]).
    index: HashMap<Vec<u64>, usize>,
    sets: Vec<Responses>,
    /// The key and place of the set last used: the steps of one
    /// configuration find it by comparing keys, without hashing.
    current: Option<(Vec<u64>, usize)>,
    /// The key of the step at hand, written over at each step.
    key: Vec<u64>,
    /// The step's elements, written over at each step.
    elements: Vec<Element>,
    /// Solves of one step's nodes (one per step, three where it is doubled).
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
    /// The free motion of the last step's start ([`Free`]).
    free: Free,
    /// The last step's forces ([`Forces`]), Newton's first guess for the
    /// next.
    forces: Option<Forces>,
    /// The Newton solves' buffers and the last one's linearization.
    solver: Newton,
    /// A series whose vectors the next dense output reuses
    /// ([`Collocation::recycle`]).
    spare: Series,
    /// The free motion from a doubled step's middle, its vectors reused
    /// from one doubled step to the next.
    middle: Series,
}

/// The free motion from a step's start, with what fixes it: the start
/// (u, u̇), the load q, the ground (a_g, ȧ_g, σ) there, the scales and the
/// configuration's response set. A step rejected for its error, and a step
/// retaken to place an event, start there again with the same series.
#[derive(Debug, Default)]
struct Free {
    key: Vec<u64>,
    /// The key of the step at hand, formed here before it is compared
    /// with the last, then swapped with it (no vector is made per step).
    next: Vec<u64>,
    series: Series,
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

/// The step's elements into `out`: the dampers, then the system's products.
fn elements_into(dampers: &[Damper], system: &System, mass: &[f64], out: &mut Vec<Element>) {
    out.clear();
    out.extend(dampers.iter().map(|d| Element {
        left: d.left,
        right: d.right,
        left_rate: d.left_rate,
        right_rate: d.right_rate,
        law: Law::Damper {
            damping: d.damping,
            exponent: d.exponent,
        },
    }));
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
}

/// The cache key into `key`: K and C's nonzero entries and the elements,
/// which fix the responses.
fn key(system: &System, elements: &[Element], key: &mut Vec<u64>) {
    key.clear();
    for i in 0..system.load.len() {
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
}

/// Δu_e and Δv_e of element e at (u, u̇).
fn measure(e: &Element, u: &[f64], v: &[f64]) -> (f64, f64) {
    (u[e.left] - u[e.right], v[e.left] - v[e.right])
}

impl Free {
    /// The free motion from y0 over a step of length h: the series kept
    /// where it starts from the same state in the same configuration under
    /// the same ground and reaches h, else filled afresh to the order that
    /// carries it over h ([`Series::fill_linear`]).
    fn refresh(&mut self, row: &Row, set: usize, y0: &[f64], h: f64) {
        let n = y0.len() / 2;
        let ground = (row.ground)(0.0);
        let key = &mut self.next;
        key.clear();
        key.extend(y0.iter().chain(&row.system.load).map(|x| x.to_bits()));
        key.extend([ground.0, ground.1, ground.2, row.scale.0, row.scale.1].map(f64::to_bits));
        key.push(set as u64);
        std::mem::swap(&mut self.key, &mut self.next);
        if self.key == self.next && h <= self.series.radius {
            return;
        }
        let start = (&y0[..n], &y0[n..]);
        self.series
            .fill_linear(row.system, start, ground, row.scale, h);
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
    /// The place of the responses of the configuration of `system` with
    /// the elements `self.elements`, made when missing: found by comparing
    /// the key with the last step's, else by hashing it.
    fn responses(&mut self, system: &System) -> usize {
        key(system, &self.elements, &mut self.key);
        if let Some((last, place)) = &self.current
            && *last == self.key
        {
            return *place;
        }
        let place = match self.index.get(&self.key) {
            Some(&place) => place,
            None => {
                if self.sets.len() >= CAPACITY {
                    self.sets.clear();
                    self.index.clear();
                }
                self.made += 1;
                let mut rest = system.clone();
                rest.load.fill(0.0);
                rest.products.clear();
                self.sets.push(Responses::make(&rest, &self.elements));
                self.index.insert(self.key.clone(), self.sets.len() - 1);
                self.sets.len() - 1
            }
        };
        self.current = Some((self.key.clone(), place));
        place
    }

    /// The end of one solve of length h on `free` (from y0) and the nodes'
    /// forces X, from the first guess `guess` (X's values at the nodes when
    /// given, else each force as at the start), counted.
    fn solve(
        &mut self,
        row: &Row,
        set: usize,
        (free, y0): (&Series, &[f64]),
        h: f64,
        guess: Option<DVector<f64>>,
    ) -> Option<Solved> {
        let (end, iterations) =
            self.solver
                .solve(row, &self.elements, &self.sets[set], (free, y0), h, guess);
        self.solves += 1;
        self.newton += iterations;
        end
    }

    /// The dense output of a step of length h from y0: the motion under
    /// each force's cubic through the nodes plus its defect model
    /// (`model`, in powers of s: (κ_e + Σ_q a_{e,q} θ^q)π(θ),
    /// [`defect_polynomial`]), so that its interior misses the force by the
    /// model's remainder where the cubic alone misses it by O(h⁴): `free`
    /// plus each response's series times its coefficient. Its end is the
    /// step's.
    fn motion(
        &mut self,
        set: usize,
        free: &Series,
        h: f64,
        x: &DVector<f64>,
        model: &[[f64; POWERS]],
    ) -> Series {
        let mut motion = std::mem::take(&mut self.spare);
        motion.clone_from(free);
        let ne = self.elements.len();
        let responses = &self.sets[set];
        let forces: Vec<[f64; POWERS]> =
            (0..ne).map(|e| corrected(x, ne, e, h, &model[e])).collect();
        let w = responses.weights(ne, |e| forces[e]);
        // The responses to the free motion's degree, which carries the
        // step to the series' tolerance.
        let width = free.degree + 1;
        // Both series hold their orders in the same columns, so that the
        // orders they share are one run of memory in each.
        for (series, &wr) in responses.series.iter().zip(&w) {
            if wr == 0.0 {
                continue;
            }
            let shared = width.min(series.degree + 1);
            let r = &series.held()[..2 * series.n * shared];
            for (m, r) in motion.orders_mut(shared).iter_mut().zip(r) {
                *m += wr * r;
            }
        }
        motion.radius = h;
        // Each damper's force, the polynomial the motion answers, in the
        // series' blocks of its degree + 1 (the dampers are the first
        // elements): where the damper all but locks, its law at the
        // motion's interpolated Δv amplifies Δv's error by α/|Δv|, and
        // always adds to the dissipation c|Δv|^(α+1), however Δv errs.
        motion.forces.clear();
        if width >= POWERS {
            let dampers = self
                .elements
                .iter()
                .take_while(|el| matches!(el.law, Law::Damper { .. }));
            for (p, _) in forces.iter().zip(dampers) {
                motion.forces.extend_from_slice(p);
                motion
                    .forces
                    .extend(std::iter::repeat_n(0.0, width - POWERS));
            }
        }
        motion
    }

    /// Keeps a dense output the caller is done with, so that the next
    /// one reuses its vectors.
    pub fn recycle(&mut self, series: Series) {
        self.spare = series;
    }

    /// One step of length h from y0 = (u, u̇): its end and error
    /// estimate (below), its series in [`Collocation::last`] where `dense`
    /// asks for it (a step retaken to place an event needs only its end);
    /// or None when
    /// Newton's method does not converge, h passes the reach of the free
    /// motion's series, or the end is not finite: a step so short that the
    /// basis, in powers of 1/h up to h^(1−2S), overflows (an event placed
    /// next to a step's start asks for such steps), whose forces are then
    /// not kept as the next step's first guess.
    ///
    /// The collocated force misses the law on the collocated motion by the
    /// defect d_e(s) = Σ_j X_{e,j} ℓ_j(s/h) − x_e(s), zero at the four
    /// nodes: d_e(θh) = −x_e[c₁, …, c₄, θh] π(θ). Where the force is
    /// smooth over the step the divided difference is nearly a cubic in θ,
    ///
    /// ```text
    /// d_e(θh) ≈ −(κ_e + a_{e,1}θ + a_{e,2}θ² + a_{e,3}θ³) π(θ),
    /// ```
    ///
    /// κ_e from the defect at the start (`kappa`), the a_{e,q} from the
    /// defect midway between consecutive nodes on the collocated motion,
    /// and the model checked against the defect at θ = 1/2
    /// (`defect_model`), for
    /// a damper and a contact's product alike. The end's error is then
    /// the response to the model plus the forces' own answer to it
    /// (`feedback`), O(h⁸): the step returns the end under the corrected
    /// force, y_h + E with E that response at h, the dense output's own
    /// end, and E as its error estimate (a result of the cubic's order
    /// against one of higher order, as an embedded pair's). Only π's
    /// orthogonality to 1, θ and θ² makes the response to those terms
    /// small beside the defect, which is why the term in θ³ and the
    /// forces' answer count: the θ³ term's response is of the defect's
    /// own size times h. Where the check fails (a damper's Δv near 0,
    /// where F is not analytic in time), the error is estimated by step
    /// doubling, (y_h − y_{h/2,h/2})/(2^(1+α) − 1) (`doubling`), and the
    /// step returns y_{h/2,h/2}.
    pub fn step(
        &mut self,
        row: &Row,
        y0: &[f64],
        (h, dense): (f64, bool),
    ) -> Option<(Vec<f64>, Vec<f64>)> {
        self.last = None;
        elements_into(row.dampers, row.system, row.mass, &mut self.elements);
        let set = self.responses(row.system);
        let mut free = std::mem::take(&mut self.free);
        free.refresh(row, set, y0, h);
        let out = if free.series.degree > ORDER || h > free.series.radius {
            None
        } else {
            self.step_on(row, set, &free.series, y0, (h, dense))
        };
        self.free = free;
        let finite =
            |(end, error): &(Vec<f64>, Vec<f64>)| end.iter().chain(error).all(|x| x.is_finite());
        if out.as_ref().is_some_and(|out| !finite(out)) {
            self.forces = None;
            self.last = None;
            return None;
        }
        out
    }

    /// [`Collocation::step`] on the free motion `free` from y0.
    fn step_on(
        &mut self,
        row: &Row,
        set: usize,
        free: &Series,
        y0: &[f64],
        (h, dense): (f64, bool),
    ) -> Option<(Vec<f64>, Vec<f64>)> {
        let n = y0.len() / 2;
        let guess = self.guess(y0, h);
        let (whole, x) = self.solve(row, set, (free, y0), h, guess)?;
        let ne = self.elements.len();
        let kappa = kappa(&self.elements, y0, &x);
        if let Some(slope) = self.defect_model(set, free, h, &x, &kappa, row.scale.1) {
            let model: Vec<[f64; POWERS]> = (0..ne)
                .map(|e| defect_polynomial(kappa[e], slope[e], h))
                .collect();
            let linearized = self.solver.linearized()?;
            let feedback = self.feedback(set, (h, free.degree), &model, linearized)?;
            let model: Vec<[f64; POWERS]> = (0..ne)
                .map(|e| corrected(&feedback, ne, e, h, &model[e]))
                .collect();
            // The end under the corrected force, and the error the
            // difference: from the dense output where it is made.
            let (end, error): (Vec<f64>, Vec<f64>) = if dense {
                let motion = self.motion(set, free, h, &x, &model);
                let mut u = vec![0.0; 2 * n];
                let (eu, ev) = u.split_at_mut(n);
                motion.state(h, eu, ev);
                let error = u.iter().zip(&whole).map(|(e, y)| e - y).collect();
                self.last = Some(motion);
                (u, error)
            } else {
                let responses = &self.sets[set];
                let w = responses.weights(ne, |e| model[e]);
                let mut error = vec![0.0; 2 * n];
                let (eu, ev) = error.split_at_mut(n);
                responses.add_state(&w, (h, free.degree), (eu, ev));
                let end = whole.iter().zip(&error).map(|(y, e)| y + e).collect();
                (end, error)
            };
            self.remember(y0, &end, h, &x, &model);
            return Some((end, error));
        }
        // The dense output under a product's cubic and κπ (the fitted
        // terms are not checked here), and under a damper's cubic alone:
        // a damper's κ rests on the law's force at the start, and where
        // the damper all but locks near a reversal of Δv (which is where
        // its steps are doubled, the defect model failing on the law's
        // values inside), the law's slope c_l α|Δv|^(α−1) amplifies Δv's
        // error without bound (with α = 0.2 and c_l = 1e7, 3e-15 m/s at
        // Δv = 0 is 1.1e4 N), and κπ on such a κ bulged the output
        // between the step's ends: the damper's peak stroke, read there
        // at the reversal, stood up to 6.7e-7 above its floors' motion
        // (improved Kelvin contact, the 57-cycle sine), within 1.8e-9 of
        // it without κπ.
        let last = dense.then(|| {
            let model: Vec<[f64; POWERS]> = (self.elements.iter().zip(&kappa))
                .map(|(el, &k)| match el.law {
                    Law::Damper { .. } => [0.0; POWERS],
                    Law::Product { .. } => defect_polynomial(k, [0.0; MODEL], h),
                })
                .collect();
            self.motion(set, free, h, &x, &model)
        });
        // The halves start from the whole step's forces, interpolated.
        let guess = |half: usize| {
            DVector::from_fn(STAGES * ne, |r, _| {
                let (i, e) = (r / ne, r % ne);
                (0..STAGES)
                    .map(|j| x[j * ne + e] * AT_HALVES[half][i][j])
                    .sum()
            })
        };
        let (half, ..) = self.solve(row, set, (free, y0), 0.5 * h, Some(guess(0)))?;
        let (u, v) = half.split_at(n);
        let mut middle = std::mem::take(&mut self.middle);
        middle.fill_linear(
            row.system,
            (u, v),
            (row.ground)(0.5 * h),
            row.scale,
            0.5 * h,
        );
        let twice = self.solve(row, set, (&middle, &half), 0.5 * h, Some(guess(1)));
        self.middle = middle;
        let (twice, ..) = twice?;
        let divisor = doubling(&self.elements);
        let error = whole
            .iter()
            .zip(&twice)
            .map(|(a, b)| (a - b) / divisor)
            .collect();
        self.last = last;
        let model: Vec<[f64; POWERS]> = (0..ne)
            .map(|e| defect_polynomial(kappa[e], [0.0; MODEL], h))
            .collect();
        self.remember(y0, &twice, h, &x, &model);
        Some((twice, error))
    }

    /// The end of `parts` collocated steps of length h/parts from y0, each
    /// from the free motion at its own start: the reference against which
    /// a step's true local error is measured (that of the parts is
    /// parts⁷ times smaller where the force is smooth over the step).
    /// None where a part's Newton's method fails.
    #[cfg(test)]
    pub(super) fn substepped(
        &mut self,
        row: &Row,
        y0: &[f64],
        h: f64,
        parts: usize,
    ) -> Option<Vec<f64>> {
        let n = y0.len() / 2;
        elements_into(row.dampers, row.system, row.mass, &mut self.elements);
        let set = self.responses(row.system);
        let part = h / parts as f64;
        let mut y = y0.to_vec();
        for k in 0..parts {
            let mut free = Series::default();
            let start = (&y[..n], &y[n..]);
            let ground = (row.ground)(k as f64 * part);
            free.fill_linear(row.system, start, ground, row.scale, part);
            let (solved, _) = self.solver.solve(
                row,
                &self.elements,
                &self.sets[set],
                (&free, &y),
                part,
                None,
            );
            y = solved?.0;
        }
        Some(y)
    }
}
