//! The equations of motion of one segment between events, as Taylor-series
//! recurrences (SPEC §2–4).
//!
//! Between events each spring is on one branch of the bilinear law (SPEC §3),
//! on which f_s is affine in x:
//!
//! ```text
//! elastic, z = x − p (p the plastic offset):  f_s = k x − (1 − Π_α) k p
//! yielded, z = σ Π_uy:                         f_s = Π_α k x + (1 − Π_α) k σ Π_uy
//! ```
//!
//! so each structure obeys m ẍ + c ẋ + K x = Q − m g(τ) ∓ f_p with constant
//! K (k or Π_α k) and Q. With x(τ₀ + t) = Σ x_k t^k and g(τ₀ + t) = Σ g_k t^k,
//! matching powers of t gives the recurrence
//!
//! ```text
//! m (k+1)(k+2) x_{k+2} = Q [k = 0] − m g_k − c (k+1) x_{k+1} − K x_k ∓ f_k,
//! ```
//!
//! where f_k are the coefficients of the pounding force. Out of contact
//! f_k = 0 and each structure is a linear oscillator with constant
//! coefficients: its series is its closed-form response, summed to
//! round-off. In contact (SPEC §4), f_p = k̄δ + cδ̇ + hδδ̇ with
//! δ = x1 − x2 − Π_d, so
//!
//! ```text
//! f_k = k̄ δ_k + c (k+1) δ_{k+1} + h Σ_{j=0}^{k} δ_j (k−j+1) δ_{k−j+1},
//! ```
//!
//! which needs only coefficients up to k+1: the recurrence stays explicit.

use crate::model::{ContactLaw, Params};

use super::series::{MAX_DEGREE, Series};
use crate::numerics::madd;

/// One spring's branch between events (SPEC §3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Branch {
    /// z = x − offset, |z| < Π_uy.
    Elastic { offset: f64 },
    /// z = sign · Π_uy, while sign · ẋ > 0.
    Yielded { sign: f64 },
}

impl Branch {
    /// 0 on the elastic branch, 1 yielded: the index of the branch's stiffness
    /// (k or Π_α k) in tables kept per kind, such as the quiet segments' transitions.
    #[inline]
    pub fn kind(self) -> usize {
        match self {
            Branch::Elastic { .. } => 0,
            Branch::Yielded { .. } => 1,
        }
    }
}

/// The constant coefficients of one structure (SPEC §2–3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Structure {
    /// m: Π_m (left) or 1 (right).
    pub mass: f64,
    /// c: 2Π_ξΠ_mΠ_ω1 or 2Π_ξΠ_ω2.
    pub damping: f64,
    /// Elastic k: Π_m Π_ω1² or Π_ω2².
    pub stiffness: f64,
    pub alpha: f64,
    /// Π_uy (infinite: elastic for ever).
    pub yield_displacement: f64,
    /// Fastest rate of the structure's free motion on any branch, a bound on
    /// the modulus of the eigenvalues of its first-order system: ξω + √(ξ²ω² + ω²).
    pub rate: f64,
}

impl Structure {
    pub fn pair(p: &Params) -> [Structure; 2] {
        let make = |mass: f64, omega: f64, uy: f64| {
            let zw = p.damping * omega;
            Structure {
                mass,
                damping: 2.0 * zw * mass,
                stiffness: mass * omega * omega,
                alpha: p.alpha,
                yield_displacement: uy,
                rate: zw + (zw * zw + omega * omega).sqrt(),
            }
        };
        [
            make(p.mass_ratio, p.omega1, p.yield1),
            make(1.0, p.omega2, p.yield2),
        ]
    }

    /// (K, Q) of m ẍ + c ẋ + K x = Q − m g ∓ f_p on `branch`.
    #[inline]
    pub fn affine(&self, branch: Branch) -> (f64, f64) {
        let k = self.stiffness;
        match branch {
            Branch::Elastic { offset } => (k, (1.0 - self.alpha) * k * offset),
            Branch::Yielded { sign } => (
                self.alpha * k,
                -(1.0 - self.alpha) * k * sign * self.yield_displacement,
            ),
        }
    }

    /// z at displacement x on `branch`.
    #[inline]
    pub fn elastic_part(&self, branch: Branch, x: f64) -> f64 {
        match branch {
            Branch::Elastic { offset } => x - offset,
            Branch::Yielded { sign } => sign * self.yield_displacement,
        }
    }

    /// f_s = Π_α k x + (1 − Π_α) k z (SPEC §3).
    #[inline]
    pub fn spring_force(&self, branch: Branch, x: f64) -> f64 {
        let k = self.stiffness;
        self.alpha * k * x + (1.0 - self.alpha) * k * self.elastic_part(branch, x)
    }

