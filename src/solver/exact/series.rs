//! Truncated Taylor series of one quantity about the start of a segment,
//!
//! ```text
//! q(t) = Σ_{k=0}^{n} c_k t^k,   t = τ − τ₀ ∈ [0, h],
//! ```
//!
//! with the operations the event-driven method needs: value and derivatives
//! by Horner's rule, and bounds of the tail used to prove that an event
//! function keeps its sign on a sub-interval.

use crate::numerics::madd;

/// Largest degree kept. Series are truncated where their terms fall below
/// round-off over the segment (see [`super::dynamics`]), well before this.
pub const MAX_DEGREE: usize = 20;

/// C(k, 3) = k(k−1)(k−2)/6.
const BINOMIAL_3: [f64; MAX_DEGREE + 1] = {
    let mut b = [0.0; MAX_DEGREE + 1];
    let mut k = 3;
    while k <= MAX_DEGREE {
        b[k] = (k * (k - 1) * (k - 2) / 6) as f64;
        k += 1;
    }
    b
};

/// k as a float, for the derivative's coefficients k c_k (a load, not a
/// conversion, in the loops).
const ORDER: [f64; MAX_DEGREE + 1] = {
    let mut f = [0.0; MAX_DEGREE + 1];
    let mut k = 0;
    while k <= MAX_DEGREE {
        f[k] = k as f64;
        k += 1;
    }
    f
};

/// Coefficients c₀ … c_n of one Taylor series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Series {
    pub c: [f64; MAX_DEGREE + 1],
    /// Degree n: c_k = 0 for k > n.
    pub degree: usize,
}

impl Default for Series {
    fn default() -> Self {
        Series {
            c: [0.0; MAX_DEGREE + 1],
            degree: 0,
        }
    }
}

impl Series {
    /// q(t).
    ///
    /// By Horner's rule in u = t² on the even and odd coefficients,
    /// q(t) = E(u) + t·O(u): two independent chains of half the length,
    /// since evaluations wait on the latency of one multiply-add per term.
    #[inline]
    pub fn value(&self, t: f64) -> f64 {
        split_sum(self.degree.min(MAX_DEGREE), t, |k| self.c[k])
    }

    /// (q(t), q'(t)), with q = E(u) + t·O(u) as in [`Series::value`]:
    /// q' = O + 2u·O' + 2t·E' (primes in u).
    #[inline]
    pub fn value_slope(&self, t: f64) -> (f64, f64) {
        let u = t * t;
        let [[e, de], [o, d_o]] = halves::<2>(self.degree.min(MAX_DEGREE), u, |k| self.c[k]);
        (e + t * o, o + 2.0 * (u * d_o + t * de))
    }

    /// q at each of N points, by Horner's rule with the N chains side by
    /// side (one vector operation per term where N fills a register).
    #[inline(always)]
    pub fn values_at<const N: usize>(&self, t: &[f64; N]) -> [f64; N] {
        let n = self.degree.min(MAX_DEGREE);
        let mut acc = [self.c[n]; N];
        for k in (0..n).rev() {
            for j in 0..N {
                acc[j] = madd(acc[j], t[j], self.c[k]);
            }
        }
        acc
    }

    /// (q(t), q'(t), q''(t)/2), with q = E(u) + t·O(u) as in
    /// [`Series::value`]: q''/2 = E' + 4u·E''/2 + 3t·O' + 4tu·O''/2.
    #[inline]
    pub fn derivatives(&self, t: f64) -> [f64; 3] {
        let u = t * t;
        let [[e, de, e2], [o, d_o, o2]] =
            halves::<3>(self.degree.min(MAX_DEGREE), u, |k| self.c[k]);
        [
            e + t * o,
            o + 2.0 * (u * d_o + t * de),
            de + 3.0 * t * d_o + 4.0 * u * (e2 + t * o2),
        ]
    }

    /// (q, q', q''/2, bound of |q'''|/6 on [t, t + w]): the cubic majorant
    /// q(t + s) ≤ q + q' s + (q''/2) s² + M s³ for s ∈ [0, w], with
    /// M = Σ_k C(k,3) |c_k| (|t| + w)^{k−3} (Taylor's theorem with the
    /// remainder bounded term by term; t ≥ 0 on a segment).
    #[inline]
    pub fn cubic_majorant(&self, t: f64, w: f64) -> [f64; 4] {
        let n = self.degree;
        let [d0, d1, d2] = if t == 0.0 {
            [self.c[0], self.c[1], self.c[2]]
        } else {
            // Derivatives at t via the shifted coefficients d_j = Σ_k C(k,j) c_k t^{k−j}, j ≤ 2.
            self.derivatives(t)
        };
        // M = Σ_{j≥0} C(j+3,3) |c_{j+3}| r^j.
        let m = if n < 3 {
            0.0
        } else {
            split_sum(n - 3, t.abs() + w, |j| {
                BINOMIAL_3[j + 3] * self.c[j + 3].abs()
            })
        };
        [d0, d1, d2, m]
    }

