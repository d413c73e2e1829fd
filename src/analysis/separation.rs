//! The separation at a probability over a suite of records (SPEC §12), and
//! how the code rules of SPEC §11 fare on the suite.
//!
//! Each record j gives, from its run without contact, the exact minimum gap
//! d_j = Π_d,min,j of SPEC §11 and the separate peaks u1_j, u2_j
//! ([`RecordGap`]). All lengths of one suite must share a unit: metres for a
//! physical suite, whose records each have their own Π scale l_e = a_p/ω_p²
//! (SPEC §8, §12); Π-units only when every record shares one a_p and ω_p.
//! The frequencies enter the rules only through ω1/ω2, so Π_ω or rad/s will
//! do. Each d_j is a number ≥ 0: 0 for a record whose structures never
//! approach (no gap needed); ∞ is allowed (a record that would pound at any
//! gap) and, like 0, counted apart from the lognormal fit.
//!
//! - The probabilities asked for, from the command line
//!   ([`parse_probabilities`]).
//! - The gap that prevents pounding with probability p
//!   ([`gap_at_probability`]): with d_(1) ≤ … ≤ d_(N) sorted,
//!   ```text
//!   d(p) = d_(⌈pN⌉),   0 < p < 1.
//!   ```
//! - The probability of pounding at a gap d ([`probability_of_pounding`]):
//!   the fraction of records with d_j > d.
//! - A lognormal fit of the d_j ([`lognormal_fit`]): median exp(mean ln d),
//!   dispersion the standard deviation of ln d (N − 1 in the denominator),
//!   over the d_j that are finite and > 0; zeros and infinities are counted
//!   and left out of the logarithms (SPEC §12's rule for statistics).
//! - The code rules on the suite ([`study`]): a rule R "holds" for record j
//!   when R_j ≥ d_j; the study reports the fraction of records for which each
//!   rule holds, beside the rule applied to the median peaks, the probability
//!   of pounding at that value and the requested probabilities at which it
//!   suffices (it is at least d(p)).

use serde::Serialize;

use super::gap::CodeRules;
use super::subject::Subject;
pub use super::subject::demands::JointRecord;
use super::suite::SuiteRun;
use crate::model::params::echo;
use crate::numerics::normal;
use crate::output::report::{float_or_inf, option_float_or_inf};

/// One record's result from its run without contact (module docs for units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RecordGap {
    /// Π_d,min (or in m): the smallest gap at which this record never pounds.
    pub min_gap: f64,
    /// Peak displacements Π_u1, Π_u2 of the separate structures (same unit).
    pub peak_left: f64,
    pub peak_right: f64,
    /// Frequencies Π_ω1, Π_ω2 (or in rad/s) and damping ratio, for DDC's ρ.
    pub omega1: f64,
    pub omega2: f64,
    pub damping: f64,
}

impl RecordGap {
    /// A suite record's minimum gap and separate peaks in m, from its run
    /// without contact (frequencies in Π_ω: only their ratio enters).
    pub fn of(run: &SuiteRun) -> RecordGap {
        RecordGap {
            min_gap: run.min_gap_m(),
            peak_left: run.free_si.left.peak_displacement_m,
            peak_right: run.free_si.right.peak_displacement_m,
            omega1: run.params.omega1,
            omega2: run.params.omega2,
            damping: run.params.damping,
        }
    }
}

/// The rank ⌈pN⌉ in 1 ..= N. When pN is an integer written in decimal
/// (p = 0.7, N = 10), p·N may round to 7.000000000000001 and its ceiling
/// would be 8: the product is within ε·pN of the exact one (p carries a
/// relative error ≤ ε/2, the product another ε/2), so a pN within 4ε·pN of
/// an integer is that integer.
fn rank(p: f64, n: usize) -> usize {
    let product = p * n as f64;
    let nearest = product.round();
    let k = if (product - nearest).abs() <= 4.0 * f64::EPSILON * product {
        nearest
    } else {
        product.ceil()
    };
    (k as usize).clamp(1, n)
}

