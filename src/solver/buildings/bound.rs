//! Rigorous ranges of the watched quantities over a sub-step out of contact
//! (SPEC §13), which decide whether the cached map may take it.
//!
//! Out of contact, on fixed branches, the augmented state w = (u, u̇, a_g,
//! ȧ_g, M⁻¹q) of [`super::propagator`] moves by w' = 𝒜w exactly, so every
//! watched quantity q = cᵀw (a displacement, a velocity, an absolute
//! acceleration, a drift, a relative displacement) has the derivatives
//! q⁽ᵏ⁾ = cᵀ𝒜ᵏw, all linear in the state. At the two ends of a sub-step
//! q, q̇ and q̈ are therefore known exactly, and the Hermite cubic through
//! (q, q̇) has the range of q within h⁴/384 · max|q⁗| ([`super::hermite`]);
//! the cubic through (q̇, q̈) bounds q̇ the same way with max|q⁽⁵⁾|.
//!
//! The bound on max|q⁽ᵏ⁾| over the sub-step: with the diagonal scaling
//! D = diag(sI, I, 1/s, 1/s², I/s) (s the fastest rate of the row, so
//! that 𝒜̃ = D𝒜D⁻¹ has entries of order s and ‖𝒜̃‖h stays a few units) and
//! the ∞-norm,
//!
//! ```text
//! |q⁽ᵏ⁾(t)| = |(cᵀ𝒜ᵏD⁻¹)(D w(t))| ≤ ‖cᵀ𝒜ᵏD⁻¹‖₁ · ‖e^{𝒜̃t}‖∞ · ‖D w(0)‖∞,
//! ```
//!
//! and sup over t ∈ [0, h] of ‖e^{𝒜̃t}‖∞ is at most B, bounded from its
//! values on a grid of the sub-step, the last of which is the map
//! ([`super::sweep`]). The row norms and B depend only on the
//! configuration, h and σ, so they are made with its map and cached. A
//! sub-step then costs one ∞-norm of the state (O(dofs) from the rest point
//! too, [`Equilibrium`]) and, at each end, ü and u⃛ for every floor (two
//! products by M⁻¹K and M⁻¹C, O(dofs²); u⁗, a third, only where an
//! acceleration's rate is asked for), of which each quantity's q, q̇, q̈
//! are a few terms. The bound
//! follows the whole state (a high mode's swing shows in q⁗ even when q's
//! own end values are small), which is what the Hermite estimate alone
//! cannot see. B is widened by a relative 1e-6 for the round-off of the
//! exponential and the norms, far above it.
//!
//! Where a peak may still rise inside, the quintic Hermite through (q, q̇,
//! q̈) at both ends is asked next ([`super::quintic`]): its error is
//! h⁶/46080 · max|q⁽⁶⁾|, bounded the same way by ‖cᵀ𝒜⁶D⁻¹‖₁ · B.
//!
//! The rows cᵀ𝒜⁴, cᵀ𝒜⁵ and cᵀ𝒜⁶ come from rows n … 2n of the powers 𝒜² … 𝒜⁷
//! (six products of n + 1 rows by the sparse 𝒜, [`super::sparse`]), since
//! each c is a unit row or a row of 𝒜 beside one, and 𝒜̃² is one product by
//! the sparse 𝒜̃; the map itself, e^{𝒜h} = D⁻¹e^{𝒜̃h}D, is the grid's last
//! point, so that a configuration costs one matrix exponential (of the
//! scaled matrix over a quarter of h, of norm below one: no squaring) and
//! three products in blocks.

use nalgebra::DMatrix;

use crate::numerics::extremes::largest;

use super::quintic;
use super::sparse::Sparse;
use super::sweep::sweep;
use super::system::System;

mod equilibrium;
mod ground_jump;

pub use equilibrium::{Equilibrium, Rest};
pub use ground_jump::GroundJump;

/// Relative allowance for the round-off of the exponential and the norms
/// (of order 1e-13 for the rows' sizes met here).
const ROUNDING: f64 = 1e-6;

