//! How far each floor's u and u̇ can move from their start over a series
//! step (SPEC §13), so that a step's search for events and peaks can pass
//! over a quantity that cannot reach its threshold without forming its
//! polynomial.
//!
//! On [0, s] a floor's displacement u(t) = Σ u_k t^k moves from u_0 by at
//! most
//!
//! ```text
//! R_u = Σ_{k≥1} |u_k| s^k,
//! ```
//!
//! and likewise its velocity by R_v. A quantity of a few floors (an event
//! function, a drift, a relative displacement),
//!
//! ```text
//! q = Σ w_i u_i + Σ w'_i u̇_i + c,
//! ```
//!
//! is then within q(0) ± (Σ|w_i| R_u,i + Σ|w'_i| R_v,i),
//! which is at least the bounds of [`super::poly`] on q's own polynomial
//! (its coefficients are those sums, each no larger in magnitude than the
//! sum of magnitudes). So where this reach clears a threshold, so would
//! q's polynomial: the search skips q and finds exactly what it found
//! before. A relative allowance of 1e-12 covers the round-off of the sums.

use super::poly;
use super::taylor::Series;

/// Terms (floor, weight) of a linear form.
pub type Terms<'a> = &'a [(usize, f64)];

/// Relative allowance for the round-off of the reaches and of q(0).
const ROUNDING: f64 = 1e-12;

/// R_u and R_v of every floor over [0, s] of one step, with u_0 and u̇_0
/// (where they start), reused from step to step: each as the series holds
/// an order ([`super::taylor::orders`]), the n floors' u, then their u̇.
#[derive(Debug, Clone, Default)]
pub struct Reach {
    n: usize,
    reach: Vec<f64>,
    start: Vec<f64>,
    /// [`poly::bound_lanes`]' chains.
    chains: Vec<f64>,
}

impl Reach {
    /// The reaches of every floor of `series` over [0, s]: R = s Σ_{k≥1}
    /// |c_k| s^{k−1} by [`poly::bound`]'s chains on c_1 … c_K, every
    /// floor's u and u̇ side by side.
    pub fn set(&mut self, series: &Series, s: f64) {
        let n = series.n;
        self.n = n;
        self.start.clear();
        self.start.extend_from_slice(series.column(0));
        self.reach.clear();
        self.reach.resize(2 * n, 0.0);
        if series.degree == 0 {
            return;
        }
        let c = &series.held()[2 * n..];
        poly::bound_lanes(c, s, &mut self.chains, &mut self.reach);
        for r in &mut self.reach {
            *r *= s;
        }
    }

    /// An upper bound over the step of q = Σ w_i u_i + Σ w'_i u̇_i + c
    /// (terms on u, terms on u̇, the constant), from its value at the start.
    pub fn upper(&self, (on_u, on_v): (Terms, Terms), constant: f64) -> f64 {
        let (mut start, mut size, mut reach) = (constant, constant.abs(), 0.0);
        // u_i at i, u̇_i at n + i.
        let n = self.n;
        let terms = on_u
            .iter()
            .copied()
            .chain(on_v.iter().map(|&(i, w)| (n + i, w)));
        for (at, w) in terms {
            let x = w * self.start[at];
            start += x;
            size += x.abs();
            reach += w.abs() * self.reach[at];
        }
        start + reach + ROUNDING * (size + reach)
    }

    /// An upper bound over the step of |u̇_i|.
    pub fn speed(&self, i: usize) -> f64 {
        let (start, reach) = (self.start[self.n + i].abs(), self.reach[self.n + i]);
        start + reach + ROUNDING * (start + reach)
    }

    /// An upper bound over the step of |q|, q as in [`Reach::upper`] with
    /// terms on u alone.
    pub fn magnitude(&self, on_u: Terms) -> f64 {
        let negated: [(usize, f64); 2] =
            std::array::from_fn(|k| on_u.get(k).map_or((0, 0.0), |&(i, w)| (i, -w)));
        let up = self.upper((on_u, &[]), 0.0);
        let down = self.upper((&negated[..on_u.len().min(2)], &[]), 0.0);
        up.max(down)
    }
}

#[cfg(test)]
mod tests {
    use super::Reach;
    use crate::model::buildings;
    use crate::solver::buildings::config::Config;
    use crate::solver::buildings::layout::Layout;
    use crate::solver::buildings::poly;
    use crate::solver::buildings::system::System;
    use crate::solver::buildings::taylor::Series;