/// A list of probabilities that cannot be read, as one line naming the
/// flag, the item and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct ProbabilityError(pub String);

/// Reads the probabilities given to `flag` as a comma-separated list, each
/// strictly between 0 and 1 (`0.5,0.9,0.99`), in the order given.
pub fn parse_probabilities(flag: &str, text: &str) -> Result<Vec<f64>, ProbabilityError> {
    text.split(',')
        .map(|item| {
            item.trim()
                .parse::<f64>()
                .ok()
                .filter(|p| *p > 0.0 && *p < 1.0)
                .ok_or_else(|| {
                    ProbabilityError(format!(
                        "{flag} `{}`: must be a probability strictly between 0 and 1, e.g. 0.5,0.9,0.99",
                        echo::text(item.trim())
                    ))
                })
        })
        .collect()
}

/// Refuses minimum gaps that are NaN or negative (a caller's bug).
fn check(values: &[f64]) {
    assert!(
        values.iter().all(|&d| d >= 0.0),
        "minimum gaps must be numbers ≥ 0"
    );
}

/// `values` sorted ascending.
fn sorted(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    v
}

/// The gap that prevents pounding with probability p, d_(⌈pN⌉) of the
/// sorted minimum gaps (SPEC §12): the p·N records with the smallest d_j do
/// not pound at it. p = 0.9, N = 10 gives the 9th value.
///
/// # Panics
/// If `values` is empty, a value is NaN or negative, or p is not in (0, 1).
pub fn gap_at_probability(values: &[f64], p: f64) -> f64 {
    assert!(!values.is_empty(), "no records");
    assert!(p > 0.0 && p < 1.0, "probability {p} is not in (0, 1)");
    check(values);
    sorted(values.iter().copied())[rank(p, values.len()) - 1]
}

/// The probability of pounding at gap `gap`: the fraction of records with
/// d_j > gap (SPEC §12). 0 for no records.
pub fn probability_of_pounding(values: &[f64], gap: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.iter().filter(|&&d| d > gap).count() as f64 / values.len() as f64
}

/// A lognormal fit of the minimum gaps (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LognormalFit {
    /// exp(μ), μ the mean of ln d_j over the fitted values.
    pub median: f64,
    /// β, the standard deviation of ln d_j (N − 1 in the denominator).
    pub dispersion: f64,
    /// How many values are in the fit (finite and > 0).
    pub fitted: usize,
    /// How many were 0 (the structures never approach: no gap needed) and ∞.
    pub zeros: usize,
    pub infinite: usize,
}

/// The lognormal fit of `values`, or `None` with fewer than two values
/// finite and > 0 (the dispersion needs two).
///
/// # Panics
/// If a value is NaN or negative.
pub fn lognormal_fit(values: &[f64]) -> Option<LognormalFit> {
    check(values);
    let logs: Vec<f64> = values
        .iter()
        .copied()
        .filter(|d| d.is_finite() && *d > 0.0)
        .map(f64::ln)
        .collect();
    let zeros = values.iter().filter(|&&d| d == 0.0).count();
    let infinite = values.iter().filter(|d| d.is_infinite()).count();
    let n = logs.len();
    if n < 2 {
        return None;
    }
    let mean = logs.iter().sum::<f64>() / n as f64;
    let variance = logs.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    Some(LognormalFit {
        median: mean.exp(),
        dispersion: variance.sqrt(),
        fitted: n,
        zeros,
        infinite,
    })
}

