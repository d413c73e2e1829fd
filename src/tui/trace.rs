//! The history a chart shows: the run decimated to the visible time window
//! [τ0, τ1] in equal buckets (two per plot column, as Braille has two dots
//! per cell), keeping per bucket the minimum and maximum of every channel
//! (so peaks survive) and the last sample (for the cursor readout and the
//! force–drift trace). Zoomed in, the same buckets cover a shorter window,
//! so detail appears; outside the window nothing is kept.

use crate::solver::Observer;
use crate::solver::observer::{CHANNELS, Sample};

/// One time bucket.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slice {
    /// Start of the bucket in τ.
    pub tau: f64,
    pub min: [f64; CHANNELS],
    pub max: [f64; CHANNELS],
    /// The last sample that fell in the bucket, and its τ.
    pub last: [f64; CHANNELS],
    pub last_tau: f64,
    /// Least and greatest x1 − x2 in the bucket (contact while it exceeds
    /// Π_d, SPEC §4).
    pub relative: [f64; 2],
    pub filled: bool,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    pub window: [f64; 2],
    pub slices: Vec<Slice>,
    /// The contact gap Π_d whose force–penetration loop is kept (None: none kept).
    gap: Option<f64>,
    /// (δ, f_p) of every sample in contact, δ = x1 − x2 − Π_d > 0 (SPEC §4),
    /// each contact ended by a (NaN, NaN) break; at most [`LOOP_POINTS`].
    pub contact: Vec<(f64, f64)>,
}

/// Most samples kept of the force–penetration loop (later contacts are left out).
pub const LOOP_POINTS: usize = 50_000;

impl Trace {
    pub fn new(buckets: usize, window: [f64; 2]) -> Trace {
        let n = buckets.max(1);
        let width = (window[1] - window[0]) / n as f64;
        Trace {
            window,
            slices: (0..n)
                .map(|i| Slice {
                    tau: window[0] + i as f64 * width,
                    min: [f64::INFINITY; CHANNELS],
                    max: [f64::NEG_INFINITY; CHANNELS],
                    last: [f64::NAN; CHANNELS],
                    last_tau: f64::NAN,
                    relative: [f64::INFINITY, f64::NEG_INFINITY],
                    filled: false,
                })
                .collect(),
            gap: None,
            contact: Vec::new(),
        }
    }

    /// Also keeps the force–penetration loop of contacts across `gap`.
    pub fn with_contact(mut self, gap: f64) -> Trace {
        self.gap = gap.is_finite().then_some(gap);
        self
    }

    pub fn filled(&self) -> impl Iterator<Item = &Slice> {
        self.slices.iter().filter(|s| s.filled)
    }

    /// A channel as (τ, min, max) spans, plus `offset`.
    pub fn spans(&self, channel: usize, offset: f64) -> Vec<(f64, f64, f64)> {
        self.filled()
            .map(|s| (s.tau, s.min[channel] + offset, s.max[channel] + offset))
            .filter(|(_, a, b)| a.is_finite() && b.is_finite())
            .collect()
    }

    /// x1 − x2 as (τ, min, max) spans.
    pub fn relative_spans(&self) -> Vec<(f64, f64, f64)> {
        self.filled()
            .map(|s| (s.tau, s.relative[0], s.relative[1]))
            .filter(|(_, a, b)| a.is_finite() && b.is_finite())
            .collect()
    }

    /// Two channels against each other through each bucket's last sample.
    pub fn pairs(&self, cx: usize, cy: usize) -> Vec<(f64, f64)> {
        self.filled()
            .map(|s| (s.last[cx], s.last[cy]))
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect()
    }

    /// The sample recorded nearest before τ (its τ and channels), if any.
    pub fn at(&self, tau: f64) -> Option<(f64, [f64; CHANNELS])> {
        let n = self.slices.len();
        let span = self.window[1] - self.window[0];
        if span.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
            || tau < self.window[0]
            || tau > self.window[1]
        {
            return None;
        }
        let i = (((tau - self.window[0]) / span) * n as f64) as usize;
        self.slices[..=i.min(n - 1)]
            .iter()
            .rev()
            .find(|s| s.filled)
            .map(|s| (s.last_tau, s.last))
    }
}

