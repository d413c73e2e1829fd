//! A building preset (SPEC §13): a TOML file of `[[building]]` tables left to
//! right and one `[[joint]]` per neighbouring pair, with the contact law at
//! the top level. Every value is checked here, once; an error is one line
//! naming the file, the building or joint, the key, the value and what is
//! allowed.

use std::fmt;
use std::path::Path;

use crate::model::ContactModel;

use super::row::{Building, Joint, PDelta, Row};

/// Most buildings in a row.
pub const MAX_BUILDINGS: usize = 10;
/// Most storeys of one building.
pub const MAX_STOREYS: usize = 200;

/// A preset that cannot be used: where, and why (one line).
#[derive(Debug, Clone, PartialEq)]
pub struct BuildingsError {
    pub file: String,
    pub message: String,
}

impl fmt::Display for BuildingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.file, self.message)
    }
}

impl std::error::Error for BuildingsError {}

const TOP_KEYS: &[&str] = &[
    "name",
    "description",
    "model",
    "restitution",
    "min_impact_velocity",
    "building",
    "joint",
];
const BUILDING_KEYS: &[&str] = &[
    "name",
    "storeys",
    "mass",
    "stiffness",
    "height",
    "yield_drift",
    "alpha",
    "damping",
    "p_delta",
    "gravity_mass",
    "collapse_drift_ratio",
];
const JOINT_KEYS: &[&str] = &["gap", "stiffness"];

/// Parses and checks a preset's text; `file` names it in messages.
pub fn parse(file: &str, text: &str) -> Result<Row, BuildingsError> {
    let fail = |message: String| BuildingsError {
        file: file.to_string(),
        message,
    };
    let table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| fail(e.message().replace('\n', " ")))?;
    unknown_keys(&table, TOP_KEYS, "").map_err(fail)?;
    let model = match table.get("model") {
        None => ContactModel::ImprovedKelvin,
        Some(v) => {
            let s = v.as_str().unwrap_or("");
            s.parse().map_err(|_| {
                fail(format!(
                    "`model` = {v}: must be one of {}",
                    ContactModel::ALL.map(|m| m.name()).join(", ")
                ))
            })?
        }
    };
    let restitution = number(&table, "restitution", "", Some(0.65)).map_err(fail)?;
    if !(restitution > 0.0 && restitution <= 1.0) {
        return Err(fail(format!(
            "`restitution` = {restitution}: must be in (0, 1]"
        )));
    }
    let min_impact_velocity =
        number(&table, "min_impact_velocity", "", Some(1e-3)).map_err(fail)?;
    if !(min_impact_velocity > 0.0 && min_impact_velocity.is_finite()) {
        return Err(fail(format!(
            "`min_impact_velocity` = {min_impact_velocity}: must be a finite number > 0 (m/s)"
        )));
    }
    let buildings = tables(&table, "building").map_err(fail)?;
    if buildings.is_empty() || buildings.len() > MAX_BUILDINGS {
        return Err(fail(format!(
            "{} [[building]] tables: must be 1 to {MAX_BUILDINGS}",
            buildings.len()
        )));
    }
    let joints = tables(&table, "joint").map_err(fail)?;
    if joints.len() + 1 != buildings.len() {
        return Err(fail(format!(
            "{} [[joint]] tables for {} buildings: must be {} (one per neighbouring pair)",
            joints.len(),
            buildings.len(),
            buildings.len() - 1
        )));
    }
    let buildings = buildings
        .iter()
        .enumerate()
        .map(|(i, t)| building(i, t))
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let joints = joints
        .iter()
        .enumerate()
        .map(|(i, t)| joint(i, t))
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let name = match table.get("name").and_then(|v| v.as_str()) {
        Some(n) => n.to_string(),
        None => Path::new(file)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default(),
    };
    Ok(Row {
        name,
        buildings,
        joints,
        model,
        restitution,
        min_impact_velocity,
    })
}

fn unknown_keys(t: &toml::Table, allowed: &[&str], whose: &str) -> Result<(), String> {
    match t.keys().find(|k| !allowed.contains(&k.as_str())) {
        Some(k) => Err(format!(
            "{whose}unknown key `{k}`: allowed are {}",
            allowed.join(", ")
        )),
        None => Ok(()),
    }
}

fn tables<'a>(t: &'a toml::Table, key: &str) -> Result<Vec<&'a toml::Table>, String> {
    match t.get(key) {
        None => Ok(Vec::new()),
        Some(toml::Value::Array(items)) => items
            .iter()
            .map(|v| {
                v.as_table()
                    .ok_or_else(|| format!("`{key}` must be an array of tables ([[{key}]])"))
            })
            .collect(),
        Some(_) => Err(format!("`{key}` must be an array of tables ([[{key}]])")),
    }
}

