//! What a request will cost, estimated before it starts, and the bounds
//! above which the user must confirm it (`--allow-long`, `--allow-large`).
//!
//! The estimate counts nominal Newmark steps, τ_end/Δτ per run, and an exact
//! run as the Newmark steps of the same time ([`run_steps`], from
//! [`analysis::work`](crate::analysis::work)): contact sub-steps add about
//! 10 % on the paper's sets (set1: 55 840 accepted steps for 50 266 nominal)
//! and more for stiff contact, so the estimate is an order of magnitude of
//! the work's time, not a measurement.

use clap::Args;

use super::CliError;
use crate::analysis::work;
use crate::model::Params;

/// Work above which a command asks for `--allow-long`: 1e10 steps, about
/// five minutes at [`SECONDS_PER_STEP`].
pub const MAX_STEPS: f64 = 1e10;
/// Cost of one Newmark step ([`work::SECONDS_PER_NEWMARK_STEP`]): the unit of [`Work::steps`].
pub const SECONDS_PER_STEP: f64 = work::SECONDS_PER_NEWMARK_STEP;
/// History size above which `run` asks for `--allow-large`: 1 GB.
pub const MAX_OUTPUT_BYTES: f64 = 1e9;
/// Bytes of one history CSV row, as estimated.
/// Rows of the paper's sets measure 180 (set1) and 185 (set2) bytes on
/// average; a row is at most 250 bytes (ten cells of 24 characters).
pub const HISTORY_ROW_BYTES: f64 = 200.0;
/// Cost of formatting and writing one history row, measured in a release
/// build: about 1 µs of CPU (`run --cycles 20000 --history /dev/null
/// --allow-large`: 135 s of user time for 1.38e8 rows).
pub const SECONDS_PER_ROW: f64 = 1e-6;

/// `--allow-long`, as every command that can be asked for long work takes it.
#[derive(Debug, Clone, Copy, Default, Args)]
pub struct LongArg {
    /// Run even when the estimated work exceeds 1e10 steps (several minutes).
    #[arg(long)]
    pub allow_long: bool,
}

/// The work of one run of `p` in Newmark steps: τ_end/Δτ by Newmark; by
/// the exact method, the Newmark steps of its estimated time (an exact run
/// of set 1 costs about what 1 500 steps do, a thirtieth of Newmark's).
pub fn run_steps(p: &Params) -> f64 {
    work::seconds(p) / SECONDS_PER_STEP
}

/// The work per unit τ of one run of `p` ([`run_steps`] / τ_end): how far a
/// progress bar moves as the run advances.
pub fn steps_per_tau(p: &Params) -> f64 {
    run_steps(p) / p.tau_end()
}

/// The estimated cost of a request; the cost of several is their sum.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Work {
    /// Newmark steps over all runs.
    pub steps: f64,
    /// History CSV rows written.
    pub rows: f64,
}

impl Work {
    /// The work of `steps` Newmark steps, writing no history.
    pub fn steps(steps: f64) -> Work {
        Work { steps, rows: 0.0 }
    }

    /// Estimated wall time in seconds.
    pub fn seconds(&self) -> f64 {
        self.steps * SECONDS_PER_STEP + self.rows * SECONDS_PER_ROW
    }

    /// Estimated history size in bytes (header aside).
    pub fn bytes(&self) -> f64 {
        self.rows * HISTORY_ROW_BYTES
    }

    /// Refuses work beyond [`MAX_STEPS`] without `allow_long` and output
    /// beyond [`MAX_OUTPUT_BYTES`] without `allow_large`; `what` describes
    /// the request in the message.
    pub fn check(&self, what: &str, allow_long: bool, allow_large: bool) -> Result<(), CliError> {
        if !allow_long && !within(self.steps, MAX_STEPS) {
            return Err(CliError::Usage(format!(
                "{what}: about {:.1e} steps (Newmark's, or their time by the exact method), \
                 an estimated {} (limit {MAX_STEPS:.0e} steps, about {}); pass --allow-long to run it",
                self.steps,
                duration(self.seconds()),
                duration(MAX_STEPS * SECONDS_PER_STEP)
            )));
        }
        if !allow_large && !within(self.bytes(), MAX_OUTPUT_BYTES) {
            return Err(CliError::Usage(format!(
                "{what}: the history would be about {} ({:.1e} rows; limit {}); \
                 pass --allow-large to write it",
                size(self.bytes()),
                self.rows,
                size(MAX_OUTPUT_BYTES)
            )));
        }
        Ok(())
    }
}

impl std::iter::Sum for Work {
    fn sum<I: Iterator<Item = Work>>(works: I) -> Work {
        works.fold(Work::default(), |sum, w| Work {
            steps: sum.steps + w.steps,
            rows: sum.rows + w.rows,
        })
    }
}

/// `value <= bound`, false for NaN (an estimate that is not a number is refused).
fn within(value: f64, bound: f64) -> bool {
    value.partial_cmp(&bound).is_some_and(|o| o.is_le())
}

/// A duration for people: `40 s`, `5 min`, `2.5 h`, `35 days`.
pub fn duration(seconds: f64) -> String {
    if !seconds.is_finite() {
        "forever".into()
    } else if seconds < 90.0 {
        format!("{seconds:.0} s")
    } else if seconds < 5400.0 {
        format!("{:.0} min", seconds / 60.0)
    } else if seconds < 172_800.0 {
        format!("{:.1} h", seconds / 3600.0)
    } else if seconds < 3.2e9 {
        format!("{:.0} days", seconds / 86_400.0)
    } else {
        format!("{:.1e} years", seconds / 3.156e7)
    }
}

/// A size for people in decimal units: `850 MB`, `25 GB`.
pub fn size(bytes: f64) -> String {
    let units = ["B", "kB", "MB", "GB", "TB", "PB"];
    let mut v = bytes;
    let mut i = 0;
    while v >= 1000.0 && i + 1 < units.len() {
        v /= 1000.0;
        i += 1;
    }
    if i + 1 == units.len() && v >= 1000.0 {
        format!("{bytes:.1e} B")
    } else {
        format!("{v:.0} {}", units[i])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_need_their_flags() {
        let long = Work::steps(1e14);
        let e = long.check("run", false, false).unwrap_err().to_string();
        assert!(e.contains("--allow-long") && e.contains("35 days"), "{e}");
        assert!(long.check("run", true, false).is_ok());
        let large = Work {
            steps: 1.3e8,
            rows: 1.3e8,
        };
        let e = large.check("run", false, false).unwrap_err().to_string();
        assert!(e.contains("--allow-large") && e.contains("26 GB"), "{e}");
        assert!(large.check("run", false, true).is_ok());
        let nan = Work::steps(f64::NAN);
        assert!(nan.check("run", false, true).is_err());
    }

    #[test]
    fn sizes_and_durations_read_well() {
        assert_eq!(size(8.5e8), "850 MB");
        assert_eq!(size(2.5e10), "25 GB");
        assert_eq!(duration(40.0), "40 s");
        assert_eq!(duration(300.0), "5 min");
        assert_eq!(duration(3.0e6), "35 days");
    }
}
