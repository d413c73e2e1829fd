//! Records scaled to a target spectrum as the codes ask (SPEC §12), the
//! step between the site's hazard ([`TargetSpectrum`]) and a suite list of
//! `PATH SCALE` lines.
//!
//! **The period grid.** The rule is checked over T ∈ [lo·T1, hi·T1]
//! ([`PeriodRange`], 0.2 to 2 by default) on [`GRID_POINTS`] periods spaced
//! evenly in ln T, with T1 and the target's corner periods inside the range
//! added ([`Design::grid`]): a mean spectrum dips below a code spectrum
//! most often at its corners.
//!
//! **Each record's factor** is the least-squares fit in ln Sa over the
//! grid, as the PEER ground-motion database's tool scales a record:
//!
//! ```text
//! ln f_j = (1/K) Σ_k [ln S_T(T_k) − ln Sa_j(T_k)],
//! misfit_j = √((1/K) Σ_k [ln S_T(T_k) − ln(f_j Sa_j(T_k))]²)
//! ```
//!
//! (`misfit_j`, the ln-misfit, is the root mean square of what the factor
//! leaves; it does not depend on any common factor).
//!
//! **One common factor** c then lifts the whole suite until the code's rule
//! holds (c ≥ 1: a suite whose fitted mean already meets the rule is left
//! at its fit); every record runs at c·f_j. With the mean spectrum
//! m(T) = (1/N) Σ_j f_j Sa_j(T):
//!
//! ```text
//! c = max(1, 0.9 / min_k m(T_k)/S_T(T_k), [EC8] S_T(0) / ((1/N) Σ_j f_j PGA_j))
//! ```
//!
//! **The rules** ([`Code`]), checked on the scaled suite ([`RuleCheck`]):
//!
//! - EN 1998-1:2004 §3.2.3.1.2(4): (a) at least 3 accelerograms; (b) the
//!   mean of the zero-period spectral values (the PGAs) not below a_g·S,
//!   the target at T = 0; (c) between 0.2·T1 and 2·T1, no value of the mean
//!   5 %-damped spectrum below 90 % of the elastic spectrum;
//! - ASCE/SEI 7-16 §16.2.2 and §16.2.3 (the same in 7-22): at least 11
//!   ground motions (§16.2.2); the period range's upper bound at least
//!   twice the largest first-mode period and its lower bound at most 20 %
//!   of the smallest (§16.2.3.1), so 0.2·T1 to 2·T1 for one building; and
//!   the suite's mean spectrum not below 90 % of the target at any period
//!   of that range (§16.2.3.2, amplitude scaling). The standard takes the
//!   maximum-direction spectrum of each pair of components; one component
//!   of a pair in the plane is what shakes the buildings here.
//!
//! "Not below" is read to rounding: a ratio of 0.9·(1 − 10⁻¹²) passes, so a
//! suite scaled to sit at exactly 90 % passes however its last bit falls.

use rayon::prelude::*;
use serde::Serialize;

use crate::model::intensity::IntensityMeasure;
use crate::model::suite::SuiteMember;
use crate::model::target_spectrum::TargetSpectrum;

/// The fraction of the target the suite's mean may not fall below.
pub const FRACTION: f64 = 0.9;

/// The relative rounding a ratio may fall short of [`FRACTION`] by.
pub const ROUNDING: f64 = 1e-12;

/// Periods spaced evenly in ln T across the range (T1 and the target's
/// corners inside it are added).
pub const GRID_POINTS: usize = 50;

/// Factors outside this band are marked in the tables: a record scaled by
/// more than 4 or less than 1/4 is rarely accepted as a credible motion.
pub const FACTOR_BAND: (f64, f64) = (0.25, 4.0);

/// The code whose record rule a suite must meet.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Code {
    Ec8,
    Asce7,
}

impl Code {
    pub const NAMES: &'static str = "ec8, asce7";

    pub fn parse(text: &str) -> Option<Code> {
        match text.trim().to_ascii_lowercase().as_str() {
            "ec8" => Some(Code::Ec8),
            "asce7" => Some(Code::Asce7),
            _ => None,
        }
    }

    /// The rule of the target's own code: EC8 for an EC8 spectrum, ASCE 7
    /// otherwise (a table has no zero-period anchor for EC8's (b)).
    pub fn of(target: &TargetSpectrum) -> Code {
        match target {
            TargetSpectrum::Ec8(_) => Code::Ec8,
            _ => Code::Asce7,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Code::Ec8 => "ec8",
            Code::Asce7 => "asce7",
        }
    }