/// A number, or `"inf"`, as f64.
fn as_f64(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        toml::Value::String(s) if s == "inf" => Some(f64::INFINITY),
        _ => None,
    }
}

fn number(t: &toml::Table, key: &str, whose: &str, default: Option<f64>) -> Result<f64, String> {
    match (t.get(key), default) {
        (None, Some(d)) => Ok(d),
        (None, None) => Err(format!("{whose}missing key `{key}`")),
        (Some(v), _) => as_f64(v).ok_or_else(|| format!("{whose}`{key}` = {v}: must be a number")),
    }
}

/// A per-storey quantity: a number (every storey) or a list of `storeys`
/// numbers, bottom to top, each accepted by `ok` (whose text says what is allowed).
fn per_storey(
    t: &toml::Table,
    key: &str,
    whose: &str,
    storeys: usize,
    default: Option<f64>,
    ok: (fn(f64) -> bool, &str),
) -> Result<Vec<f64>, String> {
    let listed = matches!(t.get(key), Some(toml::Value::Array(_)));
    let values = match t.get(key) {
        Some(toml::Value::Array(items)) => {
            if items.len() != storeys {
                return Err(format!(
                    "{whose}`{key}` has {} values: must be a number or a list of {storeys} (one per storey)",
                    items.len()
                ));
            }
            items
                .iter()
                .map(|v| {
                    as_f64(v).ok_or_else(|| format!("{whose}`{key}` holds {v}: must be numbers"))
                })
                .collect::<Result<Vec<_>, _>>()?
        }
        _ => vec![number(t, key, whose, default)?; storeys],
    };
    for (i, &x) in values.iter().enumerate() {
        if !(ok.0)(x) {
            let at = if listed {
                format!("[{}]", i + 1)
            } else {
                String::new()
            };
            return Err(format!("{whose}`{key}`{at} = {x}: must be {}", ok.1));
        }
    }
    Ok(values)
}

fn positive_finite(x: f64) -> bool {
    x > 0.0 && x.is_finite()
}

fn positive(x: f64) -> bool {
    x > 0.0
}

fn building(index: usize, t: &toml::Table) -> Result<Building, String> {
    let name = match t.get("name") {
        Some(v) => v
            .as_str()
            .ok_or_else(|| format!("building {}: `name` = {v}: must be a string", index + 1))?
            .to_string(),
        None => format!("b{}", index + 1),
    };
    let whose = format!("building `{name}`: ");
    unknown_keys(t, BUILDING_KEYS, &whose)?;
    let storeys = match t.get("storeys") {
        None => return Err(format!("{whose}missing key `storeys`")),
        Some(v) => match v.as_integer() {
            Some(n) if (1..=MAX_STOREYS as i64).contains(&n) => n as usize,
            _ => {
                return Err(format!(
                    "{whose}`storeys` = {v}: must be a whole number from 1 to {MAX_STOREYS}"
                ));
            }
        },
    };
    let finite = (positive_finite as fn(f64) -> bool, "a finite number > 0");
    let mass = per_storey(
        t,
        "mass",
        &whose,
        storeys,
        None,
        (finite.0, "a finite number > 0 (kg)"),
    )?;
    let stiffness = per_storey(
        t,
        "stiffness",
        &whose,
        storeys,
        None,
        (finite.0, "a finite number > 0 (N/m)"),
    )?;
    let height = per_storey(
        t,
        "height",
        &whose,
        storeys,
        Some(3.0),
        (finite.0, "a finite number > 0 (m)"),
    )?;
    let yield_drift = per_storey(
        t,
        "yield_drift",
        &whose,
        storeys,
        Some(f64::INFINITY),
        (positive, "a number > 0 (m) or \"inf\""),
    )?;
    let alpha = number(t, "alpha", &whose, Some(0.1))?;
    if !(0.0..=1.0).contains(&alpha) {
        return Err(format!("{whose}`alpha` = {alpha}: must be in [0, 1]"));
    }
    let damping = number(t, "damping", &whose, Some(0.05))?;
    if !(0.0..1.0).contains(&damping) {
        return Err(format!("{whose}`damping` = {damping}: must be in [0, 1)"));
    }
    let p_delta = p_delta(t, &whose, &mass)?;
    let building = Building {
        name,
        mass,
        stiffness,
        height,
        yield_drift,
        alpha,
        damping,
        p_delta,
    };
    for i in 0..storeys {
        let theta = building.stability_coefficient(i);
        if theta >= 1.0 {
            return Err(format!(
                "{whose}storey {}: θ = P/(k h) = {theta:.4} from `gravity_mass`, `stiffness` and `height`: \
                 must be < 1 (a storey with θ ≥ 1 cannot stand under its own gravity load)",
                i + 1
            ));
        }
    }
    Ok(building)
}

