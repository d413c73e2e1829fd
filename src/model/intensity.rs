//! Intensity measures of a ground motion (SPEC §12): the peak ground
//! acceleration and the 5 %-damped pseudo-spectral acceleration Sa(T), in g,
//! of the unscaled record. Scaling a record by s scales both by s, so a suite
//! scales record j to a level X by s_j = X / IM_j.
//!
//! Sa(T) = ω² max_t |u(t)| for the linear oscillator
//!
//! ```text
//! ü + 2ξω u̇ + ω² u = −a(t),   ω = 2π/T, ξ = 0.05,   u(0) = u̇(0) = 0,
//! ```
//!
//! under the record's piecewise-linear a(t), over the record only (no free
//! tail). It is computed exactly: on each sample interval the load is linear
//! in time, so the response is known in closed form (the Nigam–Jennings
//! recurrence, `Interval` below), and the maximum of |u| is located where u̇
//! changes sign inside an interval rather than read at the samples.

use std::f64::consts::PI;
use std::fmt;

use super::record::{Record, STANDARD_GRAVITY};

/// The damping ratio of Sa (SPEC §12).
pub const SA_DAMPING: f64 = 0.05;

/// The longest period Sa accepts (s).
pub const MAX_PERIOD: f64 = 10.0;

/// How a record's intensity is measured (SPEC §12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum IntensityMeasure {
    /// Peak ground acceleration max |a|, in g.
    Pga,
    /// 5 %-damped pseudo-spectral acceleration at `period` seconds, in g.
    Sa { period: f64 },
}

/// An intensity measure that could not be parsed: the text and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("intensity measure `{text}`: {reason}")]
pub struct IntensityError {
    pub text: String,
    pub reason: String,
}

impl IntensityMeasure {
    /// The names [`IntensityMeasure::parse`] takes, for messages.
    pub const NAMES: &'static str = "pga or sa:T (T in seconds, in (0, 10])";

    /// Parses `pga` or `sa:T` with the period T in (0, 10] s.
    pub fn parse(text: &str) -> Result<IntensityMeasure, IntensityError> {
        let fail = |reason: String| IntensityError {
            text: text
                .chars()
                .take(40)
                .flat_map(char::escape_default)
                .collect(),
            reason,
        };
        let t = text.trim();
        if t.eq_ignore_ascii_case("pga") {
            return Ok(IntensityMeasure::Pga);
        }
        let Some(period) = t.strip_prefix("sa:").or_else(|| t.strip_prefix("Sa:")) else {
            return Err(fail(format!("must be {}", Self::NAMES)));
        };
        match period.trim().parse::<f64>() {
            Ok(period) if period > 0.0 && period <= MAX_PERIOD => {
                Ok(IntensityMeasure::Sa { period })
            }
            Ok(_) => Err(fail(format!(
                "the period must be in (0, {MAX_PERIOD}] seconds"
            ))),
            Err(_) => Err(fail(format!(
                "the period after `sa:` is not a number; must be {}",
                Self::NAMES
            ))),
        }
    }

    /// The name as [`IntensityMeasure::parse`] reads it: `pga`, `sa:0.95`.
    pub fn label(&self) -> String {
        self.to_string()
    }

    /// The measure of the unscaled `record`, in g.
    pub fn measure(&self, record: &Record) -> f64 {
        match *self {
            IntensityMeasure::Pga => record.peak / STANDARD_GRAVITY,
            IntensityMeasure::Sa { period } => {
                spectral_acceleration(&record.acceleration, record.dt, period, SA_DAMPING)
                    / STANDARD_GRAVITY
            }
        }
    }
}

impl fmt::Display for IntensityMeasure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IntensityMeasure::Pga => write!(f, "pga"),
            IntensityMeasure::Sa { period } => write!(f, "sa:{period}"),
        }
    }
}

/// Sa = ω² max |u| (in the unit of `acceleration`) of the oscillator of
/// `period` seconds and damping ratio `damping` (< 1), at rest at t = 0, under the
/// samples `acceleration` at interval `dt`, linear between them, over
/// t ∈ [0, (N − 1)·dt]. Exact up to rounding: see the module doc.
pub fn spectral_acceleration(acceleration: &[f64], dt: f64, period: f64, damping: f64) -> f64 {
    let oscillator = Oscillator::new(period, damping, dt);
    let (mut u, mut v) = (0.0f64, 0.0f64);
    let mut peak = 0.0f64;
    for pair in acceleration.windows(2) {
        let interval = oscillator.interval(u, v, pair[0], pair[1]);
        let (u1, v1) = interval.end();
        peak = peak.max(u1.abs()).max(interval.inner_peak(v, v1));
        (u, v) = (u1, v1);
    }
    oscillator.omega * oscillator.omega * peak
}

/// The oscillator and the constants of one sample interval Δ.
struct Oscillator {
    omega: f64,
    damping: f64,
    /// ω_d = ω √(1 − ξ²).
    omega_d: f64,
    dt: f64,
    /// e^{−ξωΔ}, cos ω_dΔ, sin ω_dΔ.
    decay: f64,
    cos: f64,
    sin: f64,
}