/// A watched quantity: q = Σ weight · x_i^(order) over its terms (floor i,
/// weight), where order 0 is u, 1 is u̇ and 2 the absolute acceleration
/// ü + a_g (the ground term taken once per unit weight).
#[derive(Debug, Clone, PartialEq)]
pub struct Watch {
    pub terms: Vec<(usize, f64)>,
    pub order: usize,
}

/// The per-configuration part of the bounds: the error allowances of each
/// quantity's two Hermite cubics per unit of ‖D w(0)‖∞.
#[derive(Debug, Clone)]
pub struct Bounds {
    /// h⁴/384 · ‖cᵀ𝒜⁴D⁻¹‖₁ · B: the cubic of q.
    value_error: Vec<f64>,
    /// h⁴/384 · ‖cᵀ𝒜⁵D⁻¹‖₁ · B: the cubic of q̇.
    rate_error: Vec<f64>,
    /// h⁶/46080 · ‖cᵀ𝒜⁶D⁻¹‖₁ · B: the quintic of q ([`super::quintic`]).
    quintic_error: Vec<f64>,
    scale: Vec<f64>,
    /// The configuration's rest points, to measure the state from
    /// ([`Equilibrium`]); none where K is singular.
    equilibrium: Option<Equilibrium>,
}

/// u, u̇, ü, u⃛, u⁗ of every floor at one instant out of contact, and the
/// ground's a_g, ȧ_g, ä_g: the exact derivatives of the motion there.
#[derive(Debug, Clone, Default)]
pub struct Stack {
    pub rates: [Vec<f64>; 5],
    pub ground: [f64; 3],
    /// Whether u⁗ is made: [`Stack::set_to_jerk`] leaves it to
    /// [`Stack::make_snap`], since the quiet test reads it only for a
    /// floor's ü + a_g that its first pass cannot clear (the rate of its
    /// cubic), which most sub-steps never ask for.
    pub snap: bool,
}

impl Stack {
    /// At (u, u̇) under ground (a, ȧ) on a piece with σ, for `system`:
    /// ü = −M⁻¹Ku − M⁻¹Cu̇ + M⁻¹q − a_g, then each further rate by the same
    /// equation differentiated (the load constant, ä_g = σa_g).
    pub fn at(
        system: &System,
        (u, v): (&[f64], &[f64]),
        (a, rate, sigma): (f64, f64, f64),
    ) -> Stack {
        let mut stack = Stack::default();
        stack.set(system, (u, v), (a, rate, sigma));
        stack
    }

    /// [`Stack::at`] written over this stack, its vectors reused.
    pub fn set(
        &mut self,
        system: &System,
        (u, v): (&[f64], &[f64]),
        (a, rate, sigma): (f64, f64, f64),
    ) {
        self.set_to_jerk(system, (u, v), (a, rate, sigma));
        self.make_snap(system);
    }

    /// [`Stack::set`] but u⁗, left for [`Stack::make_snap`].
    pub fn set_to_jerk(
        &mut self,
        system: &System,
        (u, v): (&[f64], &[f64]),
        (a, rate, sigma): (f64, f64, f64),
    ) {
        self.ground = [a, rate, sigma * a];
        self.snap = false;
        // By columns of M⁻¹K and M⁻¹C ([`System::columns`]).
        let [x, y, acc, jerk, _] = &mut self.rates;
        x.clear();
        x.extend_from_slice(u);
        y.clear();
        y.extend_from_slice(v);
        let columns = &system.columns;
        columns.rate((u, v), Some(&system.load), a, acc);
        columns.rate((v, acc), None, rate, jerk);
    }

    /// u⁗ = −ä_g 1 − M⁻¹K ü − M⁻¹C u⃛ of `system`, unless made already.
    pub fn make_snap(&mut self, system: &System) {
        if self.snap {
            return;
        }
        let [_, _, acc, jerk, snap] = &mut self.rates;
        system.columns.rate((acc, jerk), None, self.ground[2], snap);
        self.snap = true;
    }

