//! The retrofit keys of a row preset (SPEC §14), checked once here:
//!
//! ```toml
//! [[joint]]
//! gap = 0.02
//! stiffness = 2.0e10
//! bumper = { thickness = 0.015, stiffness = 2.0e8, restitution = 0.8, floors = [3] }
//! [[link]]
//! joint = 1
//! floor = 3
//! stiffness = 0.0
//! damping = 4.0e6
//! exponent = 1.0
//! ```
//!
//! Each error is one line naming the joint or link, the key, the value and
//! what is allowed, as every other key's.

use crate::model::params::echo::number as number_text;

use super::keys::{number, tables, unknown_keys};
use super::limits::{
    MAX_CONTACT_STIFFNESS_PER_MASS, MAX_HERTZ_STIFFNESS_PER_MASS, MIN_RESTITUTION,
};
use super::retrofit::{Bumper, Link};
use super::row::Row;

const BUMPER_KEYS: &[&str] = &["thickness", "stiffness", "restitution", "floors"];
const LINK_KEYS: &[&str] = &["joint", "floor", "stiffness", "damping", "exponent"];

/// Most a link's dashpot may be per kilogram of the reduced mass m̄ of the
/// floors it joins (1/s, at |Δv| = 1 m/s): c_l/m̄ ≤ 1e5 /s, the rate of the
/// stiffest contact a row takes ([`MAX_CONTACT_STIFFNESS_PER_MASS`]).
pub const MAX_LINK_DAMPING_PER_MASS: f64 = 1e5;

/// The `bumper` of joint `whose` (its gap `gap`), if any.
pub fn bumper(t: &toml::Table, whose: &str, gap: f64) -> Result<Option<Bumper>, String> {
    let Some(value) = t.get("bumper") else {
        return Ok(None);
    };
    let b = value.as_table().ok_or_else(|| {
        format!("{whose}`bumper` must be a table: bumper = {{ thickness = …, stiffness = …, restitution = … }}")
    })?;
    let whose = format!("{whose}bumper ");
    unknown_keys(b, BUMPER_KEYS, &whose)?;
    let thickness = number(b, "thickness", &whose, None)?;
    if !(thickness > 0.0 && thickness <= gap) {
        return Err(format!(
            "{whose}`thickness` = {}: must be in (0, {}] (m; more than 0, at most the joint's gap)",
            number_text(thickness),
            number_text(gap)
        ));
    }
    let stiffness = number(b, "stiffness", &whose, None)?;
    if !(stiffness > 0.0 && stiffness.is_finite()) {
        return Err(format!(
            "{whose}`stiffness` = {}: must be a finite number > 0 (N/m, or N/m^1.5 for Hertz-type laws)",
            number_text(stiffness)
        ));
    }
    let restitution = number(b, "restitution", &whose, None)?;
    if !(MIN_RESTITUTION..=1.0).contains(&restitution) {
        return Err(format!(
            "{whose}`restitution` = {}: must be in [{MIN_RESTITUTION}, 1]",
            number_text(restitution)
        ));
    }
    let floors = match b.get("floors") {
        None => None,
        Some(v) => {
            let list = v
                .as_array()
                .filter(|a| !a.is_empty())
                .ok_or_else(|| format!("{whose}`floors` = {v}: must be a list of floor numbers of the left building, such as [3]"))?;
            let floors = list
                .iter()
                .map(|f| {
                    f.as_integer()
                        .filter(|&n| n >= 1)
                        .map(|n| n as usize)
                        .ok_or_else(|| {
                            format!("{whose}`floors` holds {f}: must be whole numbers ≥ 1")
                        })
                })
                .collect::<Result<Vec<_>, _>>()?;
            Some(floors)
        }
    };
    Ok(Some(Bumper {
        thickness,
        stiffness,
        restitution,
        floors,
    }))
}

/// The `[[link]]` tables of a preset, checked against the row's joints and floors.
pub fn links(table: &toml::Table, row: &Row) -> Result<Vec<Link>, String> {
    tables(table, "link")?
        .iter()
        .enumerate()
        .map(|(i, t)| link(i, t, row))
        .collect()
}

fn whole(
    t: &toml::Table,
    key: &str,
    whose: &str,
    range: (usize, usize),
    what: &str,
) -> Result<usize, String> {
    let v = t
        .get(key)
        .ok_or_else(|| format!("{whose}missing key `{key}`"))?;
    v.as_integer()
        .filter(|&n| n >= range.0 as i64 && n <= range.1 as i64)
        .map(|n| n as usize)
        .ok_or_else(|| {
            format!(
                "{whose}`{key}` = {v}: must be a whole number from {} to {} ({what})",
                range.0, range.1
            )
        })
}

