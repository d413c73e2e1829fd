//! Output formats shared by the commands: a table for people, JSON and CSV for scripts.

use clap::ValueEnum;

use crate::model::Params;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum Format {
    /// Aligned columns for people.
    #[default]
    Table,
    /// Exactly one JSON object on stdout.
    Json,
    /// A header row, then one row per record.
    Csv,
}

/// Every parameter key and value as a JSON object (infinite values as "inf").
pub fn params_json(p: &Params) -> serde_json::Value {
    serde_json::to_value(p).unwrap_or(serde_json::Value::Null)
}

/// A float for tables and CSV: `inf` for infinity, otherwise the shortest exact form.
pub fn num(v: f64) -> String {
    if v.is_infinite() {
        if v > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{v}")
    }
}