    /// Block-and-frame at rest in its configuration, and `count` states
    /// of a few centimetres and tens of centimetres per second, signs
    /// mixed, each with a ground (a, ȧ, 0): a deterministic spread.
    type State = (Vec<f64>, Vec<f64>, (f64, f64, f64));
    fn scattered(count: u32) -> (Layout, System, Vec<State>) {
        let row = buildings::load("block-and-frame").expect("shipped");
        let layout = Layout::of(&row);
        let n = layout.dofs;
        let config = Config::at_rest(layout.storeys.len(), layout.pairs.len());
        let system = System::of(&layout, &config);
        let states = (1..=count)
            .map(|seed| {
                let wave = |i: usize, k: u32| ((i as f64 + 1.0) * 0.7 * f64::from(seed + k)).sin();
                let u: Vec<f64> = (0..n).map(|i| 0.03 * wave(i, 0)).collect();
                let v: Vec<f64> = (0..n).map(|i| 0.4 * wave(i, 11)).collect();
                (u, v, (3.0 * wave(0, 5), 200.0 * wave(1, 7), 0.0))
            })
            .collect();
        (layout, system, states)
    }

    /// Every floor's reach, taken side by side, is the one of its own
    /// polynomial, Σ_{k≥1}|c_k| s^k = [`poly::bound`] of c_1 … c_K times s,
    /// to the bit, and its start is c_0: block-and-frame from scattered
    /// states, at the fixed order and at the lower orders of shorter steps
    /// (every degree mod 4 among them).
    #[test]
    fn every_floors_reach_is_its_polynomials_bound() {
        let (layout, system, states) = scattered(19);
        let n = layout.dofs;
        let mut reach = Reach::default();
        let mut series = Series::default();
        let mut degrees = std::collections::BTreeSet::new();
        for (u, v, ground) in states {
            let fixed = Series::new(&system, &u, &v, ground, (0.03, 0.4));
            for part in [1.0, 0.5, 0.3, 0.15, 0.05, 0.02, 0.01, 3e-3, 1e-3, 1e-4] {
                let want = part * fixed.radius;
                series.fill_over(&system, (&u, &v), ground, (0.03, 0.4), want);
                for (series, s) in [(&fixed, want), (&series, want)] {
                    degrees.insert(series.degree);
                    reach.set(series, s);
                    for i in 0..n {
                        for (at, c) in [(i, series.displacement(i)), (n + i, series.velocity(i))] {
                            let want = poly::bound(&c[1..], s) * s;
                            assert_eq!(reach.reach[at].to_bits(), want.to_bits(), "floor {i}");
                            assert_eq!(reach.start[at].to_bits(), c[0].to_bits());
                        }
                    }
                }
            }
        }
        let remainders: std::collections::BTreeSet<usize> = degrees.iter().map(|d| d % 4).collect();
        assert_eq!(remainders.len(), 4, "degrees {degrees:?}");
    }

    /// Block-and-frame from scattered states, on steps up to the series'
    /// radius: every drift and relative displacement, sampled densely on
    /// its polynomial, stays within the reach's bounds, which are at least
    /// the polynomial's own bounds of [`poly`] (so a quantity the reach
    /// passes over is one the polynomial's search would find nothing in).
    #[test]
    fn the_reach_bounds_every_quantity_and_its_polynomial_bound() {
        let (layout, system, states) = scattered(39);
        let n = layout.dofs;
        let mut reach = Reach::default();
        let mut checked = 0;
        for (u, v, ground) in states {
            let series = Series::new(&system, &u, &v, ground, (0.03, 0.4));
            let end = series.radius.min(0.01);
            reach.set(&series, end);
            let mut c = Vec::new();
            for s in &layout.storeys {
                let du = [(s.upper, 1.0), (s.lower.unwrap_or(s.upper), -1.0)];
                let terms = if s.lower.is_some() { &du[..] } else { &du[..1] };
                series.combine(terms, &[], &mut c);
                let top = reach.magnitude(terms);
                assert!(poly::magnitude_bound(&c, end) <= top);
                for p in 0..=200 {
                    assert!(poly::eval(&c, end * f64::from(p) / 200.0).abs() <= top);
                }
                checked += 1;
            }
            for p in &layout.facing {
                let terms = [(p.left_dof, 1.0), (p.right_dof, -1.0)];
                series.combine(&terms, &[], &mut c);
                let top = reach.upper((&terms, &[]), 0.0);
                assert!(poly::upper_bound(&c, end) <= top);
                checked += 1;
            }
            for i in 0..n {
                let top = reach.speed(i);
                assert!(poly::magnitude_bound(series.velocity(i), end) <= top);
                let top = reach.magnitude(&[(i, 1.0)]);
                assert!(poly::magnitude_bound(series.displacement(i), end) <= top);
                checked += 1;
            }
        }
        assert!(checked > 500, "{checked} quantities checked");
    }
}
