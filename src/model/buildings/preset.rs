//! A building preset (SPEC §13): a TOML file of `[[building]]` tables left to
//! right and one `[[joint]]` per neighbouring pair, with the contact law at
//! the top level. Every value is checked here, once; an error is one line
//! naming the file, the building or joint, the key, the value and what is
//! allowed.

use std::fmt;
use std::path::Path;

use crate::model::ContactModel;
use crate::model::params::echo::number as number_text;

use super::keys::{as_f64, number, tables, unknown_keys};
pub use super::limits::{
    MAX_CONTACT_STIFFNESS_PER_MASS, MAX_HERTZ_STIFFNESS_PER_MASS, MIN_RESTITUTION,
};
use super::retrofit_preset;
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
    "link",
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
const JOINT_KEYS: &[&str] = &["gap", "stiffness", "bumper"];

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
    // e ≥ 1e-3 as for the pair (`model::params::table`): the improved
    // Kelvin damping 3(1−e)/(2e) grows without bound as e → 0, and at
    // e = 1e-10 a row's run does not end.
    let restitution = number(&table, "restitution", "", Some(0.65)).map_err(fail)?;
    if !(MIN_RESTITUTION..=1.0).contains(&restitution) {
        return Err(fail(format!(
            "`restitution` = {}: must be in [{MIN_RESTITUTION}, 1]",
            number_text(restitution)
        )));
    }
    // The v₀ floor (SPEC §4) divides the damping of the laws that use it:
    // below 1e-9 m/s a grazing contact's damping is without bound, and
    // above 1 m/s the floor is no longer a floor but the law itself.
    let min_impact_velocity =
        number(&table, "min_impact_velocity", "", Some(1e-3)).map_err(fail)?;
    if !(MIN_IMPACT_VELOCITY.0..=MIN_IMPACT_VELOCITY.1).contains(&min_impact_velocity) {
        return Err(fail(format!(
            "`min_impact_velocity` = {}: must be in [{:e}, {}] (m/s)",
            number_text(min_impact_velocity),
            MIN_IMPACT_VELOCITY.0,
            MIN_IMPACT_VELOCITY.1
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
    // A building is named in `--drift NAME:…`, `--building NAME`, `--set
    // NAME.KEY=…` and in every pair of the output: two of one name would
    // leave all of these ambiguous.
    for (i, b) in buildings.iter().enumerate() {
        if let Some(first) = buildings[..i].iter().position(|a| a.name == b.name) {
            return Err(fail(format!(
                "building {}: `name` = \"{}\": building {} has this name already; every building needs a name of its own",
                i + 1,
                b.name,
                first + 1
            )));
        }
    }
    let name = match table.get("name").and_then(|v| v.as_str()) {
        Some(n) => n.to_string(),
        None => Path::new(file)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default(),
    };
    let mut row = Row {
        name,
        buildings,
        joints,
        model,
        restitution,
        min_impact_velocity,
        links: Vec::new(),
    };
    for b in &row.buildings {
        periods_in_range(b).map_err(fail)?;
    }
    contact_in_range(&row).map_err(fail)?;
    row.links = retrofit_preset::links(&table, &row).map_err(fail)?;
    retrofit_preset::check_bumpers(&row).map_err(fail)?;
    Ok(row)
}

/// Shortest and longest period a building's modes may have (s). Periods
/// come from `mass` and `stiffness` together (SPEC §13): below 1 ms a
/// storey is stiffer than any structure and a run takes without end (a
/// storey of 1e30 N/m under 4e5 kg does not finish); above 100 s a
/// building barely stands (the tallest towers are near 10 s), and the
/// default free vibration after the motion, four fundamental periods,
/// grows without bound.
pub const PERIOD_RANGE: (f64, f64) = (1e-3, 100.0);

/// Range of the v₀ floor `min_impact_velocity` (m/s).
pub const MIN_IMPACT_VELOCITY: (f64, f64) = (1e-9, 1.0);

/// Every period of `b`'s modes within [`PERIOD_RANGE`].
fn periods_in_range(b: &Building) -> Result<(), String> {
    let periods = super::matrices::periods(b);
    let (shortest, longest) = (periods[periods.len() - 1], periods[0]);
    let (lo, hi) = PERIOD_RANGE;
    if shortest >= lo && longest <= hi {
        return Ok(());
    }
    let (which, value) = if shortest < lo || shortest.is_nan() {
        ("shortest", shortest)
    } else {
        ("longest", longest)
    };
    Err(format!(
        "building `{}`: `mass` and `stiffness` give a {which} period of {value:.3e} s: every period must be in [{lo}, {hi}] s",
        b.name
    ))
}

/// Every joint's stiffness within [`MAX_CONTACT_STIFFNESS_PER_MASS`] (or
/// [`MAX_HERTZ_STIFFNESS_PER_MASS`]) of the floor pairs it joins.
fn contact_in_range(row: &Row) -> Result<(), String> {
    let (per_mass, frequency) = if row.model.is_hertzian() {
        (
            MAX_HERTZ_STIFFNESS_PER_MASS,
            "a contact frequency √(1.5β√δ/m̄) of at most 2.2e5 rad/s at δ = 1 mm",
        )
    } else {
        (
            MAX_CONTACT_STIFFNESS_PER_MASS,
            "a contact frequency √(k̄/m̄) of at most 1e5 rad/s",
        )
    };
    for pair in row.pairs() {
        let m_bar = super::contact::reduced_mass(row, &pair);
        let k = row.joints[pair.joint].stiffness;
        let most = per_mass * m_bar;
        if k > most {
            return Err(format!(
                "joint{}: `stiffness` = {}: must be at most {most:.3e} here ({per_mass:e} times m̄ = {m_bar:.4e} kg of floors {}, {frequency})",
                pair.joint + 1,
                number_text(k),
                row.pair_name(&pair),
            ));
        }
    }
    Ok(())
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
            return Err(format!(
                "{whose}`{key}`{at} = {}: must be {}",
                number_text(x),
                ok.1
            ));
        }
    }
    Ok(values)
}

fn positive_finite(x: f64) -> bool {
    x > 0.0 && x.is_finite()
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
    // Physical ranges, wide enough for a laboratory model and for a tower:
    // a floor of 1 kg to 1e9 kg, a storey of 100 N/m to 1e13 N/m and
    // 0.1 m to 100 m high, yielding at a drift of 10 μm or more. Mass and
    // stiffness together give the periods, checked by [`periods_in_range`].
    let mass = per_storey(
        t,
        "mass",
        &whose,
        storeys,
        None,
        (|x| (1.0..=1e9).contains(&x), "in [1, 1e9] (kg)"),
    )?;
    let stiffness = per_storey(
        t,
        "stiffness",
        &whose,
        storeys,
        None,
        (|x| (1e2..=1e13).contains(&x), "in [100, 1e13] (N/m)"),
    )?;
    let height = per_storey(
        t,
        "height",
        &whose,
        storeys,
        Some(3.0),
        (|x| (0.1..=100.0).contains(&x), "in [0.1, 100] (m)"),
    )?;
    let yield_drift = per_storey(
        t,
        "yield_drift",
        &whose,
        storeys,
        Some(f64::INFINITY),
        (|x| x >= 1e-5, "a number ≥ 1e-5 (m) or \"inf\""),
    )?;
    let alpha = number(t, "alpha", &whose, Some(0.1))?;
    if !(0.0..=1.0).contains(&alpha) {
        return Err(format!(
            "{whose}`alpha` = {}: must be in [0, 1]",
            number_text(alpha)
        ));
    }
    let damping = number(t, "damping", &whose, Some(0.05))?;
    if !(0.0..1.0).contains(&damping) {
        return Err(format!(
            "{whose}`damping` = {}: must be in [0, 1)",
            number_text(damping)
        ));
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
                "{whose}storey {}: θ = P/(k h) = {} from `gravity_mass`, `stiffness` and `height`: \
                 must be < 1 (a storey with θ ≥ 1 cannot stand under its own gravity load)",
                i + 1,
                // Five significant digits, in the short form every range message uses.
                number_text(format!("{theta:.4e}").parse().unwrap_or(theta))
            ));
        }
    }
    Ok(building)
}

