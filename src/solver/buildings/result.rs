//! What a row run returns (SPEC §13): per floor the peaks, per storey the
//! drift demands, per floor pair the impacts.

/// Peaks of one floor and of the storey below it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FloorPeaks {
    /// max |u_i| (m).
    pub displacement: f64,
    /// max |u̇_i| (m/s).
    pub velocity: f64,
    /// max |ü_i + ü_g| (m/s²).
    pub absolute_acceleration: f64,
    /// max |Δ_i| (m).
    pub drift: f64,
    /// max |Δ_i| / h_i.
    pub drift_ratio: f64,
    /// max |Δ_i| / Δ_y,i (∞ for an elastic storey).
    pub ductility: f64,
    /// (1 − α)(Δ_i − z_i) at the end (m).
    pub residual_drift: f64,
}

/// One impact at a floor pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairImpact {
    pub start: f64,
    /// When it separated (NaN if still in contact at the end).
    pub end: f64,
    /// δ̇ at onset (m/s).
    pub approach_velocity: f64,
    /// −δ̇ at separation (m/s).
    pub separation_velocity: f64,
    /// Largest force (N) and penetration (m) during it.
    pub max_force: f64,
    pub max_penetration: f64,
}

/// The impacts of one floor pair.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PairResult {
    pub impacts: Vec<PairImpact>,
}

impl PairResult {
    pub fn max_force(&self) -> f64 {
        self.impacts.iter().map(|i| i.max_force).fold(0.0, f64::max)
    }
    pub fn max_penetration(&self) -> f64 {
        self.impacts
            .iter()
            .map(|i| i.max_penetration)
            .fold(0.0, f64::max)
    }
}

/// A row run: floors of each building bottom to top, pairs in the layout's order.
#[derive(Debug, Clone, PartialEq)]
pub struct RowRun {
    pub floors: Vec<Vec<FloorPeaks>>,
    pub pairs: Vec<PairResult>,
    pub duration: f64,
    /// (u, u̇) of every floor at the end, in the row's order.
    pub final_displacement: Vec<f64>,
    pub final_velocity: Vec<f64>,
    /// max over time of u_A − u_B at each facing floor pair
    /// ([`crate::model::buildings::Row::facing_floors`]), m; at rest 0.
    pub max_relative: Vec<f64>,
    /// The energy balance, when asked for ([`super::RowOptions::energy`]).
    pub energy: Option<super::energy::RowEnergy>,
    /// Linear maps made, and sub-steps taken with them, and sub-steps that
    /// needed the series.
    pub maps_made: usize,
    pub map_steps: usize,
    pub series_steps: usize,
    /// Configurations (branch patterns) seen out of contact.
    pub configurations: usize,
}

impl RowRun {
    pub fn impacts(&self) -> usize {
        self.pairs.iter().map(|p| p.impacts.len()).sum()
    }
}
