//! What a run records is the caller's choice: the driver hands every accepted
//! state to an [`Observer`]. The run summary (peaks, impacts, energy) is
//! always kept by the driver itself, so "peaks only" is the empty observer
//! `()`, which records nothing and allocates nothing per step.

use std::io::{self, Write};

use crate::model::Excitation;
use crate::output::Num;

/// One accepted state of the two-structure system (SPEC §2–4).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sample {
    /// Dimensionless time τ.
    pub tau: f64,
    /// Displacements x1, x2 relative to the ground.
    pub x: [f64; 2],
    /// Velocities ẋ1, ẋ2.
    pub v: [f64; 2],
    /// Accelerations ẍ1, ẍ2.
    pub a: [f64; 2],
    /// Spring forces f_s1, f_s2 (SPEC §3).
    pub fs: [f64; 2],
    /// Pounding force f_p (SPEC §4); positive pushes the structures apart.
    pub fp: f64,
    /// Whether the structures are in contact at this state.
    pub in_contact: bool,
}

/// Number of recorded channels, in the order of [`Sample::channels`].
pub const CHANNELS: usize = 9;
/// Names of the channels, as in the history CSV header after `tau`.
pub const CHANNEL_NAMES: [&str; CHANNELS] =
    ["x1", "v1", "a1", "x2", "v2", "a2", "fs1", "fs2", "fp"];

impl Sample {
    /// The recorded values in the order of [`CHANNEL_NAMES`].
    #[inline]
    pub fn channels(&self) -> [f64; CHANNELS] {
        [
            self.x[0], self.v[0], self.a[0], self.x[1], self.v[1], self.a[1], self.fs[0],
            self.fs[1], self.fp,
        ]
    }
}

/// Receives every accepted state, in time order, starting with τ = 0.
pub trait Observer {
    /// Whether this observer looks at samples at all. Peaks only (`()`) does
    /// not, so a method that must construct each sample (the event-driven
    /// one evaluates its series at output instants) skips that work.
    const RECORDS: bool = true;

    fn record(&mut self, sample: &Sample);

    /// Told now and then how far the run has come, also when the observer
    /// does not record samples (progress bars).
    fn reached(&mut self, _tau: f64) {}

    /// Polled now and then by the driver; returning `false` stops the run
    /// early (its result says so). Lets a worker cancel a superseded run.
    fn keep_going(&mut self) -> bool {
        true
    }
}

/// Peaks only: records nothing (the run summary carries the peaks).
impl Observer for () {
    const RECORDS: bool = false;
    #[inline]
    fn record(&mut self, _: &Sample) {}
}

impl<O: Observer + ?Sized> Observer for &mut O {
    const RECORDS: bool = O::RECORDS;
    #[inline]
    fn record(&mut self, sample: &Sample) {
        (**self).record(sample)
    }
    fn reached(&mut self, tau: f64) {
        (**self).reached(tau)
    }
    fn keep_going(&mut self) -> bool {
        (**self).keep_going()
    }
}

/// The full history: every accepted state.
#[derive(Debug, Clone, Default)]
pub struct FullHistory {
    pub samples: Vec<Sample>,
}

impl FullHistory {
    /// An empty history with room for `steps` samples.
    pub fn with_capacity(steps: usize) -> Self {
        FullHistory {
            samples: Vec::with_capacity(steps),
        }
    }
}

impl Observer for FullHistory {
    #[inline]
    fn record(&mut self, sample: &Sample) {
        self.samples.push(*sample);
    }
}

/// The header of the history CSV without the ground: τ, then the channels.
pub const CSV_HEADER: &str = "tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp";

/// Names of the ground columns the history CSV appends (SPEC §9, Π form):
/// the ground acceleration g, velocity u̇_g ω_p/a_p and displacement u_g ω_p²/a_p.
pub const GROUND_NAMES: [&str; 3] = ["ag", "vg", "ug"];

/// One row of the history CSV (every value in its shortest round-trip form),
/// with the ground motion at τ appended when `ground` is given.
pub fn write_csv_row(
    out: &mut impl Write,
    s: &Sample,
    ground: Option<&Excitation>,
) -> io::Result<()> {
    write!(out, "{}", Num(s.tau))?;
    for v in s.channels() {
        write!(out, ",{}", Num(v))?;
    }
    if let Some(e) = ground {
        for v in e.ground(s.tau) {
            write!(out, ",{}", Num(v))?;
        }
    }
    out.write_all(b"\n")
}

/// The history streamed as CSV ([`CSV_HEADER`], then [`GROUND_NAMES`] when
/// the excitation is given; one row per accepted state) to a writer while
/// the run goes, so memory stays bounded whatever its length. The first
/// write error stops the run; [`CsvHistory::finish`] returns it.
pub struct CsvHistory<W: Write> {
    out: W,
    rows: u64,
    error: Option<io::Error>,
    /// The run's excitation, whose ground motion each row carries.
    ground: Option<Excitation>,
}

impl<W: Write> CsvHistory<W> {
    /// Writes the header (the structures only) to `out`.
    pub fn new(out: W) -> Self {
        Self::start(out, None)
    }

    /// Writes the header to `out`, with the ground columns of `excitation`
    /// (as the solvers take it: [`crate::model::Params::ground`]).
    pub fn with_ground(out: W, excitation: Excitation) -> Self {
        Self::start(out, Some(excitation))
    }

