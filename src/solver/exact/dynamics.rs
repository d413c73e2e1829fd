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
    for j in 1..n.saturating_sub(1) {
        for i in 0..2 {
            let xi = &mut x[i];
            xi.c[j + 2] = next_free_coefficient(c[i], k[i], g.c[j], j, xi.c[j], xi.c[j + 1]);
        }
    }
}

/// x_{j+2} of ẍ + c ẋ + k x = −g (mass divided out, j ≥ 1), from x_j and
/// x_{j+1}: the bracket of [`free_series`] first, then one multiply-add.
#[inline]
fn next_free_coefficient(c: f64, k: f64, g_j: f64, j: usize, x_j: f64, x_j1: f64) -> f64 {
    let known = (-g_j - k * x_j) * INV_PAIR[j];
    known - c * INV_NEXT2[j] * x_j1
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
    for j in 1..n.saturating_sub(1) {
        x.c[j + 2] = next_free_coefficient(c, k, g.c[j], j, x.c[j], x.c[j + 1]);
    }
    x
}

/// The coupled contact recurrence to degree `n` of both structures, into
/// `x`, and of the pounding force f_p (to degree n − 2), into `force`.
///
/// Written so that each order waits on the last for as little as possible.
/// With R_{i,j} the right-hand side of structure i without the pounding
/// force and a_{i,j} = 1/(m_i (j+1)(j+2)),
///
/// ```text
/// x_{1,j+2} = (R_{1,j} − f_j) a_{1,j},   x_{2,j+2} = (R_{2,j} + f_j) a_{2,j},
/// δ_{j+2}   = (R_{1,j} a_{1,j} − R_{2,j} a_{2,j}) − f_j (a_{1,j} + a_{2,j}),
/// f_j       = [k̄ δ_j + h ((j+1)/2) Σ_{i=1}^{j} δ_i δ_{j+1−i}] + (c + h δ₀)(j+1) δ_{j+1},
/// ```
///
/// (the last from (δδ̇)_j = ((j+1)/2)(δ²)_{j+1}, since δδ̇ = ½ d(δ²)/dt),
/// so that from δ_{j+1} to δ_{j+2} there are two multiply-adds; the
/// convolution and the structures' own terms are off that path.
#[allow(clippy::too_many_arguments)]
pub fn contact_series(
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
    let kq = [s[0].affine(branch[0]), s[1].affine(branch[1])];
    let inv_m = [1.0 / s[0].mass, 1.0 / s[1].mass];
    let mass = [s[0].mass, s[1].mass];
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
    let (kc, cc, hc) = (law.stiffness, law.linear_damping, law.hertz_damping);
    // The coefficient of δ_{j+1} in f_j, per unit of (j + 1).
    let rate_gain = cc + hc * delta[0];
    let orders = Orders {
        k: [kq[0].0, kq[1].0],
        damping: [s[0].damping, s[1].damping],
        mass,
        inv_m,
        kc,
        rate_gain,
        half_h: hc * 0.5,
    };
    let [x0s, x1s] = x;
    if hc != 0.0 {
        orders.run::<true>(n, [kq[0].1, kq[1].1], g, [x0s, x1s], &mut delta, force);
    } else {
        orders.run::<false>(n, [kq[0].1, kq[1].1], g, [x0s, x1s], &mut delta, force);
    }
    force.degree = n.saturating_sub(2);
}

/// The constants of [`contact_series`]'s recurrence, per structure where
/// they differ: K, c, m and 1/m of each branch, and of the law k̄, the
/// rate gain c + h δ₀ and h/2.
struct Orders {
    k: [f64; 2],
    damping: [f64; 2],
    mass: [f64; 2],
    inv_m: [f64; 2],
    kc: f64,
    rate_gain: f64,
    half_h: f64,
}

impl Orders {
    /// Orders 2 … n of x1, x2 and δ, and 0 … n − 2 of f_p, from orders 0
    /// and 1 in place; `HERTZ`: the law has the δδ̇ term.
    #[inline(always)]
    fn run<const HERTZ: bool>(
        &self,
        n: usize,
        q: [f64; 2],
        g: &Series,
        x: [&mut Series; 2],
        delta: &mut [f64; MAX_DEGREE + 1],
        force: &mut Series,
    ) {
        let [xa, xb] = x;
        for j in 0..n.saturating_sub(1).min(MAX_DEGREE - 1) {
            let next = NEXT[j];
            let mut f_known = self.kc * delta[j];
            if HERTZ && j > 0 {
                f_known += self.half_h * next * inner_square_coefficient(delta, j + 1);
            }
            let a = [self.inv_m[0] * INV_PAIR[j], self.inv_m[1] * INV_PAIR[j]];
            let (l0, l1) = if j == 0 { (q[0], q[1]) } else { (0.0, 0.0) };
            let r0 = l0
                - self.damping[0] * next * xa.c[j + 1]
                - self.k[0] * xa.c[j]
                - self.mass[0] * g.c[j];
            let r1 = l1
                - self.damping[1] * next * xb.c[j + 1]
                - self.k[1] * xb.c[j]
                - self.mass[1] * g.c[j];
            let f = f_known + self.rate_gain * next * delta[j + 1];
            force.c[j] = f;
            xa.c[j + 2] = (r0 - f) * a[0];
            xb.c[j + 2] = (r1 + f) * a[1];
            delta[j + 2] = (r0 * a[0] - r1 * a[1]) - f * (a[0] + a[1]);
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
        acc[i % 4] += delta[i] * delta[m - i];
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
