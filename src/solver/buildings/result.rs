//! What a row run returns (SPEC §13): per floor the peaks, per storey the
//! drift demands, per floor pair the impacts.

use serde::{Deserialize, Serialize};

/// Peaks of one floor and of the storey below it.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
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
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
    /// The floors' displacements over time, when asked for
    /// ([`super::RowOptions::trace`]).
    pub trace: Option<RowTrace>,
    /// The contact force of every floor pair over time, when asked for
    /// ([`super::RowOptions::forces`]).
    pub forces: Option<ForceHistory>,
    /// Where and when a building with P-Δ collapsed (SPEC §15): the run
    /// stops there, and every peak is the peak up to that instant.
    #[serde(default)]
    pub collapse: Option<Collapse>,
    /// Why sub-steps took the series, and where the time went
    /// ([`super::profile`]); not part of a run's output.
    #[serde(skip)]
    pub profile: super::profile::RowProfile,
    /// The contacts of every bumper element (SPEC §14), in the order of
    /// [`crate::model::buildings::Row::bumper_elements`]; empty without bumpers.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub bumpers: Vec<PairResult>,
    /// Every link's peaks and energy (SPEC §14), in file order; empty without links.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub links: Vec<super::link::LinkResult>,
}

/// A collapse (SPEC §15): the first instant a storey's |Δ_i|/h_i reaches
/// its building's `collapse_drift_ratio`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Collapse {
    /// Index of the building, left to right.
    pub building: usize,
    /// 1-based storey of that building, bottom to top.
    pub storey: usize,
    /// s.
    pub time: f64,
}

/// The contact force f_p(t) of every floor pair (SPEC §13), N: 0 at every
/// onset and separation, and inside each impact the force at the start and
/// end of every step the exact method takes through it and at the largest
/// value located on each step, so that its largest point is the impact's
/// [`PairImpact::max_force`]. Between two impacts the pair is open and the
/// force 0, a straight line between their points.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ForceHistory {
    /// Per pair in the layout's order, (t in s, f_p in N), t increasing.
    pub pairs: Vec<Vec<(f64, f64)>>,
    /// The same for every bumper element (SPEC §14); empty without bumpers.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub bumpers: Vec<Vec<(f64, f64)>>,
    /// Every link's force F (N) at the end of every sub-step and step
    /// (SPEC §14); empty without links.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub links: Vec<Vec<(f64, f64)>>,
}

impl ForceHistory {
    /// Appends (t, f) to pair `pair`'s history, unless it repeats the last point.
    pub fn push(&mut self, pair: usize, t: f64, f: f64) {
        let history = &mut self.pairs[pair];
        if history.last() != Some(&(t, f)) {
            history.push((t, f));
        }
    }
}

/// The displacement u_i(t) of every floor at the end of every sub-step:
/// exact there (SPEC §13's closed form or its series), and at most one
/// sub-step apart (one radian of the fastest mode, and the record's samples).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct RowTrace {
    /// Floors in the row's order.
    pub dofs: usize,
    /// Times (s), increasing, from 0.
    pub times: Vec<f64>,
    /// u of every floor at each time, `dofs` values a time (m).
    pub displacement: Vec<f64>,
}

impl RowTrace {
    pub fn new(dofs: usize) -> RowTrace {
        RowTrace {
            dofs,
            times: vec![0.0],
            displacement: vec![0.0; dofs],
        }
    }

    /// Appends the state u at time t.
    pub fn push(&mut self, t: f64, u: &[f64]) {
        self.times.push(t);
        self.displacement.extend_from_slice(u);
    }

    /// The displacements at the k-th recorded time.
    pub fn point(&self, k: usize) -> &[f64] {
        &self.displacement[k * self.dofs..(k + 1) * self.dofs]
    }

    /// u of every floor at time t, linear between the two recorded times
    /// around it (the recorded values themselves at those times); the ends
    /// hold outside [0, last time].
    pub fn at(&self, t: f64) -> Vec<f64> {
        let k = self.times.partition_point(|&s| s <= t);
        if k == 0 {
            return self.point(0).to_vec();
        }
        if k == self.times.len() {
            return self.point(k - 1).to_vec();
        }
        let (t0, t1) = (self.times[k - 1], self.times[k]);
        let w = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
        self.point(k - 1)
            .iter()
            .zip(self.point(k))
            .map(|(a, b)| a + w * (b - a))
            .collect()
    }
}

impl RowRun {
    /// Hard impacts at every floor pair (the bumpers' contacts aside).
    pub fn impacts(&self) -> usize {
        self.pairs.iter().map(|p| p.impacts.len()).sum()
    }

    /// Contacts of every kind: hard impacts and bumper contacts (SPEC §14).
    /// A run with none is the run of its buildings apart.
    pub fn contacts(&self) -> usize {
        self.impacts() + self.bumpers.iter().map(|p| p.impacts.len()).sum::<usize>()
    }
}
