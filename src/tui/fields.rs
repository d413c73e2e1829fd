//! The rows of a parameter pane: the ten Π-groups of SPEC §1, then the
//! contact model (SPEC §4), the duration in cycles (SPEC §2) and Δτ (SPEC §5),
//! each with its symbol, its meaning and the step a nudge moves it by.

use crate::model::Params;

/// One editable row of a parameter pane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Field {
    /// The key of `Params::set` and of preset files.
    pub key: &'static str,
    /// The paper's symbol.
    pub symbol: &'static str,
    /// What it means, in a few words.
    pub meaning: &'static str,
    /// One nudge (←/→); Shift moves ×10, the fine step is ÷10.
    pub step: f64,
}

const fn field(key: &'static str, symbol: &'static str, meaning: &'static str, step: f64) -> Field {
    Field {
        key,
        symbol,
        meaning,
        step,
    }
}

/// Every row, in pane order.
pub const FIELDS: [Field; 13] = [
    field("mass_ratio", "Π_m", "mass ratio m1/m2", 0.05),
    field("omega1", "Π_ω1", "left frequency ω1/ωp", 0.05),
    field("omega2", "Π_ω2", "right frequency ω2/ωp", 0.05),
    field("yield1", "Π_uy1", "left yield displacement", 0.05),
    field("yield2", "Π_uy2", "right yield displacement", 0.05),
    field("damping", "Π_ξ", "damping ratio ξ", 0.01),
    field("alpha", "Π_α", "post-yield stiffness", 0.01),
    field("contact_omega", "Π_ωcon", "contact frequency ω̄/ωp", 5.0),
    field("restitution", "Π_e", "restitution e", 0.05),
    field("gap", "Π_d", "initial gap d ωp²/ap", 0.05),
    field("model", "model", "contact element", 1.0),
    field("cycles", "cycles", "excitation cycles", 1.0),
    field("dt", "Δτ", "Newmark time step", 0.0005),
];

/// How big a nudge is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepSize {
    Fine,
    Normal,
    Coarse,
}

impl StepSize {
    fn factor(self) -> f64 {
        match self {
            StepSize::Fine => 0.1,
            StepSize::Normal => 1.0,
            StepSize::Coarse => 10.0,
        }
    }
}

/// The text of a row's value as the pane shows it.
pub fn value_text(p: &Params, f: &Field) -> String {
    match f.key {
        "model" => p.model.name().to_string(),
        "cycles" => p.cycles.to_string(),
        key => {
            let v = p.get(key).unwrap_or(f64::NAN);
            if v.is_infinite() {
                "inf".into()
            } else {
                format!("{v}")
            }
        }
    }
}

/// The text a nudge of `direction` (±1) steps of `size` would set, or `None`
/// when the row cannot be nudged from its value (an infinite one).
/// The result is rounded to 1e-9 so repeated nudges print cleanly.
pub fn nudged_text(p: &Params, f: &Field, direction: f64, size: StepSize) -> Option<String> {
    match f.key {
        "model" => Some(p.model.toggled().name().to_string()),
        "cycles" => {
            let step = (f.step * size.factor()).max(1.0);
            let n = (p.cycles as f64 + direction * step).max(1.0);
            Some(format!("{n}"))
        }
        key => {
            let v = p.get(key)?;
            if !v.is_finite() {
                return None;
            }
            let next = v + direction * f.step * size.factor();
            Some(format!("{}", (next * 1e9).round() / 1e9))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn every_field_is_a_key() {
        for f in &FIELDS {
            assert!(SET1.get(f.key).is_some(), "{}", f.key);
        }
    }

    #[test]
    fn nudges_round_cleanly() {
        let gap = &FIELDS[9];
        assert_eq!(
            nudged_text(&SET1, gap, 1.0, StepSize::Normal).unwrap(),
            "0.25"
        );
        assert_eq!(
            nudged_text(&SET1, gap, -1.0, StepSize::Fine).unwrap(),
            "0.195"
        );
        assert_eq!(
            nudged_text(&SET1, gap, 1.0, StepSize::Coarse).unwrap(),
            "0.7"
        );
        let inf = Params {
            gap: f64::INFINITY,
            ..SET1
        };
        assert_eq!(nudged_text(&inf, gap, 1.0, StepSize::Normal), None);
    }
}