impl LognormalFit {
    /// The fitted probability that a record needs no more than `gap`,
    /// P(d_j ≤ d) = (Z + F·Φ((ln d − μ)/β))/N, the inverse of
    /// [`LognormalFit::gap_at_probability`]: Z/N at d = 0, (Z + F)/N as d → ∞.
    pub fn probability(&self, gap: f64) -> f64 {
        let (zeros, fitted) = (self.zeros as f64, self.fitted as f64);
        let total = zeros + fitted + self.infinite as f64;
        let within = if gap <= 0.0 {
            0.0
        } else if gap.is_infinite() {
            1.0
        } else {
            normal::cdf((gap / self.median).ln() / self.dispersion)
        };
        (zeros + fitted * within) / total
    }

    /// The gap that prevents pounding with probability p under the fit:
    ///
    /// ```text
    /// d(p) = exp(μ + β Φ⁻¹(p))
    /// ```
    ///
    /// when every value was fitted. Zeros and infinities keep their share of
    /// the suite: with N = Z + F + I (zeros, fitted, infinite),
    /// P(d_j ≤ d) = (Z + F·Φ((ln d − μ)/β))/N, so d(p) = 0 for p ≤ Z/N,
    /// ∞ for p > (Z + F)/N, and exp(μ + β Φ⁻¹((pN − Z)/F)) between.
    pub fn gap_at_probability(&self, p: f64) -> f64 {
        let (zeros, fitted) = (self.zeros as f64, self.fitted as f64);
        let total = zeros + fitted + self.infinite as f64;
        let within = (p * total - zeros) / fitted;
        if within <= 0.0 {
            0.0
        } else if within >= 1.0 {
            f64::INFINITY
        } else {
            (self.median.ln() + self.dispersion * normal::quantile(within)).exp()
        }
    }
}

/// The gap at one requested probability.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GapAtProbability {
    pub probability: f64,
    /// d_(⌈pN⌉) of the records ([`gap_at_probability`]).
    #[serde(serialize_with = "float_or_inf")]
    pub empirical: f64,
    /// The lognormal fit's d(p), if there is a fit.
    #[serde(serialize_with = "option_float_or_inf")]
    pub lognormal: Option<f64>,
}

/// One code rule over the suite.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RuleOnSuite {
    /// `ABS`, `SRSS` or `DDC`.
    pub rule: &'static str,
    /// The fraction of records j for which R_j ≥ d_j.
    pub holds: f64,
    /// The rule applied to the median peaks.
    pub at_median_peaks: f64,
    /// The probability of pounding at that gap.
    pub pounding_probability: f64,
    /// The requested probabilities p at which `at_median_peaks` ≥ d(p).
    pub sufficient_at: Vec<f64>,
}

/// The separation study of a suite (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeparationStudy {
    pub records: usize,
    /// Records whose minimum gap is 0: they pound at no gap ≥ 0.
    pub zero_gaps: usize,
    /// Median of the minimum gaps (linear between order statistics, SPEC §12).
    #[serde(serialize_with = "float_or_inf")]
    pub median_min_gap: f64,
    /// The gap at each requested probability, in the order asked.
    pub at_probability: Vec<GapAtProbability>,
    pub lognormal: Option<LognormalFit>,
    /// Medians of the separate peaks u1, u2 over the records.
    pub median_peaks: [f64; 2],
    /// The double-difference rule's ρ for the median peaks: the median of
    /// the records' ρ (all equal in a physical suite, where ω1/ω2 and ξ are
    /// the buildings').
    pub correlation: f64,
    /// ABS, SRSS, DDC.
    pub rules: Vec<RuleOnSuite>,
}

/// The median of `values`, linear between the two middle order statistics
/// (numpy's default, SPEC §12). NaN when there are none.
pub fn median(values: impl Iterator<Item = f64>) -> f64 {
    super::statistics::quantile(&sorted(values), 0.5)
}

impl From<&RecordGap> for JointRecord {
    fn from(r: &RecordGap) -> JointRecord {
        JointRecord {
            min_gap: r.min_gap,
            rules: CodeRules::of(r.peak_left, r.peak_right, r.omega1, r.omega2, r.damping),
            floors: vec![(r.peak_left, r.peak_right)],
        }
    }
}