    /// The branch at the start of a run from displacement x, with no plastic history.
    pub fn initial_branch(&self, x: f64, v: f64) -> Branch {
        let uy = self.yield_displacement;
        if x.abs() > uy || (x.abs() == uy && x * v > 0.0) {
            Branch::Yielded { sign: x.signum() }
        } else {
            Branch::Elastic { offset: 0.0 }
        }
    }
}

/// 1/((j+1)(j+2)), the divisor of the recurrence, and j + 1, as floats.
const INV_PAIR: [f64; MAX_DEGREE + 1] = {
    let mut r = [0.0; MAX_DEGREE + 1];
    let mut j = 0;
    while j <= MAX_DEGREE {
        r[j] = 1.0 / ((j + 1) * (j + 2)) as f64;
        j += 1;
    }
    r
};
const NEXT: [f64; MAX_DEGREE + 1] = {
    let mut r = [0.0; MAX_DEGREE + 1];
    let mut j = 0;
    while j <= MAX_DEGREE {
        r[j] = (j + 1) as f64;
        j += 1;
    }
    r
};

/// 1/(j + 2), as floats.
const INV_NEXT2: [f64; MAX_DEGREE + 1] = {
    let mut r = [0.0; MAX_DEGREE + 1];
    let mut j = 0;
    while j <= MAX_DEGREE {
        r[j] = 1.0 / (j + 2) as f64;
        j += 1;
    }
    r
};

/// Series of both structures out of contact, each alone on its branch:
/// x_i from x₀, ẋ₀ and the ground series `g`, to degree `n`. The recurrence
/// is taken as
///
/// ```text
/// x_{j+2} = −(c/m)/(j+2) · x_{j+1} + [−(K/m) x_j − g_j] / ((j+1)(j+2)),
/// ```
///
/// so that each coefficient waits on the one before by a single
/// multiply-add (the bracket is ready a step earlier), and the two
/// structures' chains run side by side.
pub fn free_series(
    s: &[Structure; 2],
    branch: [Branch; 2],
    x0: [f64; 2],
    v0: [f64; 2],
    g: &Series,
    n: usize,
    x: &mut [Series; 2],
) {
    let n = n.min(MAX_DEGREE);
    let mut k = [0.0; 2];
    let mut c = [0.0; 2];
    for i in 0..2 {
        let inv_m = 1.0 / s[i].mass;
        let (ki, qi) = s[i].affine(branch[i]);
        k[i] = ki * inv_m;
        c[i] = s[i].damping * inv_m;
        x[i].c[n + 1..].fill(0.0);
        x[i].degree = n;
        x[i].c[0] = x0[i];
        x[i].c[1] = v0[i];
        // The constant load enters the first step only.
        x[i].c[2] = (qi * inv_m - g.c[0] - c[i] * v0[i] - k[i] * x0[i]) * INV_PAIR[0];
    }
    // The last two coefficients of each chain ride in registers, so that
    // each step waits on one multiply-add and not on a store and a load.
    let mut last = [[x[0].c[1], x[0].c[2]], [x[1].c[1], x[1].c[2]]];
    for j in 1..n.saturating_sub(1) {
        for i in 0..2 {
            let [xj, xj1] = last[i];
            let next = next_free_coefficient(c[i], k[i], g.c[j], j, xj, xj1);
            x[i].c[j + 2] = next;
            last[i] = [xj1, next];
        }
    }
}

/// x_{j+2} of ẍ + c ẋ + k x = −g (mass divided out, j ≥ 1), from x_j and
/// x_{j+1}: the bracket of [`free_series`] first, then one multiply-add.
#[inline]
fn next_free_coefficient(c: f64, k: f64, g_j: f64, j: usize, x_j: f64, x_j1: f64) -> f64 {
    let known = (-g_j - k * x_j) * INV_PAIR[j];
    madd(-c * INV_NEXT2[j], x_j1, known)
}

/// The series of ẍ + c ẋ + k x = load − g from (x₀, ẋ₀), to degree `n`:
/// one structure of [`free_series`] with its mass divided out.
pub fn oscillator(c: f64, k: f64, load: f64, x0: f64, v0: f64, g: &Series, n: usize) -> Series {
    let n = n.min(MAX_DEGREE);
    let mut x = Series {
        degree: n,
        ..Series::default()
    };
    x.c[0] = x0;
    x.c[1] = v0;
    if n >= 2 {
        x.c[2] = (load - g.c[0] - c * v0 - k * x0) * INV_PAIR[0];
    }
    // As in free_series: the last two coefficients in registers.
    let [mut xj, mut xj1] = [x.c[1], x.c[2]];
    for j in 1..n.saturating_sub(1) {
        let next = next_free_coefficient(c, k, g.c[j], j, xj, xj1);
        x.c[j + 2] = next;
        [xj, xj1] = [xj1, next];
    }
    x
}

