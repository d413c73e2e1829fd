//! Ground acceleration g(τ) per unit amplitude a_p (SPEC §2, §9): the
//! paper's sine, the cycloidal pulses of Makris and co-workers, and recorded
//! accelerograms, linear between samples.

use std::f64::consts::PI;
use std::fmt;
use std::str::FromStr;
use std::sync::Arc;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::record::{self, Record, RecordError};

/// A cycloidal pulse (SPEC §9): one or a few sine pieces, then g = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pulse {
    /// Type A: g = sin τ on [0, 2π]; the ground velocity 1 − cos τ is one-sided.
    A,
    /// Type B: g = −sin τ on [0, 2π]; the ground starts with velocity V_p, so
    /// in relative coordinates both structures start with ẋ_i(0) = −1.
    B,
    /// Type Cn: g = cos(τ + φ) on [0, (2n+1)π − 2φ], with φ the phase that
    /// brings the ground displacement back to zero at the pulse's end.
    C { n: u32, phase: f64 },
}

impl Pulse {
    /// The type Cn pulse, its phase solved from
    /// 2 cos φ = sin φ · ((2n+1)π − 2φ) (SPEC §9) by Newton's method from
    /// φ = 0.2; φ ≈ 0.21898 for n = 1, 0.12873 for n = 2.
    pub fn c(n: u32) -> Pulse {
        let big = (2 * n + 1) as f64 * PI;
        let mut phi: f64 = 0.2;
        for _ in 0..50 {
            let (s, c) = phi.sin_cos();
            let f = 2.0 * c - s * (big - 2.0 * phi);
            let df = -2.0 * s - c * (big - 2.0 * phi) + 2.0 * s;
            let step = f / df;
            phi -= step;
            if step.abs() < 1e-17 {
                break;
            }
        }
        Pulse::C { n, phase: phi }
    }

    /// End of the pulse in τ: 2π for A and B, (2n+1)π − 2φ for Cn.
    pub fn end(self) -> f64 {
        match self {
            Pulse::A | Pulse::B => 2.0 * PI,
            Pulse::C { n, phase } => (2 * n + 1) as f64 * PI - 2.0 * phase,
        }
    }

    /// The ground's velocity u̇_g ω_p/a_p at τ = 0: 1 for type B (u̇_g =
    /// V_p cos ω_p t, a_p = ω_p V_p), 0 for A and Cn, which start from rest.
    pub fn ground_velocity(self) -> f64 {
        match self {
            Pulse::B => 1.0,
            Pulse::A | Pulse::C { .. } => 0.0,
        }
    }

    /// The pulse's sinusoid g = A sin(τ + θ) written as (amplitude, phase θ):
    /// A: (1, 0); B: (−1, 0); Cn: cos(τ + φ) = sin(τ + φ + π/2).
    pub fn sinusoid(self) -> (f64, f64) {
        match self {
            Pulse::A => (1.0, 0.0),
            Pulse::B => (-1.0, 0.0),
            Pulse::C { phase, .. } => (1.0, phase + 0.5 * PI),
        }
    }
}

/// A recorded accelerogram scaled into Π form (SPEC §9, §12):
/// g(τ) = s·a(τ/ω_p)/a_p, the record scaled by s (1 as read).
///
/// The motion shares its record with every other motion scaled from it (a
/// suite at each intensity of an IDA, the explorer's reruns): cloning one
/// counts one more holder, and the samples are freed with the last.
#[derive(Debug, Clone)]
pub struct RecordMotion {
    pub record: Arc<Record>,
    /// The factor s on the record's accelerations (SPEC §12: a record scaled
    /// to an intensity); 1 as read.
    pub scale: f64,
    /// a_p in m/s² (default: the scaled record's peak s·max|a|).
    pub amplitude: f64,
    /// ω_p in rad/s (default: the frequency of its largest Fourier amplitude).
    pub omega: f64,
}

impl PartialEq for RecordMotion {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.record, &other.record)
            && self.scale == other.scale
            && self.amplitude == other.amplitude
            && self.omega == other.omega
    }
}

impl RecordMotion {
    /// The record at its defaults: a_p = peak |a|, ω_p = dominant frequency.
    pub fn new(record: Arc<Record>) -> Self {
        RecordMotion {
            scale: 1.0,
            amplitude: if record.peak > 0.0 { record.peak } else { 1.0 },
            omega: record.dominant_omega(),
            record,
        }
    }

