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
//! coefficients to ü's, and a fluid viscous damper's c_l|Δv|^α sgn Δv
//! (SPEC §14) its own, by the recurrence of a real power of a series
//! ([`super::power_series`]), where [`Series::fill_damped`] carries it. The series is used on [0, radius], where its last two terms
//! are below [`TOLERANCE`] of the state's scale.
//!
//! A step that needs only [0, L] ([`Series::fill_over`]) stops at the lowest
//! order K whose last two terms are within [`TOLERANCE`] at L,
//!
//! ```text
//! ‖u_k, u̇_k‖ L^k ≤ TOLERANCE · scale,   k = K − 1, K,
//! ```
//!
//! the same test as the radius's, so the truncation is the one the fixed
//! order leaves at its radius; and it goes on past [`ORDER`], up to
//! [`MAX_ORDER`], where L is beyond the radius of order [`ORDER`]. A linear
//! motion's coefficients fall like (ωs)^k/k!, so a short step needs few
//! orders. The improved Kelvin law's product δδ̇ gives the motion in
//! contact a complex singularity at a distance ρ ≈ 2.3/ω̄ (ω̄ the contact
//! frequency; in ω̄t the law x'' = −x(1 + λx') is scale-free): its
//! coefficients fall only like ρ^{−k}, the radius is ρ·TOLERANCE^{1/K}
//! (0.2ρ at K = 24, 0.38ρ at K = 40), and only more orders lengthen its steps.

pub mod orders;

use std::cell::OnceCell;

use super::damper::Damper;
use super::poly;
use super::power_series::DamperPowers;
use super::system::{Product, System, padded};
use orders::Floors;

/// Highest order kept.
pub const ORDER: usize = 24;
/// Highest order [`Series::fill_over`] goes to.
pub const MAX_ORDER: usize = 40;
/// Lowest order [`Series::fill_over`] stops at: below it two small terms
/// in a row may be a chance cancellation rather than the series' decay.
const MIN_ORDER: usize = 8;
/// Relative size of the last terms at the end of a step.
pub const TOLERANCE: f64 = 1e-17;

/// Whether x·L^k > [`TOLERANCE`] is certain from p, L^k formed by a
/// running product, so that the stop test of [`Series::fill_over`] need
/// not form L^k by [`f64::powi`] to find it fails (as it does at every
/// order but the last one or two).
///
/// p is within (k − 1)ε of L^k, and `powi`'s repeated squaring within
/// 2 log₂k · ε; with both products' rounding, x·p and x·L.powi(k) differ
/// by less than 60ε ≈ 7e-15 relative for k ≤ [`MAX_ORDER`], well inside
/// the 1e-13 allowed here: where this says above, the test with `powi`
/// says so too, and the order a step stops at is the same. A p below
/// 2⁻¹⁰⁰⁰ (near or past underflow, where the relative error grows), a NaN
/// or x = 0 leave the test to `powi`; an overflowed p is above for any
/// x > 0, as L^k itself is past the largest float.
#[inline]
fn surely_above(x: f64, p: f64) -> bool {
    const SLACK: f64 = 1.0 + 1e-13;
    p >= TINY_POWER && x * p > TOLERANCE * SLACK
}

/// 2⁻¹⁰⁰⁰: a running power above it has not lost bits to underflow.
const TINY_POWER: f64 = 9.332636185032189e-302;