impl Observer for Trace {
    #[inline]
    fn record(&mut self, s: &Sample) {
        let [t0, t1] = self.window;
        if s.tau < t0 || s.tau > t1 {
            return;
        }
        let n = self.slices.len();
        let i = if t1 > t0 {
            (((s.tau - t0) / (t1 - t0)) * n as f64) as usize
        } else {
            0
        };
        let b = &mut self.slices[i.min(n - 1)];
        b.filled = true;
        let values = s.channels();
        for (k, v) in values.into_iter().enumerate() {
            b.min[k] = b.min[k].min(v);
            b.max[k] = b.max[k].max(v);
        }
        let relative = s.x[0] - s.x[1];
        b.relative = [b.relative[0].min(relative), b.relative[1].max(relative)];
        b.last = values;
        b.last_tau = s.tau;
        if let Some(gap) = self.gap {
            let delta = s.x[0] - s.x[1] - gap;
            let force = values[8];
            let in_contact = delta > 0.0 || force != 0.0;
            if in_contact && self.contact.len() < LOOP_POINTS {
                self.contact.push((delta.max(0.0), force));
            } else if !in_contact && self.contact.last().is_some_and(|p| p.0.is_finite()) {
                self.contact.push((f64::NAN, f64::NAN));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sine(trace: &mut Trace) {
        for i in 0..=10_000 {
            let tau = i as f64 * 1e-3;
            trace.record(&Sample {
                tau,
                x: [(3.0 * tau).sin(), 0.0],
                ..Default::default()
            });
        }
    }

    #[test]
    fn a_window_keeps_only_its_samples_and_reads_out_exactly() {
        let mut t = Trace::new(20, [2.0, 3.0]);
        sine(&mut t);
        assert!(t.slices.iter().all(|s| s.filled));
        assert!(
            t.slices
                .iter()
                .all(|s| s.last_tau >= 2.0 && s.last_tau <= 3.0)
        );
        let (tau, v) = t.at(2.5).unwrap();
        assert!((tau - 2.5).abs() <= 0.05 + 1e-12, "{tau}");
        assert!((v[0] - (3.0 * tau).sin()).abs() < 1e-12);
        assert_eq!(t.at(3.5), None);
    }

    #[test]
    fn the_contact_loop_keeps_samples_past_the_gap_and_breaks_between_contacts() {
        let mut t = Trace::new(4, [0.0, 10.0]).with_contact(0.5);
        sine(&mut t);
        // x1 = sin 3τ > 0.5 where 3τ ∈ (π/6, 5π/6) + 2πk: five arcs in
        // [0, 10] (the last ends at τ ≈ 9.25), each closed by a break.
        let breaks = t.contact.iter().filter(|p| p.0.is_nan()).count();
        assert_eq!(breaks, 5, "{breaks}");
        let top = t.contact.iter().fold(0f64, |m, p| m.max(p.0));
        assert!((top - 0.5).abs() < 1e-5, "{top}");
        assert!(t.contact.iter().all(|p| p.0.is_nan() || p.0 > 0.0));
    }

    #[test]
    fn peaks_survive_decimation() {
        let mut t = Trace::new(4, [0.0, 10.0]);
        sine(&mut t);
        let max = t.spans(0, 0.0).iter().fold(f64::MIN, |m, s| m.max(s.2));
        assert!(max > 0.99999, "{max}");
        // x2 = 0 here, so x1 − x2 keeps the same peaks as x1.
        let rel = t.relative_spans();
        let top = rel.iter().fold(f64::MIN, |m, s| m.max(s.2));
        let bottom = rel.iter().fold(f64::MAX, |m, s| m.min(s.1));
        assert!(top > 0.99999 && bottom < -0.99999, "{top} {bottom}");
    }
}
