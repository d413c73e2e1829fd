//! Lognormal fragility by maximum likelihood (SPEC §12, after Baker 2015).
//!
//! At intensity levels x_1 … x_L (in g, any positive measure: PGA or Sa(T)),
//! n_l records were run and k_l of them exceeded a limit state
//! ([`super::limit_state`]). The fragility
//!
//! ```text
//! P(exceed | IM = x) = Φ(ln(x/θ)/β)                      (θ > 0 median, β > 0 dispersion)
//! ```
//!
//! is the (θ, β) that maximizes the binomial likelihood
//!
//! ```text
//! L(θ, β) = Π_l C(n_l, k_l) p_l^{k_l} (1 − p_l)^{n_l − k_l},   p_l = Φ(ln(x_l/θ)/β).
//! ```
//!
//! # How it is maximized
//!
//! With t = ln x, the fragility is the probit model p = Φ(a + b t), b = 1/β,
//! a = −ln θ/β, and
//!
//! ```text
//! ℓ(a, b) = Σ_l k_l ln Φ(η_l) + (n_l − k_l) ln Φ(−η_l) + ln C(n_l, k_l),   η_l = a + b t_l,
//! ∂ℓ/∂η_l = k_l λ(η_l) − (n_l − k_l) λ(−η_l),
//! −∂²ℓ/∂η_l² = k_l κ(η_l) + (n_l − k_l) κ(−η_l) > 0,
//! ```
//!
//! (λ, κ the slopes of ln Φ, [`normal::ln_cdf_slopes`]). ln Φ and ln(1 − Φ) are
//! strictly concave, so ℓ is strictly concave in (a, b) once two distinct
//! levels were run: its maximum, where it exists, is the only stationary
//! point, and Newton's method with a backtracking (Armijo) line search on the
//! exact gradient and Hessian reaches it from any start. It starts from the
//! least-squares line through Φ⁻¹((k_l + ½)/(n_l + 1)) against t_l (weights
//! n_l), with t centred on its weighted mean so that the two unknowns are
//! nearly uncorrelated. Once a Newton step moves each unknown by less than
//! 1e-6 of its size, ℓ can no longer tell the iterates apart (it changes by
//! about the square of that, relative), so steps are taken whole; they stop
//! at 1e-12, or where they no longer shrink, the rounding floor of the
//! gradient (5 to 15 iterations in the tests). ln Φ is exact far into both
//! tails ([`normal::ln_cdf`]), so a poor start, or a level where p_l is
//! 1e-300, cannot make the likelihood infinite.
//!
//! # When there is no fit
//!
//! The maximum exists (Albert and Anderson 1984) only if some level where a
//! record exceeded lies above some level where a record did not. Each other
//! case is reported as what it is, never as a fit; [`fit`] checks them in
//! this order:
//! - [`Fragility::TooFewRecords`]: no level ran two records or more (a suite
//!   of one record runs it once per level; SPEC §12 fits no fragility from it);
//! - [`Fragility::NeverExceeded`], [`Fragility::AlwaysExceeded`];
//! - [`Fragility::OneLevel`]: every run at one intensity, outcomes mixed: any
//!   curve through that one fraction fits it as well;
//! - [`Fragility::Separated`]: no record exceeded below some level and all
//!   did above it; the likelihood grows without bound as β → 0 with θ
//!   between the two levels named (SPEC §12);
//! - [`Fragility::NotIncreasing`]: the fractions fall, or do not rise, with
//!   intensity: over β > 0 the likelihood is largest as β → ∞, one
//!   probability at every level.
//!
//! # Use
//!
//! Count, at each level, the runs whose demands exceed a limit state, then
//! fit. A fitted θ outside the levels run is an extrapolation.
//!
//! ```
//! use pounding::analysis::fragility::{self, Fragility, LevelCount};
//! use pounding::analysis::limit_state::LimitParser;
//! use pounding::analysis::subject::demands::{BuildingDemand, JointDemand};
//!
//! let limit = &LimitParser::pair().ductility("left:2").unwrap()[0];
//! // The suite runner's demands: one run per record at each level (two here).
//! let structure = |ductility, acceleration_g| BuildingDemand {
//!     peak_drift_m: 0.0,
//!     drift_ratio: None,
//!     ductility,
//!     acceleration_g,
//!     collapsed: false,
//!     cut_short: false,
//! };
//! let joint = JointDemand { impacts: 1, max_force_kn: 120.0, min_gap_m: 0.0 };
//! // The right structure is elastic (μ = ∞), the left one yields at 0.1.
//! let run = |peak_left: f64| ([structure(peak_left / 0.1, 0.4), structure(f64::INFINITY, 0.2)], [joint]);
//! let suite = [
//!     (0.2, [run(0.1), run(0.25)]),
//!     (0.4, [run(0.15), run(0.3)]),
//!     (0.8, [run(0.5), run(0.3)]),
//! ];
//! let counts: Vec<LevelCount> = suite
//!     .iter()
//!     .map(|(level, runs)| LevelCount {
//!         level: *level,
//!         runs: runs.len(),
//!         exceeded: runs.iter().filter(|(b, j)| limit.exceeded(b, j)).count(),
//!     })
//!     .collect();
//! let Fragility::Fitted { theta, beta, .. } = fragility::fit(&counts) else {
//!     panic!("no fit");
//! };
//! let half = fragility::probability(theta, theta, beta); // 0.5 at the median
//! assert!(theta > 0.2 && theta < 0.8 && half == 0.5);
//! ```