/// The separation study of `records` at `probabilities` (module docs).
///
/// # Panics
/// If `records` is empty, a minimum gap is NaN or negative, or a
/// probability is not in (0, 1).
pub fn study(records: &[RecordGap], probabilities: &[f64]) -> SeparationStudy {
    let records: Vec<JointRecord> = records.iter().map(JointRecord::from).collect();
    joint_study(&records, probabilities)
}

/// The separation study of one joint over the records (module docs), the
/// one path of the pair and of every joint of a row (SPEC §12, §13).
///
/// The double-difference rule's ρ on the median peaks is the median of the
/// records' ρ (all equal where ω1/ω2 and ξ are the buildings'). The rules on
/// the median peaks are, for each paired floor, the rules on that floor's
/// median separate peaks over the records, the largest over the floors; the
/// study's `median_peaks` are those of the floor where ABS on them is
/// largest (the pair's one floor: its medians).
///
/// # Panics
/// As [`study`].
pub fn joint_study(records: &[JointRecord], probabilities: &[f64]) -> SeparationStudy {
    assert!(!records.is_empty(), "no records");
    let gaps: Vec<f64> = records.iter().map(|r| r.min_gap).collect();
    let record_rules: Vec<CodeRules> = records.iter().map(|r| r.rules).collect();
    let rho = median(record_rules.iter().map(|r| r.correlation));
    let mut at_median = CodeRules::with_correlation(0.0, 0.0, rho);
    let mut median_peaks = [0.0; 2];
    for floor in 0..records[0].floors.len() {
        let ua = median(records.iter().map(|r| r.floors[floor].0));
        let ub = median(records.iter().map(|r| r.floors[floor].1));
        let rules = CodeRules::with_correlation(ua, ub, rho);
        if rules.absolute_sum > at_median.absolute_sum {
            median_peaks = [ua, ub];
        }
        at_median = CodeRules {
            absolute_sum: at_median.absolute_sum.max(rules.absolute_sum),
            srss: at_median.srss.max(rules.srss),
            double_difference: at_median.double_difference.max(rules.double_difference),
            ..at_median
        };
    }
    study_of(&gaps, &record_rules, at_median, median_peaks, probabilities)
}

/// One joint's separation over a suite: the pair's one joint, or a joint
/// of a row.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointSeparation {
    pub left: String,
    pub right: String,
    /// The joint's gap at rest in the preset (m; may be infinite).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub gap_m: f64,
    /// The fraction of records whose minimum gap exceeds it.
    pub pounding_probability_at_gap: f64,
    pub study: SeparationStudy,
}

/// The separation at each of `probabilities` (each in (0, 1)) for every
/// joint of `subject` over the suite's `runs` ([`joint_study`]), each
/// record's gaps from [`Subject::joint_records`].
///
/// # Panics
/// If `runs` is empty or a probability is not in (0, 1).
pub fn joint_separations<S: Subject>(
    subject: &S,
    runs: &[S::Run],
    probabilities: &[f64],
) -> Vec<JointSeparation> {
    let mut records: Vec<Vec<JointRecord>> = Vec::new();
    for run in runs {
        for (j, record) in subject.joint_records(run).into_iter().enumerate() {
            if records.len() <= j {
                records.push(Vec::with_capacity(runs.len()));
            }
            records[j].push(record);
        }
    }
    subject
        .joints()
        .into_iter()
        .zip(records)
        .map(|(joint, records)| {
            let gaps: Vec<f64> = records.iter().map(|r| r.min_gap).collect();
            JointSeparation {
                pounding_probability_at_gap: probability_of_pounding(&gaps, joint.gap_m),
                study: joint_study(&records, probabilities),
                left: joint.left,
                right: joint.right,
                gap_m: joint.gap_m,
            }
        })
        .collect()
}