    /// q, q̇, q̈ of `w`.
    pub fn of(&self, w: &Watch) -> [f64; 3] {
        let mut out = [0.0; 3];
        for (k, out) in out.iter_mut().enumerate() {
            let x = &self.rates[w.order + k];
            for &(i, c) in &w.terms {
                *out += c * x[i];
                if w.order == 2 {
                    *out += c * self.ground[k];
                }
            }
        }
        out
    }
}

/// The diagonal D of the scaling by the row's fastest rate `s` and the
/// scaled augmented matrix 𝒜̃ = D𝒜D⁻¹ of `a` (dofs `n`): D is s on u, 1 on
/// u̇, 1/s on a_g, 1/s² on ȧ_g and 1/s on M⁻¹q, so that every entry of
/// the scaled state is of one size.
pub fn scaled(a: &DMatrix<f64>, n: usize, s: f64) -> (Vec<f64>, DMatrix<f64>) {
    let d = a.nrows();
    let mut scale = vec![1.0; d];
    for i in 0..n {
        scale[i] = s;
        scale[2 * n + 2 + i] = 1.0 / s;
    }
    scale[2 * n] = 1.0 / s;
    scale[2 * n + 1] = 1.0 / (s * s);
    let scaled = DMatrix::from_fn(d, d, |i, j| scale[i] * a[(i, j)] / scale[j]);
    (scale, scaled)
}

impl Bounds {
    /// For the augmented matrix `a` (dofs `n`), over length `h`, with the
    /// scaling rate `s`.
    ///
    /// Returns them with the map's rows of (u, u̇), e^{𝒜h} = D⁻¹e^{𝒜̃h}D,
    /// e^{𝒜̃h} being the last point of the grid of [`super::sweep`].
    pub fn with_map(
        a: &DMatrix<f64>,
        n: usize,
        h: f64,
        s: f64,
        watch: &[Watch],
    ) -> (Bounds, DMatrix<f64>) {
        let d = a.nrows();
        let (scale, scaled) = scaled(a, n, s);
        let t = 2 * n;
        let (sweep, power) = sweep(&scaled, t, h);
        let (x, y) = (&power.x, &power.y);
        // e^{𝒜h} = D⁻¹ e^{𝒜̃h} D: the top rows of the grid's last point.
        let map = DMatrix::from_fn(t, d, |i, j| {
            let w = if j < t { x[(i, j)] } else { y[(i, j - t)] };
            w * scale[j] / scale[i]
        });
        let sweep = sweep * (1.0 + ROUNDING);
        let factor = h.powi(4) / 384.0 * sweep;
        let scaled_norm = |r: &[f64]| {
            r.iter()
                .zip(&scale)
                .map(|(x, s)| (x / s).abs())
                .sum::<f64>()
        };
        // cᵀ𝒜⁴, cᵀ𝒜⁵ and cᵀ𝒜⁶ of each quantity from rows of 𝒜⁴ … 𝒜⁷: c is a
        // few unit rows (u_i, u̇_i) or, for ü_i + a_g, row n + i of 𝒜 and the
        // unit row of a_g, so cᵀ𝒜ᵏ = row n + i of 𝒜ᵏ⁺¹ + row 2n of 𝒜ᵏ. Only
        // rows n … 2n of the powers are made, V_k = rows n … 2n of 𝒜ᵏ, by
        // V_{k+1} = V_k 𝒜: the rows of u are 𝒜's rows of u̇ shifted, so row
        // i < n of 𝒜ᵏ is row n + i of 𝒜ᵏ⁻¹, row i − n of V_{k−1}.
        let unscaled = Sparse::of(a);
        let mut v = vec![a.rows(n, n + 1).clone_owned()];
        for _ in 1..7 {
            let next = v.last().map(|m| unscaled.times(m)).expect("V_1");
            v.push(next);
        }
        let power_row = |k: usize, row: usize| {
            if row < n {
                v[k - 2].row(row)
            } else {
                v[k - 1].row(row - n)
            }
        };
        let mut value_error = Vec::with_capacity(watch.len());
        let mut rate_error = Vec::with_capacity(watch.len());
        let mut quintic_error = Vec::with_capacity(watch.len());
        let sixth = h.powi(6) / quintic::REMAINDER * sweep;
        let (mut r4, mut r5, mut r6) = (vec![0.0; d], vec![0.0; d], vec![0.0; d]);
        let add = |r: &mut [f64], k: usize, row: usize, x: f64| {
            for (r, m) in r.iter_mut().zip(power_row(k, row).iter()) {
                *r += x * m;
            }
        };
        for w in watch {
            r4.fill(0.0);
            r5.fill(0.0);
            r6.fill(0.0);
            for &(i, x) in &w.terms {
                match w.order {
                    0 | 1 => {
                        let row = w.order * n + i;
                        add(&mut r4, 4, row, x);
                        add(&mut r5, 5, row, x);
                        add(&mut r6, 6, row, x);
                    }
                    _ => {
                        add(&mut r4, 5, n + i, x);
                        add(&mut r4, 4, 2 * n, x);
                        add(&mut r5, 6, n + i, x);
                        add(&mut r5, 5, 2 * n, x);
                        add(&mut r6, 7, n + i, x);
                        add(&mut r6, 6, 2 * n, x);
                    }
                }
            }
            value_error.push(factor * scaled_norm(&r4));
            rate_error.push(factor * scaled_norm(&r5));
            quintic_error.push(sixth * scaled_norm(&r6));
        }
        let bounds = Bounds {
            value_error,
            rate_error,
            quintic_error,
            scale,
            equilibrium: Equilibrium::of(a, n),
        };
        (bounds, map)
    }