    /// Σ_{k≥1} |c_k| h^k: how far q can move from q(0) on [0, h], so that
    /// |q(t) − c₀| ≤ this for every t ∈ [0, h].
    #[inline]
    pub fn swing(&self, h: f64) -> f64 {
        match self.degree {
            0 => 0.0,
            n => h * split_sum(n - 1, h, |j| self.c[j + 1].abs()),
        }
    }

    /// Writes the series of q' into `d` and returns the swings of q and of
    /// q' over [0, h] ([`Series::swing`] of each), in one pass over the
    /// coefficients: Σ_{k≥1} |c_k| h^k and Σ_{k≥2} k |c_k| h^{k−1}. Written
    /// in place, as segments are rebuilt in storage they reuse.
    #[inline]
    pub fn derivative_and_swings_into(&self, h: f64, d: &mut Series) -> (f64, f64) {
        let n = self.degree;
        d.c[n.saturating_sub(1)..].fill(0.0);
        d.degree = n.saturating_sub(1);
        if n == 0 {
            return (0.0, 0.0);
        }
        d.c[0] = self.c[1];
        // The terms in pairs (k, k + 1), with h^{k−1}, h^k and h^{k+1}
        // each carried on by h²: the sums and powers wait on one operation
        // per pair instead of per term.
        let h2 = h * h;
        let mut powers = [h, h2, h2 * h];
        let mut swing = [self.c[1].abs() * h, 0.0];
        let mut rate_swing = [0.0; 2];
        let mut k = 2;
        while k < n {
            let (a, b) = (ORDER[k] * self.c[k], ORDER[k + 1] * self.c[k + 1]);
            d.c[k - 1] = a;
            d.c[k] = b;
            rate_swing[0] = madd(a.abs(), powers[0], rate_swing[0]);
            rate_swing[1] = madd(b.abs(), powers[1], rate_swing[1]);
            swing[0] = madd(self.c[k].abs(), powers[1], swing[0]);
            swing[1] = madd(self.c[k + 1].abs(), powers[2], swing[1]);
            powers = powers.map(|p| p * h2);
            k += 2;
        }
        if k == n {
            let a = ORDER[k] * self.c[k];
            d.c[k - 1] = a;
            rate_swing[0] = madd(a.abs(), powers[0], rate_swing[0]);
            swing[0] = madd(self.c[k].abs(), powers[1], swing[0]);
        }
        (swing[0] + swing[1], rate_swing[0] + rate_swing[1])
    }

    /// The series of q' (degree n − 1).
    pub fn derivative(&self) -> Series {
        let mut d = Series::default();
        if self.degree == 0 {
            return d;
        }
        d.degree = self.degree - 1;
        let n = self.degree;
        for (dk, (c, k)) in d.c[..n]
            .iter_mut()
            .zip(self.c[1..=n].iter().zip(&ORDER[1..=n]))
        {
            *dk = k * c;
        }
        d
    }

    /// q − a (a constant shift), for event functions such as δ = x1 − x2 − Π_d.
    pub fn shifted(&self, a: f64) -> Series {
        let mut s = *self;
        s.c[0] -= a;
        s
    }

    /// σ·q.
    pub fn scaled(&self, sigma: f64) -> Series {
        let mut s = *self;
        for k in 0..=s.degree {
            s.c[k] *= sigma;
        }
        s
    }

    /// q − r.
    pub fn minus(&self, r: &Series) -> Series {
        let mut s = Series {
            degree: self.degree.max(r.degree),
            ..Series::default()
        };
        for k in 0..=s.degree {
            s.c[k] = self.c[k] - r.c[k];
        }
        s
    }
}

/// Σ_{j=0}^{top} a(j) x^j by Horner's rule in x² on the even and the odd
/// terms, E(x²) + x·O(x²): two chains of half the length (evaluations wait
/// on the latency of one multiply-add per term, not on their number).
#[inline(always)]
fn split_sum(top: usize, x: f64, a: impl Fn(usize) -> f64) -> f64 {
    let [even, odd] = halves::<1>(top, x * x, a);
    even[0] + x * odd[0]
}

