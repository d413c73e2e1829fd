//! Polynomials on [0, s]: values, bounds, the first instant one turns
//! positive (an event) and the largest magnitude (a peak). A polynomial is
//! its coefficients, lowest order first: p(s) = Σ c_k s^k.

/// Sample points per interval when scanning for sign changes: the Taylor
/// steps hold less than one radian of the fastest mode, so a polynomial
/// on one has at most a few turning points.
const SCAN: usize = 16;

#[inline]
pub fn eval(c: &[f64], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * s + x)
}

/// p'(s).
#[inline]
pub fn eval_derivative(c: &[f64], s: f64) -> f64 {
    let mut acc = 0.0;
    for k in (1..c.len()).rev() {
        acc = acc * s + k as f64 * c[k];
    }
    acc
}

/// Σ |c_k| s^k ≥ max over [0, s] of |p|.
#[inline]
pub fn bound(c: &[f64], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * s + x.abs())
}

/// p''(s).
#[inline]
pub fn eval_second_derivative(c: &[f64], s: f64) -> f64 {
    let mut acc = 0.0;
    for k in (2..c.len()).rev() {
        acc = acc * s + (k * (k - 1)) as f64 * c[k];
    }
    acc
}

/// A root of `f` bracketed by f(lo) ≤ 0 < f(hi), by Newton's method kept
/// inside the bracket (a bisection where a Newton step would leave it);
/// returns a point where f > 0, within a few ulps of the root, so that an
/// event is applied on its far side.
fn bisect(f: impl Fn(f64) -> f64, df: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let mut x = 0.5 * (lo + hi);
    for _ in 0..200 {
        let fx = f(x);
        if fx > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        if hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(f64::MIN_POSITIVE) {
            break;
        }
        let d = df(x);
        let newton = x - fx / d;
        if d != 0.0 && (newton - x).abs() <= 4.0 * f64::EPSILON * x.abs() {
            // Converged: the first point past the root where f > 0.
            let mut y = newton.max(lo);
            for _ in 0..16 {
                if y >= hi {
                    break;
                }
                if f(y) > 0.0 {
                    return y;
                }
                y = y.next_up();
            }
        }
        x = if d != 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if x == lo || x == hi {
            x = 0.5 * (lo + hi);
            if x == lo || x == hi {
                break;
            }
        }
    }
    hi
}

/// The first s in [0, end] where p turns positive, if any: scanned on
/// [`SCAN`] points, with a positive hump between two non-positive points
/// caught by the sign change of p' between them. A p already positive at 0
/// counts at 0 if rising there; if falling (it was just switched on, at its
/// own root, and rounding put it a hair above zero) only after it has been
/// non-positive again.
pub fn first_rise(c: &[f64], end: f64) -> Option<f64> {
    // p(s) ≤ c₀ + Σ_{k≥1} |c_k| s^k: when that stays ≤ 0, nothing to scan.
    if c[0] <= 0.0 && c[0] + bound(&c[1..], end) * end <= 0.0 {
        return None;
    }
    let f = |s: f64| eval(c, s);
    let df = |s: f64| eval_derivative(c, s);
    let ddf = |s: f64| eval_second_derivative(c, s);
    let mut lo = 0.0;
    let mut f_lo = f(0.0);
    let mut d_lo = df(0.0);
    if f_lo > 0.0 && d_lo > 0.0 {
        return Some(0.0);
    }
    let mut armed = f_lo <= 0.0;
    for i in 1..=SCAN {
        let s = end * i as f64 / SCAN as f64;
        let fs = f(s);
        let ds = df(s);
        if armed {
            if fs > 0.0 {
                return Some(bisect(f, df, lo, s));
            }
            if d_lo > 0.0 && ds < 0.0 {
                // A maximum inside (lo, s): is it above zero?
                let top = bisect(|x| -df(x), |x| -ddf(x), lo, s);
                if f(top) > 0.0 {
                    return Some(bisect(f, df, lo, top));
                }
            }
        } else if fs <= 0.0 {
            armed = true;
        }
        lo = s;
        f_lo = fs;
        d_lo = ds;
    }
    let _ = f_lo;
    None
}

/// max |p| over [0, end]: the ends and every turning point, found where p'
/// changes sign on [`SCAN`] points.
pub fn max_abs(c: &[f64], end: f64) -> f64 {
    let f = |s: f64| eval(c, s);
    let df = |s: f64| eval_derivative(c, s);
    let ddf = |s: f64| eval_second_derivative(c, s);
    let mut best = f(0.0).abs().max(f(end).abs());
    let mut lo = 0.0;
    let mut d_lo = df(0.0);
    for i in 1..=SCAN {
        let s = end * i as f64 / SCAN as f64;
        let ds = df(s);
        if (d_lo > 0.0) != (ds > 0.0) && d_lo != 0.0 {
            let root = if d_lo > 0.0 {
                bisect(|x| -df(x), |x| -ddf(x), lo, s)
            } else {
                bisect(df, ddf, lo, s)
            };
            best = best.max(f(root).abs());
        }
        lo = s;
        d_lo = ds;
    }
    best
}

/// max p over [0, end] (signed), by the same scan.
pub fn max(c: &[f64], end: f64) -> f64 {
    let f = |s: f64| eval(c, s);
    let df = |s: f64| eval_derivative(c, s);
    let ddf = |s: f64| eval_second_derivative(c, s);
    let mut best = f(0.0).max(f(end));
    let mut lo = 0.0;
    let mut d_lo = df(0.0);
    for i in 1..=SCAN {
        let s = end * i as f64 / SCAN as f64;
        let ds = df(s);
        if d_lo > 0.0 && ds <= 0.0 {
            best = best.max(f(bisect(|x| -df(x), |x| -ddf(x), lo, s)));
        }
        lo = s;
        d_lo = ds;
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_roots_and_extremes() {
        // p = (s − 0.3)(s − 0.7) = 0.21 − s + s²: negative on (0.3, 0.7).
        let c = [0.21, -1.0, 1.0];
        let neg = [-0.21, 1.0, -1.0];
        assert!((first_rise(&neg, 1.0).unwrap() - 0.3).abs() < 1e-15);
        assert!((max_abs(&c, 1.0) - 0.21).abs() < 1e-15);
        assert!((max(&neg, 1.0) - 0.04).abs() < 1e-15);
        assert!(first_rise(&c[..1].iter().map(|x| -x).collect::<Vec<_>>(), 1.0).is_none());
    }
}