    /// The least number of records the rule asks for.
    pub fn min_records(self) -> usize {
        match self {
            Code::Ec8 => 3,
            Code::Asce7 => 11,
        }
    }

    /// The clause of the rule.
    pub fn clause(self) -> &'static str {
        match self {
            Code::Ec8 => "EN 1998-1 §3.2.3.1.2(4)",
            Code::Asce7 => "ASCE/SEI 7-16 §16.2.3.2 (7-22 alike)",
        }
    }

    /// The rule in words, for headers.
    pub fn rule(self) -> String {
        match self {
            Code::Ec8 => format!(
                "{}: at least 3 records; mean PGA at least a_g·S; mean spectrum nowhere below 90 % \
                 of the target over the range",
                self.clause()
            ),
            Code::Asce7 => format!(
                "{}: at least 11 records; mean spectrum nowhere below 90 % of the target over the range",
                self.clause()
            ),
        }
    }
}

/// The periods of the rule as multiples of T1: [low·T1, high·T1].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeriodRange {
    pub low: f64,
    pub high: f64,
}

impl Default for PeriodRange {
    /// 0.2·T1 to 2·T1: EN 1998-1 §3.2.3.1.2(4)c, and ASCE 7-16 §16.2.3.1
    /// for one building (lower bound ≤ 0.2·T1, upper bound ≥ 2·T1).
    fn default() -> Self {
        PeriodRange {
            low: 0.2,
            high: 2.0,
        }
    }
}

impl PeriodRange {
    /// `LO:HI`, multiples of T1 with 0 < LO ≤ 1 ≤ HI and LO < HI.
    pub fn parse(text: &str) -> Result<PeriodRange, DesignError> {
        let fail = |allowed: &str| DesignError::new("range", text, allowed);
        let (low, high) = text
            .split_once(':')
            .ok_or_else(|| fail("must be LO:HI, multiples of T1, e.g. 0.2:2.0"))?;
        let number = |s: &str| s.trim().parse::<f64>().ok().filter(|v| v.is_finite());
        let (Some(low), Some(high)) = (number(low), number(high)) else {
            return Err(fail(
                "must be LO:HI, two numbers, multiples of T1, e.g. 0.2:2.0",
            ));
        };
        if low <= 0.0 || low >= high {
            return Err(fail("the low end must be positive and below the high end"));
        }
        if !(low <= 1.0 && high >= 1.0) {
            return Err(fail("the range must hold T1: LO ≤ 1 ≤ HI"));
        }
        Ok(PeriodRange { low, high })
    }
}

/// An input out of range: its key (the command line's flag without `--`),
/// the value given, and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("--{key} {value}: {allowed}")]
pub struct DesignError {
    pub key: &'static str,
    pub value: String,
    pub allowed: String,
}

impl DesignError {
    pub fn new(key: &'static str, value: &str, allowed: impl Into<String>) -> DesignError {
        DesignError {
            key,
            value: crate::output::escape_controls(value.chars().take(80)),
            allowed: allowed.into(),
        }
    }
}

/// A scaling asked for: the target, the code's rule, T1 and the range.
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    pub target: TargetSpectrum,
    pub code: Code,
    /// T1 (s).
    pub period: f64,
    pub range: PeriodRange,
}

impl Design {
    /// The design, checked: T1 in (0, 10] s and the range inside the
    /// target's periods.
    pub fn new(
        target: TargetSpectrum,
        code: Code,
        period: f64,
        range: PeriodRange,
    ) -> Result<Design, DesignError> {
        let max = crate::model::intensity::MAX_PERIOD;
        if !(period > 0.0 && period <= max) {
            return Err(DesignError::new(
                "period",
                &period.to_string(),
                format!("T1 must be in (0, {max}] s"),
            ));
        }
        let (low, high) = (range.low * period, range.high * period);
        let (first, last) = target.periods();
        if low < first || high > last.min(max) {
            return Err(DesignError::new(
                "range",
                &format!("{}:{}", range.low, range.high),
                format!(
                    "at T1 = {period} s it spans {low}–{high} s, outside the target's periods \
                     {first}–{} s",
                    last.min(max)
                ),
            ));
        }
        Ok(Design {
            target,
            code,
            period,
            range,
        })
    }