fn link(index: usize, t: &toml::Table, row: &Row) -> Result<Link, String> {
    let whose = format!("link{}: ", index + 1);
    unknown_keys(t, LINK_KEYS, &whose)?;
    let joints = row.joints.len();
    if joints == 0 {
        return Err(format!("{whose}a row of one building has no joint to link"));
    }
    let joint = whole(t, "joint", &whose, (1, joints), "the joints of this row")? - 1;
    let left = &row.buildings[joint];
    let floor = whole(
        t,
        "floor",
        &whose,
        (1, left.storeys()),
        &format!("the floors of building `{}`", left.name),
    )?;
    if !row
        .facing_floors()
        .iter()
        .any(|p| p.joint == joint && p.left_floor == floor)
    {
        let right = &row.buildings[joint + 1];
        return Err(format!(
            "{whose}`floor` = {floor}: floor {floor} of `{}` has no floor of `{}` at its elevation ({:.3} m, within 1 mm) to link to",
            left.name,
            right.name,
            left.elevation(floor)
        ));
    }
    let stiffness = number(t, "stiffness", &whose, Some(0.0))?;
    let damping = number(t, "damping", &whose, Some(0.0))?;
    for (key, x) in [("stiffness", stiffness), ("damping", damping)] {
        if !(x >= 0.0 && x.is_finite()) {
            let unit = if key == "stiffness" {
                "N/m"
            } else {
                "N·(s/m)^exponent"
            };
            return Err(format!(
                "{whose}`{key}` = {}: must be a finite number ≥ 0 ({unit})",
                number_text(x)
            ));
        }
    }
    if stiffness == 0.0 && damping == 0.0 {
        return Err(format!(
            "{whose}`stiffness` = 0 and `damping` = 0: a link needs one of them > 0"
        ));
    }
    let exponent = number(t, "exponent", &whose, Some(1.0))?;
    if !(exponent > 0.0 && exponent <= 1.0) {
        return Err(format!(
            "{whose}`exponent` = {}: must be in (0, 1] (1 a linear dashpot, 0.3 to 0.5 a fluid viscous damper)",
            number_text(exponent)
        ));
    }
    let link = Link {
        joint,
        floor,
        stiffness,
        damping,
        exponent,
    };
    // As a contact's, a link's spring and dashpot are bounded by the
    // floors' reduced mass, so that the solvers resolve them.
    let pair = row
        .facing_floors()
        .into_iter()
        .find(|p| p.joint == joint && p.left_floor == floor)
        .expect("checked above");
    let m_bar = super::contact::reduced_mass(row, &pair);
    let most_k = MAX_CONTACT_STIFFNESS_PER_MASS * m_bar;
    if stiffness > most_k {
        return Err(format!(
            "{whose}`stiffness` = {}: must be at most {most_k:.3e} here ({MAX_CONTACT_STIFFNESS_PER_MASS:e} times m̄ = {m_bar:.4e} kg of floors {})",
            number_text(stiffness),
            row.pair_name(&pair)
        ));
    }
    let most_c = MAX_LINK_DAMPING_PER_MASS * m_bar;
    if damping > most_c {
        return Err(format!(
            "{whose}`damping` = {}: must be at most {most_c:.3e} here ({MAX_LINK_DAMPING_PER_MASS:e} times m̄ = {m_bar:.4e} kg of floors {})",
            number_text(damping),
            row.pair_name(&pair)
        ));
    }
    Ok(link)
}

/// The bumpers' floors name floors that pair at their joint, and their
/// stiffness is one the solvers resolve (as the joint's own, SPEC §14).
pub fn check_bumpers(row: &Row) -> Result<(), String> {
    let facing = row.facing_floors();
    for (j, joint) in row.joints.iter().enumerate() {
        let Some(b) = &joint.bumper else { continue };
        for &f in b.floors.iter().flatten() {
            if !facing.iter().any(|p| p.joint == j && p.left_floor == f) {
                let (left, right) = (&row.buildings[j], &row.buildings[j + 1]);
                return Err(format!(
                    "joint{}: bumper `floors` holds {f}: building `{}` has no floor {f} facing a floor of `{}` at its elevation (within 1 mm)",
                    j + 1,
                    left.name,
                    right.name
                ));
            }
        }
    }
    let per_mass = if row.model.is_hertzian() {
        MAX_HERTZ_STIFFNESS_PER_MASS
    } else {
        MAX_CONTACT_STIFFNESS_PER_MASS
    };
    for e in row.bumper_elements() {
        let m_bar = super::contact::reduced_mass(row, &e.pair);
        let most = per_mass * m_bar;
        if e.stiffness > most {
            return Err(format!(
                "joint{}: bumper `stiffness` = {}: must be at most {most:.3e} here ({per_mass:e} times m̄ = {m_bar:.4e} kg of floors {})",
                e.pair.joint + 1,
                number_text(e.stiffness),
                row.pair_name(&e.pair)
            ));
        }
    }
    Ok(())
}