/// The ground's Taylor coefficients a_k from (a, ȧ, σ) at s = 0:
/// a₀ = a, a₁ = ȧ, a_{k+2} = σ a_k/((k+1)(k+2)) (ä_g = σ a_g on the piece).
///
/// On a record's pieces (lines, σ = 0) σ a_k is already a zero (or a NaN),
/// which the division leaves as it is: the product alone, without the
/// chain of divisions, gives the same coefficients to the bit.
pub fn ground_coefficients((a, rate, sigma): (f64, f64, f64)) -> [f64; MAX_ORDER + 1] {
    let mut g = [0.0; MAX_ORDER + 1];
    g[0] = a;
    g[1] = rate;
    for k in 0..MAX_ORDER - 1 {
        let product = sigma * g[k];
        g[k + 2] = if sigma == 0.0 {
            product
        } else {
            product / ((k + 1) * (k + 2)) as f64
        };
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
    /// x_0 … x_5 (N, N/s, …, N/s⁵): up to the quintic of a force
    /// collocated at six nodes.
    pub force: [f64; 6],
}

/// The coefficients of u and u̇ ([`orders`]: order by order, every
/// floor's side by side, as the recurrence forms them).
#[derive(Debug)]
pub struct Series {
    pub n: usize,
    /// Order k's 2n coefficients at [2nk, 2n(k + 1)): u_k of every floor,
    /// then u̇_k; orders 0 to [`Series::degree`] are the series' (the
    /// buffer may run on past them, left from a longer fill).
    orders: Vec<f64>,
    /// Floor by floor copies of `orders`, made on a reader's first ask
    /// for a floor's polynomial as one slice ([`Series::displacement`]).
    floors: OnceCell<Floors>,
    /// The ground's coefficients a_k.
    pub ground: [f64; MAX_ORDER + 1],
    /// Where the series stays within [`TOLERANCE`].
    pub radius: f64,
    /// Highest order of u held (coefficients above it are zero):
    /// [`ORDER`] for the series, less for a polynomial written as one.
    pub degree: usize,
    /// Each fluid viscous damper's force F_k (N), damper by damper in
    /// blocks of [`Series::degree`] + 1, where the series carries the
    /// dampers ([`Series::fill_damped`]) or is a collocated step's motion
    /// (the force polynomial it answers, [`super::damper_collocation`]);
    /// empty otherwise.
    pub forces: Vec<f64>,
    /// The recurrence's buffers, reused from fill to fill.
    pub work: Workspace,
}

/// The buffers of [`Series::fill`]'s recurrence, kept so that a run's
/// thousands of steps allocate nothing: ü's coefficient being summed,
/// each product's δ_k and δ̇_k, and each damper's powers. They hold
/// nothing between fills: a clone starts empty.
#[derive(Debug, Default)]
pub struct Workspace {
    acc: Vec<f64>,
    delta: Vec<f64>,
    rate_d: Vec<f64>,
    powers: DamperPowers,
}

impl Clone for Workspace {
    fn clone(&self) -> Workspace {
        Workspace::default()
    }
}

impl Workspace {
    /// Room for orders 0 to `top` of n floors and `products` products.
    /// Every entry up to the order reached is written before it is read:
    /// the buffers are grown, never cleared.
    fn size(&mut self, n: usize, products: usize, top: usize) {
        let w = top + 1;
        for (buffer, len) in [
            (&mut self.acc, padded(n)),
            (&mut self.delta, products * w),
            (&mut self.rate_d, products * w),
        ] {
            if buffer.len() < len {
                buffer.resize(len, 0.0);
            }
        }
    }
}

impl Default for Series {
    fn default() -> Series {
        Series {
            n: 0,
            orders: Vec::new(),
            floors: OnceCell::new(),
            ground: [0.0; MAX_ORDER + 1],
            radius: 0.0,
            degree: 0,
            forces: Vec::new(),
            work: Workspace::default(),
        }
    }
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
        self.fill_with(
            system,
            &system.products,
            start,
            ground,
            scale,
            (forcing, &[]),
            None,
        );
    }

    /// [`Series::fill`] without forces, to the lowest order that carries it
    /// over [0, `want`] (at most [`MAX_ORDER`]; the module's opening).
    pub fn fill_over(
        &mut self,
        system: &System,
        start: (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        want: f64,
    ) {
        self.fill_damped(system, start, ground, scale, (want, &[]));
    }

    /// [`Series::fill_over`] with the fluid viscous dampers' forces in the
    /// series (SPEC §14, [`super::power_series`]): each damper's Δv at the
    /// start must not be 0; where the force weighs on the motion, the
    /// radius stops short of Δv's nearest zero, the force's branch point.
    pub fn fill_damped(
        &mut self,
        system: &System,
        start: (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        (want, dampers): (f64, &[Damper]),
    ) {
        let products = &system.products;
        let forces = (&[][..], dampers);
        self.fill_with(system, products, start, ground, scale, forces, Some(want));
    }

    /// [`Series::fill_over`] of the configuration's linear motion alone:
    /// K, C and q, its products h δ δ̇ left out (a collocated step carries
    /// them as forces, [`super::damper_collocation`]), to the lowest order
    /// that carries it over [0, `want`].
    pub fn fill_linear(
        &mut self,
        system: &System,
        start: (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        want: f64,
    ) {
        self.fill_with(system, &[], start, ground, scale, (&[], &[]), Some(want));
    }

    /// The series with the products `products` in place of the system's,
    /// to [`ORDER`], or with `want` to the order that carries it over
    /// [0, want].
    ///
    /// The recurrence runs order by order on the series' own columns
    /// ([`orders`]: all floors' u_k, then all their u̇_k), so that
    /// u_{k+1} = u̇_k/(k+1), each row of (M⁻¹K, M⁻¹C) and the norms of the
    /// test run over contiguous memory, and the coefficients stay where
    /// they are formed. Each sum is taken in the same order as floor by
    /// floor: the series is the same to the bit.
    #[allow(clippy::too_many_arguments)]
    fn fill_with(
        &mut self,
        system: &System,
        products: &[Product],
        (u0, v0): (&[f64], &[f64]),
        ground: (f64, f64, f64),
        scale: (f64, f64),
        (forcing, dampers): (&[Forcing], &[Damper]),
        want: Option<f64>,
    ) {
        let top = if want.is_some() { MAX_ORDER } else { ORDER };
        let n = u0.len();
        let g = ground_coefficients(ground);
        let w = top + 1;
        // The floors' copies are of the last fill's orders.
        self.floors.take();
        let (orders, work) = (&mut self.orders, &mut self.work);
        // Grown, never cleared: every order up to the one reached is
        // written before it is read.
        if orders.len() < 2 * n * w {
            orders.resize(2 * n * w, 0.0);
        }
        work.size(n, products.len(), top);
        work.powers.size(dampers.len(), top);
        let Workspace {
            acc,
            delta,
            rate_d,
            powers,
        } = work;
        orders[..n].copy_from_slice(u0);
        orders[n..2 * n].copy_from_slice(v0);
        // max_i |u_k,i| / scale_u against max_i |u̇_k,i| / scale_v (a NaN
        // passed over, as f64::max does, without its test for one).
        let norm = |column: &[f64]| {
            let (u, v) = column.split_at(n);
            let largest = |x: &[f64]| {
                let mut m = 0.0f64;
                for x in x {
                    let x = x.abs();
                    if x > m {
                        m = x;
                    }
                }
                m
            };
            (largest(u) / scale.0).max(largest(v) / scale.1)
        };
        let mut degree = top;
        // Whether the test below reads order k's norm (as order k or k + 1
        // of its pair): only with `want`, and from MIN_ORDER − 1 on; the
        // radius takes its own norms of the last two orders.
        let tested = |k: usize| want.is_some() && k + 1 >= MIN_ORDER;
        // The norm of order k, kept from the step before (the test asks for
        // orders k and k + 1).
        let mut last = if tested(0) {
            norm(&orders[..2 * n])
        } else {
            0.0
        };
        // want^k by a running product, for [`surely_above`].
        let mut power = 1.0;
        for k in 0..top {
            let (done, next) = orders.split_at_mut(2 * n * (k + 1));
            let (uk, vk) = done[2 * n * k..].split_at(n);
            let next = &mut next[..2 * n];
            // ü's coefficient before the contacts: −a_k − Σ_j ((M⁻¹K)_ij u_k,j
            // + (M⁻¹C)_ij u̇_k,j), plus M⁻¹q at k = 0, rows in vector blocks.
            let load = (k == 0).then_some(&system.load[..]);
            system
                .columns
                .rate_into((uk, vk), load, g[k], &mut acc[..padded(n)]);
            for (pi, p) in products.iter().enumerate() {
                let row = pi * w;
                delta[row + k] = uk[p.left] - uk[p.right] - if k == 0 { p.gap } else { 0.0 };
                rate_d[row + k] = vk[p.left] - vk[p.right];
                // Σ_j δ_j δ̇_{k−j}.
                let conv = poly::product_coefficient(&delta[row..=row + k], &rate_d[row..=row + k]);
                acc[p.left] -= p.left_rate * conv;
                acc[p.right] += p.right_rate * conv;
            }
            for f in forcing {
                if let Some(&x) = f.force.get(k) {
                    acc[f.left] -= f.left_rate * x;
                    acc[f.right] += f.right_rate * x;
                }
            }
            for (di, d) in dampers.iter().enumerate() {
                let rate = vk[d.left] - vk[d.right];
                let f = powers.force(di, d, k, rate);
                acc[d.left] -= d.left_rate * f;
                acc[d.right] += d.right_rate * f;
            }
            let inv = 1.0 / (k + 1) as f64;
            let (un, vn) = next.split_at_mut(n);
            for (x, &v) in un.iter_mut().zip(vk) {
                *x = v * inv;
            }
            for (x, &a) in vn.iter_mut().zip(&acc[..n]) {
                *x = a * inv;
            }
            let now = if tested(k + 1) { norm(next) } else { 0.0 };
            // The last two terms within the tolerance at `want`: enough.
            if let Some(want) = want
                && k + 1 >= MIN_ORDER
                && !surely_above(last, power)
                && last * want.powi(k as i32) <= TOLERANCE
                && now * want.powi(k as i32 + 1) <= TOLERANCE
            {
                degree = k + 1;
                break;
            }
            last = now;
            power *= want.unwrap_or(1.0);
        }
        let radius = [degree - 1, degree]
            .iter()
            .map(|&k| {
                let nk = norm(&orders[2 * n * k..2 * n * (k + 1)]);
                if nk > 0.0 {
                    (TOLERANCE / nk).powf(1.0 / k as f64)
                } else {
                    f64::INFINITY
                }
            })
            .fold(f64::INFINITY, f64::min);
        // Stopped early, the test above held at `want` (the radius may
        // round a hair below it).
        let radius = match want {
            Some(want) if degree < top => radius.max(want),
            _ => radius,
        };
        // Each damper's force to the degree written out: its order
        // `degree`, one past the last the motion's recurrence needed, from
        // that order's Δv, then F_k = c_l σ w_k block by block.
        self.forces.clear();
        let width = degree + 1;
        let vd = &orders[2 * n * degree + n..2 * n * width];
        for (di, d) in dampers.iter().enumerate() {
            powers.force(di, d, degree, vd[d.left] - vd[d.right]);
            powers.write_forces(di, d, width, &mut self.forces);
        }
        self.n = n;
        self.ground = g;
        self.radius = radius;
        self.degree = degree;
    }

    /// The force coefficients F_0 … F_degree of the `index`-th fluid
    /// viscous damper, where the series carries the dampers.
    #[inline]
    pub fn damper_force(&self, index: usize) -> Option<&[f64]> {
        let width = self.degree + 1;
        self.forces.get(index * width..(index + 1) * width)
    }
}

#[cfg(test)]
mod tests {
    use super::{MAX_ORDER, ORDER, Series, TOLERANCE, ground_coefficients, surely_above};
    use crate::model::buildings;
    use crate::model::buildings::contact::element_law;
    use crate::solver::buildings::config::{Closed, Config};
    use crate::solver::buildings::layout::Layout;
    use crate::solver::buildings::poly;
    use crate::solver::buildings::system::System;

    /// Block-and-frame just after its roofs close under improved Kelvin
    /// (δ = 10 µm, v₀ = 0.05 m/s): its system, state, the state's scale
    /// and the fixed order's series from there.
    type Start = (System, (Vec<f64>, Vec<f64>), (f64, f64), Series);
    const GROUND: (f64, f64, f64) = (1.5, 40.0, 0.0);

    fn roof_contact() -> Start {
        let row = buildings::load("block-and-frame").expect("shipped");
        let layout = Layout::of(&row);
        let n = layout.dofs;
        let mut config = Config::at_rest(layout.storeys.len(), layout.pairs.len());
        let roof = layout.pairs.len() - 1;
        let p = layout.pairs[roof];
        let v0 = 0.05;
        config.contact[roof] = Some(Closed {
            law: element_law(&row, &layout.elements[roof], v0),
            approach_velocity: v0,
        });
        let system = System::of(&layout, &config);
        assert!(!system.products.is_empty(), "improved Kelvin's δδ̇ term");
        let mut u: Vec<f64> = (0..n).map(|i| 1e-3 * (i as f64 + 1.0)).collect();
        u[p.left_dof] = u[p.right_dof] + layout.gaps[roof] + 1e-5;
        let mut v: Vec<f64> = (0..n).map(|i| 0.02 * (i as f64 * 0.9).sin()).collect();
        v[p.left_dof] = v[p.right_dof] + v0;
        let sc = (scale(&u), scale(&v));
        let fixed = Series::new(&system, &u, &v, GROUND, sc);
        (system, (u, v), sc, fixed)
    }

    /// (u, u̇) of `series` at s.
    fn at(series: &Series, s: f64) -> (Vec<f64>, Vec<f64>) {
        let (mut u, mut v) = (vec![0.0; series.n], vec![0.0; series.n]);
        series.state(s, &mut u, &mut v);
        (u, v)
    }

    fn scale(x: &[f64]) -> f64 {
        x.iter().fold(1e-6f64, |m, x| m.max(x.abs()))
    }

    /// A short step stops at a low order, its coefficients those of the
    /// fixed order's (the same recurrence), and its end state within 1e-15
    /// of the fixed order's at that instant.
    #[test]
    fn a_short_step_stops_early_and_agrees_with_the_fixed_order() {
        let (system, (u, v), sc, fixed) = roof_contact();
        let n = u.len();
        let want = 0.05 * fixed.radius;
        let mut short = Series::default();
        short.fill_over(&system, (&u, &v), GROUND, sc, want);
        assert!(short.degree < 16, "degree {}", short.degree);
        assert!(short.radius >= want);
        for i in 0..n {
            let d = short.degree;
            assert_eq!(short.displacement(i), &fixed.displacement(i)[..=d]);
            assert_eq!(short.velocity(i), &fixed.velocity(i)[..=d]);
        }
        let ((a, b), (c, d)) = (at(&short, want), at(&fixed, want));
        for i in 0..n {
            assert!((a[i] - c[i]).abs() <= 1e-15 * sc.0, "u_{i}");
            assert!((b[i] - d[i]).abs() <= 1e-15 * sc.1, "u̇_{i}");
        }
    }

    /// A fill over buffers left by earlier fills (a longer one, and one of
    /// another configuration, without the product) gives the series a
    /// fresh one gives, to the bit: nothing of the earlier fills is read.
    #[test]
    fn a_reused_workspace_leaves_no_trace() {
        let (system, (u, v), sc, fixed) = roof_contact();
        let want = 0.3 * fixed.radius;
        let mut fresh = Series::default();
        fresh.fill_over(&system, (&u, &v), GROUND, sc, want);
        let mut reused = Series::default();
        reused.fill_over(&system, (&u, &v), GROUND, sc, 10.0 * fixed.radius);
        let linear: Vec<f64> = v.iter().map(|x| -x).collect();
        reused.fill_linear(&system, (&v, &linear), (0.3, -5.0, -40.0), sc, fixed.radius);
        reused.fill_over(&system, (&u, &v), GROUND, sc, want);
        assert!(fresh.degree < MAX_ORDER, "degree {}", fresh.degree);
        assert_eq!(reused.degree, fresh.degree);
        assert_eq!(reused.radius.to_bits(), fresh.radius.to_bits());
        assert_eq!(reused.held(), fresh.held());
        let clone = reused.clone();
        assert_eq!(clone.held(), fresh.held());
    }

    /// The state at s, taken four floors side by side, is each floor's
    /// Horner sum ([`poly::eval`] of its block) to the bit, at the fixed
    /// order and at the lower orders of short steps, for all eleven floors
    /// (two groups of four and three left over).
    #[test]
    fn the_state_is_each_floors_horner_sum() {
        let (system, (u, v), sc, fixed) = roof_contact();
        let n = u.len();
        assert_eq!(n % 4, 3, "a remainder of floors after the groups");
        let mut short = Series::default();
        for series in [&fixed, {
            short.fill_over(&system, (&u, &v), GROUND, sc, 0.1 * fixed.radius);
            &short
        }] {
            for s in [0.0, 0.3 * series.radius, series.radius] {
                let (a, b) = at(series, s);
                for i in 0..n {
                    let (eu, ev) = (
                        poly::eval(series.displacement(i), s),
                        poly::eval(series.velocity(i), s),
                    );
                    assert_eq!(a[i].to_bits(), eu.to_bits(), "u_{i} at {s}");
                    assert_eq!(b[i].to_bits(), ev.to_bits(), "u̇_{i} at {s}");
                }
            }
        }
        assert!(short.degree < fixed.degree, "degree {}", short.degree);
    }

    /// Every order of the series is the recurrence of the module's opening,
    /// summed row by row on the nonzeros of (M⁻¹K, M⁻¹C) ([`System::row`])
    /// with the improved Kelvin product's convolution, to the bit: the
    /// columns' layout, kept as the series holds it, changes no coefficient.
    /// At order 0 that sum is ü of the equation of motion at the start
    /// ([`System::acceleration`]).
    #[test]
    fn each_order_is_the_row_wise_recurrence() {
        let (system, (u, v), _, fixed) = roof_contact();
        let n = u.len();
        let mut acc = vec![0.0; n];
        system.acceleration(&u, &v, GROUND.0, &mut acc);
        for (i, &a) in acc.iter().enumerate() {
            assert!(fixed.velocity(i)[1] == a, "ü_{i}(0)");
        }
        let (us, vs) = (
            |k: usize, i: usize| fixed.displacement(i)[k],
            |k: usize, i: usize| fixed.velocity(i)[k],
        );
        for k in 0..fixed.degree {
            let inv = 1.0 / (k + 1) as f64;
            let mut rows: Vec<f64> = (0..n)
                .map(|i| {
                    let mut s = -fixed.ground[k];
                    if k == 0 {
                        s += system.load[i];
                    }
                    for &(j, kij, cij) in system.row(i) {
                        s -= kij * us(k, j) + cij * vs(k, j);
                    }
                    s
                })
                .collect();
            for p in &system.products {
                let delta =
                    |j: usize| us(j, p.left) - us(j, p.right) - if j == 0 { p.gap } else { 0.0 };
                let rate = |j: usize| vs(j, p.left) - vs(j, p.right);
                let conv: f64 = (0..=k).map(|j| delta(j) * rate(k - j)).sum();
                rows[p.left] -= p.left_rate * conv;
                rows[p.right] += p.right_rate * conv;
            }
            for (i, &row) in rows.iter().enumerate() {
                assert!(us(k + 1, i) == vs(k, i) * inv, "u_{} of floor {i}", k + 1);
                assert!(vs(k + 1, i) == row * inv, "u̇_{} of floor {i}", k + 1);
            }
        }
    }

    /// Where the running power says x·L^k is surely above the tolerance,
    /// `powi`'s L^k says so too: for L from 1e-6 to 1e3, k to
    /// [`MAX_ORDER`], and x at the threshold TOLERANCE/L^k moved by a few
    /// ulps to 1e-12 either way (the near ties the slack is there for).
    #[test]
    fn a_running_power_is_surely_above_only_where_powi_is() {
        let mut said = 0;
        for e in 0..=900 {
            let l = 10f64.powf(-6.0 + e as f64 / 100.0);
            let mut power = 1.0;
            for k in 0..=MAX_ORDER {
                let exact = l.powi(k as i32);
                for moved in [
                    -1e-12, -1e-13, -1e-14, -1e-15, 0.0, 1e-15, 1e-14, 1e-13, 1e-12,
                ] {
                    let x = TOLERANCE / exact * (1.0 + moved);
                    if surely_above(x, power) {
                        said += 1;
                        assert!(x * exact > TOLERANCE, "L {l}, k {k}, x {x:e}");
                    }
                }
                power *= l;
            }
        }
        // It does clear the ones well above (1e-12 past the threshold).
        assert!(said > 30_000, "{said}");
    }

    /// In improved Kelvin contact the fixed order's radius is short (its
    /// coefficients fall geometrically); [`MAX_ORDER`] reaches at least 1.8
    /// times as far, and its state there is that of fixed-order steps
    /// re-expanded along the way, to 1e-14 of the scale (measured: a gain
    /// of 2.1, 1.5e-15).
    #[test]
    fn more_orders_reach_further_in_improved_kelvin_contact() {
        let (system, (u, v), sc, fixed) = roof_contact();
        let n = u.len();
        let mut long = Series::default();
        long.fill_over(&system, (&u, &v), GROUND, sc, 10.0 * fixed.radius);
        assert_eq!(long.degree, MAX_ORDER);
        assert_eq!(fixed.degree, ORDER);
        let gain = long.radius / fixed.radius;
        assert!(
            gain > 1.8,
            "radius {} against {}",
            long.radius,
            fixed.radius
        );
        let end = long.radius;
        let (a, b) = at(&long, end);
        // Fixed-order steps of equal length, each re-expanded at its start
        // with the ground carried there.
        let steps = (end / (0.9 * fixed.radius)).ceil();
        let h = end / steps;
        let (mut c, mut d) = (u.clone(), v.clone());
        for j in 0..steps as usize {
            let s = h * j as f64;
            let ground = (GROUND.0 + GROUND.1 * s, GROUND.1, 0.0);
            let step = Series::new(&system, &c, &d, ground, sc);
            assert!(h < step.radius);
            (c, d) = at(&step, h);
        }
        let worst = (0..n)
            .map(|i| ((a[i] - c[i]).abs() / sc.0).max((b[i] - d[i]).abs() / sc.1))
            .fold(0.0, f64::max);
        println!("radius gain {gain}, {steps} steps, worst {worst:e}");
        assert!(worst < 1e-14, "worst {worst:e}, radius gain {gain}");
    }

    /// On a line (σ = ±0) the ground's coefficients are the recurrence's
    /// a_{k+2} = σ a_k/((k+1)(k+2)) to the bit, the sign of each zero
    /// included, and a sine's (σ = −ω²) follow a cos(ωs) + (ȧ/ω) sin(ωs).
    #[test]
    fn the_ground_series_is_the_recurrence_on_lines_and_sines() {
        let recurrence = |(a, rate, sigma): (f64, f64, f64)| {
            let mut g = [0.0; MAX_ORDER + 1];
            g[0] = a;
            g[1] = rate;
            for k in 0..MAX_ORDER - 1 {
                g[k + 2] = sigma * g[k] / ((k + 1) * (k + 2)) as f64;
            }
            g
        };
        let bits = |g: [f64; MAX_ORDER + 1]| g.map(f64::to_bits);
        for a in [1.5, -2.0, 0.0, -0.0, 1e300] {
            for rate in [0.25, -3.0, 0.0, -0.0] {
                for sigma in [0.0, -0.0] {
                    let ground = (a, rate, sigma);
                    assert_eq!(bits(ground_coefficients(ground)), bits(recurrence(ground)));
                }
            }
        }
        let (a, rate, w) = (0.7, -1.3, 3.0);
        let g = ground_coefficients((a, rate, -w * w));
        let s = 0.4f64;
        let sum: f64 = g.iter().rev().fold(0.0, |acc, &c| acc * s + c);
        let exact = a * (w * s).cos() + rate / w * (w * s).sin();
        assert!((sum - exact).abs() < 1e-15, "{sum} against {exact}");
    }
}