    /// The periods (s) of the range: lo·T1 … hi·T1 (K points, even in ln T)
    /// and T1 itself.
    pub fn log_grid(period: f64, range: PeriodRange) -> Vec<f64> {
        let (low, high) = (range.low * period, range.high * period);
        let n = GRID_POINTS;
        let mut grid: Vec<f64> = (0..n)
            .map(|k| match k {
                0 => low,
                k if k == n - 1 => high,
                k => low * (high / low).powf(k as f64 / (n - 1) as f64),
            })
            .collect();
        grid.push(period);
        grid.sort_by(f64::total_cmp);
        grid.dedup();
        grid
    }

    /// The check's periods (s): [`Design::log_grid`] and the target's
    /// corners inside the range, ascending.
    pub fn grid(&self) -> Vec<f64> {
        let mut grid = Design::log_grid(self.period, self.range);
        let (low, high) = (grid[0], grid[grid.len() - 1]);
        grid.extend(
            self.target
                .corners()
                .into_iter()
                .filter(|t| *t > low && *t < high),
        );
        grid.sort_by(f64::total_cmp);
        grid.dedup();
        grid
    }

    /// The rule's words with the range in seconds, for headers.
    pub fn words(&self) -> String {
        format!(
            "scaled to {} at T1 = {} s by {} over {}–{} s",
            self.target.label(),
            self.period,
            self.code.clause(),
            self.range.low * self.period,
            self.range.high * self.period
        )
    }
}

/// A record's 5 %-damped Sa (g, unscaled) at each of `periods`.
pub fn record_spectrum(member: &SuiteMember, periods: &[f64]) -> Vec<f64> {
    periods
        .iter()
        .map(|&period| IntensityMeasure::Sa { period }.measure(&member.record))
        .collect()
}

/// Every member's spectrum on `periods` ([`record_spectrum`]), the
/// records in parallel.
pub fn spectra(members: &[SuiteMember], periods: &[f64]) -> Vec<Vec<f64>> {
    members
        .par_iter()
        .map(|m| record_spectrum(m, periods))
        .collect()
}

/// The least-squares factor and ln-misfit of a spectrum `sa` against
/// `target` on the same periods (module doc); `None` when a value of `sa`
/// is not positive (a silent record has no logarithm).
pub fn least_squares(target: &[f64], sa: &[f64]) -> Option<(f64, f64)> {
    if sa.iter().any(|s| !(*s > 0.0 && s.is_finite())) || sa.is_empty() {
        return None;
    }
    let residual: Vec<f64> = target
        .iter()
        .zip(sa)
        .map(|(t, s)| t.ln() - s.ln())
        .collect();
    let k = residual.len() as f64;
    let ln_factor = residual.iter().sum::<f64>() / k;
    let misfit = (residual
        .iter()
        .map(|r| (r - ln_factor).powi(2))
        .sum::<f64>()
        / k)
        .sqrt();
    Some((ln_factor.exp(), misfit))
}

/// A record that cannot be scaled: its spectrum is zero somewhere.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "record `{record}`: its Sa is 0 at T = {period} s, so no factor can scale it to the target"
)]
pub struct SilentRecord {
    pub record: String,
    pub period: f64,
}

/// One record of a scaled suite.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecordMatch {
    pub record: String,
    /// The factor it runs at: c·f_j when scaled, the list's scale when checked.
    pub factor: f64,
    /// f_j, its own least-squares factor.
    pub least_squares_factor: f64,
    /// √(mean of [ln S_T − ln(f_j Sa_j)]²) over the grid.
    pub ln_misfit: f64,
    /// factor·Sa_j(T1) / S_T(T1).
    pub ratio_at_period: f64,
    /// Whether `factor` is outside [`FACTOR_BAND`].
    pub outside_band: bool,
    /// factor·PGA_j (g).
    pub pga_g: f64,
    /// factor·Sa_j on the grid (g).
    pub spectrum: Vec<f64>,
}

/// What set the common factor.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Binding {
    /// The fitted mean met the rule: c = 1.
    Fit,
    /// The mean spectrum at this period (s) sits at 90 % of the target.
    Spectrum { period_s: f64 },
    /// The mean PGA sits at the target's zero-period value (EC8's a_g·S).
    ZeroPeriod,
    /// The list's scales, checked as they are.
    List,
}

/// The rule applied to a suite at its factors.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RuleCheck {
    pub code: Code,
    pub clause: &'static str,
    pub records: usize,
    pub min_records: usize,
    /// min over the grid of mean(T)/S_T(T), and the period (s) where.
    pub min_ratio: f64,
    pub at_period_s: f64,
    /// min_ratio/0.9 − 1: how far above the 90 % line the suite sits.
    pub margin: f64,
    /// EC8's (b): the mean PGA (g) and the target at T = 0 (a_g·S), when
    /// the rule is EC8's and the target has a value at T = 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_pga_g: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zero_period_target_g: Option<f64>,
    pub holds: bool,
    /// Why it does not hold, one item a condition; empty when it holds.
    pub failures: Vec<String>,
}