/// The P-Δ keys of a building (SPEC §15): `p_delta = true` turns it on;
/// `gravity_mass` (kg per floor, finite and > 0; the floor masses by
/// default) and `collapse_drift_ratio` (in (0, 1); 0.10 by default) apply
/// only with it.
fn p_delta(t: &toml::Table, whose: &str, mass: &[f64]) -> Result<Option<PDelta>, String> {
    let on = match t.get("p_delta") {
        None => false,
        Some(v) => v
            .as_bool()
            .ok_or_else(|| format!("{whose}`p_delta` = {v}: must be true or false"))?,
    };
    if !on {
        if let Some(key) = ["gravity_mass", "collapse_drift_ratio"]
            .into_iter()
            .find(|k| t.contains_key(*k))
        {
            return Err(format!(
                "{whose}`{key}` applies with P-Δ only: set `p_delta = true`, or remove `{key}`"
            ));
        }
        return Ok(None);
    }
    let gravity_mass = if t.contains_key("gravity_mass") {
        per_storey(
            t,
            "gravity_mass",
            whose,
            mass.len(),
            None,
            (positive_finite, "a finite number > 0 (kg)"),
        )?
    } else {
        mass.to_vec()
    };
    let collapse_drift_ratio = number(t, "collapse_drift_ratio", whose, Some(0.10))?;
    if !(collapse_drift_ratio > 0.0 && collapse_drift_ratio < 1.0) {
        return Err(format!(
            "{whose}`collapse_drift_ratio` = {collapse_drift_ratio}: must be in (0, 1)"
        ));
    }
    Ok(Some(PDelta {
        gravity_mass,
        collapse_drift_ratio,
    }))
}

fn joint(index: usize, t: &toml::Table) -> Result<Joint, String> {
    let whose = format!("joint{}: ", index + 1);
    unknown_keys(t, JOINT_KEYS, &whose)?;
    let gap = number(t, "gap", &whose, None)?;
    if gap.is_nan() || gap < 0.0 {
        return Err(format!(
            "{whose}`gap` = {gap}: must be a number ≥ 0 (m) or \"inf\""
        ));
    }
    let stiffness = number(t, "stiffness", &whose, None)?;
    if !positive_finite(stiffness) {
        return Err(format!(
            "{whose}`stiffness` = {stiffness}: must be a finite number > 0 (N/m, or N/m^1.5 for Hertz-type laws)"
        ));
    }
    Ok(Joint { gap, stiffness })
}

#[cfg(test)]
mod tests {
    use super::*;

    const TWO: &str = "model = \"kelvin\"\n[[building]]\nname = \"a\"\nstoreys = 2\nmass = 1e5\nstiffness = [2e8, 1e8]\n\
                       [[building]]\nname = \"b\"\nstoreys = 1\nmass = 1e5\nstiffness = 1e8\n[[joint]]\ngap = 0.01\nstiffness = 1e9\n";

    #[test]
    fn reads_a_row_and_pairs_floors_at_one_elevation() {
        let row = parse("t.toml", TWO).unwrap();
        assert_eq!(row.dofs(), 3);
        let pairs = row.pairs();
        assert_eq!(pairs.len(), 1);
        assert_eq!((pairs[0].left_floor, pairs[0].right_floor), (1, 1));
        assert_eq!((pairs[0].left_dof, pairs[0].right_dof), (0, 2));
    }

    #[test]
    fn names_file_building_key_value_and_range() {
        let bad = TWO.replace("[2e8, 1e8]", "[2e8]");
        let e = parse("t.toml", &bad).unwrap_err().to_string();
        assert_eq!(
            e,
            "t.toml: building `a`: `stiffness` has 1 values: must be a number or a list of 2 (one per storey)"
        );
        let e = parse(
            "t.toml",
            &TWO.replace("mass = 1e5\nstiffness = 1e8", "mass = -1\nstiffness = 1e8"),
        )
        .unwrap_err()
        .to_string();
        assert_eq!(
            e,
            "t.toml: building `b`: `mass` = -1: must be a finite number > 0 (kg)"
        );
        let e = parse(
            "t.toml",
            &TWO.replace("gap = 0.01", "gap = 0.01\ncolour = 1"),
        )
        .unwrap_err()
        .to_string();
        assert!(e.starts_with("t.toml: joint1: unknown key `colour`"), "{e}");
    }
}