    /// Sample spacing in τ: DT·ω_p.
    #[inline]
    fn spacing(&self) -> f64 {
        self.record.dt * self.omega
    }

    /// End of the samples in τ: (N − 1)·DT·ω_p.
    pub fn end(&self) -> f64 {
        self.record.duration() * self.omega
    }

    /// The sample interval [k, k+1] holding τ (k = N − 1 past the end),
    /// chosen so that (k + 1)·spacing > τ.
    #[inline]
    pub fn interval(&self, tau: f64) -> usize {
        let last = self.record.acceleration.len() - 1;
        let h = self.spacing();
        let mut k = (tau / h).floor().max(0.0) as usize;
        while k < last && (k + 1) as f64 * h <= tau {
            k += 1;
        }
        k.min(last)
    }

    /// For a run standing at τ = k·spacing, the start of sample interval
    /// k < N − 1: its end τ_{k+1} and (g, dg/dτ) at τ_k, the values that
    /// [`Excitation::next_break`] and [`Excitation::phasor`] give there
    /// (computed as they compute them), without locating the interval.
    #[inline]
    pub fn at_sample(&self, k: usize) -> Option<(f64, [f64; 2])> {
        let a = &self.record.acceleration;
        if k + 1 >= a.len() {
            return None;
        }
        let h = self.spacing();
        let slope = self.scale * (a[k + 1] - a[k]) / (h * self.amplitude);
        Some((
            (k + 1) as f64 * h,
            [self.scale * a[k] / self.amplitude, slope],
        ))
    }

    /// (g, dg/dτ) at τ as the limit from the left: on a sample τ_k the
    /// segment [τ_{k−1}, τ_k] ending there (at the last sample, its value
    /// before g drops to 0); elsewhere [`RecordMotion::value_slope`].
    #[inline]
    fn value_slope_before(&self, tau: f64) -> [f64; 2] {
        let a = &self.record.acceleration;
        let h = self.spacing();
        let k = self.interval(tau);
        if k >= 1 && k as f64 * h >= tau {
            let slope = self.scale * (a[k] - a[k - 1]) / (h * self.amplitude);
            return [
                self.scale * a[k - 1] / self.amplitude + slope * (tau - (k - 1) as f64 * h),
                slope,
            ];
        }
        self.value_slope(tau)
    }

    /// (g, dg/dτ) at τ: linear on [τ_k, τ_{k+1}), zero from the last sample on.
    #[inline]
    fn value_slope(&self, tau: f64) -> [f64; 2] {
        let a = &self.record.acceleration;
        let k = self.interval(tau);
        // From the last sample on, g = 0 (the formula of [τ_{N−1}, ∞)).
        if tau < 0.0 || k + 1 >= a.len() {
            return [0.0, 0.0];
        }
        let h = self.spacing();
        let slope = self.scale * (a[k + 1] - a[k]) / (h * self.amplitude);
        let g = self.scale * a[k] / self.amplitude + slope * (tau - k as f64 * h);
        [g, slope]
    }
}

/// The excitation a run is driven by (`Clone`, not `Copy`: a record is
/// shared with its other holders, see [`RecordMotion`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Excitation {
    /// g(τ) = sin τ, the paper's sinusoidal pulse train.
    #[default]
    Sine,
    /// g(τ) = 0: free motion from the initial state (isolated impacts, tests).
    None,
    /// A cycloidal pulse, then free vibration.
    Pulse(Pulse),
    /// A recorded accelerogram, then free vibration.
    Record(RecordMotion),
}

/// The names `--excitation`, presets and `--set` take (a record is `record:PATH`).
pub const NAMES: [&str; 6] = [
    "sine",
    "pulse-a",
    "pulse-b",
    "pulse-c1",
    "pulse-c2",
    "record:PATH",
];

impl Excitation {
    /// Parses a name of [`NAMES`]; `record:PATH` reads the file (once per path).
    pub fn parse(text: &str) -> Result<Excitation, ExcitationError> {
        let t = text.trim();
        if let Some(path) = t.strip_prefix("record:") {
            return record::load(path)
                .map(|r| Excitation::Record(RecordMotion::new(r)))
                .map_err(ExcitationError::Record);
        }
        Ok(match t {
            "sine" => Excitation::Sine,
            "none" => Excitation::None,
            "pulse-a" => Excitation::Pulse(Pulse::A),
            "pulse-b" => Excitation::Pulse(Pulse::B),
            "pulse-c1" => Excitation::Pulse(Pulse::c(1)),
            "pulse-c2" => Excitation::Pulse(Pulse::c(2)),
            _ => return Err(ExcitationError::Unknown),
        })
    }

