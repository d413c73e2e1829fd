//! The exact method's cost under a record against the floor of
//! [`super::floor`], side by side in one process (`pounding bench
//! --excitation record:PATH`): three cases (the elastic pair apart; the
//! inelastic pair apart; the pair pounding), each as a peaks-only run (the
//! peaks and the impacts, as a sweep runs it) and as a full run (energy,
//! absolute accelerations, every contact extreme), each with the record's
//! quiet samples mapped and with every interval on the series (the method
//! before the maps, [`ExactOptions::quiet_samples`]).

use serde::Serialize;

use super::floor::NigamJennings;
use super::timing::median_ms;
use crate::model::Params;
use crate::solver::dispatch::exact_options;
use crate::solver::exact::{self, ContactExtremes, ExactOptions};

/// One case of one run kind.
#[derive(Debug, Clone, Serialize)]
pub struct RecordRow {
    pub case: &'static str,
    /// `peaks` (peaks and impacts) or `full` (energy and demands).
    pub run: &'static str,
    /// Intervals of the run: the record's and its free tail's.
    pub intervals: usize,
    /// Every interval on the series (the method before the quiet samples).
    pub series_ms: f64,
    /// Quiet samples by the linear map.
    pub ms: f64,
    pub ns_per_interval: f64,
    /// The Nigam–Jennings pass over the same intervals.
    pub floor_ms: f64,
    /// ms / floor_ms.
    pub ratio: f64,
    /// Impacts of the run.
    pub impacts: usize,
    /// Largest relative difference of the four peaks between the two paths.
    pub peak_difference: f64,
}

/// The three cases of `base` (which must carry a record).
pub fn cases(base: &Params) -> [(&'static str, Params); 3] {
    [
        (
            "elastic, no pounding",
            Params {
                yield1: f64::INFINITY,
                yield2: f64::INFINITY,
                gap: f64::INFINITY,
                ..base.clone()
            },
        ),
        (
            "inelastic, no pounding",
            Params {
                gap: f64::INFINITY,
                ..base.clone()
            },
        ),
        ("inelastic, pounding", base.clone()),
    ]
}

/// The two kinds of run of `p`: `peaks` (the peaks and the impacts, as a
/// sweep runs it) and `full` (energy, absolute accelerations, every contact
/// extreme, as `run` does).
pub fn runs(p: &Params) -> [(&'static str, ExactOptions); 2] {
    let full = exact_options(p);
    let peaks = ExactOptions {
        energy: false,
        absolute_acceleration: false,
        extremes: ContactExtremes::None,
        ..full.clone()
    };
    [("peaks", peaks), ("full", full)]
}

/// Every row for `base` under its record; `None` if its excitation is not one.
pub fn rows(base: &Params) -> Option<Vec<RecordRow>> {
    let floor = NigamJennings::new(base)?;
    let (floor_ms, _) = median_ms(|| floor.peaks());
    let intervals = floor.intervals();
    let mut out = Vec::new();
    for (case, p) in cases(base) {
        for (run, options) in runs(&p) {
            let series = ExactOptions {
                quiet_samples: false,
                ..options.clone()
            };
            let (series_ms, old) = median_ms(|| exact::simulate(&p, &series, &mut ()));
            let (ms, new) = median_ms(|| exact::simulate(&p, &options, &mut ()));
            let peak_difference = old
                .peaks()
                .iter()
                .zip(new.peaks())
                .map(|(a, b)| (a - b).abs() / a.abs().max(1e-300))
                .fold(0.0, f64::max);
            out.push(RecordRow {
                case,
                run,
                intervals,
                series_ms,
                ms,
                ns_per_interval: ms * 1e6 / intervals as f64,
                floor_ms,
                ratio: ms / floor_ms,
                impacts: new.impacts.len(),
                peak_difference,
            });
        }
    }
    Some(out)
}