    /// ‖D w‖∞ of the augmented state at (u, u̇) under ground (a, ȧ) with
    /// load M⁻¹q, or ‖D(w − w*)‖∞ from the configuration's rest point w*
    /// when smaller ([`Equilibrium`]), in the configuration of `branches`
    /// whose rest point `rest` keeps.
    pub fn size(
        &self,
        (u, v): (&[f64], &[f64]),
        (a, rate): (f64, f64),
        load: &[f64],
        rest: (&[u8], &mut Rest),
    ) -> f64 {
        let n = u.len();
        let s = &self.scale;
        let (on_u, on_v, on_load) = (&s[..n], &s[n..2 * n], &s[2 * n + 2..3 * n + 2]);
        let (v, load) = (&v[..n], &load[..n]);
        let mut m = largest((a * s[2 * n]).abs(), (rate * s[2 * n + 1]).abs());
        for i in 0..n {
            m = largest(m, (u[i] * on_u[i]).abs());
            m = largest(m, (v[i] * on_v[i]).abs());
            m = largest(m, (load[i] * on_load[i]).abs());
        }
        match &self.equilibrium {
            Some(e) => m.min(e.size((u, v), (a, rate), load, s, rest)),
            None => m,
        }
    }

    /// Bounds on the errors of the cubics of q and q̇ of quantity `k`, for a
    /// sub-step starting from a state of size `size` ([`Bounds::size`]).
    pub fn errors(&self, k: usize, size: f64) -> (f64, f64) {
        (self.value_error[k] * size, self.rate_error[k] * size)
    }

    /// A bound on the error of the quintic of q of quantity `k`
    /// ([`super::quintic`]), for a sub-step starting from a state of size
    /// `size` ([`Bounds::size`]).
    pub fn quintic_error(&self, k: usize, size: f64) -> f64 {
        self.quintic_error[k] * size
    }

    /// The bounds of [`Bounds::errors`] per unit size, of every quantity:
    /// those of the cubics of q, then of q̇.
    pub fn unit_errors(&self) -> (&[f64], &[f64]) {
        (&self.value_error, &self.rate_error)
    }
}
