//! The rows of a parameter pane: every row of the parameter table
//! ([`crate::model::params::FIELDS`]), in its order, each with its symbol,
//! meaning and nudge step. This file only adds what a nudge does.

use crate::model::Params;
use crate::model::params::echo::g4;
pub use crate::model::params::{FIELDS, Field, Kind, Step};

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
    f.text(p)
}

/// The text a nudge of `direction` (±1) steps of `size` would set, or `None`
/// when the row cannot be nudged from its value (an infinite one). A choice
/// moves to the next (or previous) name. A number moves by its row's
/// [`Step`]: added, rounded to 1e-9 so repeated nudges print cleanly; or
/// multiplied (×r, Shift ×r², fine ×r^{1/10}), to four significant digits;
/// Π_K's 0 ("derived") from the derived value, another 0 not at all.
pub fn nudged_text(p: &Params, f: &Field, direction: f64, size: StepSize) -> Option<String> {
    match f.kind {
        Kind::Choice { names, get, .. } => {
            let n = names.len() as isize;
            let i = names.iter().position(|x| *x == get(p)).unwrap_or(0) as isize;
            let next = (i + direction.signum() as isize).rem_euclid(n) as usize;
            Some(names[next].to_string())
        }
        Kind::Integer { get, .. } => {
            let unit = match f.step {
                Step::Add(d) => d,
                Step::Times(_) => 1.0,
            };
            let step = (unit * size.factor()).max(1.0);
            let n = (get(p) as f64 + direction * step).max(1.0);
            Some(format!("{n}"))
        }
        Kind::Number { get, .. } => {
            let v = get(p);
            if !v.is_finite() {
                return None;
            }
            match f.step {
                Step::Add(d) => {
                    let next = v + direction * d * size.factor();
                    Some(format!("{}", (next * 1e9).round() / 1e9))
                }
                Step::Times(r) => {
                    // A factor cannot move 0. Π_K = 0 means "derived from
                    // Π_ωcon": its nudge starts from the derived value, the
                    // one the run uses, and sets it explicitly.
                    let v = match (v, f.key) {
                        (0.0, "hertz_stiffness") => p.hertz_stiffness(),
                        (0.0, _) => return None,
                        _ => v,
                    };
                    let power = match size {
                        StepSize::Fine => 0.1,
                        StepSize::Normal => 1.0,
                        StepSize::Coarse => 2.0,
                    };
                    Some(g4(v * r.powf(direction * power)))
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ContactModel, Method, SET1};

    fn row(key: &str) -> &'static Field {
        crate::model::params::field(key).unwrap()
    }

    /// The contact tolerance spans decades: a nudge multiplies it.
    #[test]
    fn a_tolerance_is_nudged_by_factors() {
        let tol = row("contact_tolerance");
        assert_eq!(
            nudged_text(&SET1, tol, 1.0, StepSize::Normal).unwrap(),
            "1e-10"
        );
        assert_eq!(
            nudged_text(&SET1, tol, -1.0, StepSize::Coarse).unwrap(),
            "1e-13"
        );
        assert_eq!(
            nudged_text(&SET1, tol, -1.0, StepSize::Fine).unwrap(),
            "7.943e-12"
        );
        let mut p = SET1;
        p.set(
            "contact_tolerance",
            &nudged_text(&SET1, tol, -1.0, StepSize::Normal).unwrap(),
        )
        .unwrap();
        assert_eq!(p.contact_tolerance, 1e-12);
    }

    /// Π_ωcon and Π_K span decades: a nudge multiplies them. Π_K = 0
    /// (derived from Π_ωcon) moves from the derived value, both ways, and
    /// a nudge back returns to it (written out).
    #[test]
    fn contact_frequency_and_hertz_stiffness_are_nudged_by_factors() {
        let omega = row("contact_omega");
        assert_eq!(
            nudged_text(&SET1, omega, 1.0, StepSize::Normal).unwrap(),
            "100"
        );
        assert_eq!(
            nudged_text(&SET1, omega, -1.0, StepSize::Coarse).unwrap(),
            "12.5"
        );
        let k = row("hertz_stiffness");
        assert_eq!(SET1.hertz_stiffness, 0.0);
        let derived = SET1.hertz_stiffness();
        for direction in [1.0, -1.0] {
            let text = nudged_text(&SET1, k, direction, StepSize::Normal).unwrap();
            let mut p = SET1;
            p.set("hertz_stiffness", &text).unwrap();
            let ratio = p.hertz_stiffness / derived;
            let want = 2f64.powf(direction);
            assert!((ratio / want - 1.0).abs() < 1e-3, "{text}: ×{ratio}");
            let back = nudged_text(&p, k, -direction, StepSize::Normal).unwrap();
            p.set("hertz_stiffness", &back).unwrap();
            assert!((p.hertz_stiffness / derived - 1.0).abs() < 1e-3, "{back}");
        }
        // An explicit Π_K moves by the factor itself.
        let p = Params {
            hertz_stiffness: 400.0,
            ..SET1
        };
        assert_eq!(nudged_text(&p, k, 1.0, StepSize::Normal).unwrap(), "800");
    }

    #[test]
    fn nudges_round_cleanly() {
        let gap = row("gap");
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

    #[test]
    fn choices_cycle() {
        let mut p = SET1;
        for (key, expect) in [("model", "hertz"), ("method", "exact")] {
            let text = nudged_text(&p, row(key), 1.0, StepSize::Normal).unwrap();
            assert_eq!(text, expect);
            p.set(key, &text).unwrap();
        }
        assert_eq!((p.model, p.method), (ContactModel::Hertz, Method::Exact));
        assert_eq!(value_text(&p, row("method")), "exact");
    }
}