impl RuleCheck {
    /// The verdict in words: `the rule of CLAUSE holds`, or why it does not.
    pub fn verdict(&self) -> String {
        if self.holds {
            format!("the rule of {} holds", self.clause)
        } else {
            format!(
                "the rule of {} does not hold: {}",
                self.clause,
                self.failures.join("; ")
            )
        }
    }
}

/// A suite matched to a target: the grid, the target on it, each record,
/// the suite's mean and percentiles, the common factor and the rule.
#[derive(Debug, Clone, PartialEq)]
pub struct Matching {
    /// The grid (s) and the target on it (g).
    pub periods: Vec<f64>,
    pub target: Vec<f64>,
    pub records: Vec<RecordMatch>,
    /// The mean, 16th and 84th percentiles of the scaled spectra (g).
    pub mean: Vec<f64>,
    pub p16: Vec<f64>,
    pub p84: Vec<f64>,
    /// c (1 when checked).
    pub common_factor: f64,
    pub binding: Binding,
    pub check: RuleCheck,
}

/// Scales `members` to `design` (module doc): each its least-squares
/// factor, then one common factor for the rule.
pub fn scale(design: &Design, members: &[SuiteMember]) -> Result<Matching, SilentRecord> {
    let periods = design.grid();
    let sa = spectra(members, &periods);
    let target = target_on(design, &periods);
    let fits = fits(members, &periods, &target, &sa)?;
    let own: Vec<f64> = fits.iter().map(|f| f.0).collect();
    let (common, binding) = common_factor(design, members, &periods, &target, &sa, &own);
    let factors: Vec<f64> = own.iter().map(|f| common * f).collect();
    Ok(assemble(
        design, members, periods, target, &sa, &fits, &factors, common, binding,
    ))
}

/// The rule applied to `members` at their list's scales, as they are.
pub fn check(design: &Design, members: &[SuiteMember]) -> Result<Matching, SilentRecord> {
    let periods = design.grid();
    let sa = spectra(members, &periods);
    let target = target_on(design, &periods);
    let fits = fits(members, &periods, &target, &sa)?;
    let factors: Vec<f64> = members.iter().map(|m| m.scale).collect();
    Ok(assemble(
        design,
        members,
        periods,
        target,
        &sa,
        &fits,
        &factors,
        1.0,
        Binding::List,
    ))
}

/// The target on the grid (inside its periods by [`Design::new`]).
fn target_on(design: &Design, periods: &[f64]) -> Vec<f64> {
    periods
        .iter()
        .map(|&t| design.target.sa(t).unwrap_or(f64::NAN))
        .collect()
}

/// Each record's least-squares (factor, misfit), or the first silent one.
fn fits(
    members: &[SuiteMember],
    periods: &[f64],
    target: &[f64],
    sa: &[Vec<f64>],
) -> Result<Vec<(f64, f64)>, SilentRecord> {
    members
        .iter()
        .zip(sa)
        .map(|(m, s)| {
            least_squares(target, s).ok_or_else(|| SilentRecord {
                record: m.name.clone(),
                period: periods[s
                    .iter()
                    .position(|v| !v.is_finite() || *v <= 0.0)
                    .unwrap_or(0)],
            })
        })
        .collect()
}

/// The mean of the records' spectra at `factors`, period by period.
fn mean_spectrum(sa: &[Vec<f64>], factors: &[f64]) -> Vec<f64> {
    let n = sa.len() as f64;
    let k = sa.first().map_or(0, Vec::len);
    (0..k)
        .map(|i| sa.iter().zip(factors).map(|(s, f)| f * s[i]).sum::<f64>() / n)
        .collect()
}

/// The PGA of a member's record as recorded (g), as the studies measure it.
fn pga(member: &SuiteMember) -> f64 {
    IntensityMeasure::Pga.measure(&member.record)
}

/// The target at T = 0 when EC8's zero-period condition applies.
fn zero_period_target(design: &Design) -> Option<f64> {
    (design.code == Code::Ec8)
        .then(|| design.target.sa(0.0))
        .flatten()
}

