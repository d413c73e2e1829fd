//! Where a row run's time goes (SPEC §13): why each sub-step left the
//! cached linear map for the series, how many series steps each reason
//! cost, which events changed the configuration, and, when asked for
//! ([`super::RowOptions::profile`]), the time in map steps, series steps
//! and matrix exponentials.
//!
//! The counts are a function of the run alone (the same for every run of
//! the same row and ground); the times are measured, so they are zero
//! unless asked for, and two runs of the same inputs compare equal.

/// Why a sub-step went by the series instead of the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// A floor pair may close inside it (its gap's range reaches d).
    Onset,
    /// An elastic storey may reach its yield drift.
    Yield,
    /// A yielding storey's drift rate may change sign.
    Unload,
    /// A storey of a building with P-Δ may reach its collapse drift.
    Collapse,
    /// A floor's |u|, |u̇|, |ü + ü_g|, a drift or a relative displacement
    /// may pass its running peak inside, not monotone there.
    Peak,
    /// A floor pair is in contact (a contact phase).
    Contact,
    /// The row has a fluid viscous damper (SPEC §14): its force is
    /// nonlinear at every instant, so no sub-step goes by the map.
    Damper,
    /// The configuration has been met fewer than
    /// [`super::driver::FRESH`] times in this run: over so few sub-steps a
    /// map costs more than the series.
    Fresh,
    /// Every sub-step by the series was asked for
    /// ([`super::RowOptions::series_only`]).
    SeriesOnly,
    /// The sub-step in which a run continued from a checkpoint starts
    /// ([`super::driver::Checkpoint`]): from the checkpoint's instant
    /// inside it, by the series.
    Continued,
}

/// Counts per [`Cause`], in its order.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PerCause(pub [usize; 10]);

impl PerCause {
    pub fn add(&mut self, cause: Cause, count: usize) {
        self.0[cause as usize] += count;
    }
    pub fn of(&self, cause: Cause) -> usize {
        self.0[cause as usize]
    }
    pub fn total(&self) -> usize {
        self.0.iter().sum()
    }
}

/// Events applied, by kind: each changes the configuration (the collapse
/// stops the run; a Jankowski turn changes only the damping's sign, a
/// damper's reversal only the sign its next one is watched against).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Events {
    pub yields: usize,
    pub unloads: usize,
    pub onsets: usize,
    pub separations: usize,
    pub turns: usize,
    pub collapses: usize,
    /// Reversals of a fluid viscous damper's Δv (SPEC §14).
    pub reversals: usize,
}

/// What the collocated steps of a row with dampers cost: steps accepted
/// and rejected for their error, solves of their nodes (one per step,
/// three where the step is doubled near a damper's reversal, and those of
/// the steps retaken to place events), Newton iterations over the solves,
/// and response sets made (one per configuration met).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CollocationSteps {
    pub accepted: usize,
    pub rejected: usize,
    pub solves: usize,
    pub newton: usize,
    pub responses: usize,
    /// Steps of such a row taken instead by the series with the dampers'
    /// forces in it ([`super::power_series`]).
    pub series: usize,
}

/// The profile of one run.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RowProfile {
    /// Sub-steps taken by the cached map.
    pub map_steps: usize,
    /// Of those, sub-steps whose rising peaks were located on their closed
    /// form (a series from their start) instead of a series walk.
    pub located: usize,
    /// Of the map steps, those that the cubics' ranges could not clear of
    /// an onset, a yield or a peak rising inside, and that the quintics of
    /// [`super::quintic`] cleared of each, so that nothing was located.
    pub held: usize,
    /// Sub-steps that went by the series, by cause.
    pub careful: PerCause,
    /// Series (or Runge–Kutta) steps, by the cause of their sub-step.
    pub series: PerCause,
    pub events: Events,
    /// The steps of a row with a fluid viscous damper by exponential
    /// collocation ([`super::damper_collocation`]).
    pub collocation: CollocationSteps,
    /// Linear maps made (each a matrix exponential and its bounds).
    pub maps_made: usize,
    /// Seconds in map steps (every quiet test, passed or not, and the maps
    /// made there), in series sub-steps, and in making maps (a part of the
    /// first); 0 unless asked for.
    pub map_seconds: f64,
    pub series_seconds: f64,
    pub exponential_seconds: f64,
}

/// Names of the causes, in [`Cause`]'s order, for tables.
pub const CAUSES: [&str; 10] = [
    "onset",
    "yield",
    "unload",
    "collapse",
    "peak",
    "contact",
    "damper",
    "fresh",
    "series-only",
    "continued",
];