    /// The name, as [`Excitation::parse`] reads it.
    pub fn name(&self) -> &str {
        match self {
            Excitation::Sine => "sine",
            Excitation::None => "none",
            Excitation::Pulse(Pulse::A) => "pulse-a",
            Excitation::Pulse(Pulse::B) => "pulse-b",
            Excitation::Pulse(Pulse::C { n: 1, .. }) => "pulse-c1",
            Excitation::Pulse(Pulse::C { .. }) => "pulse-c2",
            Excitation::Record(m) => &m.record.spec,
        }
    }

    /// What a run's output says about its excitation beyond the name (SPEC §9),
    /// or nothing for the sine: the type B pulse's initial velocity, the
    /// scaling of a record (with the scaled excitation of `Params::ground`).
    pub fn note(&self) -> Option<String> {
        match self {
            Excitation::Pulse(Pulse::B) => Some(
                "the ground starts with velocity V_p: both structures start with ẋ(0) = −1"
                    .to_string(),
            ),
            Excitation::Record(m) => Some(format!(
                "{} samples at DT = {} s{}; a_p = {} m/s², ω_p = {} rad/s",
                m.record.acceleration.len(),
                m.record.dt,
                if m.scale == 1.0 {
                    String::new()
                } else {
                    format!(", scaled by {}", m.scale)
                },
                m.amplitude,
                m.omega,
            )),
            _ => None,
        }
    }

    /// Whether (g, dg/dτ) advance by a rotation ([`Rotation`]): the sine and zero only.
    #[inline]
    pub fn rotates(&self) -> bool {
        matches!(self, Excitation::Sine | Excitation::None)
    }

    /// ẋ_i(0) the excitation imposes in relative coordinates: −1 for the
    /// type B pulse, whose ground starts with velocity V_p (SPEC §9); else 0.
    pub fn initial_velocity(&self) -> [f64; 2] {
        match self {
            Excitation::Pulse(p) if p.ground_velocity() != 0.0 => [-p.ground_velocity(); 2],
            _ => [0.0; 2],
        }
    }

    /// Where the excitation stops (g = 0 after): the pulse's or the
    /// record's end; infinite for the sine.
    pub fn end(&self) -> f64 {
        match self {
            Excitation::Sine => f64::INFINITY,
            Excitation::None => 0.0,
            Excitation::Pulse(p) => p.end(),
            Excitation::Record(m) => m.end(),
        }
    }

    /// g(τ).
    #[inline]
    pub fn at(&self, tau: f64) -> f64 {
        self.phasor(tau)[0]
    }

    /// (g(τ), dg/dτ): for the sine, (sin τ, cos τ). Carried along a run so the
    /// next value can be had by a rotation instead of a new `sin` (see
    /// [`Rotation`]) where [`Excitation::rotates`]. A pulse is its sinusoid
    /// on [0, end) and zero from its end on; a record is linear between samples.
    #[inline]
    pub fn phasor(&self, tau: f64) -> [f64; 2] {
        match self {
            Excitation::Sine => {
                let (s, c) = tau.sin_cos();
                [s, c]
            }
            Excitation::None => [0.0, 0.0],
            Excitation::Pulse(p) => {
                if (0.0..p.end()).contains(&tau) {
                    let (amp, theta) = p.sinusoid();
                    let (s, c) = (tau + theta).sin_cos();
                    [amp * s, amp * c]
                } else {
                    [0.0, 0.0]
                }
            }
            Excitation::Record(m) => m.value_slope(tau),
        }
    }

    /// (g, dg/dτ) at τ as the limit from the left: equal to
    /// [`Excitation::phasor`] except on a break ([`Excitation::next_break`]),
    /// where it is the value of the formula that ends there (the pulse's
    /// last value, a record's last sample). A time step that ends on a break
    /// integrates the formula before it, so this is its end value.
    #[inline]
    pub fn phasor_before(&self, tau: f64) -> [f64; 2] {
        match self {
            Excitation::Pulse(p) if tau > 0.0 && tau <= p.end() => {
                let (amp, theta) = p.sinusoid();
                let (s, c) = (tau + theta).sin_cos();
                [amp * s, amp * c]
            }
            Excitation::Record(m) => m.value_slope_before(tau),
            _ => self.phasor(tau),
        }
    }