/// c of the module doc, and what set it.
fn common_factor(
    design: &Design,
    members: &[SuiteMember],
    periods: &[f64],
    target: &[f64],
    sa: &[Vec<f64>],
    own: &[f64],
) -> (f64, Binding) {
    let mean = mean_spectrum(sa, own);
    let (k, ratio) = min_ratio(&mean, target);
    let mut best = (1.0, Binding::Fit);
    let spectral = FRACTION / ratio;
    if spectral > best.0 {
        best = (
            spectral,
            Binding::Spectrum {
                period_s: periods[k],
            },
        );
    }
    if let Some(anchor) = zero_period_target(design) {
        let mean_pga = members
            .iter()
            .zip(own)
            .map(|(m, f)| f * pga(m))
            .sum::<f64>()
            / members.len() as f64;
        if anchor / mean_pga > best.0 {
            best = (anchor / mean_pga, Binding::ZeroPeriod);
        }
    }
    best
}

/// The index and value of min_k mean_k/target_k.
fn min_ratio(mean: &[f64], target: &[f64]) -> (usize, f64) {
    mean.iter()
        .zip(target)
        .map(|(m, t)| m / t)
        .enumerate()
        .fold(
            (0, f64::INFINITY),
            |best, (k, r)| if r < best.1 { (k, r) } else { best },
        )
}

#[allow(clippy::too_many_arguments)]
fn assemble(
    design: &Design,
    members: &[SuiteMember],
    periods: Vec<f64>,
    target: Vec<f64>,
    sa: &[Vec<f64>],
    fits: &[(f64, f64)],
    factors: &[f64],
    common: f64,
    binding: Binding,
) -> Matching {
    let at_t1 = periods
        .iter()
        .position(|&t| t == design.period)
        .unwrap_or(0);
    let records: Vec<RecordMatch> = members
        .iter()
        .zip(sa)
        .zip(fits.iter().zip(factors))
        .map(|((m, s), (&(own, misfit), &factor))| RecordMatch {
            record: m.name.clone(),
            factor,
            least_squares_factor: own,
            ln_misfit: misfit,
            ratio_at_period: factor * s[at_t1] / target[at_t1],
            outside_band: !(FACTOR_BAND.0..=FACTOR_BAND.1).contains(&factor),
            pga_g: factor * pga(m),
            spectrum: s.iter().map(|v| factor * v).collect(),
        })
        .collect();
    let mean = mean_spectrum(sa, factors);
    let percentile = |q: f64| -> Vec<f64> {
        (0..periods.len())
            .map(|k| {
                let mut column: Vec<f64> = records.iter().map(|r| r.spectrum[k]).collect();
                column.sort_by(f64::total_cmp);
                super::statistics::quantile(&column, q)
            })
            .collect()
    };
    let (p16, p84) = (percentile(0.16), percentile(0.84));
    let check = rule_check(design, &periods, &target, &mean, &records);
    Matching {
        periods,
        target,
        records,
        mean,
        p16,
        p84,
        common_factor: common,
        binding,
        check,
    }
}

/// The rule of `design.code` on the scaled suite.
fn rule_check(
    design: &Design,
    periods: &[f64],
    target: &[f64],
    mean: &[f64],
    records: &[RecordMatch],
) -> RuleCheck {
    let code = design.code;
    let (k, ratio) = min_ratio(mean, target);
    let mut failures = Vec::new();
    if records.len() < code.min_records() {
        failures.push(format!(
            "{} records; the rule asks for at least {}",
            records.len(),
            code.min_records()
        ));
    }
    let floor = FRACTION * (1.0 - ROUNDING);
    if ratio < floor {
        failures.push(format!(
            "the mean spectrum is {:.4} of the target at T = {} s, below {FRACTION}",
            ratio, periods[k]
        ));
    }
    let anchor = zero_period_target(design);
    let mean_pga =
        anchor.map(|_| records.iter().map(|r| r.pga_g).sum::<f64>() / records.len() as f64);
    if let (Some(anchor), Some(mean_pga)) = (anchor, mean_pga)
        && mean_pga < anchor * (1.0 - ROUNDING)
    {
        failures.push(format!(
            "the mean PGA {mean_pga:.4} g is below a_g·S = {anchor:.4} g"
        ));
    }
    RuleCheck {
        code,
        clause: code.clause(),
        records: records.len(),
        min_records: code.min_records(),
        min_ratio: ratio,
        at_period_s: periods[k],
        margin: ratio / FRACTION - 1.0,
        mean_pga_g: mean_pga,
        zero_period_target_g: anchor,
        holds: failures.is_empty(),
        failures,
    }
}
