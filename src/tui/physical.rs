//! The physical-units view of a set whose preset has a `[physical]` table
//! (SPEC §8): masses, periods, yield displacements and gap in metres, a_p in
//! g and the excitation period, editable; the Π-groups follow from them.
//!
//! The set's [`Params`] stay the one truth. The view keeps only the three
//! base quantities a_p, ω_p and m2 ([`Base`]); every physical value shown is
//! [`Physical::from_params`] of the current Π-groups, and an edit goes back
//! through [`Physical::to_params`], which validates it.

use std::f64::consts::TAU;

use crate::model::params::echo;
use crate::model::physical::{G, Physical, parse_acceleration};
use crate::model::{Params, Preset};

/// The base quantities: excitation amplitude a_p (m/s²), its circular
/// frequency ω_p (rad/s) and the right-hand mass m2 (kg).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Base {
    pub ap: f64,
    pub omega_p: f64,
    pub m2: f64,
}

impl Base {
    /// The base of a preset with a readable `[physical]` table.
    pub fn of(preset: &Preset) -> Option<Base> {
        let ph = Physical::from_table(preset.physical.as_ref()?).ok()?;
        Some(Base {
            ap: ph.ap,
            omega_p: ph.omega_p,
            m2: ph.mass[1],
        })
    }

    pub fn physical(&self, p: &Params) -> Physical {
        Physical::from_params(p, self.ap, self.omega_p, self.m2)
    }

    /// Metres per unit of Π_u: l_e = a_p/ω_p².
    pub fn length(&self) -> f64 {
        self.ap / (self.omega_p * self.omega_p)
    }

    /// Metres per second per unit of Π_v: a_p/ω_p.
    pub fn velocity(&self) -> f64 {
        self.ap / self.omega_p
    }

    /// Newtons per unit of force: m2·a_p.
    pub fn force(&self) -> f64 {
        self.m2 * self.ap
    }

    /// Seconds per unit of τ: 1/ω_p.
    pub fn time(&self) -> f64 {
        1.0 / self.omega_p
    }
}

/// One editable physical quantity.
pub struct Row {
    pub label: &'static str,
    pub unit: &'static str,
    pub get: fn(&Physical) -> f64,
    pub set: fn(&mut Physical, f64),
    /// The Π-groups it moves, for the info line.
    pub moves: &'static str,
}

pub const ROWS: [Row; 9] = [
    Row {
        label: "m1",
        unit: "t",
        get: |p| p.mass[0] / 1e3,
        set: |p, v| p.mass[0] = v * 1e3,
        moves: "Π_m",
    },
    Row {
        label: "m2",
        unit: "t",
        get: |p| p.mass[1] / 1e3,
        set: |p, v| p.mass[1] = v * 1e3,
        moves: "Π_m and the force scale m2·a_p",
    },
    Row {
        label: "T1",
        unit: "s",
        get: |p| TAU / p.omega[0],
        set: |p, v| p.omega[0] = TAU / v,
        moves: "Π_ω1",
    },
    Row {
        label: "T2",
        unit: "s",
        get: |p| TAU / p.omega[1],
        set: |p, v| p.omega[1] = TAU / v,
        moves: "Π_ω2",
    },
    Row {
        label: "u_y1",
        unit: "mm",
        get: |p| p.yield_displacement[0] * 1e3,
        set: |p, v| p.yield_displacement[0] = v / 1e3,
        moves: "Π_uy1",
    },
    Row {
        label: "u_y2",
        unit: "mm",
        get: |p| p.yield_displacement[1] * 1e3,
        set: |p, v| p.yield_displacement[1] = v / 1e3,
        moves: "Π_uy2",
    },
    Row {
        label: "d",
        unit: "mm",
        get: |p| p.gap * 1e3,
        set: |p, v| p.gap = v / 1e3,
        moves: "Π_d",
    },
    Row {
        label: "a_p",
        unit: "g",
        get: |p| p.ap / G,
        set: |p, v| p.ap = v * G,
        moves: "Π_uy1, Π_uy2, Π_d (lengths fixed)",
    },
    Row {
        label: "T_p",
        unit: "s",
        get: |p| TAU / p.omega_p,
        set: |p, v| p.omega_p = TAU / v,
        moves: "every Π_ω, Π_uy and Π_d",
    },
];