    /// The ground motion at τ in Π form: (g, u̇_g ω_p/a_p, u_g ω_p²/a_p), the
    /// acceleration, velocity and displacement of the ground (SPEC §9), from
    /// rest at τ = 0 except for the type B pulse, whose ground velocity starts at 1.
    pub fn ground(&self, tau: f64) -> [f64; 3] {
        let g = self.at(tau);
        match self {
            Excitation::Sine => [g, 1.0 - tau.cos(), tau - tau.sin()],
            Excitation::None => [0.0; 3],
            Excitation::Pulse(p) => {
                let end = p.end();
                let t = tau.min(end);
                let (vel, disp) = match p {
                    // u̇ = 1 − cos τ, u = τ − sin τ.
                    Pulse::A => (1.0 - t.cos(), t - t.sin()),
                    // u̇ = cos τ, u = sin τ.
                    Pulse::B => (t.cos(), t.sin()),
                    // u̇ = sin(τ+φ) − sin φ, u = cos φ − cos(τ+φ) − τ sin φ.
                    Pulse::C { phase, .. } => {
                        let (s0, c0) = phase.sin_cos();
                        ((t + phase).sin() - s0, c0 - (t + phase).cos() - t * s0)
                    }
                };
                [g, vel, disp + vel * (tau - t)]
            }
            Excitation::Record(m) => {
                let r = &*m.record;
                let scale_v = m.scale * m.omega / m.amplitude;
                let scale_u = m.scale * m.omega * m.omega / m.amplitude;
                let t = (tau / m.omega).clamp(0.0, r.duration());
                let k = m.interval(t * m.omega);
                let s = t - k as f64 * r.dt;
                let a0 = r.acceleration[k];
                let slope = if k + 1 < r.acceleration.len() {
                    (r.acceleration[k + 1] - a0) / r.dt
                } else {
                    0.0
                };
                let vel = r.velocity[k] + a0 * s + 0.5 * slope * s * s;
                let disp = r.displacement[k]
                    + r.velocity[k] * s
                    + 0.5 * a0 * s * s
                    + slope * s * s * s / 6.0;
                let rest = (tau / m.omega - t).max(0.0);
                [g, vel * scale_v, (disp + vel * rest) * scale_u]
            }
        }
    }
}

/// Why an excitation name was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum ExcitationError {
    /// None of [`NAMES`].
    Unknown,
    /// `record:PATH` named a file that could not be read.
    Record(RecordError),
}

impl fmt::Display for ExcitationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExcitationError::Unknown => write!(f, "must be one of: {}", NAMES.join(", ")),
            ExcitationError::Record(e) => e.fmt(f),
        }
    }
}

impl FromStr for Excitation {
    type Err = ExcitationError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Excitation::parse(s)
    }
}

impl fmt::Display for Excitation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl Serialize for Excitation {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> Deserialize<'de> for Excitation {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let text = String::deserialize(d)?;
        Excitation::parse(&text)
            .map_err(|e| serde::de::Error::custom(format!("excitation `{text}`: {e}")))
    }
}

/// 1/k for k < 64 (1/0 unused), so that 1/k! comes by multiplication.
const RECIPROCALS: [f64; 64] = {
    let mut r = [0.0; 64];
    let mut k = 1;
    while k < 64 {
        r[k] = 1.0 / k as f64;
        k += 1;
    }
    r
};

/// 1/k! for k < 64, each the one before times 1/k (with 1/k from
/// [`RECIPROCALS`]), a table so that the coefficients of a segment's ground
/// series are independent products.
const INV_FACTORIALS: [f64; 64] = {
    let mut f = [1.0; 64];
    let mut k = 1;
    while k < 64 {
        f[k] = f[k - 1] * RECIPROCALS[k];
        k += 1;
    }
    f
};