use serde::Serialize;

use crate::model::params::echo;
use crate::numerics::normal;

/// The counts at one intensity level.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LevelCount {
    /// x_l, the intensity measure the records were scaled to, in g (> 0).
    pub level: f64,
    /// n_l, the records run at this level (a level with none is ignored).
    pub runs: usize,
    /// k_l ≤ n_l, the runs that exceeded the limit state.
    pub exceeded: usize,
}

/// The fitted fragility, or why there is none (module docs). Serialized
/// with its kind in `outcome` (`fitted`, `too_few_records`, …).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "outcome", rename_all = "snake_case")]
pub enum Fragility {
    /// The maximum-likelihood lognormal: median θ (g) and dispersion β, with
    /// the log-likelihood ln L at the maximum, binomial coefficients included.
    /// `extrapolated` when θ lies outside the levels run (below the lowest
    /// or above the highest): the median is then where the curve is only
    /// drawn on, not where any record was run, and every output says so.
    Fitted {
        theta: f64,
        beta: f64,
        log_likelihood: f64,
        extrapolated: bool,
    },
    /// No level ran two records or more.
    TooFewRecords,
    /// No run exceeded the limit state.
    NeverExceeded,
    /// Every run at every level exceeded it.
    AlwaysExceeded,
    /// Every run was at one `level` (g), where a `fraction` of them exceeded.
    OneLevel { level: f64, fraction: f64 },
    /// At every level below `above` no run exceeded, and at every level
    /// above `below` every run did (below ≤ above, both in g): the limit
    /// state is crossed between them, and the fit tends to β → 0 there.
    /// `below == above` when one level holds both outcomes: θ → that level.
    Separated { below: f64, above: f64 },
    /// The fractions do not rise with intensity (the maximum over all
    /// (a, b) has b ≤ 0, or η moves by less than 1e-9 over the levels): the
    /// best fit over β > 0 is the β → ∞ limit, the pooled `fraction` Σk/Σn
    /// at every level.
    NotIncreasing { fraction: f64 },
}

/// Levels to run where a fit found the outcomes [`Fragility::Separated`]:
/// `count` levels spaced evenly in ln x strictly between the highest level
/// where every run survived and the lowest where every run exceeded. The
/// MLE of SPEC §12 needs mixed outcomes at two levels or more to pin β > 0;
/// the limit state is crossed inside that bracket, so that is where the
/// new levels can find them. The bracket is read from `levels` (the levels
/// run, ascending): below `below` and above `above` when a single level
/// holds both outcomes, or the half and the double of it at the ends of
/// the levels. Empty for any other outcome. Levels are rounded to 12
/// significant digits, as `--levels` rounds its grid.
pub fn bridging_levels(levels: &[f64], fit: &Fragility, count: usize) -> Vec<f64> {
    let Fragility::Separated { below, above } = *fit else {
        return Vec::new();
    };
    let lower = levels
        .iter()
        .copied()
        .filter(|&x| x < below)
        .fold(below / 2.0, f64::max);
    let upper = levels
        .iter()
        .copied()
        .filter(|&x| x > above)
        .fold(2.0 * above, f64::min);
    let span = |from: f64, to: f64, n: usize| {
        (1..=n).map(move |k| {
            let x = from * (to / from).powf(k as f64 / (n + 1) as f64);
            format!("{x:.11e}").parse().unwrap_or(x)
        })
    };
    if below < above {
        span(below, above, count).collect()
    } else {
        // One level holds both outcomes: the crossing lies on either side.
        let half = count / 2;
        span(lower, below, count - half)
            .chain(span(below, upper, half))
            .collect()
    }
}

/// P(exceed | IM = x) = Φ(ln(x/θ)/β) (SPEC §12): 0 at x = 0.
pub fn probability(x: f64, theta: f64, beta: f64) -> f64 {
    normal::cdf((x / theta).ln() / beta)
}

/// How [`describe`] marks a θ outside the levels run.
pub const EXTRAPOLATED: &str = " (extrapolated)";