/// The separation study from each record's minimum gap `gaps[j]` and code
/// rules `record_rules[j]`, with the rules `at_median` on the median peaks
/// `median_peaks` (module docs), as [`joint_study`] finds them.
///
/// # Panics
/// As [`study`]; and if the two lists differ in length.
pub fn study_of(
    gaps: &[f64],
    record_rules: &[CodeRules],
    at_median: CodeRules,
    median_peaks: [f64; 2],
    probabilities: &[f64],
) -> SeparationStudy {
    assert!(!gaps.is_empty(), "no records");
    assert_eq!(
        gaps.len(),
        record_rules.len(),
        "one set of rules per record"
    );
    check(gaps);
    let lognormal = lognormal_fit(gaps);
    let at_probability: Vec<GapAtProbability> = probabilities
        .iter()
        .map(|&p| GapAtProbability {
            probability: p,
            empirical: gap_at_probability(gaps, p),
            lognormal: lognormal.map(|fit| fit.gap_at_probability(p)),
        })
        .collect();
    let rules = at_median
        .named()
        .into_iter()
        .enumerate()
        .map(|(i, (rule, value))| {
            let holds = gaps
                .iter()
                .zip(record_rules)
                .filter(|(d, rules)| rules.named()[i].1 >= **d)
                .count();
            RuleOnSuite {
                rule,
                holds: holds as f64 / gaps.len() as f64,
                at_median_peaks: value,
                pounding_probability: probability_of_pounding(gaps, value),
                sufficient_at: at_probability
                    .iter()
                    .filter(|g| value >= g.empirical)
                    .map(|g| g.probability)
                    .collect(),
            }
        })
        .collect();
    SeparationStudy {
        records: gaps.len(),
        zero_gaps: gaps.iter().filter(|&&d| d == 0.0).count(),
        median_min_gap: median(gaps.iter().copied()),
        at_probability,
        lognormal,
        median_peaks,
        correlation: at_median.correlation,
        rules,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEN: [f64; 10] = [0.5, 0.1, 0.9, 0.3, 0.7, 0.2, 1.0, 0.4, 0.8, 0.6];

    #[test]
    fn rank_is_the_ceiling_of_p_n_even_where_p_n_rounds_up() {
        assert_eq!(rank(0.9, 10), 9);
        assert_eq!(rank(0.7, 10), 7, "0.7·10 = {}", 0.7 * 10.0);
        assert_eq!(rank(0.91, 10), 10);
        assert_eq!(rank(0.5, 3), 2);
        assert_eq!(rank(0.01, 10), 1);
        assert_eq!(rank(0.95, 20), 19);
        assert_eq!(rank(0.999_999, 10), 10);
        // Every p = i/N, however it rounds, is the i-th; just above it, the next.
        for n in 1..=300 {
            for i in 1..n {
                let p = i as f64 / n as f64;
                assert_eq!(rank(p, n), i, "p = {i}/{n}");
                assert_eq!(rank(p + 1e-9, n), i + 1, "p = {i}/{n} + 1e-9");
            }
        }
        for (decimal, n, want) in [(0.1, 30, 3), (0.3, 10, 3), (0.6, 5, 3), (0.35, 20, 7)] {
            assert_eq!(rank(decimal, n), want, "{decimal}·{n}");
        }
    }

    #[test]
    fn parses_probabilities() {
        assert_eq!(
            parse_probabilities("--probability", "0.5, 0.9,0.99").unwrap(),
            [0.5, 0.9, 0.99]
        );
        assert_eq!(
            parse_probabilities("--probability", "0.5,1")
                .unwrap_err()
                .to_string(),
            "--probability `1`: must be a probability strictly between 0 and 1, e.g. 0.5,0.9,0.99"
        );
        for bad in ["", "0", "-0.1", "nan", "0.5,", "half"] {
            assert!(parse_probabilities("--p", bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn gap_at_probability_is_the_order_statistic() {
        assert_eq!(gap_at_probability(&TEN, 0.9), 0.9);
        assert_eq!(gap_at_probability(&TEN, 0.7), 0.7);
        assert_eq!(gap_at_probability(&TEN, 0.85), 0.9);
        assert_eq!(gap_at_probability(&TEN, 0.05), 0.1);
        assert_eq!(gap_at_probability(&TEN, 0.999), 1.0);
        assert_eq!(gap_at_probability(&[2.5], 0.5), 2.5);
        assert_eq!(
            gap_at_probability(&[0.0, 3.0, f64::INFINITY], 0.9),
            f64::INFINITY
        );
    }

    #[test]
    fn probability_of_pounding_counts_strictly_larger_gaps() {
        assert_eq!(probability_of_pounding(&TEN, 0.9), 0.1);
        assert_eq!(probability_of_pounding(&TEN, 0.85), 0.2);
        assert_eq!(probability_of_pounding(&TEN, 0.0), 1.0);
        assert_eq!(probability_of_pounding(&TEN, 1.0), 0.0);
        // The gap at p leaves at most 1 − p pounding.
        for p in [0.1, 0.5, 0.9] {
            assert!(probability_of_pounding(&TEN, gap_at_probability(&TEN, p)) <= 1.0 - p + 1e-15);
        }
    }

    /// ln of 1, e, e², e³ is 0, 1, 2, 3: mean 1.5, variance 5/3 (N − 1).
    #[test]
    fn lognormal_fit_by_hand() {
        let e = std::f64::consts::E;
        let values = [1.0, e, e * e, e * e * e, 0.0, 0.0];
        let fit = lognormal_fit(&values).unwrap();
        assert_eq!((fit.fitted, fit.zeros, fit.infinite), (4, 2, 0));
        assert!((fit.median - 1.5f64.exp()).abs() < 1e-14);
        assert!((fit.dispersion - (5.0f64 / 3.0).sqrt()).abs() < 1e-14);
        // p ≤ Z/N = 1/3 needs no gap; above, the fitted part's quantile.
        assert_eq!(fit.gap_at_probability(0.3), 0.0);
        let p = 0.9;
        let within = (p * 6.0 - 2.0) / 4.0;
        let want = (1.5 + (5.0f64 / 3.0).sqrt() * normal::quantile(within)).exp();
        assert!((fit.gap_at_probability(p) - want).abs() < 1e-12 * want);
        // Without zeros: exp(μ + β Φ⁻¹(p)); Φ⁻¹(0.975) = 1.959963984540054.
        let fit = lognormal_fit(&values[..4]).unwrap();
        let want = (1.5 + (5.0f64 / 3.0).sqrt() * 1.959_963_984_540_054).exp();
        assert!((fit.gap_at_probability(0.975) - want).abs() < 1e-12 * want);
        assert!((fit.gap_at_probability(0.5) - fit.median).abs() < 1e-15 * fit.median);
        // An infinite gap takes the top share.
        let fit = lognormal_fit(&[1.0, e, e * e, f64::INFINITY]).unwrap();
        assert_eq!(fit.infinite, 1);
        assert_eq!(fit.gap_at_probability(0.8), f64::INFINITY);
        assert!(lognormal_fit(&[0.0, 2.0]).is_none());
    }

    /// The fitted probability inverts the fitted gap, zeros and infinities
    /// keeping their shares.
    #[test]
    fn lognormal_probability_inverts_the_gap() {
        let e = std::f64::consts::E;
        let fit = lognormal_fit(&[0.0, 1.0, e, e * e, e * e * e, f64::INFINITY]).unwrap();
        assert_eq!(fit.probability(0.0), 1.0 / 6.0);
        assert_eq!(fit.probability(f64::INFINITY), 5.0 / 6.0);
        for p in [0.2, 0.5, 0.7, 0.8] {
            let d = fit.gap_at_probability(p);
            assert!((fit.probability(d) - p).abs() < 1e-12, "p = {p}");
        }
    }

    #[test]
    fn medians_interpolate_between_the_middle_values() {
        let median_of = |v: &[f64]| median(v.iter().copied());
        assert_eq!(median_of(&[4.0, 1.0, 2.0]), 2.0);
        assert_eq!(median_of(&[8.0, 1.0, 4.0, 2.0]), 3.0);
        assert_eq!(median_of(&[1.0, f64::INFINITY]), f64::INFINITY);
        assert_eq!(median_of(&[f64::INFINITY, f64::INFINITY]), f64::INFINITY);
        assert!(median_of(&[]).is_nan());
    }

    /// Four records by hand, with equal frequencies (ρ = 1, DDC = |u1 − u2|).
    #[test]
    fn study_by_hand() {
        let record = |min_gap, peak_left, peak_right| RecordGap {
            min_gap,
            peak_left,
            peak_right,
            omega1: 2.0,
            omega2: 2.0,
            damping: 0.05,
        };
        // Peaks (3, 4): ABS 7, SRSS 5, DDC 1, and so on.
        let records = [
            record(4.5, 3.0, 4.0),
            record(6.0, 6.0, 8.0),
            record(1.0, 1.0, 1.0),
            record(0.0, 2.0, 2.0),
        ];
        let s = study(&records, &[0.5, 0.75, 0.9]);
        assert_eq!((s.records, s.zero_gaps), (4, 1));
        assert_eq!(s.median_min_gap, 2.75);
        let empirical: Vec<f64> = s.at_probability.iter().map(|g| g.empirical).collect();
        assert_eq!(empirical, [1.0, 4.5, 6.0]);
        assert_eq!(s.median_peaks, [2.5, 3.0]);
        assert_eq!(s.correlation, 1.0);
        let by_name = |name| s.rules.iter().find(|r| r.rule == name).unwrap();
        // ABS 7, 14, 2, 4 ≥ 4.5, 6, 1, 0: all hold. At the median peaks 5.5.
        let abs = by_name("ABS");
        assert_eq!((abs.holds, abs.at_median_peaks), (1.0, 5.5));
        assert_eq!(abs.pounding_probability, 0.25);
        assert_eq!(abs.sufficient_at, [0.5, 0.75]);
        // SRSS 5, 10, √2, 2√2: all hold; at the medians √(2.5² + 3²) = 3.905.
        let srss = by_name("SRSS");
        assert_eq!(srss.holds, 1.0);
        assert!((srss.at_median_peaks - 2.5f64.hypot(3.0)).abs() < 1e-15);
        assert_eq!(srss.pounding_probability, 0.5);
        assert_eq!(srss.sufficient_at, [0.5]);
        // DDC 1, 2, 0, 0 against 4.5, 6, 1, 0: holds for the last only.
        let ddc = by_name("DDC");
        assert_eq!(ddc.holds, 0.25);
        assert!((ddc.at_median_peaks - 0.5).abs() < 1e-15);
        assert_eq!(ddc.pounding_probability, 0.75);
        assert!(ddc.sufficient_at.is_empty());
        // Lognormal over 1, 4.5, 6 (the zero counted apart).
        let fit = s.lognormal.unwrap();
        assert_eq!((fit.fitted, fit.zeros), (3, 1));
        assert!((fit.median - 27f64.powf(1.0 / 3.0)).abs() < 1e-13);
        assert_eq!(
            s.at_probability[0].lognormal,
            Some(fit.gap_at_probability(0.5))
        );
    }

    #[test]
    fn serializes_infinite_gaps_as_inf() {
        let g = GapAtProbability {
            probability: 0.9,
            empirical: f64::INFINITY,
            lognormal: None,
        };
        assert_eq!(
            serde_json::to_string(&g).unwrap(),
            r#"{"probability":0.9,"empirical":"inf","lognormal":null}"#
        );
    }
}