impl Excitation {
    /// Taylor coefficients of g about τ: g(τ + t) = Σ_k `out[k]` t^k, for
    /// k < out.len(). For the sine, g^{(k)}(τ) cycles through sin τ, cos τ,
    /// −sin τ, −cos τ, so `out[k]` = g^{(k)}(τ)/k!. The event-driven method
    /// expands the ground motion this way on each segment.
    pub fn taylor(&self, tau: f64, out: &mut [f64]) {
        match self {
            Excitation::Sine => sinusoid_taylor(1.0, tau, out),
            Excitation::None => out.iter_mut().for_each(|o| *o = 0.0),
            Excitation::Pulse(p) => {
                if (0.0..p.end()).contains(&tau) {
                    let (amp, theta) = p.sinusoid();
                    sinusoid_taylor(amp, tau + theta, out);
                } else {
                    out.iter_mut().for_each(|o| *o = 0.0);
                }
            }
            Excitation::Record(m) => {
                out.iter_mut().for_each(|o| *o = 0.0);
                let [g, slope] = m.value_slope(tau);
                if let Some(o) = out.get_mut(0) {
                    *o = g;
                }
                if let Some(o) = out.get_mut(1) {
                    *o = slope;
                }
            }
        }
    }

    /// The first τ after `tau` at which g changes formula (a kink or jump),
    /// where a segment of the event-driven method must end: never, for the
    /// sine; the pulse's end; the next sample of a record (its last sample,
    /// after which g = 0). Always > `tau`, so a segment never has zero length.
    pub fn next_break(&self, tau: f64) -> f64 {
        match self {
            Excitation::Sine | Excitation::None => f64::INFINITY,
            Excitation::Pulse(p) => {
                if tau < p.end() {
                    p.end()
                } else {
                    f64::INFINITY
                }
            }
            Excitation::Record(m) => {
                let k = m.interval(tau);
                let next = (k + 1) as f64 * m.spacing();
                if k + 1 < m.record.acceleration.len() && next > tau {
                    next
                } else {
                    f64::INFINITY
                }
            }
        }
    }
}

/// Taylor coefficients of a sin(θ + t) about t = 0: the derivatives cycle
/// through a(sin θ, cos θ, −sin θ, −cos θ), divided by k!.
fn sinusoid_taylor(amplitude: f64, theta: f64, out: &mut [f64]) {
    let (s, c) = theta.sin_cos();
    let cycle = [s, c, -s, -c].map(|v| amplitude * v);
    // Four terms at a time, one per phase of the cycle (a vector product).
    let (head, tail) = out.split_at_mut(out.len().min(INV_FACTORIALS.len()));
    for (o, f) in head.chunks_mut(4).zip(INV_FACTORIALS.chunks(4)) {
        for ((o, f), g) in o.iter_mut().zip(f).zip(cycle) {
            *o = g * f;
        }
    }
    // Terms past the 63rd (never asked for: series stop at degree 20) are
    // below 1/64! ≈ 8e-90 of the amplitude: zero.
    tail.fill(0.0);
}

/// Advances the phasor (sin τ, cos τ) by a fixed step h:
/// sin(τ+h) = sin τ cos h + cos τ sin h, cos(τ+h) = cos τ cos h − sin τ sin h.
/// Each use adds about one rounding error, so a run re-synchronises the
/// phasor from τ now and then ([`Excitation::phasor`]). It maps the zero
/// phasor of [`Excitation::None`] to itself.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    pub step: f64,
    sin: f64,
    cos: f64,
}

impl Rotation {
    pub fn new(step: f64) -> Self {
        let (sin, cos) = step.sin_cos();
        Rotation { step, sin, cos }
    }

    #[inline]
    pub fn advance(&self, [s, c]: [f64; 2]) -> [f64; 2] {
        [s * self.cos + c * self.sin, c * self.cos - s * self.sin]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_tracks_sine() {
        let r = Rotation::new(0.001);
        let mut p = Excitation::Sine.phasor(0.0);
        for _ in 0..1000 {
            p = r.advance(p);
        }
        assert!((p[0] - 1f64.sin()).abs() < 1e-14 && (p[1] - 1f64.cos()).abs() < 1e-14);
    }

    #[test]
    fn taylor_series_of_the_sine_sums_to_it() {
        let mut c = [0.0; 24];
        Excitation::Sine.taylor(0.3, &mut c);
        let t: f64 = 1.2;
        let sum: f64 = c
            .iter()
            .enumerate()
            .map(|(k, a)| a * t.powi(k as i32))
            .sum();
        assert!((sum - 1.5f64.sin()).abs() < 1e-15);
    }
}