/// A fragility in words: θ and β of a fit, or why there is none; a θ
/// outside the levels run is marked [`EXTRAPOLATED`].
pub fn describe(f: &Fragility) -> String {
    match *f {
        Fragility::Fitted {
            theta,
            beta,
            extrapolated,
            ..
        } => {
            let outside = if extrapolated { EXTRAPOLATED } else { "" };
            format!("θ = {} g{outside}, β = {:.3}", echo::g4(theta), beta)
        }
        Fragility::TooFewRecords => "not fitted: fewer than two records".into(),
        Fragility::NeverExceeded => "never exceeded".into(),
        Fragility::AlwaysExceeded => "exceeded at every level".into(),
        Fragility::OneLevel { level, fraction } => {
            format!(
                "one level only: {:.0} % at {} g",
                100.0 * fraction,
                echo::g4(level)
            )
        }
        Fragility::Separated { below, above } if below == above => format!(
            "no fit: mixed only at {} g (θ → {} g, β → 0)",
            echo::g4(below),
            echo::g4(below)
        ),
        Fragility::Separated { below, above } => format!(
            "no fit: crossed between {} g and {} g (β → 0)",
            echo::g4(below),
            echo::g4(above)
        ),
        Fragility::NotIncreasing { fraction } => {
            format!(
                "no fit: does not rise with intensity ({:.0} %)",
                100.0 * fraction
            )
        }
    }
}

/// The maximum-likelihood fragility of `counts`, or why there is none (the
/// order of the checks is in the module docs). Levels may come in any order
/// and repeat.
///
/// # Panics
/// If a level is not finite and > 0, or `exceeded > runs`: a caller's bug,
/// since the suite runner makes the counts.
pub fn fit(counts: &[LevelCount]) -> Fragility {
    for c in counts {
        assert!(
            c.level.is_finite() && c.level > 0.0,
            "intensity level {} is not finite and > 0",
            c.level
        );
        assert!(
            c.exceeded <= c.runs,
            "{} of {} runs exceeded at level {}",
            c.exceeded,
            c.runs,
            c.level
        );
    }
    let run: Vec<&LevelCount> = counts.iter().filter(|c| c.runs > 0).collect();
    if run.iter().all(|c| c.runs < 2) {
        return Fragility::TooFewRecords;
    }
    if run.iter().all(|c| c.exceeded == 0) {
        return Fragility::NeverExceeded;
    }
    if run.iter().all(|c| c.exceeded == c.runs) {
        return Fragility::AlwaysExceeded;
    }
    let (total_runs, total_exceeded) = run
        .iter()
        .fold((0, 0), |(n, k), c| (n + c.runs, k + c.exceeded));
    let pooled = total_exceeded as f64 / total_runs as f64;
    let lowest = run.iter().map(|c| c.level).fold(f64::INFINITY, f64::min);
    if run.iter().all(|c| c.level == lowest) {
        return Fragility::OneLevel {
            level: lowest,
            fraction: pooled,
        };
    }
    // Where each outcome was seen: some run exceeded at `exceeded.0 ..= exceeded.1`,
    // some run did not at `survived.0 ..= survived.1`.
    let span = |seen: &dyn Fn(&LevelCount) -> bool| {
        run.iter()
            .filter(|c| seen(c))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                (lo.min(c.level), hi.max(c.level))
            })
    };
    let exceeded = span(&|c| c.exceeded > 0);
    let survived = span(&|c| c.exceeded < c.runs);
    if survived.1 <= exceeded.0 {
        return Fragility::Separated {
            below: survived.1,
            above: exceeded.0,
        };
    }
    if exceeded.1 <= survived.0 {
        return Fragility::NotIncreasing { fraction: pooled };
    }
    let points: Vec<Point> = run
        .iter()
        .map(|c| Point {
            ln_level: c.level.ln(),
            runs: c.runs as f64,
            exceeded: c.exceeded as f64,
        })
        .collect();
    let Probit { a, b } = maximize(&points);
    let (theta, beta) = ((-a / b).exp(), 1.0 / b);
    // η = a + b ln x moves by b·ln(x_max/x_min) over the levels: equal
    // fractions give b = 0 but for rounding, and a curve that flat has no θ
    // in floating point either.
    let highest = run.iter().map(|c| c.level).fold(0.0, f64::max);
    if b * (highest / lowest).ln() <= FLAT || !(theta.is_finite() && theta > 0.0) {
        return Fragility::NotIncreasing { fraction: pooled };
    }
    let binomial: f64 = run.iter().map(|c| ln_binomial(c.runs, c.exceeded)).sum();
    Fragility::Fitted {
        theta,
        beta,
        log_likelihood: log_likelihood(&points, 0.0, a, b) + binomial,
        extrapolated: theta < lowest || theta > highest,
    }
}

/// ln C(n, k) = Σ_{i=1}^{m} ln((n − m + i)/i), m = min(k, n − k).
fn ln_binomial(n: usize, k: usize) -> f64 {
    let m = k.min(n - k);
    (1..=m).map(|i| ((n - m + i) as f64 / i as f64).ln()).sum()
}