/// A row's value as the pane shows it.
pub fn value_text(base: &Base, p: &Params, row: &Row) -> String {
    echo::g4((row.get)(&base.physical(p)))
}

/// Sets row `index` to `text` (a number in the row's unit; a_p also as
/// `0.5g`): the new Π-groups and base, or why not.
pub fn apply(base: &Base, p: &Params, index: usize, text: &str) -> Result<(Params, Base), String> {
    let row = &ROWS[index];
    let value = if row.label == "a_p" {
        parse_acceleration(text).map(|a| a / G)
    } else {
        text.trim().parse::<f64>().ok()
    }
    .filter(|v| v.is_finite() && *v > 0.0 || row.label == "d" && *v == f64::INFINITY)
    .ok_or_else(|| {
        format!(
            "{} = {text}: must be a number > 0 in {}",
            row.label, row.unit
        )
    })?;
    let mut ph = base.physical(p);
    (row.set)(&mut ph, value);
    let next = ph.to_params(p).map_err(|e| e.to_string())?;
    Ok((
        next,
        Base {
            ap: ph.ap,
            omega_p: ph.omega_p,
            m2: ph.mass[1],
        },
    ))
}

/// Row `index` nudged by `steps` of 5 %.
pub fn nudged(base: &Base, p: &Params, index: usize, steps: f64) -> Result<(Params, Base), String> {
    let v = (ROWS[index].get)(&base.physical(p)) * 1.05f64.powf(steps);
    let text = if ROWS[index].label == "a_p" {
        format!("{v}g")
    } else {
        format!("{v}")
    };
    apply(base, p, index, &text)
}

/// A `[physical]` table for saving: the structures as the Π-groups and the
/// base now describe them.
pub fn table(base: &Base, p: &Params) -> toml::Table {
    let ph = base.physical(p);
    let mut t = toml::Table::new();
    let mut put = |k: &str, v: f64| {
        t.insert(k.into(), toml::Value::Float(v));
    };
    put("m1", ph.mass[0]);
    put("m2", ph.mass[1]);
    put("omega1", ph.omega[0]);
    put("omega2", ph.omega[1]);
    put("yield1", ph.yield_displacement[0]);
    put("yield2", ph.yield_displacement[1]);
    put("gap", ph.gap);
    put("damping", ph.damping);
    put("alpha", ph.alpha);
    put("contact_omega", ph.contact_omega);
    put("restitution", ph.restitution);
    put("ap", ph.ap);
    put("omega_p", ph.omega_p);
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_buildings() -> (Base, Params) {
        let p = crate::model::preset::builtin("two-buildings").unwrap();
        (Base::of(&p).unwrap(), p.params)
    }

    #[test]
    fn editing_a_gap_in_millimetres_moves_only_pi_d() {
        let (base, p) = two_buildings();
        let d = (ROWS[6].get)(&base.physical(&p));
        let (next, nb) = apply(&base, &p, 6, &format!("{}", 2.0 * d)).unwrap();
        assert!((next.gap / p.gap - 2.0).abs() < 1e-12);
        assert_eq!(next.omega1, p.omega1);
        assert_eq!(nb, base);
    }

    #[test]
    fn a_period_edit_moves_its_frequency_and_a_bad_value_is_refused() {
        let (base, p) = two_buildings();
        let (next, _) = apply(&base, &p, 2, "0.5").unwrap();
        assert!((next.omega1 - TAU / 0.5 / base.omega_p).abs() < 1e-12);
        assert!(apply(&base, &p, 2, "-1").is_err());
        assert!(apply(&base, &p, 7, "abc").is_err());
    }

    #[test]
    fn the_saved_table_reads_back_to_the_same_groups() {
        let (base, p) = two_buildings();
        let back = Physical::from_table(&table(&base, &p))
            .unwrap()
            .to_params(&p)
            .unwrap();
        for key in ["mass_ratio", "omega1", "omega2", "yield1", "gap"] {
            let (a, b) = (p.get(key).unwrap(), back.get(key).unwrap());
            assert!((a - b).abs() <= 1e-12 * a.abs(), "{key}: {a} {b}");
        }
    }
}