/// The constants of the coupled contact recurrence, order by order, for
/// one pair of structures: fixed for a run, so that each contact segment
/// spends its multiplications on the state alone.
///
/// With the mass divided out, structure i's equation gives
///
/// ```text
/// x_{i,j+2} = u_{i,j} ∓ p_{i,j} f_j,
/// u_{i,j}   = −(c/m)/(j+2) · x_{i,j+1} − (K/m)/((j+1)(j+2)) · x_{i,j}
///             − g_j/((j+1)(j+2))  [+ (Q/m)/2 at j = 0],
/// p_{i,j}   = 1/(m (j+1)(j+2)),
/// δ_{j+2}   = (u_{1,j} − u_{2,j}) − (p_{1,j} + p_{2,j}) f_j,
/// f_j       = [k̄ δ_j + h ((j+1)/2) Σ_{i=1}^{j} δ_i δ_{j+1−i}] + (c + h δ₀)(j+1) δ_{j+1},
/// ```
///
/// (the last from (δδ̇)_j = ((j+1)/2)(δ²)_{j+1}, since δδ̇ = ½ d(δ²)/dt).
/// The coefficients of x_{i,j+1}, x_{i,j} and f_j are tabulated here, the
/// second per branch (K is k or Π_α k), so that an order's products are
/// those with the state; with fused multiply-adds ([`madd`]) each is one
/// instruction, and the chain from δ_{j+1} to δ_{j+2} two.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRecurrence {
    /// −(c/m)/(j+2) of each structure.
    rate: [[f64; MAX_DEGREE + 1]; 2],
    /// −(K/m)/((j+1)(j+2)) of each structure, elastic and yielded ([`Branch::kind`]).
    spring: [[[f64; MAX_DEGREE + 1]; 2]; 2],
    /// p_{i,j} = 1/(m (j+1)(j+2)) of each structure.
    push: [[f64; MAX_DEGREE + 1]; 2],
    /// p_{1,j} + p_{2,j}.
    push_sum: [f64; MAX_DEGREE + 1],
}

impl ContactRecurrence {
    pub fn new(s: &[Structure; 2]) -> Self {
        let inv_m = s.map(|s| 1.0 / s.mass);
        let rate = [0, 1].map(|i| {
            let c = s[i].damping * inv_m[i];
            std::array::from_fn(|j| -c * INV_NEXT2[j])
        });
        let spring = [0, 1].map(|i| {
            [s[i].stiffness, s[i].alpha * s[i].stiffness].map(|k| {
                let k = k * inv_m[i];
                std::array::from_fn(|j| -k * INV_PAIR[j])
            })
        });
        let push: [[f64; MAX_DEGREE + 1]; 2] =
            inv_m.map(|inv_m| std::array::from_fn(|j| inv_m * INV_PAIR[j]));
        let push_sum = std::array::from_fn(|j| push[0][j] + push[1][j]);
        ContactRecurrence {
            rate,
            spring,
            push,
            push_sum,
        }
    }

    /// The series of both structures in contact to degree `n`, into `x`,
    /// and of the pounding force f_p (to degree n − 2), into `force`.
    #[allow(clippy::too_many_arguments)]
    pub fn series(
        &self,
        s: &[Structure; 2],
        branch: [Branch; 2],
        x0: [f64; 2],
        v0: [f64; 2],
        gap: f64,
        law: &ContactLaw,
        g: &Series,
        n: usize,
        x: &mut [Series; 2],
        force: &mut Series,
    ) {
        let n = n.min(MAX_DEGREE);
        force.c = [0.0; MAX_DEGREE + 1];
        let mut delta = [0.0; MAX_DEGREE + 1];
        for i in 0..2 {
            x[i].c[n + 1..].fill(0.0);
            x[i].degree = n;
            x[i].c[0] = x0[i];
            x[i].c[1] = v0[i];
        }
        delta[0] = x0[0] - x0[1] - gap;
        delta[1] = v0[0] - v0[1];
        // Q/m · 1/2 of each branch: the load enters order 0 alone.
        let load = [0, 1].map(|i| s[i].affine(branch[i]).1 * self.push[i][0]);
        let spring = [0, 1].map(|i| &self.spring[i][branch[i].kind()]);
        let orders = Orders {
            table: self,
            spring,
            load,
            kc: law.stiffness,
            // The coefficient of δ_{j+1} in f_j, per unit of (j + 1).
            rate_gain: law.linear_damping + law.hertz_damping * delta[0],
            half_h: law.hertz_damping * 0.5,
        };
        let [xa, xb] = x;
        if law.hertz_damping != 0.0 {
            orders.run::<true>(n, g, [xa, xb], &mut delta, force);
        } else {
            orders.run::<false>(n, g, [xa, xb], &mut delta, force);
        }
        force.degree = n.saturating_sub(2);
    }
}

