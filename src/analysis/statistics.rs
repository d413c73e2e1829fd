//! Statistics of a demand over the records of a suite (SPEC §12).
//!
//! For N values d_1 … d_N of one demand (one per record):
//!
//! - the median and the 16th and 84th percentiles are those of the empirical
//!   distribution, with linear interpolation between order statistics
//!   (numpy's default, "type 7"): with the values sorted, d_(1) ≤ … ≤ d_(N),
//!   the q-quantile is read at the fractional rank h = (N − 1) q (0-based),
//!   `d_(⌊h⌋) + (h − ⌊h⌋)(d_(⌊h⌋+1) − d_(⌊h⌋))`;
//! - the lognormal dispersion β is the standard deviation of ln d_j with
//!   N − 1 in the denominator, over the values that have a logarithm:
//!   values of 0 or ∞ are counted in the quantiles but excluded from the
//!   logarithms, and the summary says how many were.
//!
//! A value that is not a number (a demand a run did not compute) takes part
//! in nothing and is counted as missing.

use serde::Serialize;

use crate::output::report::float_or_inf;

/// The q-quantile (0 ≤ q ≤ 1) of `sorted` (ascending, no NaN) by linear
/// interpolation between order statistics (numpy's default). NaN for no values.
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let n = sorted.len();
    if n == 0 {
        return f64::NAN;
    }
    let h = (n - 1) as f64 * q.clamp(0.0, 1.0);
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(n - 1);
    let (a, b) = (sorted[lo], sorted[hi]);
    // Equal neighbours (two infinities among them) need no interpolation,
    // and ∞ − ∞ would make it NaN.
    if a == b || h == lo as f64 {
        return a;
    }
    a + (h - lo as f64) * (b - a)
}

/// The summary of one demand over a suite (SPEC §12).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Summary {
    /// 50th percentile.
    #[serde(serialize_with = "float_or_inf")]
    pub median: f64,
    /// 16th percentile.
    #[serde(serialize_with = "float_or_inf")]
    pub p16: f64,
    /// 84th percentile.
    #[serde(serialize_with = "float_or_inf")]
    pub p84: f64,
    /// Standard deviation of the natural logarithms (N − 1 in the
    /// denominator) over the positive finite values; NaN with fewer than two.
    #[serde(serialize_with = "float_or_inf")]
    pub dispersion: f64,
    /// Values that entered the quantiles (every one but the missing).
    pub count: usize,
    /// Values of 0, counted in the quantiles, excluded from the logarithms.
    pub zeros: usize,
    /// Infinite values, counted in the quantiles, excluded from the logarithms.
    pub infinite: usize,
    /// Values that were not computed (NaN), excluded from everything.
    pub missing: usize,
}

impl Summary {
    /// The summary of `values` (one per record; any order).
    pub fn of(values: &[f64]) -> Summary {
        let mut sorted: Vec<f64> = values.iter().copied().filter(|v| !v.is_nan()).collect();
        sorted.sort_by(f64::total_cmp);
        let logs: Vec<f64> = sorted
            .iter()
            .filter(|v| **v > 0.0 && v.is_finite())
            .map(|v| v.ln())
            .collect();
        Summary {
            median: quantile(&sorted, 0.5),
            p16: quantile(&sorted, 0.16),
            p84: quantile(&sorted, 0.84),
            dispersion: sample_std(&logs),
            count: sorted.len(),
            zeros: sorted.iter().filter(|v| **v == 0.0).count(),
            infinite: sorted.iter().filter(|v| v.is_infinite()).count(),
            missing: values.len() - sorted.len(),
        }
    }

    /// Values left out of the logarithms, in words for a table ("" for none).
    pub fn excluded(&self) -> String {
        let mut parts = Vec::new();
        if self.zeros > 0 {
            parts.push(format!("{} zero", self.zeros));
        }
        if self.infinite > 0 {
            parts.push(format!("{} inf", self.infinite));
        }
        if self.missing > 0 {
            parts.push(format!("{} missing", self.missing));
        }
        parts.join(", ")
    }
}

/// The sample standard deviation (N − 1 in the denominator); NaN for fewer
/// than two values.
pub fn sample_std(values: &[f64]) -> f64 {
    let n = values.len();
    if n < 2 {
        return f64::NAN;
    }
    let mean = values.iter().sum::<f64>() / n as f64;
    let ss: f64 = values.iter().map(|v| (v - mean) * (v - mean)).sum();
    (ss / (n - 1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// numpy.percentile(values, q) for the same values, by hand.
    #[test]
    fn quantiles_interpolate_as_numpy() {
        let v = [3.0, 1.0, 4.0, 1.5, 9.0, 2.6];
        let s = Summary::of(&v);
        // Sorted: 1, 1.5, 2.6, 3, 4, 9. h = 5q.
        // Median: h = 2.5 → 2.6 + 0.5·0.4 = 2.8.
        assert!((s.median - 2.8).abs() < 1e-15);
        // 16th: h = 0.8 → 1 + 0.8·0.5 = 1.4.
        assert!((s.p16 - 1.4).abs() < 1e-15);
        // 84th: h = 4.2 → 4 + 0.2·5 = 5.
        assert!((s.p84 - 5.0).abs() < 1e-14);
        assert_eq!(s.count, 6);
        // β: std of the logs, N − 1 = 5.
        let logs: Vec<f64> = v.iter().map(|x: &f64| x.ln()).collect();
        let mean = logs.iter().sum::<f64>() / 6.0;
        let var = logs.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / 5.0;
        assert!((s.dispersion - var.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn one_value_is_its_own_quantiles_without_dispersion() {
        let s = Summary::of(&[0.7]);
        assert_eq!((s.median, s.p16, s.p84), (0.7, 0.7, 0.7));
        assert!(s.dispersion.is_nan());
    }

    #[test]
    fn zeros_and_infinities_count_in_quantiles_not_in_logarithms() {
        let s = Summary::of(&[0.0, 2.0, f64::INFINITY, 8.0, f64::INFINITY, f64::NAN]);
        assert_eq!((s.count, s.zeros, s.infinite, s.missing), (5, 1, 2, 1));
        // Sorted: 0, 2, 8, inf, inf; median is the third.
        assert_eq!(s.median, 8.0);
        assert_eq!(s.p84, f64::INFINITY);
        // Logs of 2 and 8 only: |ln 8 − ln 2| / √2.
        assert!((s.dispersion - (8f64 / 2.0).ln() / 2f64.sqrt()).abs() < 1e-15);
        assert_eq!(s.excluded(), "1 zero, 2 inf, 1 missing");
    }

    #[test]
    fn quantile_of_nothing_is_nan() {
        assert!(quantile(&[], 0.5).is_nan());
    }
}
