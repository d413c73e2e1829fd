//! How a [`Series`] holds its coefficients, and how its readers take them
//! (SPEC §13).
//!
//! The recurrence forms the series order by order, every floor's
//! coefficient of one order side by side; the series keeps them so,
//!
//! ```text
//! orders[2nk + i] = u_{k,i},   orders[2nk + n + i] = u̇_{k,i},   k = 0 … degree,
//! ```
//!
//! rather than copying them out floor by floor after every fill. A reader
//! over every floor at once (the state at s, a step's reach,
//! [`super::super::reach`]) runs across the floors on contiguous memory; a
//! reader of a few floors (a linear combination, an absolute acceleration)
//! steps through a floor's coefficients 2n apart; a reader that needs one
//! floor's polynomial as a slice takes a copy of it
//! ([`Series::displacement_into`]), or the floor-by-floor blocks made once,
//! on its first ask ([`Series::displacement`]). Every reader takes the same
//! coefficients in the same order as from blocks: the numbers are the same
//! to the bit.

use std::cell::OnceCell;

use super::{ORDER, Series};

/// Entries of a column whose chains [`Series::state`] runs side by side.
const STATE_LANES: usize = 8;

/// Floor-by-floor copies of a series' coefficients: floor i's u_k at
/// `u[i (degree + 1) + k]`, and likewise u̇_k in `v`.
#[derive(Debug, Clone)]
pub(super) struct Floors {
    u: Vec<f64>,
    v: Vec<f64>,
}

impl Clone for Series {
    /// The orders up to the degree, not the buffer past them; the
    /// floor-by-floor copies are made again if asked for (a clone is
    /// usually written to, which drops them), and the workspace starts
    /// empty.
    fn clone(&self) -> Series {
        Series {
            n: self.n,
            orders: self.held().to_vec(),
            floors: OnceCell::new(),
            ground: self.ground,
            radius: self.radius,
            degree: self.degree,
            forces: self.forces.clone(),
            work: self.work.clone(),
        }
    }

    /// The same series written over this one, its vectors reused (its
    /// workspace kept: it holds nothing between fills).
    fn clone_from(&mut self, source: &Series) {
        self.n = source.n;
        self.orders.clear();
        self.orders.extend_from_slice(source.held());
        self.floors.take();
        self.ground = source.ground;
        self.radius = source.radius;
        self.degree = source.degree;
        self.forces.clone_from(&source.forces);
    }
}

impl Series {
    /// A polynomial of `degree` on n floors given floor by floor (blocks
    /// of degree + 1 coefficients of u and of u̇, lowest order first), as
    /// a series; its ground and radius are the caller's to set.
    pub fn from_floors(n: usize, degree: usize, (u, v): (&[f64], &[f64])) -> Series {
        let width = degree + 1;
        let mut orders = vec![0.0; 2 * n * width];
        for (k, column) in orders.chunks_exact_mut(2 * n).enumerate() {
            let (cu, cv) = column.split_at_mut(n);
            for i in 0..n {
                cu[i] = u[i * width + k];
                cv[i] = v[i * width + k];
            }
        }
        Series {
            n,
            orders,
            degree,
            ..Series::default()
        }
    }

    /// Every coefficient of the series, orders 0 to [`Series::degree`]
    /// in the layout of the module's opening.
    #[inline]
    pub fn held(&self) -> &[f64] {
        &self.orders[..2 * self.n * (self.degree + 1)]
    }

    /// Orders 0 to `count` − 1 as one slice to write, in the layout of
    /// the module's opening (the floor-by-floor copies, if made, are
    /// dropped).
    #[inline]
    pub fn orders_mut(&mut self, count: usize) -> &mut [f64] {
        self.floors.take();
        &mut self.orders[..2 * self.n * count]
    }

    /// Order k's 2n coefficients: u_k of every floor, then u̇_k.
    #[inline]
    pub fn column(&self, k: usize) -> &[f64] {
        let n = self.n;
        &self.orders[2 * n * k..2 * n * (k + 1)]
    }

    /// Order k of every floor: (u_k, u̇_k), floor i at index i.
    #[inline]
    pub fn order(&self, k: usize) -> (&[f64], &[f64]) {
        self.column(k).split_at(self.n)
    }

    /// [`Series::order`] to write (the floor-by-floor copies, if made, are
    /// dropped).
    #[inline]
    pub fn order_mut(&mut self, k: usize) -> (&mut [f64], &mut [f64]) {
        let n = self.n;
        self.floors.take();
        self.orders[2 * n * k..2 * n * (k + 1)].split_at_mut(n)
    }