impl Oscillator {
    fn new(period: f64, damping: f64, dt: f64) -> Oscillator {
        let omega = 2.0 * PI / period;
        let omega_d = omega * (1.0 - damping * damping).sqrt();
        let (sin, cos) = (omega_d * dt).sin_cos();
        Oscillator {
            omega,
            damping,
            omega_d,
            dt,
            decay: (-damping * omega * dt).exp(),
            cos,
            sin,
        }
    }

    /// The closed form on an interval that starts at (u0, u̇0) with the load
    /// going linearly from a0 to a1.
    fn interval(&self, u0: f64, v0: f64, a0: f64, a1: f64) -> Interval<'_> {
        let (w, xi) = (self.omega, self.damping);
        let slope = (a1 - a0) / self.dt;
        // Particular solution A + Bτ of ü + 2ξωu̇ + ω²u = −(a0 + slope·τ).
        let b = -slope / (w * w);
        let a = (-a0 + 2.0 * xi * slope / w) / (w * w);
        // Homogeneous part e^{−ξωτ}(C cos ω_dτ + D sin ω_dτ) from the start.
        let c = u0 - a;
        let d = (v0 - b + xi * w * c) / self.omega_d;
        Interval {
            oscillator: self,
            a,
            b,
            c,
            d,
        }
    }
}

/// The response on one interval, τ ∈ [0, Δ] from its start (Nigam and
/// Jennings 1969; SPEC §9, §12):
///
/// ```text
/// u(τ)  = A + Bτ + e^{−ξωτ}(C cos ω_dτ + D sin ω_dτ),
/// u̇(τ)  = B + e^{−ξωτ}(F cos ω_dτ + G sin ω_dτ),   F = ω_d D − ξωC, G = −(ω_d C + ξωD),
/// ü(τ)  =     e^{−ξωτ}(P cos ω_dτ + Q sin ω_dτ),   P = ω_d G − ξωF, Q = −(ω_d F + ξωG),
/// ```
///
/// with B = −s/ω², A = (−a0 + 2ξs/ω)/ω² (s the load's slope), C = u0 − A,
/// D = (u̇0 − B + ξωC)/ω_d. Between consecutive zeros of ü, at
/// ω_dτ = mπ − atan2(P, Q), u̇ is monotone, so it has at most one root
/// there, and it has one exactly when its ends differ in sign.
struct Interval<'a> {
    oscillator: &'a Oscillator,
    a: f64,
    b: f64,
    c: f64,
    d: f64,
}

