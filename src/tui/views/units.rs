//! The scaling of every axis and readout: Π-groups (x in a_p/ω_p², forces
//! in m2·a_p, time τ with 2π per excitation cycle), or physical units for a
//! set with a `[physical]` table in the physical view.

use crate::tui::app::App;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    /// Multipliers from the Π quantities to the shown ones.
    pub time: f64,
    pub length: f64,
    pub velocity: f64,
    pub force: f64,
    pub energy: f64,
    /// Ground acceleration (a_p in Π form).
    pub acceleration: f64,
    /// Axis names with their scaling.
    pub time_axis: &'static str,
    pub length_unit: &'static str,
    pub velocity_unit: &'static str,
    pub force_unit: &'static str,
    pub energy_unit: &'static str,
    pub acceleration_unit: &'static str,
    pub physical: bool,
}

pub const PI_UNITS: Units = Units {
    time: 1.0,
    length: 1.0,
    velocity: 1.0,
    force: 1.0,
    energy: 1.0,
    acceleration: 1.0,
    time_axis: "τ [2π = 1 cycle]",
    length_unit: "a_p/ω_p²",
    velocity_unit: "a_p/ω_p",
    force_unit: "m2·a_p",
    energy_unit: "m2·a_p²/ω_p²",
    acceleration_unit: "a_p",
    physical: false,
};

impl Units {
    /// The units of set `i` as the view shows it.
    pub fn of(app: &App, i: usize) -> Units {
        match (&app.sets[i].base, app.view.physical) {
            (Some(b), true) => Units {
                time: b.time(),
                length: b.length() * 1e3,
                velocity: b.velocity(),
                force: b.force() / 1e3,
                energy: b.force() * b.length() / 1e3,
                // a_p = (a_p/ω_p²)/(1/ω_p)².
                acceleration: b.length() / (b.time() * b.time()),
                time_axis: "t [s]",
                length_unit: "mm",
                velocity_unit: "m/s",
                force_unit: "kN",
                energy_unit: "kJ",
                acceleration_unit: "m/s²",
                physical: true,
            },
            _ => PI_UNITS,
        }
    }

    /// Units of the active set.
    pub fn active(app: &App) -> Units {
        Units::of(app, app.active)
    }

    /// A chart title: the quantity and its scaling.
    pub fn title(&self, quantity: &str, unit: &str) -> String {
        format!("{quantity} [{unit}]")
    }

    /// Spans scaled by `k`.
    pub fn scale_spans(spans: Vec<(f64, f64, f64)>, t: f64, k: f64) -> Vec<(f64, f64, f64)> {
        spans
            .into_iter()
            .map(|(x, a, b)| (x * t, a * k, b * k))
            .collect()
    }
}
