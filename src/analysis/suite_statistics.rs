//! The statistics of a suite (SPEC §12): every demand its subject names
//! ([`Subject::columns`], the pair's or a row's), summarised over the
//! records by [`Summary::of`]: median, 16th and 84th percentiles and the
//! lognormal dispersion.

use serde::Serialize;

use super::statistics::Summary;
use super::subject::Subject;

/// One demand's statistics over a suite.
#[derive(Debug, Clone, Serialize)]
pub struct DemandSummary {
    /// The demand's key (`left.peak_displacement_m`, `max_force_kn`, …).
    pub demand: String,
    pub unit: &'static str,
    #[serde(flatten)]
    pub summary: Summary,
}

/// The statistics of a suite (SPEC §12).
#[derive(Debug, Clone, Serialize)]
pub struct SuiteStatistics {
    pub records: usize,
    /// Records with at least one impact.
    pub pounded: usize,
    pub demands: Vec<DemandSummary>,
}

impl SuiteStatistics {
    /// The statistics of a suite's `runs` of `subject`: every demand the
    /// subject names ([`Subject::columns`]) summarised over the records.
    pub fn of<S: Subject>(subject: &S, runs: &[S::Run]) -> SuiteStatistics {
        SuiteStatistics {
            records: runs.len(),
            pounded: runs.iter().filter(|r| subject.pounded(r)).count(),
            demands: subject
                .columns(runs)
                .into_iter()
                .map(|(demand, unit, values)| DemandSummary {
                    demand,
                    unit,
                    summary: Summary::of(&values),
                })
                .collect(),
        }
    }
}
