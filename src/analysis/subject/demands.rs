//! What a study reads of one record's run, the same for the pair and a row
//! (SPEC §6, §13): per building its peak storey drift, drift ratio,
//! ductility, floor acceleration and collapse; per joint its impacts,
//! largest force and the gap that prevents pounding; all in SI. Beside
//! them, what the suite's statistics ([`Column`]) and the separation at a
//! probability ([`JointRecord`]) read of a record.

use crate::analysis::gap::CodeRules;

/// One building of a subject: its name and fundamental period T₁ (s).
#[derive(Debug, Clone, PartialEq)]
pub struct Building {
    pub name: String,
    pub period_s: f64,
}

/// One joint of a subject: the buildings on either side and the gap at
/// rest (m).
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    pub left: String,
    pub right: String,
    pub gap_m: f64,
}

/// One building's demands in one run, the largest over its storeys and
/// floors. A building that collapsed (SPEC §15) has drift ratio and
/// acceleration ∞, as a row's suite reports them; its drift and ductility
/// are the peaks up to the collapse (what the risk picture's IDA draws).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuildingDemand {
    /// max_i |Δ_i| (m); for the pair, max |x| of the one storey.
    pub peak_drift_m: f64,
    /// max_i |Δ_i|/h_i; `None` for the pair, whose table gives no height.
    pub drift_ratio: Option<f64>,
    /// max_i |Δ_i|/Δ_y,i (∞ for an elastic storey of a row; the pair's
    /// elastic structure has its own rule, SPEC §6).
    pub ductility: f64,
    /// max_i |ü_i + ü_g| (g).
    pub acceleration_g: f64,
    /// It collapsed in this run.
    pub collapsed: bool,
    /// Another building collapsed and the run stopped there.
    pub cut_short: bool,
}

/// One joint's demands in one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointDemand {
    /// Impacts over its floor pairs.
    pub impacts: usize,
    /// The largest impact force (kN), 0 without impacts.
    pub max_force_kn: f64,
    /// The gap that prevents pounding (m), from the run without contact.
    pub min_gap_m: f64,
}

/// One record's demands: with contact, per building and per joint, and the
/// buildings' with every joint open.
#[derive(Debug, Clone, PartialEq)]
pub struct Demands {
    pub buildings: Vec<BuildingDemand>,
    pub joints: Vec<JointDemand>,
    pub no_pounding: Vec<BuildingDemand>,
}

/// One demand over a suite, as a subject names it for its statistics: its
/// key (`left.peak_displacement_m`, `joint1.max_force_kn`, …), its unit and
/// one value per record.
pub type Column = (String, &'static str, Vec<f64>);

/// One record at one joint, from its run without contact: the gap that
/// prevents pounding, the code rules on its separate peaks (the largest
/// over the joint's paired floors) and each paired floor's separate peaks
/// (m). The pair has one joint and one paired floor: its left and right
/// roofs.
#[derive(Debug, Clone, PartialEq)]
pub struct JointRecord {
    pub min_gap: f64,
    pub rules: CodeRules,
    pub floors: Vec<(f64, f64)>,
}