/// A TOML value as a message shows it: a number in its shortest form,
/// anything else as written, cut where long.
fn shown(v: &toml::Value) -> String {
    match as_f64(v) {
        Some(x) => number_text(x),
        None => crate::model::params::echo::text(&v.to_string()),
    }
}

/// The P-Δ keys of a building (SPEC §15): `p_delta = true` turns it on;
/// `gravity_mass` (kg per floor, in [1, 1e10]; the floor masses by
/// default) and `collapse_drift_ratio` (in (0, 1); 0.10 by default) apply
/// only with it.
fn p_delta(t: &toml::Table, whose: &str, mass: &[f64]) -> Result<Option<PDelta>, String> {
    let on = match t.get("p_delta") {
        None => false,
        Some(v) => v
            .as_bool()
            .ok_or_else(|| format!("{whose}`p_delta` = {}: must be true or false", shown(v)))?,
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
        // A floor's own mass and the gravity system it holds up: up to ten
        // times the heaviest floor a row takes.
        per_storey(
            t,
            "gravity_mass",
            whose,
            mass.len(),
            None,
            (|x| (1.0..=1e10).contains(&x), "in [1, 1e10] (kg)"),
        )?
    } else {
        mass.to_vec()
    };
    let collapse_drift_ratio = number(t, "collapse_drift_ratio", whose, Some(0.10))?;
    if !(collapse_drift_ratio > 0.0 && collapse_drift_ratio < 1.0) {
        return Err(format!(
            "{whose}`collapse_drift_ratio` = {}: must be in (0, 1)",
            number_text(collapse_drift_ratio)
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
            "{whose}`gap` = {}: must be a number ≥ 0 (m) or \"inf\"",
            number_text(gap)
        ));
    }
    let stiffness = number(t, "stiffness", &whose, None)?;
    if !positive_finite(stiffness) {
        return Err(format!(
            "{whose}`stiffness` = {}: must be a finite number > 0 (N/m, or N/m^1.5 for Hertz-type laws)",
            number_text(stiffness)
        ));
    }
    let bumper = retrofit_preset::bumper(t, &whose, gap)?;
    Ok(Joint {
        gap,
        stiffness,
        bumper,
    })
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
            "t.toml: building `b`: `mass` = -1: must be in [1, 1e9] (kg)"
        );
        let e = parse(
            "t.toml",
            &TWO.replace("gap = 0.01", "gap = 0.01\ncolour = 1"),
        )
        .unwrap_err()
        .to_string();
        assert!(e.starts_with("t.toml: joint1: unknown key `colour`"), "{e}");
    }

    #[test]
    fn two_buildings_of_one_name_are_refused() {
        let e = parse("t.toml", &TWO.replace("name = \"b\"", "name = \"a\""))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "t.toml: building 2: `name` = \"a\": building 1 has this name already; every building needs a name of its own"
        );
        // Unnamed buildings take b1, b2, …: distinct by construction.
        let unnamed = TWO
            .replace("name = \"a\"\n", "")
            .replace("name = \"b\"\n", "");
        let row = parse("t.toml", &unnamed).unwrap();
        assert_eq!(row.buildings[0].name, "b1");
        assert_eq!(row.buildings[1].name, "b2");
    }

    #[test]
    fn a_contact_stiffer_than_the_solvers_resolve_is_refused() {
        // m̄ of floors a 1 and b 1 (1e5 kg each) is 5e4 kg: k̄ ≤ 5e14 N/m.
        let at = |k: &str| {
            parse(
                "t.toml",
                &TWO.replace("stiffness = 1e9\n", &format!("stiffness = {k}\n")),
            )
        };
        assert!(at("5e14").is_ok());
        let e = at("1e300").unwrap_err().to_string();
        assert_eq!(
            e,
            "t.toml: joint1: `stiffness` = 1e300: must be at most 5.000e14 here (1e10 times m̄ = 5.0000e4 kg of floors a 1 – b 1, a contact frequency √(k̄/m̄) of at most 1e5 rad/s)"
        );
        // An open joint pairs no floors, and its stiffness meets nothing.
        assert!(
            parse(
                "t.toml",
                &TWO.replace("gap = 0.01", "gap = \"inf\"")
                    .replace("stiffness = 1e9\n", "stiffness = 1e300\n")
            )
            .is_ok()
        );
    }

    #[test]
    fn periods_outside_what_a_building_can_have_are_refused() {
        // One storey of 1e5 kg: T = 2π√(m/k), 1 ms at k = 3.9e12 N/m.
        let e = parse(
            "t.toml",
            &TWO.replace(
                "mass = 1e5\nstiffness = 1e8",
                "mass = 1e5\nstiffness = 1e13",
            ),
        )
        .unwrap_err()
        .to_string();
        assert_eq!(
            e,
            "t.toml: building `b`: `mass` and `stiffness` give a shortest period of 6.283e-4 s: every period must be in [0.001, 100] s"
        );
        let e = parse(
            "t.toml",
            &TWO.replace("mass = 1e5\nstiffness = 1e8", "mass = 1e9\nstiffness = 100"),
        )
        .unwrap_err()
        .to_string();
        assert_eq!(
            e,
            "t.toml: building `b`: `mass` and `stiffness` give a longest period of 1.987e4 s: every period must be in [0.001, 100] s"
        );
    }

    #[test]
    fn restitution_and_the_impact_velocity_floor_have_ranges() {
        let e = parse("t.toml", &format!("restitution = 1e-10\n{TWO}"))
            .unwrap_err()
            .to_string();
        assert_eq!(e, "t.toml: `restitution` = 1e-10: must be in [0.001, 1]");
        let e = parse("t.toml", &format!("min_impact_velocity = 1e300\n{TWO}"))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "t.toml: `min_impact_velocity` = 1e300: must be in [1e-9, 1] (m/s)"
        );
    }
}