/// What one contact segment's recurrence uses: the run's table, the rows of
/// the current branches, the loads, and of the law k̄, the rate gain
/// c + h δ₀ and h/2.
struct Orders<'a> {
    table: &'a ContactRecurrence,
    spring: [&'a [f64; MAX_DEGREE + 1]; 2],
    load: [f64; 2],
    kc: f64,
    rate_gain: f64,
    half_h: f64,
}

impl Orders<'_> {
    /// Orders 2 … n of x1, x2 and δ, and 0 … n − 2 of f_p, from orders 0
    /// and 1 in place; `HERTZ`: the law has the δδ̇ term.
    #[inline(always)]
    fn run<const HERTZ: bool>(
        &self,
        n: usize,
        g: &Series,
        x: [&mut Series; 2],
        delta: &mut [f64; MAX_DEGREE + 1],
        force: &mut Series,
    ) {
        let [xa, xb] = x;
        let t = self.table;
        let [sa, sb] = self.spring;
        // Orders j and j + 1 of x1, x2 and δ ride in registers, so that the
        // chain waits on multiply-adds and not on stores and loads.
        let (mut a, mut b, mut d) = ([xa.c[0], xa.c[1]], [xb.c[0], xb.c[1]], [delta[0], delta[1]]);
        for j in 0..n.saturating_sub(1).min(MAX_DEGREE - 1) {
            let next = NEXT[j];
            let mut f = self.kc * d[0];
            if HERTZ && j > 0 {
                f = madd(
                    self.half_h * next,
                    inner_square_coefficient(delta, j + 1),
                    f,
                );
            }
            let f = madd(self.rate_gain * next, d[1], f);
            let ground = INV_PAIR[j] * g.c[j];
            let mut ua = madd(t.rate[0][j], a[1], madd(sa[j], a[0], -ground));
            let mut ub = madd(t.rate[1][j], b[1], madd(sb[j], b[0], -ground));
            if j == 0 {
                ua += self.load[0];
                ub += self.load[1];
            }
            force.c[j] = f;
            let (a2, b2) = (madd(-t.push[0][j], f, ua), madd(t.push[1][j], f, ub));
            let d2 = madd(-t.push_sum[j], f, ua - ub);
            (xa.c[j + 2], xb.c[j + 2], delta[j + 2]) = (a2, b2, d2);
            (a, b, d) = ([a[1], a2], [b[1], b2], [d[1], d2]);
        }
    }
}

/// Σ_{i=1}^{m−1} δ_i δ_{m−i}: (δ²)_m without its two terms in δ₀ δ_m, by
/// its symmetry (half the products) and in four independent partial sums
/// (the additions do not wait on one another).
#[inline(always)]
fn inner_square_coefficient(delta: &[f64; MAX_DEGREE + 1], m: usize) -> f64 {
    let pairs = m.div_ceil(2);
    let mut acc = [0.0; 4];
    for i in 1..pairs {
        acc[i % 4] = madd(delta[i], delta[m - i], acc[i % 4]);
    }
    let middle = if m.is_multiple_of(2) {
        delta[m / 2] * delta[m / 2]
    } else {
        0.0
    };
    2.0 * ((acc[0] + acc[1]) + (acc[2] + acc[3])) + middle
}

/// The largest t at which the series' last two terms are below `tol` each:
/// min over q of (tol/|c_n|)^{1/n} and (tol/|c_{n−1}|)^{1/(n−1)} (the usual
/// step choice of Taylor integrators, Jorba and Zou 2005).
pub fn step_for(series: &[&Series], tol: f64) -> f64 {
    let n = series.iter().map(|s| s.degree).max().unwrap_or(0);
    if n < 2 {
        return f64::INFINITY;
    }
    // (tol/a)^{1/k} falls as a grows: the largest term of each order, and
    // one exponential of the smaller exponent ln(tol/a)/k.
    let mut exponent = f64::INFINITY;
    for k in [n - 1, n] {
        let a = series.iter().fold(0.0f64, |a, s| a.max(s.c[k].abs()));
        if a > 0.0 {
            exponent = exponent.min((tol / a).ln() / k as f64);
        }
    }
    exponent.exp()
}
