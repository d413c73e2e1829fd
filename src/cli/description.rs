//! What a report says about itself before its results, built here only and
//! flattened (`#[serde(flatten)]`) into each command's report, so every
//! command writes the same keys in the same order:
//!
//! - [`Provenance`]: `version`, `preset`, `units` (map, spectrum, gap, similarity, run);
//! - [`Case`]: `params`, `mu`, `model`, `excitation`, `excitation_note`,
//!   `method` (map, spectrum, run);
//! - [`Description`]: both, then the `region_threshold` of SPEC §7, for the
//!   reports that classify regions (map, spectrum);
//! - [`ScalingReport`]: how a suite's records are scaled (suite, ida, gap).

use serde::Serialize;

use super::output::num;
use crate::analysis::spectrum::REGION_THRESHOLD;
use crate::model::{Method, Params};

/// The units of every report in Π-groups.
pub const DIMENSIONLESS: &str = "dimensionless (Π-groups of SPEC §1)";

/// Which program wrote a report, from which preset, in which units.
#[derive(Debug, Serialize)]
pub struct Provenance<'a> {
    version: &'static str,
    pub preset: &'a str,
    units: &'static str,
}

impl<'a> Provenance<'a> {
    pub fn new(preset: &'a str, units: &'static str) -> Self {
        Provenance {
            version: env!("CARGO_PKG_VERSION"),
            preset,
            units,
        }
    }

    /// The CSV columns that say the same as the JSON's first keys, so a row
    /// read alone names its program, preset and units.
    pub const CSV_COLUMNS: [&'static str; 3] = ["version", "preset", "units"];

    /// The cells of [`Provenance::CSV_COLUMNS`].
    pub fn csv_cells(&self) -> Vec<String> {
        vec![
            self.version.to_string(),
            self.preset.to_string(),
            self.units.to_string(),
        ]
    }
}

/// The parameter set a report is about, with the names of its contact law,
/// ground motion (and what must be said beside it, SPEC §9) and method.
#[derive(Debug, Serialize)]
pub struct Case<'a> {
    /// The fixed parameters (the keys a command sweeps are set per point).
    pub params: &'a Params,
    /// μ = Π_ω2/Π_ω1 of a sweep over Π_ω1 (absent for a single run).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mu: Option<f64>,
    pub model: &'static str,
    pub excitation: &'a str,
    /// The type B pulse's initial velocity, a record's scaling; absent for the sine.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub excitation_note: Option<String>,
    /// A record's samples, DT and the a_p, ω_p it ran at, as numbers.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub record: Option<RecordNumbers>,
    pub method: Method,
}

/// What a run under a record says of it as numbers (SPEC §9): the samples
/// and their interval DT (s), and the base quantities a_p (m/s²) and ω_p
/// (rad/s) that scale it into g(τ) = a(τ/ω_p)/a_p.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RecordNumbers {
    pub samples: usize,
    pub record_dt: f64,
    /// The factor s on its accelerations (1 as read).
    pub record_scale: f64,
    pub a_p: f64,
    pub omega_p: f64,
}

impl RecordNumbers {
    /// The numbers of `params`' record, or `None` for another excitation.
    pub fn of(params: &Params) -> Option<RecordNumbers> {
        match params.ground() {
            crate::model::Excitation::Record(m) => Some(RecordNumbers {
                samples: m.record.acceleration.len(),
                record_dt: m.record.dt,
                record_scale: m.scale,
                a_p: m.amplitude,
                omega_p: m.omega,
            }),
            _ => None,
        }
    }

    /// CSV columns of [`RecordNumbers`], empty cells for another excitation.
    pub const COLUMNS: [&'static str; 5] =
        ["samples", "record_dt", "record_scale", "a_p", "omega_p"];

    /// The cells of [`RecordNumbers::COLUMNS`] for `params`.
    pub fn cells(params: &Params) -> [String; 5] {
        match RecordNumbers::of(params) {
            Some(r) => [
                r.samples.to_string(),
                crate::output::Num(r.record_dt).to_string(),
                crate::output::Num(r.record_scale).to_string(),
                crate::output::Num(r.a_p).to_string(),
                crate::output::Num(r.omega_p).to_string(),
            ],
            None => Default::default(),
        }
    }
}

impl<'a> Case<'a> {
    /// The case of `params`, at `mu` for a sweep.
    pub fn of(params: &'a Params, mu: Option<f64>) -> Self {
        Case {
            params,
            mu,
            model: params.model.name(),
            excitation: params.excitation.name(),
            excitation_note: params.ground().note(),
            record: RecordNumbers::of(params),
            method: params.method,
        }
    }
}

/// The head of a report that classifies the left structure's regions (SPEC §7).
#[derive(Debug, Serialize)]
pub struct Description<'a> {
    #[serde(flatten)]
    pub provenance: Provenance<'a>,
    #[serde(flatten)]
    pub case: Case<'a>,
    /// Relative change of Π_u1 beyond which a point is amplification or suppression.
    pub region_threshold: f64,
}

impl<'a> Description<'a> {
    /// Preset `preset`'s parameters `params` swept at frequency ratio `mu`.
    pub fn spectral(preset: &'a str, params: &'a Params, mu: f64) -> Self {
        Description {
            provenance: Provenance::new(preset, DIMENSIONLESS),
            case: Case::of(params, Some(mu)),
            region_threshold: REGION_THRESHOLD,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_come_in_one_order_and_infinity_is_inf() {
        let p = Params {
            gap: f64::INFINITY,
            ..crate::model::SET1
        };
        let d = Description::spectral("set1", &p, 1.5);
        let text = crate::output::report::json(&d).unwrap();
        let params = serde_json::to_string(&p).unwrap();
        assert!(params.contains(r#""gap":"inf""#), "{params}");
        let expected = format!(
            "{{\"version\":\"{}\",\"preset\":\"set1\",\"units\":\"{DIMENSIONLESS}\",\
             \"params\":{params},\"mu\":1.5,\"model\":\"{}\",\"excitation\":\"sine\",\
             \"method\":\"{}\",\"region_threshold\":{}}}\n",
            env!("CARGO_PKG_VERSION"),
            p.model.name(),
            p.method.name(),
            REGION_THRESHOLD
        );
        assert_eq!(text, expected);
        // A single run has no μ.
        let v = serde_json::to_value(Case::of(&p, None)).unwrap();
        assert!(v.get("mu").is_none() && v.get("excitation_note").is_none());
    }
}

/// A suite's scaling, said in words and numbers (`suite`, `ida` and `gap`
/// on a pair or a row).
#[derive(Debug, Serialize)]
pub struct ScalingReport {
    pub measure: String,
    /// The level (g) every record is scaled to; absent: the list's scales.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub level_g: Option<f64>,
}

impl ScalingReport {
    /// How `scaling` scales a suite's records.
    pub fn of(scaling: &crate::analysis::suite::Scaling) -> Self {
        ScalingReport {
            measure: scaling.measure.to_string(),
            level_g: scaling.level,
        }
    }

    /// The scaling in words, for a table's opening lines.
    pub fn words(&self) -> String {
        match self.level_g {
            Some(x) => format!("each record scaled to {} = {} g", self.measure, num(x)),
            None => format!("records at their list's scale; {} reported", self.measure),
        }
    }
}
