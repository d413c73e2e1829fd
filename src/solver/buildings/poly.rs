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

/// Refines a root of `f` bracketed by f(lo) ≤ 0 < f(hi); returns the end
/// where f > 0, so that an event is applied on its far side.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
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
    let f = |s: f64| eval(c, s);
    let df = |s: f64| eval_derivative(c, s);
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
                return Some(bisect(f, lo, s));
            }
            if d_lo > 0.0 && ds < 0.0 {
                // A maximum inside (lo, s): is it above zero?
                let top = bisect(|x| -df(x), lo, s);
                if f(top) > 0.0 {
                    return Some(bisect(f, lo, top));
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
    let mut best = f(0.0).abs().max(f(end).abs());
    let mut lo = 0.0;
    let mut d_lo = df(0.0);
    for i in 1..=SCAN {
        let s = end * i as f64 / SCAN as f64;
        let ds = df(s);
        if (d_lo > 0.0) != (ds > 0.0) && d_lo != 0.0 {
            let root = if d_lo > 0.0 {
                bisect(|x| -df(x), lo, s)
            } else {
                bisect(df, lo, s)
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
    let mut best = f(0.0).max(f(end));
    let mut lo = 0.0;
    let mut d_lo = df(0.0);
    for i in 1..=SCAN {
        let s = end * i as f64 / SCAN as f64;
        let ds = df(s);
        if d_lo > 0.0 && ds <= 0.0 {
            best = best.max(f(bisect(|x| -df(x), lo, s)));
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
