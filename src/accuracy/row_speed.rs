//! A row run's cost against the dense floor of [`super::row_floor`], side
//! by side in one process, with the run's profile
//! ([`crate::solver::buildings::profile`]): why sub-steps took the series
//! and where the time went. `cargo bench --bench row_speed` prints it for
//! block-and-frame at three scales under both laws of the Kelvin family.

use crate::model::buildings::{Ground, Row};
use crate::solver::buildings::{RowError, RowOptions, RowProfile, run_row};

use super::row_floor::RowFloor;
use super::timing::median_ms;

/// One row of the table.
#[derive(Debug, Clone)]
pub struct RowSpeed {
    /// Median ms of a run with a fresh cache of maps (as `run` makes it).
    pub ms: f64,
    /// Median ms of the dense pass over the same pieces.
    pub floor_ms: f64,
    /// ms / floor_ms.
    pub ratio: f64,
    pub impacts: usize,
    /// The profile of one more run, timed.
    pub profile: RowProfile,
}

/// [`RowSpeed`] of `row` under `ground` over [0, `duration`].
pub fn row_speed(row: &Row, ground: &Ground, duration: f64) -> Result<RowSpeed, RowError> {
    let floor = RowFloor::new(row, ground, duration);
    let options = RowOptions::lasting(duration);
    let (floor_ms, _) = median_ms(|| floor.peaks());
    let (ms, run) = median_ms(|| run_row(row, ground, &options));
    let impacts = run?.impacts();
    let profiled = RowOptions {
        profile: true,
        ..options
    };
    let profile = run_row(row, ground, &profiled)?.profile;
    Ok(RowSpeed {
        ms,
        floor_ms,
        ratio: ms / floor_ms,
        impacts,
        profile,
    })
}
