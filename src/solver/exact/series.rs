//! Truncated Taylor series of one quantity about the start of a segment,
//!
//! ```text
//! q(t) = Σ_{k=0}^{n} c_k t^k,   t = τ − τ₀ ∈ [0, h],
//! ```
//!
//! with the operations the event-driven method needs: value and derivatives
//! by Horner's rule, and bounds of the tail used to prove that an event
//! function keeps its sign on a sub-interval.

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
    #[inline]
    pub fn value(&self, t: f64) -> f64 {
        let mut acc = self.c[self.degree];
        for k in (0..self.degree).rev() {
            acc = acc * t + self.c[k];
        }
        acc
    }

    /// (q(t), q'(t)).
    #[inline]
    pub fn value_slope(&self, t: f64) -> (f64, f64) {
        let n = self.degree;
        let mut q = self.c[n];
        let mut dq = 0.0;
        for k in (0..n).rev() {
            dq = dq * t + q;
            q = q * t + self.c[k];
        }
        (q, dq)
    }

    /// (q(t), q'(t), q''(t)/2), by Horner's rule on the shifted coefficients.
    #[inline]
    pub fn derivatives(&self, t: f64) -> [f64; 3] {
        let n = self.degree;
        let (mut d0, mut d1, mut d2) = (self.c[n], 0.0, 0.0);
        for k in (0..n).rev() {
            d2 = d2 * t + d1;
            d1 = d1 * t + d0;
            d0 = d0 * t + self.c[k];
        }
        [d0, d1, d2]
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
        // M by Horner in r from the top: Σ_{k≥3} C(k,3) |c_k| r^{k−3}.
        let r = t.abs() + w;
        let mut m = 0.0;
        for k in (3..=n).rev() {
            m = m * r + BINOMIAL_3[k] * self.c[k].abs();
        }
        [d0, d1, d2, m]
    }

    /// Σ_{k≥1} |c_k| h^k: how far q can move from q(0) on [0, h], so that
    /// |q(t) − c₀| ≤ this for every t ∈ [0, h].
    #[inline]
    pub fn swing(&self, h: f64) -> f64 {
        let mut sum = 0.0;
        let mut hk = 1.0;
        for c in &self.c[1..=self.degree] {
            hk *= h;
            sum += c.abs() * hk;
        }
        sum
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
        // h^{k−1}, at h¹ for k = 2.
        let mut hk1 = h;
        let mut swing = self.c[1].abs() * h;
        let mut rate_swing = 0.0;
        let terms = self.c[2..=n].iter().zip(&ORDER[2..=n]);
        for (dk, (c, k)) in d.c[1..n].iter_mut().zip(terms) {
            *dk = k * c;
            rate_swing += dk.abs() * hk1;
            hk1 *= h;
            swing += c.abs() * hk1;
        }
        (swing, rate_swing)
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

    #[test]
    fn horner_and_slope_of_exp() {
        let s = exp_series(20);
        let (q, dq) = s.value_slope(0.7);
        assert!((q - 0.7f64.exp()).abs() < 1e-15);
        assert!((dq - 0.7f64.exp()).abs() < 1e-14);
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