/// One level in the fit's terms: t_l = ln x_l and the counts, as reals so
/// that the tests can fit expected (fractional) counts.
#[derive(Debug, Clone, Copy)]
struct Point {
    ln_level: f64,
    runs: f64,
    exceeded: f64,
}

/// p = Φ(a + b ln x).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Probit {
    a: f64,
    b: f64,
}

/// Relative size of the last Newton step (module docs).
const STEP_TOLERANCE: f64 = 1e-12;
/// Below this change of η over the levels the fitted curve is flat
/// (rounding puts b near 1e-15 where the fractions are equal).
const FLAT: f64 = 1e-9;
/// Below this relative step, Newton's steps are taken whole (no line search).
const FULL_STEPS: f64 = 1e-6;
/// Newton iterations at most; a handful are used.
const MAX_ITERATIONS: usize = 100;
/// Armijo's sufficient-increase fraction of the line search.
const ARMIJO: f64 = 1e-4;
/// Halvings of a step before the search gives up (the rounding floor).
const MAX_HALVINGS: usize = 60;

/// ℓ without its binomial coefficients, at p = Φ(c + b (t − t̄)).
fn log_likelihood(points: &[Point], centre: f64, c: f64, b: f64) -> f64 {
    points
        .iter()
        .map(|p| {
            let eta = c + b * (p.ln_level - centre);
            p.exceeded * normal::ln_cdf(eta) + (p.runs - p.exceeded) * normal::ln_cdf(-eta)
        })
        .sum()
}