/// The even part E(u) = Σ a(2i) u^i and the odd part O(u) = Σ a(2i+1) u^i
/// of Σ_{j=0}^{top} a(j) x^j (u = x²), each with its first D − 1
/// derivatives in u (the second halved), by Horner's rule with the two
/// chains interleaved.
#[inline(always)]
fn halves<const D: usize>(top: usize, u: f64, a: impl Fn(usize) -> f64) -> [[f64; D]; 2] {
    let mut even = [0.0; D];
    let mut odd = [0.0; D];
    let step = |acc: &mut [f64; D], c: f64| {
        for d in (1..D).rev() {
            acc[d] = madd(acc[d], u, acc[d - 1]);
        }
        acc[0] = madd(acc[0], u, c);
    };
    // The top term starts its chain; then both chains step together.
    let mut i = top / 2;
    if top % 2 == 1 {
        step(&mut odd, a(top));
    }
    loop {
        step(&mut even, a(2 * i));
        if i == 0 {
            break;
        }
        i -= 1;
        step(&mut odd, a(2 * i + 1));
    }
    [even, odd]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exp_series(n: usize) -> Series {
        let mut s = Series {
            degree: n,
            ..Default::default()
        };
        let mut f = 1.0;
        for k in 0..=n {
            s.c[k] = 1.0 / f;
            f *= (k + 1) as f64;
        }
        s
    }

    #[test]
    fn derivative_and_swings_agree_with_each_alone() {
        let mut s = exp_series(20);
        s.c[3] = -s.c[3];
        let mut d = Series::default();
        let (swing, rate_swing) = s.derivative_and_swings_into(0.6, &mut d);
        assert_eq!(d, s.derivative());
        assert!((swing - s.swing(0.6)).abs() <= 1e-15 * swing);
        assert!((rate_swing - d.swing(0.6)).abs() <= 1e-15 * rate_swing);
    }

    /// The eight-point evaluation agrees with [`Series::value`] at each
    /// point, and with e^t, to a few units in the last place.
    #[test]
    fn values_at_several_points_agree_with_one_at_a_time() {
        let s = exp_series(20);
        let t = [0.0, 0.05, 0.1, 0.2, 0.35, 0.5, 0.8, 1.0];
        let many = s.values_at(&t);
        for (j, &tj) in t.iter().enumerate() {
            assert!(
                (many[j] - s.value(tj)).abs() <= 4.0 * f64::EPSILON * many[j],
                "{tj}"
            );
            assert!(
                (many[j] - tj.exp()).abs() <= 4.0 * f64::EPSILON * many[j],
                "{tj}"
            );
        }
    }

    /// The split evaluation agrees with plain Horner's rule, for every degree
    /// and both parities, to a few units in the last place.
    #[test]
    fn split_evaluation_agrees_with_horner() {
        for n in 0..=MAX_DEGREE {
            let mut s = Series {
                degree: n,
                ..Default::default()
            };
            for k in 0..=n {
                s.c[k] = ((k * 7 + 3) % 11) as f64 / 11.0 - 0.4;
            }
            for t in [0.0, 0.3, -0.45, 0.8] {
                let (mut h0, mut h1, mut h2) = (s.c[n], 0.0, 0.0);
                for k in (0..n).rev() {
                    h2 = h2 * t + h1;
                    h1 = h1 * t + h0;
                    h0 = h0 * t + s.c[k];
                }
                let [d0, d1, d2] = s.derivatives(t);
                let (v, dv) = s.value_slope(t);
                let scale = 1e-14 * (1.0 + h0.abs() + h1.abs() + h2.abs());
                assert!((s.value(t) - h0).abs() < scale, "value n={n} t={t}");
                assert!(
                    (v - h0).abs() < scale && (dv - h1).abs() < scale,
                    "slope n={n} t={t}"
                );
                assert!(
                    (d0 - h0).abs() < scale && (d1 - h1).abs() < scale && (d2 - h2).abs() < scale,
                    "derivatives n={n} t={t}: {d2} {h2}"
                );
            }
        }
    }

    #[test]
    fn horner_and_slope_of_exp() {
        let s = exp_series(20);
        let (q, dq) = s.value_slope(0.7);
        assert!((q - 0.7f64.exp()).abs() < 1e-15);
        assert!((dq - 0.7f64.exp()).abs() < 1e-14);
    }

    /// The split sum of the third-derivative bound is the plain one, for every degree.
    #[test]
    fn cubic_majorant_bound_agrees_with_the_plain_sum() {
        for n in 0..=MAX_DEGREE {
            let mut s = exp_series(n);
            s.c[n / 2] = -s.c[n / 2];
            let (t, w) = (0.3, 0.4);
            let r: f64 = t + w;
            let plain: f64 = (3..=n)
                .map(|k| BINOMIAL_3[k] * s.c[k].abs() * r.powi(k as i32 - 3))
                .sum();
            let m = s.cubic_majorant(t, w)[3];
            assert!(
                (m - plain).abs() <= 1e-15 * plain.max(1.0),
                "n={n}: {m} {plain}"
            );
        }
    }

    #[test]
    fn cubic_majorant_bounds_exp() {
        let s = exp_series(20);
        let [d0, d1, d2, m] = s.cubic_majorant(0.2, 0.5);
        assert!((d0 - 0.2f64.exp()).abs() < 1e-15 && (d1 - d0).abs() < 1e-14);
        assert!((2.0 * d2 - d0).abs() < 1e-14);
        // |q'''|/6 ≤ e^{0.7}/6 on [0.2, 0.7]; the bound must hold and not be loose by much.
        assert!(m >= 0.7f64.exp() / 6.0 - 1e-15 && m < 0.7f64.exp() / 6.0 * 1.01);
        for i in 0..=10 {
            let sv = 0.05 * i as f64;
            let bound = d0 + d1 * sv + d2 * sv * sv + m * sv * sv * sv;
            assert!(s.value(0.2 + sv) <= bound + 1e-15);
        }
    }
}