impl Interval<'_> {
    fn fg(&self) -> (f64, f64) {
        let o = self.oscillator;
        let xw = o.damping * o.omega;
        (
            o.omega_d * self.d - xw * self.c,
            -(o.omega_d * self.c + xw * self.d),
        )
    }

    fn pq(&self) -> (f64, f64) {
        let o = self.oscillator;
        let xw = o.damping * o.omega;
        let (f, g) = self.fg();
        (o.omega_d * g - xw * f, -(o.omega_d * f + xw * g))
    }

    /// (u, u̇) at the end τ = Δ, from the interval's constants.
    fn end(&self) -> (f64, f64) {
        let o = self.oscillator;
        let (f, g) = self.fg();
        (
            self.a + self.b * o.dt + o.decay * (self.c * o.cos + self.d * o.sin),
            self.b + o.decay * (f * o.cos + g * o.sin),
        )
    }

    /// (e^{−ξωτ}, cos ω_dτ, sin ω_dτ).
    fn trig(&self, tau: f64) -> (f64, f64, f64) {
        let o = self.oscillator;
        let (s, c) = (o.omega_d * tau).sin_cos();
        ((-o.damping * o.omega * tau).exp(), c, s)
    }

    fn displacement(&self, tau: f64) -> f64 {
        let (e, c, s) = self.trig(tau);
        self.a + self.b * tau + e * (self.c * c + self.d * s)
    }

    /// (u̇, ü) at τ.
    fn rates(&self, tau: f64) -> (f64, f64) {
        let (e, c, s) = self.trig(tau);
        let ((f, g), (p, q)) = (self.fg(), self.pq());
        (self.b + e * (f * c + g * s), e * (p * c + q * s))
    }

    /// The largest |u| at the roots of u̇ strictly inside the interval, or 0;
    /// `v0` and `v1` are u̇ at its ends.
    fn inner_peak(&self, v0: f64, v1: f64) -> f64 {
        let o = self.oscillator;
        let (p, q) = self.pq();
        // Zeros of ü: ω_dτ = x0 + mπ.
        let x0 = (-p.atan2(q)).rem_euclid(PI);
        let mut peak = 0.0f64;
        let (mut left, mut v_left) = (0.0, v0);
        let mut m = 0.0;
        loop {
            let cut = (x0 + m * PI) / o.omega_d;
            let (right, v_right) = if cut < o.dt {
                (cut, self.rates(cut).0)
            } else {
                (o.dt, v1)
            };
            if right > left && v_left * v_right < 0.0 {
                let root = self.velocity_root(left, right, v_left);
                peak = peak.max(self.displacement(root).abs());
            }
            if right >= o.dt {
                return peak;
            }
            (left, v_left) = (right, v_right);
            m += 1.0;
            if m >= 2.0 && self.transient_spent(left) {
                // From here on |u| = |A + Bτ| to rounding: its largest is at
                // `left` or at the end, which the caller counts.
                return peak.max((self.a + self.b * left).abs());
            }
        }
    }

    /// Whether, from τ on, the homogeneous part e^{−ξωτ}√(C² + D²) is below
    /// the rounding of the particular part max(|A|, |A + BΔ|). Only periods
    /// far below the sample interval get here (a few half-periods into an
    /// interval), so a period of 1e-4 s under 100 Hz samples costs a few
    /// hundred pieces per interval rather than millions.
    fn transient_spent(&self, tau: f64) -> bool {
        let o = self.oscillator;
        let homogeneous = (-o.damping * o.omega * tau).exp() * self.c.hypot(self.d);
        let particular = self.a.abs().max((self.a + self.b * o.dt).abs());
        homogeneous <= 1e-17 * particular
    }

    /// The root of u̇ in [left, right], where u̇ is monotone and changes sign
    /// (u̇(left) = `v_left`): Newton's method on the exact u̇ and ü, kept in
    /// the bracket by bisection.
    fn velocity_root(&self, mut left: f64, mut right: f64, v_left: f64) -> f64 {
        let rising = v_left < 0.0;
        let tolerance = 4.0 * f64::EPSILON * right;
        let mut tau = 0.5 * (left + right);
        for _ in 0..100 {
            let (v, acc) = self.rates(tau);
            if v == 0.0 {
                return tau;
            }
            if (v < 0.0) == rising {
                left = tau;
            } else {
                right = tau;
            }
            let newton = tau - v / acc;
            if (newton - tau).abs() <= tolerance && newton >= left && newton <= right {
                return newton;
            }
            tau = if newton > left && newton < right {
                newton
            } else {
                0.5 * (left + right)
            };
            if right - left <= tolerance {
                return tau;
            }
        }
        tau
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_labels() {
        assert_eq!(
            IntensityMeasure::parse("pga").unwrap(),
            IntensityMeasure::Pga
        );
        let sa = IntensityMeasure::parse("sa:0.95").unwrap();
        assert_eq!(sa, IntensityMeasure::Sa { period: 0.95 });
        assert_eq!(sa.label(), "sa:0.95");
        assert_eq!(IntensityMeasure::Pga.to_string(), "pga");
        for bad in ["sa:0", "sa:-1", "sa:11", "sa:x", "pgv", "sa:inf", "sa:nan"] {
            let e = IntensityMeasure::parse(bad).unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("(0, 10]"), "{e}");
        }
    }

    #[test]
    fn a_constant_load_peaks_at_half_a_damped_period() {
        // u = −(a/ω²)(1 − e^{−ξωt}(cos ω_d t + ξ/√(1−ξ²) sin ω_d t)): the first
        // peak, at t = π/ω_d, is (a/ω²)(1 + e^{−ξπ/√(1−ξ²)}), between samples.
        let a = vec![2.0; 400];
        let xi = SA_DAMPING;
        let want = 2.0 * (1.0 + (-xi * PI / (1.0 - xi * xi).sqrt()).exp());
        let got = spectral_acceleration(&a, 0.01, 0.77, xi);
        assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
    }

    #[test]
    fn no_peak_inside_an_interval_is_missed() {
        // Every interval's located peak is at least the largest |u| of a
        // scan of 1000 points across it (with the end values).
        let oscillator = Oscillator::new(0.5, SA_DAMPING, 0.01);
        let a: Vec<f64> = (0..400).map(|k| 3.0 * (k as f64 * 0.37).sin()).collect();
        let (mut u, mut v) = (0.0, 0.0);
        for pair in a.windows(2) {
            let interval = oscillator.interval(u, v, pair[0], pair[1]);
            let (u1, v1) = interval.end();
            let located = interval.inner_peak(v, v1).max(u.abs()).max(u1.abs());
            let scanned = (0..=1000)
                .map(|i| interval.displacement(i as f64 * 1e-5).abs())
                .fold(0.0f64, f64::max);
            assert!(scanned <= located * (1.0 + 1e-13), "{scanned} > {located}");
            (u, v) = (u1, v1);
        }
    }

    #[test]
    fn a_period_far_below_the_sample_interval_is_quick_and_tends_to_the_pga() {
        let a: Vec<f64> = (0..1000).map(|k| 3.0 * (k as f64 * 0.37).sin()).collect();
        let pga = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let sa = spectral_acceleration(&a, 0.01, 1e-4, SA_DAMPING);
        assert!((sa / pga - 1.0).abs() < 1e-3, "{sa} vs {pga}");
    }
}