/// The unconstrained maximum of ℓ over (a, b) ∈ ℝ², by Newton's method in
/// the centred unknowns (c, b), c = a + b t̄ (module docs). The points must
/// overlap (some exceedance above some survival, some survival above some
/// exceedance), so that the maximum exists.
fn maximize(points: &[Point]) -> Probit {
    let total: f64 = points.iter().map(|p| p.runs).sum();
    let centre = points.iter().map(|p| p.runs * p.ln_level).sum::<f64>() / total;
    // The start: weighted least squares of Φ⁻¹ of the smoothed fractions on
    // t − t̄; the centred abscissae make the intercept their weighted mean.
    let (mut c, mut b) = {
        let (mut zw, mut uzw, mut uuw) = (0.0, 0.0, 0.0);
        for p in points {
            let z = normal::quantile((p.exceeded + 0.5) / (p.runs + 1.0));
            let u = p.ln_level - centre;
            zw += p.runs * z;
            uzw += p.runs * u * z;
            uuw += p.runs * u * u;
        }
        (zw / total, uzw / uuw)
    };
    let mut value = log_likelihood(points, centre, c, b);
    let mut last_size = f64::INFINITY;
    for _ in 0..MAX_ITERATIONS {
        // Gradient g and the negated Hessian [[h00, h01], [h01, h11]].
        let (mut g0, mut g1, mut h00, mut h01, mut h11) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for p in points {
            let u = p.ln_level - centre;
            let eta = c + b * u;
            let (lambda_up, kappa_up) = normal::ln_cdf_slopes(eta);
            let (lambda_down, kappa_down) = normal::ln_cdf_slopes(-eta);
            let survived = p.runs - p.exceeded;
            let slope = p.exceeded * lambda_up - survived * lambda_down;
            let weight = p.exceeded * kappa_up + survived * kappa_down;
            g0 += slope;
            g1 += slope * u;
            h00 += weight;
            h01 += weight * u;
            h11 += weight * u * u;
        }
        let det = h00 * h11 - h01 * h01;
        // The Newton step solves (−H) d = g; should −H be singular in
        // floating point (every weight vanished), climb the gradient.
        let (dc, db) = if det > 0.0 {
            ((h11 * g0 - h01 * g1) / det, (h00 * g1 - h01 * g0) / det)
        } else {
            (g0, g1)
        };
        let size = (dc.abs() / c.abs().max(1.0)).max(db.abs() / b.abs().max(1.0));
        if size <= STEP_TOLERANCE {
            c += dc;
            b += db;
            break;
        }
        if size <= FULL_STEPS {
            // Newton's own region: ℓ changes by about size² of itself, below
            // its rounding, so steps are taken whole, and they shrink
            // quadratically until the rounding of the gradient holds them.
            if size >= last_size {
                break;
            }
            c += dc;
            b += db;
            value = log_likelihood(points, centre, c, b);
            last_size = size;
            continue;
        }
        // Backtrack to Armijo's sufficient increase.
        let ascent = g0 * dc + g1 * db;
        let mut step = 1.0;
        let mut moved = false;
        for _ in 0..MAX_HALVINGS {
            let trial = log_likelihood(points, centre, c + step * dc, b + step * db);
            if trial >= value + ARMIJO * step * ascent {
                c += step * dc;
                b += step * db;
                value = trial;
                moved = true;
                break;
            }
            step *= 0.5;
        }
        if !moved {
            break;
        }
    }
    Probit {
        a: c - b * centre,
        b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::random::SplitMix64;

    const THETA: f64 = 0.5;
    const BETA: f64 = 0.4;

    /// Ten levels 0.1 … 1.0 g.
    fn levels() -> Vec<f64> {
        (1..=10).map(|l| l as f64 / 10.0).collect()
    }

    fn counts(runs: usize, exceeded: &[usize]) -> Vec<LevelCount> {
        levels()
            .into_iter()
            .zip(exceeded)
            .map(|(level, &exceeded)| LevelCount {
                level,
                runs,
                exceeded,
            })
            .collect()
    }

    fn fitted(f: Fragility) -> (f64, f64, f64) {
        match f {
            Fragility::Fitted {
                theta,
                beta,
                log_likelihood,
                ..
            } => (theta, beta, log_likelihood),
            other => panic!("no fit: {other:?}"),
        }
    }

    /// ln L(θ, β) written out anew from SPEC §12 (Φ from erfc, ln C by
    /// ln Γ), for the independent optimiser and the reported maximum.
    fn likelihood(counts: &[LevelCount], theta: f64, beta: f64) -> f64 {
        counts
            .iter()
            .map(|c| {
                let p = 0.5 * libm::erfc(-(c.level / theta).ln() / beta / 2f64.sqrt());
                let (n, k) = (c.runs as f64, c.exceeded as f64);
                let ln_choose =
                    libm::lgamma(n + 1.0) - libm::lgamma(k + 1.0) - libm::lgamma(n - k + 1.0);
                let hit = if k > 0.0 { k * p.ln() } else { 0.0 };
                let miss = if k < n { (n - k) * (1.0 - p).ln() } else { 0.0 };
                ln_choose + hit + miss
            })
            .sum()
    }

    /// Nelder–Mead on (ln θ, ln β), restarted from its best vertex until a
    /// restart no longer moves it: shares nothing with Newton's method.
    fn nelder_mead(f: impl Fn(f64, f64) -> f64, start: [f64; 2]) -> [f64; 2] {
        let cost = |x: [f64; 2]| {
            let v = -f(x[0].exp(), x[1].exp());
            if v.is_nan() { f64::INFINITY } else { v }
        };
        let mut best = start;
        for _ in 0..50 {
            let mut simplex = [best, [best[0] + 0.1, best[1]], [best[0], best[1] + 0.1]];
            let mut values = simplex.map(cost);
            for _ in 0..5000 {
                let mut order = [0, 1, 2];
                order.sort_by(|&i, &j| values[i].total_cmp(&values[j]));
                simplex = order.map(|i| simplex[i]);
                values = order.map(|i| values[i]);
                let size = (simplex[1][0] - simplex[0][0])
                    .abs()
                    .max((simplex[1][1] - simplex[0][1]).abs())
                    .max(
                        (simplex[2][0] - simplex[0][0])
                            .abs()
                            .max((simplex[2][1] - simplex[0][1]).abs()),
                    );
                if size < 1e-12 {
                    break;
                }
                let centroid = [0, 1].map(|d| 0.5 * (simplex[0][d] + simplex[1][d]));
                let toward =
                    |s: f64| [0, 1].map(|d| centroid[d] + s * (simplex[2][d] - centroid[d]));
                let reflected = toward(-1.0);
                let r = cost(reflected);
                if r < values[0] {
                    let expanded = toward(-2.0);
                    let e = cost(expanded);
                    (simplex[2], values[2]) = if e < r { (expanded, e) } else { (reflected, r) };
                } else if r < values[1] {
                    (simplex[2], values[2]) = (reflected, r);
                } else {
                    let contracted = if r < values[2] {
                        toward(-0.5)
                    } else {
                        toward(0.5)
                    };
                    let k = cost(contracted);
                    if k < values[2].min(r) {
                        (simplex[2], values[2]) = (contracted, k);
                    } else {
                        for i in 1..3 {
                            simplex[i] = [0, 1].map(|d| 0.5 * (simplex[0][d] + simplex[i][d]));
                            values[i] = cost(simplex[i]);
                        }
                    }
                }
            }
            let moved = (simplex[0][0] - best[0])
                .abs()
                .max((simplex[0][1] - best[1]).abs());
            best = simplex[0];
            if moved < 1e-12 {
                break;
            }
        }
        best.map(f64::exp)
    }

    /// Asymptotic standard errors of ln θ̂ and β̂ at the truth: the inverse
    /// of the expected information Σ n φ²/(Φ(1 − Φ)) [1 t; t t²] in (a, b),
    /// carried to (ln θ, β) = (−a/b, 1/b) by its Jacobian.
    fn standard_errors(runs: f64) -> (f64, f64) {
        let (a, b) = (-THETA.ln() / BETA, 1.0 / BETA);
        let (mut i00, mut i01, mut i11) = (0.0, 0.0, 0.0);
        for x in levels() {
            let t = x.ln();
            let eta = a + b * t;
            let p = normal::cdf(eta);
            let w = runs * normal::pdf(eta).powi(2) / (p * (1.0 - p));
            i00 += w;
            i01 += w * t;
            i11 += w * t * t;
        }
        let det = i00 * i11 - i01 * i01;
        let (c00, c01, c11) = (i11 / det, -i01 / det, i00 / det);
        // J = [[−1/b, a/b²], [0, −1/b²]]; Cov = J C Jᵀ.
        let (j00, j01, j11) = (-1.0 / b, a / (b * b), -1.0 / (b * b));
        let var_ln_theta = j00 * j00 * c00 + 2.0 * j00 * j01 * c01 + j01 * j01 * c11;
        let var_beta = j11 * j11 * c11;
        (var_ln_theta.sqrt(), var_beta.sqrt())
    }

    /// (a) Binomial counts drawn from θ = 0.5 g, β = 0.4 at ten levels with
    /// 200 runs each recover θ and β within 4 asymptotic standard errors
    /// (about 0.02 in ln θ and 0.02 in β here), for each of ten seeds: a
    /// bound a correct estimator breaks with probability about 6e-5 a seed.
    #[test]
    fn recovers_a_known_fragility_from_random_counts() {
        let runs = 200;
        let (se_ln_theta, se_beta) = standard_errors(runs as f64);
        assert!(se_ln_theta < 0.03 && se_beta < 0.03);
        for seed in 0..10 {
            let mut random = SplitMix64::new(seed);
            let exceeded: Vec<usize> = levels()
                .iter()
                .map(|&x| {
                    let p = probability(x, THETA, BETA);
                    (0..runs).filter(|_| random.chance(p)).count()
                })
                .collect();
            let (theta, beta, _) = fitted(fit(&counts(runs, &exceeded)));
            assert!(
                (theta / THETA).ln().abs() < 4.0 * se_ln_theta,
                "seed {seed}: θ = {theta}"
            );
            assert!(
                (beta - BETA).abs() < 4.0 * se_beta,
                "seed {seed}: β = {beta}"
            );
        }
    }

    /// (b) Counts n·p_l rounded, and counts far in the lower tail, give the
    /// maximum Nelder–Mead finds on a likelihood written anew, to 1e-6 in θ
    /// and β; the reported ln L is that likelihood at the fit.
    #[test]
    fn matches_an_independent_optimiser() {
        let runs = 200;
        let rounded: Vec<usize> = levels()
            .iter()
            .map(|&x| (runs as f64 * probability(x, THETA, BETA)).round() as usize)
            .collect();
        let tail = [0, 0, 0, 0, 0, 0, 0, 1, 0, 2];
        for (counts, start) in [
            (counts(runs, &rounded), [0.0, 0.0]),
            (counts(1000, &tail), [1.0, -1.0]),
        ] {
            let (theta, beta, ln_l) = fitted(fit(&counts));
            let [nm_theta, nm_beta] =
                nelder_mead(|theta, beta| likelihood(&counts, theta, beta), start);
            assert!((theta - nm_theta).abs() < 1e-6, "θ {theta} vs {nm_theta}");
            assert!((beta - nm_beta).abs() < 1e-6, "β {beta} vs {nm_beta}");
            let direct = likelihood(&counts, theta, beta);
            assert!(
                (ln_l - direct).abs() < 1e-9 * direct.abs(),
                "ln L {ln_l} vs {direct}"
            );
            assert!(likelihood(&counts, nm_theta, nm_beta) <= ln_l + 1e-9 * ln_l.abs());
        }
    }

    /// Expected counts k_l = n p_l exactly (fractional) make the score vanish
    /// at the truth, so the maximum is θ = 0.5, β = 0.4 to rounding.
    #[test]
    fn expected_counts_give_the_truth() {
        let points: Vec<Point> = levels()
            .iter()
            .map(|&x| Point {
                ln_level: x.ln(),
                runs: 200.0,
                exceeded: 200.0 * probability(x, THETA, BETA),
            })
            .collect();
        let Probit { a, b } = maximize(&points);
        let (theta, beta) = ((-a / b).exp(), 1.0 / b);
        assert!((theta - THETA).abs() < 1e-12, "θ = {theta}");
        assert!((beta - BETA).abs() < 1e-12, "β = {beta}");
    }

    /// Scaling every level by s scales θ by s and leaves β and ln L; the
    /// order of the levels does not matter.
    #[test]
    fn scale_and_order_invariance() {
        let base = counts(50, &[0, 1, 4, 12, 20, 31, 35, 42, 44, 49]);
        let (theta, beta, ln_l) = fitted(fit(&base));
        let mut scaled: Vec<LevelCount> = base
            .iter()
            .map(|c| LevelCount {
                level: 3.0 * c.level,
                ..*c
            })
            .collect();
        scaled.reverse();
        let (theta3, beta3, ln_l3) = fitted(fit(&scaled));
        assert!(
            (theta3 / (3.0 * theta) - 1.0).abs() < 1e-12,
            "{theta3} {theta} {beta3} {beta}"
        );
        assert!((beta3 / beta - 1.0).abs() < 1e-12);
        assert!((ln_l3 - ln_l).abs() < 1e-10);
    }

    /// Small random suites (2 to 6 records, 2 to 6 levels over 0.05 … 2 g):
    /// each gets a named case or a fit that no nearby (θ, β) beats, and the
    /// named cases agree with the counts.
    #[test]
    fn small_random_suites_fit_or_say_why_not() {
        let mut random = SplitMix64::new(7);
        let mut fits = 0;
        for _ in 0..2000 {
            let runs = 2 + (random.unit() * 5.0) as usize;
            let n_levels = 2 + (random.unit() * 5.0) as usize;
            let (theta, beta) = (random.log_uniform(0.1, 1.0), random.uniform(0.2, 0.8));
            let counts: Vec<LevelCount> = (0..n_levels)
                .map(|_| {
                    let level = random.log_uniform(0.05, 2.0);
                    let p = probability(level, theta, beta);
                    let exceeded = (0..runs).filter(|_| random.chance(p)).count();
                    LevelCount {
                        level,
                        runs,
                        exceeded,
                    }
                })
                .collect();
            match fit(&counts) {
                Fragility::Fitted {
                    theta,
                    beta,
                    log_likelihood,
                    ..
                } => {
                    fits += 1;
                    assert!(
                        theta > 0.0 && beta > 0.0 && log_likelihood <= 0.0,
                        "{theta} {beta} {log_likelihood} {counts:?}"
                    );
                    for (dt, db) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
                        let near = likelihood(
                            &counts,
                            theta * (1.0 + 1e-4 * dt),
                            beta * (1.0 + 1e-4 * db),
                        );
                        assert!(near <= log_likelihood + 1e-12, "{counts:?}");
                    }
                }
                Fragility::NeverExceeded => assert!(counts.iter().all(|c| c.exceeded == 0)),
                Fragility::AlwaysExceeded => assert!(counts.iter().all(|c| c.exceeded == c.runs)),
                Fragility::Separated { below, above } => {
                    assert!(below <= above);
                    assert!(counts.iter().all(|c| c.level >= below || c.exceeded == 0));
                    assert!(
                        counts
                            .iter()
                            .all(|c| c.level <= above || c.exceeded == c.runs)
                    );
                }
                Fragility::NotIncreasing { fraction } => assert!(fraction > 0.0 && fraction < 1.0),
                other => panic!("{other:?} from {counts:?}"),
            }
        }
        assert!(fits > 500, "only {fits} fits");
    }

    /// (c) The cases without a fit are named, never fitted.
    #[test]
    fn cases_without_a_fit() {
        let level = |level, runs, exceeded| LevelCount {
            level,
            runs,
            exceeded,
        };
        assert_eq!(fit(&counts(20, &[0; 10])), Fragility::NeverExceeded);
        assert_eq!(fit(&counts(20, &[20; 10])), Fragility::AlwaysExceeded);
        assert_eq!(fit(&[]), Fragility::TooFewRecords);
        // One record at every level, even with a clean crossing.
        assert_eq!(
            fit(&counts(1, &[0, 0, 0, 0, 1, 0, 1, 1, 1, 1])),
            Fragility::TooFewRecords
        );
        // Complete separation: none up to 0.4 g, all from 0.5 g.
        assert_eq!(
            fit(&counts(20, &[0, 0, 0, 0, 20, 20, 20, 20, 20, 20])),
            Fragility::Separated {
                below: 0.4,
                above: 0.5
            }
        );
        // Quasi-complete: 0.5 g holds both outcomes, none below, all above.
        assert_eq!(
            fit(&counts(20, &[0, 0, 0, 0, 7, 20, 20, 20, 20, 20])),
            Fragility::Separated {
                below: 0.5,
                above: 0.5
            }
        );
        // Separation read from the levels in any order, skipping empty ones.
        assert_eq!(
            fit(&[
                level(0.9, 5, 5),
                level(0.2, 5, 0),
                level(0.6, 0, 0),
                level(0.3, 5, 0),
                level(0.7, 5, 5)
            ]),
            Fragility::Separated {
                below: 0.3,
                above: 0.7
            }
        );
        assert_eq!(
            fit(&[level(0.3, 10, 4), level(0.3, 10, 6)]),
            Fragility::OneLevel {
                level: 0.3,
                fraction: 0.5
            }
        );
        // Falling fractions: reversed separation, and an overlap whose
        // unconstrained maximum has b < 0.
        assert_eq!(
            fit(&[level(0.2, 10, 3), level(0.4, 10, 0)]),
            Fragility::NotIncreasing { fraction: 0.15 }
        );
        assert_eq!(
            fit(&[level(0.2, 10, 6), level(0.4, 10, 4), level(0.8, 10, 2)]),
            Fragility::NotIncreasing { fraction: 0.4 }
        );
    }

    #[test]
    fn probability_is_the_lognormal_cdf() {
        assert_eq!(probability(0.5, 0.5, 0.4), 0.5);
        assert_eq!(probability(0.0, 0.5, 0.4), 0.0);
        let one_sigma = probability(0.5 * 0.4f64.exp(), 0.5, 0.4);
        assert!((one_sigma - 0.841_344_746_068_542_9).abs() < 1e-15);
    }

    #[test]
    fn binomial_coefficients() {
        assert_eq!(ln_binomial(7, 0), 0.0);
        assert!((ln_binomial(10, 3) - 120f64.ln()).abs() < 1e-14);
        assert!((ln_binomial(10, 7) - 120f64.ln()).abs() < 1e-14);
    }

    #[test]
    fn serializes_with_its_outcome() {
        let j = serde_json::to_string(&Fragility::Separated {
            below: 0.4,
            above: 0.5,
        })
        .unwrap();
        assert_eq!(j, r#"{"outcome":"separated","below":0.4,"above":0.5}"#);
        let j = serde_json::to_string(&Fragility::TooFewRecords).unwrap();
        assert_eq!(j, r#"{"outcome":"too_few_records"}"#);
    }

    /// A θ beyond the highest level run is flagged, in the fit and in its
    /// words; one inside the levels is not. Counts from θ = 1.8 g, β = 0.5
    /// at 0.2 … 1 g (expected counts of 100 runs, rounded), as a μ > 4
    /// limit state that only the strongest records reach.
    #[test]
    fn a_median_outside_the_levels_run_is_flagged() {
        let levels = [0.2, 0.4, 0.6, 0.8, 1.0];
        let at = |theta: f64| -> Vec<LevelCount> {
            levels
                .iter()
                .map(|&level| LevelCount {
                    level,
                    runs: 100,
                    exceeded: (100.0 * probability(level, theta, 0.5)).round() as usize,
                })
                .collect()
        };
        let Fragility::Fitted {
            theta,
            extrapolated,
            ..
        } = fit(&at(1.8))
        else {
            panic!("no fit");
        };
        // Rounded counts (12 of 100 at 1 g) move the fit: θ = 1.66 g.
        assert!((theta / 1.8 - 1.0).abs() < 0.1, "θ = {theta}");
        assert!(theta > 1.0);
        assert!(extrapolated);
        let words = describe(&fit(&at(1.8)));
        assert!(words.contains("g (extrapolated), β ="), "{words}");
        let inside = fit(&at(0.5));
        assert!(
            matches!(
                inside,
                Fragility::Fitted {
                    extrapolated: false,
                    ..
                }
            ),
            "{inside:?}"
        );
        assert!(!describe(&inside).contains("extrapolated"));
        let json = serde_json::to_string(&fit(&at(1.8))).unwrap();
        assert!(json.contains("\"extrapolated\":true"), "{json}");
    }

    #[test]
    fn bridging_levels_fall_inside_the_separating_bracket() {
        let levels = [0.06, 0.12, 0.18, 0.24];
        let apart = Fragility::Separated {
            below: 0.06,
            above: 0.12,
        };
        let x = bridging_levels(&levels, &apart, 3);
        assert_eq!(x.len(), 3);
        // ln-spaced: 0.06·2^(k/4), k = 1, 2, 3.
        for (k, &v) in x.iter().enumerate() {
            let want = 0.06 * 2f64.powf((k + 1) as f64 / 4.0);
            // 12 significant digits.
            assert!((v - want).abs() < 1e-11 * want, "{v} against {want}");
        }
        let one = Fragility::Separated {
            below: 0.12,
            above: 0.12,
        };
        let x = bridging_levels(&levels, &one, 4);
        assert_eq!(x.len(), 4);
        assert!(x[..2].iter().all(|&v| v > 0.06 && v < 0.12), "{x:?}");
        assert!(x[2..].iter().all(|&v| v > 0.12 && v < 0.18), "{x:?}");
        // At the lowest level the bracket opens to half of it.
        let low = Fragility::Separated {
            below: 0.06,
            above: 0.06,
        };
        let x = bridging_levels(&levels, &low, 2);
        assert!(
            x[0] > 0.03 && x[0] < 0.06 && x[1] > 0.06 && x[1] < 0.12,
            "{x:?}"
        );
        let fitted = Fragility::Fitted {
            theta: 0.1,
            beta: 0.3,
            log_likelihood: -1.0,
            extrapolated: false,
        };
        assert!(bridging_levels(&levels, &fitted, 4).is_empty());
    }
}
