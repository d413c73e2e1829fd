//! The ground acceleration ü_g(t) a row is shaken by (SPEC §9, in m/s²).
//!
//! Each piece of the motion is the solution of ä = σ a on its interval: a
//! record's sample interval is a straight line (σ = 0, a and ȧ from its two
//! samples), a sine or a cycloidal pulse is one piece with σ = −ω². After the
//! motion's end ü_g = 0. The methods carry (a, ȧ) beside the state, so that
//! they stay exact on each piece.
//!
//! The cycloidal pulses of SPEC §9 are sines with a phase and an end, and the
//! type B pulse's ground starts moving:
//!
//! ```text
//! A:  ü_g =  a_p sin(ω_p t)       on [0, T_p],                 u̇_g(0) = 0,
//! B:  ü_g = −a_p sin(ω_p t)       on [0, T_p],                 u̇_g(0) = V_p = a_p/ω_p,
//! Cn: ü_g =  a_p cos(ω_p t + φ)   on [0, (n + ½ − φ/π) T_p],   u̇_g(0) = 0,
//! ```
//!
//! so that in relative coordinates every floor starts with u̇_i(0) = −u̇_g(0).

use crate::model::excitation::Pulse;
use crate::model::record::Record;

/// A ground motion in physical units.
#[derive(Debug, Clone, PartialEq)]
pub enum Ground {
    /// ü_g = A sin(ωt + θ) on [0, end], 0 after; the ground starts with
    /// velocity u̇_g(0) = `velocity` (m/s), the floors with −`velocity`
    /// relative to it.
    Sine {
        amplitude: f64,
        omega: f64,
        /// θ (rad).
        phase: f64,
        end: f64,
        /// u̇_g(0) (m/s).
        velocity: f64,
    },
    /// A record: ü_g linear between samples a_k at t = k·dt, 0 after the last.
    Samples { dt: f64, acceleration: Vec<f64> },
}

/// One smooth piece [t0, t1] of the motion: ü_g(t0) = a, its rate ȧ, and σ
/// with d²ü_g/dt² = σ ü_g on the piece.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    pub t0: f64,
    pub t1: f64,
    /// t1 − t0, exactly DT for a record's full sample interval (so that
    /// every interval has the same length, bit for bit).
    pub length: f64,
    pub a: f64,
    pub rate: f64,
    pub sigma: f64,
}

impl Ground {
    /// ü_g = A sin(ωt) on [0, end], from rest.
    pub fn sine(amplitude: f64, omega: f64, end: f64) -> Ground {
        Ground::Sine {
            amplitude,
            omega,
            phase: 0.0,
            end,
            velocity: 0.0,
        }
    }

    /// The cycloidal pulse of SPEC §9 with a_p = `amplitude` (m/s²) and
    /// ω_p = `omega` (rad/s): its sinusoid, its end and its ground's
    /// initial velocity, each as [`Pulse`] gives it in Π form.
    pub fn from_pulse(pulse: Pulse, amplitude: f64, omega: f64) -> Ground {
        let (scale, phase) = pulse.sinusoid();
        Ground::Sine {
            amplitude: scale * amplitude,
            omega,
            phase,
            end: pulse.end() / omega,
            velocity: pulse.ground_velocity() * amplitude / omega,
        }
    }

    /// u̇_g(0) (m/s): every floor starts with u̇_i(0) = −u̇_g(0).
    pub fn initial_velocity(&self) -> f64 {
        match self {
            Ground::Sine { velocity, .. } => *velocity,
            Ground::Samples { .. } => 0.0,
        }
    }

    /// What a run's output says about the motion beyond its name: that the
    /// floors start moving relative to the ground (SPEC §9, type B pulse).
    pub fn note(&self) -> Option<String> {
        let v = self.initial_velocity();
        (v != 0.0).then(|| {
            format!(
                "the ground starts with velocity V_p = {v:.6} m/s: every floor starts with u̇(0) = {:.6} m/s",
                -v
            )
        })
    }

    pub fn from_record(record: &Record, scale: f64) -> Ground {
        Ground::Samples {
            dt: record.dt,
            acceleration: record.acceleration.iter().map(|a| a * scale).collect(),
        }
    }

    /// Where the motion ends (ü_g = 0 after).
    pub fn end(&self) -> f64 {
        match self {
            Ground::Sine { end, .. } => *end,
            Ground::Samples { dt, acceleration } => dt * (acceleration.len().max(1) - 1) as f64,
        }
    }

    /// ü_g(t).
    pub fn at(&self, t: f64) -> f64 {
        match self {
            Ground::Sine {
                amplitude,
                omega,
                phase,
                end,
                ..
            } => {
                if t <= *end {
                    amplitude * (omega * t + phase).sin()
                } else {
                    0.0
                }
            }
            Ground::Samples { dt, acceleration } => {
                let k = (t / dt).floor();
                let i = k as usize;
                if t < 0.0 || i + 1 >= acceleration.len() {
                    return if i + 1 == acceleration.len() && t == k * dt {
                        acceleration[i]
                    } else {
                        0.0
                    };
                }
                let s = (t - k * dt) / dt;
                acceleration[i] * (1.0 - s) + acceleration[i + 1] * s
            }
        }
    }

    /// The motion as the negated one (the mirror image of a row).
    pub fn negated(&self) -> Ground {
        match self {
            Ground::Sine {
                amplitude,
                omega,
                phase,
                end,
                velocity,
            } => Ground::Sine {
                amplitude: -amplitude,
                omega: *omega,
                phase: *phase,
                end: *end,
                velocity: -velocity,
            },
            Ground::Samples { dt, acceleration } => Ground::Samples {
                dt: *dt,
                acceleration: acceleration.iter().map(|a| -a).collect(),
            },
        }
    }

    /// The smooth pieces covering [0, until], in order.
    pub fn pieces(&self, until: f64) -> Vec<Piece> {
        let mut out = Vec::new();
        let end = self.end().min(until);
        match self {
            Ground::Sine {
                amplitude,
                omega,
                phase,
                ..
            } => {
                if end > 0.0 {
                    let (sin, cos) = phase.sin_cos();
                    out.push(Piece {
                        t0: 0.0,
                        t1: end,
                        length: end,
                        a: amplitude * sin,
                        rate: amplitude * omega * cos,
                        sigma: -omega * omega,
                    });
                }
            }
            Ground::Samples { dt, acceleration } => {
                for k in 0..acceleration.len().saturating_sub(1) {
                    let t0 = k as f64 * dt;
                    if t0 >= end {
                        break;
                    }
                    let full = (k + 1) as f64 * dt;
                    let t1 = full.min(until);
                    out.push(Piece {
                        t0,
                        t1,
                        length: if t1 == full { *dt } else { t1 - t0 },
                        a: acceleration[k],
                        rate: (acceleration[k + 1] - acceleration[k]) / dt,
                        sigma: 0.0,
                    });
                }
            }
        }
        let last = out.last().map_or(0.0, |p| p.t1);
        if until > last {
            out.push(Piece {
                t0: last,
                t1: until,
                length: until - last,
                a: 0.0,
                rate: 0.0,
                sigma: 0.0,
            });
        }
        out
    }
}
