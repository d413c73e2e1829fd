//! The floor a record run is measured against: the Nigam–Jennings pass of
//! the two elastic oscillators over the record's samples (SPEC §9), written
//! as plainly as C would be: one exact 2 × 4 update per structure per
//! interval and the sampled peaks, no events, no contact, nothing located
//! between samples. No solver can take a record for less per sample, so
//! the ratio of a run's time to this pass's is its overhead.
//!
//! Per unit mass each structure obeys ẍ + 2ζω ẋ + ω² x = −g, g linear
//! between samples. With the free transition H(h) of the damped oscillator
//! (ω_d = ω√(1 − ζ²), e = exp(−ζωh)),
//!
//! ```text
//! H = e [cos ω_d h + (ζω/ω_d) sin ω_d h,   sin ω_d h / ω_d;
//!        −(ω²/ω_d) sin ω_d h,              cos ω_d h − (ζω/ω_d) sin ω_d h],
//! ```
//!
//! and the particular solutions x_p = −a/K for g = a and
//! x_p = −b t/K + b c/K² for g = b t (K = ω², c = 2ζω), the state one
//! interval on is y₁ = A y₀ + B (g_k, g_{k+1}), the classical recurrence.

use std::sync::Arc;

use crate::model::record::Record;
use crate::model::{Excitation, Params};

/// The Nigam–Jennings recurrence of both structures over one record.
#[derive(Debug, Clone)]
pub struct NigamJennings {
    /// Per structure: [A11, A12, A21, A22, B11, B12, B21, B22].
    coefficients: [[f64; 8]; 2],
    /// The record, whose accelerations (in its units) the pass reads, and
    /// the factor to g.
    record: Arc<Record>,
    factor: f64,
    /// Intervals of the free tail after the record (g = 0), of the same length.
    tail: usize,
}

impl NigamJennings {
    /// For `p` under a record (`None` for any other excitation, or with ζ ≥ 1).
    /// Both structures are taken elastic and apart, whatever `p` says.
    pub fn new(p: &Params) -> Option<Self> {
        let Excitation::Record(m) = p.ground() else {
            return None;
        };
        let h = m.record.dt * m.omega;
        let zeta = p.damping;
        if zeta.is_nan() || zeta >= 1.0 || m.record.acceleration.len() < 2 {
            return None;
        }
        let tail_length = p.tau_end() - m.end();
        let coefficients = [p.omega1, p.omega2].map(|omega| {
            let k = omega * omega;
            let c = 2.0 * zeta * omega;
            let wd = omega * (1.0 - zeta * zeta).sqrt();
            let e = (-zeta * omega * h).exp();
            let (sn, cs) = (wd * h).sin_cos();
            let h11 = e * (cs + zeta * omega / wd * sn);
            let h12 = e * sn / wd;
            let h21 = -e * k / wd * sn;
            let h22 = e * (cs - zeta * omega / wd * sn);
            // Unit constant g = 1 and unit ramp g = t, from rest.
            let (xa, va) = ((h11 - 1.0) / k, h21 / k);
            let xb = -h / k + c / (k * k) * (1.0 - h11) + h12 / k;
            let vb = -1.0 / k - h21 * c / (k * k) + h22 / k;
            // g = g_k + (g_{k+1} − g_k) t/h.
            [h11, h12, h21, h22, xa - xb / h, xb / h, va - vb / h, vb / h]
        });
        Some(NigamJennings {
            coefficients,
            record: m.record,
            factor: m.scale / m.amplitude,
            tail: (tail_length / h).ceil().max(0.0) as usize,
        })
    }

    /// Intervals the pass takes: the record's and the tail's.
    pub fn intervals(&self) -> usize {
        self.record.acceleration.len() - 1 + self.tail
    }

    /// The sampled peaks [max |x1|, max |ẋ1|, max |x2|, max |ẋ2|] from rest.
    pub fn peaks(&self) -> [f64; 4] {
        let [a, b] = &self.coefficients;
        let (mut x1, mut v1, mut x2, mut v2) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let (mut u1, mut w1, mut u2, mut w2) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let f = self.factor;
        let acc = &self.record.acceleration[..];
        let mut g0 = acc[0] * f;
        let mut step = |g0: f64, g1: f64| {
            let y1 = a[0] * x1 + a[1] * v1 + a[4] * g0 + a[5] * g1;
            let z1 = a[2] * x1 + a[3] * v1 + a[6] * g0 + a[7] * g1;
            let y2 = b[0] * x2 + b[1] * v2 + b[4] * g0 + b[5] * g1;
            let z2 = b[2] * x2 + b[3] * v2 + b[6] * g0 + b[7] * g1;
            (x1, v1, x2, v2) = (y1, z1, y2, z2);
            u1 = u1.max(y1.abs());
            w1 = w1.max(z1.abs());
            u2 = u2.max(y2.abs());
            w2 = w2.max(z2.abs());
        };
        for &next in &acc[1..] {
            let g1 = next * f;
            step(g0, g1);
            g0 = g1;
        }
        for _ in 0..self.tail {
            step(0.0, 0.0);
        }
        [u1, w1, u2, w2]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::record::{Record, intern};
    use crate::model::{Excitation, RecordMotion, SET1};
    use crate::solver::exact::{self, ExactOptions};

    /// The sampled peaks lie below the exact method's true peaks of the
    /// elastic pair apart, and within what a sample can miss of them.
    #[test]
    fn the_floor_samples_the_exact_elastic_response() {
        let a: Vec<f64> = (0..400)
            .map(|k| (0.37 * k as f64).sin() * (-(k as f64 - 150.0).powi(2) / 8e3).exp())
            .collect();
        let record = intern(Record::from_samples("floor-test", 0.01, a));
        let p = Params {
            excitation: Excitation::Record(RecordMotion::new(record)),
            yield1: f64::INFINITY,
            yield2: f64::INFINITY,
            gap: f64::INFINITY,
            ..SET1
        };
        let floor = NigamJennings::new(&p).expect("a record").peaks();
        let options = ExactOptions {
            energy: false,
            absolute_acceleration: false,
            ..crate::solver::dispatch::exact_options(&p)
        };
        let exact = exact::simulate(&p, &options, &mut ()).peaks();
        for (f, e) in floor.iter().zip(exact) {
            assert!(*f <= e * (1.0 + 1e-12) && *f >= 0.98 * e, "{f} vs {e}");
        }
    }
}