    fn start(mut out: W, ground: Option<Excitation>) -> Self {
        let names = if ground.is_some() {
            GROUND_NAMES.as_slice()
        } else {
            &[]
        };
        let error = write!(out, "{CSV_HEADER}")
            .and_then(|()| names.iter().try_for_each(|n| write!(out, ",{n}")))
            .and_then(|()| writeln!(out))
            .err();
        CsvHistory {
            out,
            rows: 0,
            error,
            ground,
        }
    }

    /// The writer back and the number of rows written, or the first write error.
    pub fn finish(self) -> Result<(W, u64), (W, io::Error)> {
        match self.error {
            None => Ok((self.out, self.rows)),
            Some(e) => Err((self.out, e)),
        }
    }
}

impl<W: Write> Observer for CsvHistory<W> {
    #[inline]
    fn record(&mut self, sample: &Sample) {
        if self.error.is_none() {
            match write_csv_row(&mut self.out, sample, self.ground.as_ref()) {
                Ok(()) => self.rows += 1,
                Err(e) => self.error = Some(e),
            }
        }
    }

    fn keep_going(&mut self) -> bool {
        self.error.is_none()
    }
}

/// Minimum and maximum of every channel over one time bucket.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bucket {
    /// Start of the bucket in τ.
    pub tau: f64,
    pub min: [f64; CHANNELS],
    pub max: [f64; CHANNELS],
    /// Whether any sample fell in the bucket.
    pub filled: bool,
}

/// A history decimated to `N` equal time buckets over [0, τ_end], keeping the
/// minimum and maximum of every channel per bucket, so that peaks survive
/// (a chart draws each bucket as a vertical span). Allocates once, up front.
#[derive(Debug, Clone)]
pub struct Decimated {
    tau_end: f64,
    pub buckets: Vec<Bucket>,
}

impl Decimated {
    pub fn new(buckets: usize, tau_end: f64) -> Self {
        let n = buckets.max(1);
        let width = tau_end / n as f64;
        Decimated {
            tau_end,
            buckets: (0..n)
                .map(|i| Bucket {
                    tau: i as f64 * width,
                    min: [f64::INFINITY; CHANNELS],
                    max: [f64::NEG_INFINITY; CHANNELS],
                    filled: false,
                })
                .collect(),
        }
    }

    /// The filled buckets only.
    pub fn filled(&self) -> impl Iterator<Item = &Bucket> {
        self.buckets.iter().filter(|b| b.filled)
    }
}

impl Observer for Decimated {
    #[inline]
    fn record(&mut self, s: &Sample) {
        let n = self.buckets.len();
        let i = if self.tau_end > 0.0 {
            ((s.tau / self.tau_end) * n as f64) as usize
        } else {
            0
        };
        let b = &mut self.buckets[i.min(n - 1)];
        b.filled = true;
        for (k, v) in s.channels().into_iter().enumerate() {
            b.min[k] = b.min[k].min(v);
            b.max[k] = b.max[k].max(v);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimation_keeps_peaks() {
        let mut d = Decimated::new(10, 1.0);
        for i in 0..=1000 {
            let tau = i as f64 / 1000.0;
            let s = Sample {
                tau,
                x: [(40.0 * tau).sin(), 0.0],
                ..Default::default()
            };
            d.record(&s);
        }
        let max = d.buckets.iter().map(|b| b.max[0]).fold(f64::MIN, f64::max);
        assert!(max > 0.9999, "peak lost: {max}");
        assert!(d.buckets.iter().all(|b| b.filled));
    }

    #[test]
    fn csv_history_streams_rows_that_read_back_exactly() {
        let samples = [
            Sample::default(),
            Sample {
                tau: 0.001,
                x: [1.0 / 3.0, -2e-20],
                fp: 39.224_6,
                ..Default::default()
            },
        ];
        let mut csv = CsvHistory::new(Vec::new());
        for s in &samples {
            csv.record(s);
        }
        let (bytes, rows) = csv.finish().map_err(|(_, e)| e).unwrap();
        assert_eq!(rows, 2);
        let text = String::from_utf8(bytes).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], CSV_HEADER);
        assert_eq!(CSV_HEADER, format!("tau,{}", CHANNEL_NAMES.join(",")));
        assert_eq!(lines[1], "0,0,0,0,0,0,0,0,0,0");
        let values: Vec<f64> = lines[2].split(',').map(|v| v.parse().unwrap()).collect();
        assert_eq!(values[0], 0.001);
        assert_eq!(values[1], 1.0 / 3.0);
        assert_eq!(values[4], -2e-20);
        assert_eq!(values[9], 39.224_6);
    }

    #[test]
    fn csv_history_stops_the_run_at_the_first_write_error() {
        struct Full;
        impl Write for Full {
            fn write(&mut self, _: &[u8]) -> io::Result<usize> {
                Err(io::Error::new(io::ErrorKind::StorageFull, "full"))
            }
            fn flush(&mut self) -> io::Result<()> {
                Ok(())
            }
        }
        let mut csv = CsvHistory::new(Full);
        csv.record(&Sample::default());
        assert!(!csv.keep_going());
        assert!(csv.finish().is_err());
    }
}