    /// Coefficients 0 to [`Series::degree`] of entry `at` of each order's
    /// 2n (floor i's u at i, its u̇ at n + i), one order's column after
    /// another.
    #[inline]
    fn along(&self, at: usize) -> impl Iterator<Item = f64> + '_ {
        self.held()
            .chunks_exact((2 * self.n).max(1))
            .map(move |column| column[at])
    }

    /// The coefficients of u_i, orders 0 to [`Series::degree`], into `out`.
    pub fn displacement_into(&self, i: usize, out: &mut Vec<f64>) {
        out.clear();
        out.extend(self.along(i));
    }

    /// The coefficients of u̇_i, orders 0 to [`Series::degree`], into `out`.
    pub fn velocity_into(&self, i: usize, out: &mut Vec<f64>) {
        out.clear();
        out.extend(self.along(self.n + i));
    }

    /// u_i(s) by Horner's rule down the series' columns: [`super::poly::eval`] on
    /// the floor's coefficients, to the bit, without the floor-by-floor
    /// copies ([`Series::displacement`]), which a series filled afresh at
    /// every step would make again each time.
    pub fn displacement_at(&self, i: usize, s: f64) -> f64 {
        self.entry_at(i, s)
    }

    /// u̇_i(s), as [`Series::displacement_at`].
    pub fn velocity_at(&self, i: usize, s: f64) -> f64 {
        self.entry_at(self.n + i, s)
    }

    /// Entry `at` of the columns (u_i, then u̇_i) at s by Horner's rule.
    fn entry_at(&self, at: usize, s: f64) -> f64 {
        let columns = self.held().chunks_exact((2 * self.n).max(1));
        columns.rev().fold(0.0, |acc, column| acc * s + column[at])
    }

    /// The floor-by-floor copies, made on the first ask.
    fn floors(&self) -> &Floors {
        self.floors.get_or_init(|| {
            let (n, width) = (self.n, self.degree + 1);
            let (mut u, mut v) = (vec![0.0; n * width], vec![0.0; n * width]);
            for k in 0..width {
                let (cu, cv) = self.order(k);
                for i in 0..n {
                    u[i * width + k] = cu[i];
                    v[i * width + k] = cv[i];
                }
            }
            Floors { u, v }
        })
    }

    /// The coefficients of u_i, orders 0 to [`Series::degree`], as one
    /// slice (of the floor-by-floor copies, made for every floor on the
    /// first ask).
    #[inline]
    pub fn displacement(&self, i: usize) -> &[f64] {
        let width = self.degree + 1;
        &self.floors().u[i * width..(i + 1) * width]
    }

    /// The coefficients of u̇_i, as [`Series::displacement`].
    #[inline]
    pub fn velocity(&self, i: usize) -> &[f64] {
        let width = self.degree + 1;
        &self.floors().v[i * width..(i + 1) * width]
    }

    /// (u, u̇) at s by Horner's rule,
    ///
    /// ```text
    /// u(s) = (…(u_K s + u_{K−1}) s + …) s + u_0,
    /// ```
    ///
    /// on all 2n entries of a column side by side, `STATE_LANES` (8) at a
    /// time: each group's chains advance order by order in one
    /// multiply-add of a fixed width (one chain alone waits on each
    /// multiply-add in turn). Each chain is [`super::poly::eval`]'s
    /// Horner's rule on its floor's coefficients: the same state to the
    /// bit.
    pub fn state(&self, s: f64, u: &mut [f64], v: &mut [f64]) {
        let n = self.n;
        let held = self.held();
        let (u, v) = (&mut u[..n], &mut v[..n]);
        for first in (0..2 * n).step_by(STATE_LANES) {
            let lanes = STATE_LANES.min(2 * n - first);
            let mut acc = [0.0; STATE_LANES];
            for column in held.chunks_exact(2 * n).rev() {
                // A whole group as one fixed-width load; the last, short
                // one entry by entry (its chains past the column idle).
                let c: [f64; STATE_LANES] = match column.get(first..first + STATE_LANES) {
                    Some(group) => group.try_into().expect("a whole group"),
                    None => std::array::from_fn(|j| column.get(first + j).map_or(0.0, |&c| c)),
                };
                for (a, c) in acc.iter_mut().zip(c) {
                    *a = *a * s + c;
                }
            }
            for (j, &a) in acc[..lanes].iter().enumerate() {
                match first + j {
                    at if at < n => u[at] = a,
                    at => v[at - n] = a,
                }
            }
        }
    }

    /// Coefficients of Σ_i (wu_i u_i + wv_i u̇_i) over the given (dof,
    /// weight) terms: each order's sum from 0, the terms added in the
    /// order given (u's, then u̇'s), each floor's coefficient read from
    /// the order's column. The usual two terms (a drift, a gap, a pair's
    /// Δu or Δv) go in one pass, ((0 + w₁x₁) + w₂x₂) for each order, the
    /// sum a term at a time forms.
    pub fn combine(&self, du: &[(usize, f64)], dv: &[(usize, f64)], out: &mut Vec<f64>) {
        out.clear();
        let (n, held) = (self.n, self.held());
        // Term t as (its entry in a column, its weight).
        let term = |t: usize| match du.get(t) {
            Some(&term) => term,
            None => {
                let (i, w) = dv[t - du.len()];
                (n + i, w)
            }
        };
        let columns = held.chunks_exact((2 * n).max(1));
        match du.len() + dv.len() {
            2 => {
                let ((a, wa), (b, wb)) = (term(0), term(1));
                out.extend(columns.map(|c| 0.0 + wa * c[a] + wb * c[b]));
            }
            count => {
                out.resize(self.degree + 1, 0.0);
                for (at, w) in (0..count).map(term) {
                    for (o, column) in out.iter_mut().zip(columns.clone()) {
                        *o += w * column[at];
                    }
                }
            }
        }
    }

    /// Coefficients of the absolute acceleration ü_i + ü_g (one order
    /// fewer): k u̇_k + a_{k−1} for k = 1 … [`Series::degree`], then the
    /// ground's alone to [`ORDER`].
    pub fn absolute_acceleration(&self, i: usize, out: &mut Vec<f64>) {
        out.clear();
        let (n, held) = (self.n, self.held());
        let rates = held[2 * n..].chunks_exact((2 * n).max(1)).zip(&self.ground);
        out.extend(
            rates
                .enumerate()
                .map(|(j, (column, &a))| (j + 1) as f64 * column[n + i] + a),
        );
        let top = ORDER.max(self.degree);
        out.extend(self.ground[self.degree..top].iter().map(|&a| 0.0 + a));
    }

    /// [`Series::absolute_acceleration`] of every floor into `out`, order
    /// by order: order k of every floor side by side (floor i's at
    /// k·n + i), the orders to the returned width ([`ORDER`] or the
    /// degree, if higher), each floor's coefficients the same to the bit.
    /// One pass over the series' columns forms them all, k u̇_k + a_{k−1}
    /// across a column at a time, without moving them floor by floor: a
    /// step's search for peaks bounds every floor's at once
    /// ([`poly::magnitude_bound_lanes`]) and gathers the few whose bound
    /// passes their peak ([`Series::gather`]).
    ///
    /// [`poly::magnitude_bound_lanes`]: super::super::poly::magnitude_bound_lanes
    pub fn absolute_accelerations(&self, out: &mut Vec<f64>) -> usize {
        let (n, degree) = (self.n, self.degree);
        let width = ORDER.max(degree);
        // Every entry is written below: what a longer buffer held is
        // overwritten, not cleared.
        out.resize(n * width, 0.0);
        let rates = self.held()[2 * n..]
            .chunks_exact((2 * n).max(1))
            .zip(&self.ground);
        for (j, (column, &a)) in rates.enumerate() {
            let rate = (j + 1) as f64;
            for (x, &v) in out[j * n..(j + 1) * n].iter_mut().zip(&column[n..]) {
                *x = rate * v + a;
            }
        }
        for (j, &a) in (degree..width).zip(&self.ground[degree..width]) {
            out[j * n..(j + 1) * n].fill(0.0 + a);
        }
        width
    }

    /// Floor i's polynomial out of coefficients laid order by order, as
    /// [`Series::absolute_accelerations`] lays them (`width` orders of n
    /// floors), into `out`.
    pub fn gather(orders: &[f64], n: usize, i: usize, out: &mut Vec<f64>) {
        out.clear();
        out.extend(orders.iter().skip(i).step_by(n.max(1)));
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::poly;
    use super::Series;

    /// Three floors of a quintic, floor i's u_k = (i + 1)·10^k − k and
    /// u̇_k = −(i + 2)/(k + 1), given floor by floor.
    fn quintics() -> (Series, Vec<f64>, Vec<f64>) {
        let (n, width) = (3, 6);
        let u: Vec<f64> = (0..n * width)
            .map(|j| ((j / width + 1) as f64) * 10f64.powi((j % width) as i32) - (j % width) as f64)
            .collect();
        let v: Vec<f64> = (0..n * width)
            .map(|j| -((j / width + 2) as f64) / ((j % width + 1) as f64))
            .collect();
        let mut series = Series::from_floors(n, width - 1, (&u, &v));
        series.ground[..8].copy_from_slice(&[0.5, -0.25, 3.0, 1e-3, 0.0, -7.0, 2.0, 9.0]);
        (series, u, v)
    }

    /// Read by orders, by floors as slices, as copies and along the
    /// stride, a series given floor by floor gives back each coefficient
    /// where it was put.
    #[test]
    fn every_reader_finds_each_coefficient_where_it_was_put() {
        let (series, u, v) = quintics();
        let (n, width) = (series.n, series.degree + 1);
        assert_eq!(series.held().len(), 2 * n * width);
        let mut copy = Vec::new();
        for i in 0..n {
            let (bu, bv) = (
                &u[i * width..(i + 1) * width],
                &v[i * width..(i + 1) * width],
            );
            assert_eq!(series.displacement(i), bu);
            assert_eq!(series.velocity(i), bv);
            series.displacement_into(i, &mut copy);
            assert_eq!(copy, bu);
            series.velocity_into(i, &mut copy);
            assert_eq!(copy, bv);
            for k in 0..width {
                let (cu, cv) = series.order(k);
                assert_eq!((cu[i], cv[i]), (bu[k], bv[k]));
            }
        }
    }

    /// A combination of floors is the sum of their blocks term by term in
    /// the order given, to the bit, with one, two (on u, on u̇, on both)
    /// and three terms; the absolute acceleration is
    /// k u̇_k + a_{k−1}, then the ground's own coefficients to
    /// [`super::ORDER`], the same floor by floor and for all floors in
    /// one pass.
    #[test]
    fn combinations_and_accelerations_are_the_blocks_sums() {
        let (series, _, _) = quintics();
        let width = series.degree + 1;
        // Sum of the terms' blocks, a term at a time from 0.
        type Terms<'a> = &'a [(usize, f64)];
        let blockwise = |du: Terms, dv: Terms| -> Vec<f64> {
            let mut sum = vec![0.0; width];
            for (terms, rates) in [(du, false), (dv, true)] {
                for &(i, w) in terms {
                    let block = if rates {
                        series.velocity(i)
                    } else {
                        series.displacement(i)
                    };
                    for (s, x) in sum.iter_mut().zip(block) {
                        *s += w * x;
                    }
                }
            }
            sum
        };
        let mut got = Vec::new();
        let cases: [(Terms, Terms); 5] = [
            (&[(2, 1.5), (0, -0.75)], &[(1, 0.25)]),
            (&[(2, 1.0), (1, -1.0)], &[]),
            (&[], &[(0, 1.0), (2, -1.0)]),
            (&[(1, -3.0)], &[(1, 0.5)]),
            (&[(0, 2.0)], &[]),
        ];
        for (du, dv) in cases {
            series.combine(du, dv, &mut got);
            let want = blockwise(du, dv);
            let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(&want), "{du:?} {dv:?}");
        }
        let mut every = Vec::new();
        let width = series.absolute_accelerations(&mut every);
        assert_eq!(every.len(), width * series.n);
        let mut gathered = Vec::new();
        for i in 0..series.n {
            series.absolute_acceleration(i, &mut got);
            Series::gather(&every, series.n, i, &mut gathered);
            let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&gathered), bits(&got), "floor {i}");
        }
        series.absolute_acceleration(1, &mut got);
        assert_eq!(got.len(), super::ORDER);
        for (k, &a) in got.iter().enumerate() {
            let rate = series
                .velocity(1)
                .get(k + 1)
                .map_or(0.0, |v| (k + 1) as f64 * v);
            assert_eq!(a, rate + series.ground[k], "order {k}");
        }
    }

    /// A write to an order after the floors' copies were made shows in
    /// them (the copies are made again), and in the state at s, which is
    /// each floor's Horner sum to the bit.
    #[test]
    fn a_written_order_shows_in_the_floors_and_the_state() {
        let (mut series, _, _) = quintics();
        assert_eq!(series.displacement(1)[3], 2.0 * 1e3 - 3.0);
        series.order_mut(3).0[1] = 42.0;
        series.order_mut(0).1[2] = -0.5;
        assert_eq!(series.displacement(1)[3], 42.0);
        assert_eq!(series.velocity(2)[0], -0.5);
        let (mut u, mut v) = ([0.0; 3], [0.0; 3]);
        for s in [0.0, 0.1, 0.7] {
            series.state(s, &mut u, &mut v);
            for i in 0..3 {
                let (eu, ev) = (
                    poly::eval(series.displacement(i), s),
                    poly::eval(series.velocity(i), s),
                );
                assert_eq!(
                    (u[i].to_bits(), v[i].to_bits()),
                    (eu.to_bits(), ev.to_bits())
                );
            }
        }
        let clone = series.clone();
        assert_eq!(clone.held(), series.held());
        assert_eq!(clone.displacement(1), series.displacement(1));
    }
}
