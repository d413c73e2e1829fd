//! The parameter table: one row per key a preset, `--set`, a family or the
//! explorer can set. Everything that names a key — validation, `--set`,
//! presets, the explorer's rows, the guide's key list (docs/src/physics/pair.md) and the error
//! messages — reads it from here, so a new key is one row.
//!
//! Each range is the one in which a run means something and the solver is
//! known to be right. The evidence for each bound is in the row's comment:
//! set 1 (`pounding run`, Δτ = 0.001, 8 cycles) with the one value changed,
//! Π_u1 = 3.2224 and Π_u2 = 0.4788 at set 1 itself.

use std::f64::consts::TAU;

use super::field::{Field, Group, Kind, Step};
use crate::model::excitation::{Excitation, NAMES as EXCITATIONS};
use crate::model::{ContactModel, Method};

/// Δτ's own upper bound: 20 steps per excitation period 2π. Together with
/// the structural periods it gives the bound [`super::Params::validate`]
/// checks, Δτ ≤ 2π/(20 · max(1, Π_ω1, Π_ω2)).
pub const DT_MAX: f64 = TAU / STEPS_PER_PERIOD;

/// Fewest Newmark steps per period of the excitation and of each structure.
/// Evidence (set 1, whose shortest period is 2π/Π_ω2 = 2.66): Δτ = 0.1
/// (26.6 steps) moves Π_u1 by 1.6 %, Δτ = 0.2 (13 steps) by 4.2 %, and at
/// Δτ = 0.3 (8.9 steps) the improved Kelvin element pulls (f_p = −0.38) and
/// Π_u2 is 15 % off; Δτ = 3 gives no impact at all and Δτ = 60 a single step.
pub const STEPS_PER_PERIOD: f64 = 20.0;

/// Every key, in display order: the ten Π-groups of SPEC §1, then the run settings.
pub const FIELDS: &[Field] = &[
    // Π_m: the response has reached its limits at both ends (Π_u1 = 2.622 at
    // 1e-3 against 2.620 at 1e-10; 2.418 at 1e3 against 2.426 at 1e10), so
    // no wider value says anything new. Outside, the run hangs: Π_m = 1e-320
    // (subnormal, 1/Π_m = inf) and 1e300 (Π_m² overflows) never finish.
    Field {
        key: "mass_ratio",
        symbol: "Π_m",
        ascii: "Pi_m",
        meaning: "mass ratio m1/m2",
        group: Group::Pi,
        kind: Kind::Number {
            min: 1e-3,
            max: 1e3,
            inf: false,
            get: |p| p.mass_ratio,
            set: |p, v| p.mass_ratio = v,
        },
        step: Step::Add(0.05),
    },
    // Π_ω: 0 is a structure without a spring, a free mass (the isolated
    // two-mass impact tests use it); towards 0 it drifts with the ground
    // (Π_u1 = 48.7 at 1e-2, 50.3 = τ_end at 0), finite down to 1e-320.
    // Above 1e3 it is rigid (Π_u1 = 1.7e-5 ≈ 1/Π_ω² at 1e3, and Δτ must be
    // below 3e-4 to resolve it). Π_ω1 = 1e100 hangs, 1e300 gives NaN.
    Field {
        key: "omega1",
        symbol: "Π_ω1",
        ascii: "Pi_w1",
        meaning: "left frequency ω1/ωp",
        group: Group::Pi,
        kind: Kind::Number {
            min: 0.0,
            max: 1e3,
            inf: false,
            get: |p| p.omega1,
            set: |p, v| p.omega1 = v,
        },
        step: Step::Add(0.05),
    },
    // Π_ω2: as Π_ω1.
    Field {
        key: "omega2",
        symbol: "Π_ω2",
        ascii: "Pi_w2",
        meaning: "right frequency ω2/ωp",
        group: Group::Pi,
        kind: Kind::Number {
            min: 0.0,
            max: 1e3,
            inf: false,
            get: |p| p.omega2,
            set: |p, v| p.omega2 = v,
        },
        step: Step::Add(0.05),
    },
    // Π_uy: below 1e-4 the structure yields at once and the value no longer
    // matters (Π_u1 = 5.081 at 1e-4, 5.082 at 1e-300); 1e6 is above every
    // displacement an allowed run reaches (a free mass drifts at most
    // τ_end + 1 ≤ 6.3e5), so a larger yield is never reached: write inf.
    Field {
        key: "yield1",
        symbol: "Π_uy1",
        ascii: "Pi_uy1",
        meaning: "left yield displacement",
        group: Group::Pi,
        kind: Kind::Number {
            min: 1e-4,
            max: 1e6,
            inf: true,
            get: |p| p.yield1,
            set: |p, v| p.yield1 = v,
        },
        step: Step::Add(0.05),
    },
    // Π_uy2: as Π_uy1.
    Field {
        key: "yield2",
        symbol: "Π_uy2",
        ascii: "Pi_uy2",
        meaning: "right yield displacement",
        group: Group::Pi,
        kind: Kind::Number {
            min: 1e-4,
            max: 1e6,
            inf: true,
            get: |p| p.yield2,
            set: |p, v| p.yield2 = v,
        },
        step: Step::Add(0.05),
    },
    // Π_ξ: a viscous damping ratio; at ξ ≥ 1 a structure no longer
    // oscillates (overdamped: set 1 has no impact at ξ = 2), which no
    // building is. The solver itself stays finite up to 1e300.
    Field {
        key: "damping",
        symbol: "Π_ξ",
        ascii: "Pi_xi",
        meaning: "damping ratio ξ",
        group: Group::Pi,
        kind: Kind::Number {
            min: 0.0,
            max: 1.0,
            inf: false,
            get: |p| p.damping,
            set: |p, v| p.damping = v,
        },
        step: Step::Add(0.01),
    },
    // Π_α: post-yield over elastic stiffness, from perfectly plastic (0) to
    // linear (1); both ends run cleanly in the stress test.
    Field {
        key: "alpha",
        symbol: "Π_α",
        ascii: "Pi_alpha",
        meaning: "post-yield stiffness",
        group: Group::Pi,
        kind: Kind::Number {
            min: 0.0,
            max: 1.0,
            inf: false,
            get: |p| p.alpha,
            set: |p, v| p.alpha = v,
        },
        step: Step::Add(0.01),
    },
    // Π_ωcon: a contact element slower than the excitation is no impact (at
    // 1 the improved Kelvin element already pulls, f_p = −0.089). Above,
    // the contact is resolved by sub-steps down to Δτ/2²⁰: Π_u1 stays
    // within 0.6 % up to 1e8, is 4 % off at 1e9; at 1e10 it gives 83
    // impacts instead of 9 and a pulling force of −1.5e9, at 1e15
    // Π_u1 = 32.7 with an energy residual of 2420, and 1e300 hangs. 1e6
    // keeps 20 sub-steps per contact period at every allowed Δτ
    // (2π·2²⁰/(20 · 0.314) = 1.0e6).
    Field {
        key: "contact_omega",
        symbol: "Π_ωcon",
        ascii: "Pi_wcon",
        meaning: "contact frequency ω̄/ωp",
        group: Group::Pi,
        kind: Kind::Number {
            min: 1.0,
            max: 1e6,
            inf: false,
            get: |p| p.contact_omega,
            set: |p, v| p.contact_omega = v,
        },
        // It spans six decades, and the contact's stiffness goes as its
        // square: a nudge doubles or halves it.
        step: Step::Times(2.0),
    },
    // Π_e: the improved Kelvin damping 3(1−e)/(2e) grows without bound as
    // e → 0. At 1e-3 Π_u1 = 3.094 is within 1.3 % of the Kelvin element's
    // plastic limit (3.135); at 1e-4 it is 2.234 (29 % off), at 1e-10 6.42,
    // at 1e-20 Π_u1 = 1e4 with an energy residual of 6e18, and 1e-100 hangs.
    Field {
        key: "restitution",
        symbol: "Π_e",
        ascii: "Pi_e",
        meaning: "restitution e",
        group: Group::Pi,
        kind: Kind::Number {
            min: 1e-3,
            max: 1.0,
            inf: false,
            get: |p| p.restitution,
            set: |p, v| p.restitution = v,
        },
        step: Step::Add(0.05),
    },
    // Π_d: 0 is touching at rest; above 1e6 (as for Π_uy) the gap is never
    // closed by an allowed run: write inf for no pounding.
    Field {
        key: "gap",
        symbol: "Π_d",
        ascii: "Pi_d",
        meaning: "initial gap d ωp²/ap",
        group: Group::Pi,
        kind: Kind::Number {
            min: 0.0,
            max: 1e6,
            inf: true,
            get: |p| p.gap,
            set: |p, v| p.gap = v,
        },
        step: Step::Add(0.05),
    },
    // Π_K = β√l_e/(m2 ω_p²) of the Hertz-type laws (SPEC §10); 0 derives it
    // from Π_ωcon so that a contact at v₀ = 1 lasts π/Π_ωcon, as the linear
    // element's does. Matched values run from 3e-4 (Π_ωcon = 1, Π_m = 1e-3)
    // to 4e14 (Π_ωcon = 1e6, Π_m = 1e3); 1e16 leaves room above.
    Field {
        key: "hertz_stiffness",
        symbol: "Π_K",
        ascii: "Pi_K",
        meaning: "Hertz stiffness (0: from Π_ωcon)",
        group: Group::Pi,
        kind: Kind::Number {
            min: 0.0,
            max: 1e16,
            inf: false,
            get: |p| p.hertz_stiffness,
            set: |p, v| p.hertz_stiffness = v,
        },
        // Twenty decades: a nudge doubles or halves the force. From 0 it
        // starts at the derived value the run uses (see `nudged_text`).
        step: Step::Times(2.0),
    },
    // The contact element of SPEC §4 and §10.
    Field {
        key: "model",
        symbol: "model",
        ascii: "model",
        meaning: "contact element",
        group: Group::Setting,
        kind: Kind::Choice {
            names: &[
                "kelvin",
                "improved-kelvin",
                "hertz",
                "hertzdamp",
                "jankowski",
                "hunt-crossley",
            ],
            get: |p| p.model.name(),
            set: |p, t| t.parse::<ContactModel>().map(|m| p.model = m).is_ok(),
        },
        step: Step::Add(1.0),
    },
    // The ground motion of SPEC §9; `record:PATH` reads a PEER `.AT2` file.
    Field {
        key: "excitation",
        symbol: "g(τ)",
        ascii: "g",
        meaning: "ground motion",
        group: Group::Setting,
        kind: Kind::Choice {
            names: &EXCITATIONS,
            get: |p| p.excitation.name(),
            set: |p, t| Excitation::parse(t).map(|e| p.excitation = e).is_ok(),
        },
        step: Step::Add(1.0),
    },
    // s, the factor on a record's accelerations (a record scaled to an
    // intensity, SPEC §12); 1e3 matches the largest scale of a suite list.
    Field {
        key: "record_scale",
        symbol: "s",
        ascii: "s",
        meaning: "record scale factor",
        group: Group::Setting,
        kind: Kind::Number {
            min: 1e-6,
            max: 1e3,
            inf: false,
            get: |p| p.record_scale,
            set: |p, v| p.record_scale = v,
        },
        step: Step::Times(1.258_925_411_794_167_3),
    },
    // a_p of a record (m/s²): 0 is the scaled record's peak; 1e3 m/s² is 100 g.
    Field {
        key: "record_amplitude",
        symbol: "a_p",
        ascii: "a_p",
        meaning: "record a_p in m/s² (0: peak)",
        group: Group::Setting,
        kind: Kind::Number {
            min: 0.0,
            max: 1e3,
            inf: false,
            get: |p| p.record_amplitude,
            set: |p, v| p.record_amplitude = v,
        },
        step: Step::Add(0.5),
    },
    // ω_p of a record (rad/s): 0 is its dominant frequency; 1e3 rad/s is
    // 160 Hz, above any structural band.
    Field {
        key: "record_omega",
        symbol: "ω_p",
        ascii: "w_p",
        meaning: "record ω_p in rad/s (0: dominant)",
        group: Group::Setting,
        kind: Kind::Number {
            min: 0.0,
            max: 1e3,
            inf: false,
            get: |p| p.record_omega,
            set: |p, v| p.record_omega = v,
        },
        step: Step::Add(0.5),
    },
    // The time integrator: Newmark-β at Δτ, or event-driven exact.
    Field {
        key: "method",
        symbol: "method",
        ascii: "method",
        meaning: "time integrator",
        group: Group::Setting,
        kind: Kind::Choice {
            names: &["newmark", "exact"],
            get: |p| p.method.name(),
            set: |p, t| t.parse::<Method>().map(|m| p.method = m).is_ok(),
        },
        step: Step::Add(1.0),
    },
    // The exact method's contact tolerance (Newmark ignores it). Below 1e-14
    // the error is round-off and only the cost grows (set 2, improved
    // Kelvin: 0.095 ms at 1e-14, 0.11 at 1e-16); at 1e-8 the peaks' error is
    // 5e-8 (set 1), the method's target of 1e-9 no longer held.
    Field {
        key: "contact_tolerance",
        symbol: "tol",
        ascii: "tol",
        meaning: "exact: contact tolerance",
        group: Group::Setting,
        kind: Kind::Number {
            min: 1e-16,
            max: 1e-8,
            inf: false,
            get: |p| p.contact_tolerance,
            set: |p, v| p.contact_tolerance = v,
        },
        step: Step::Times(10.0),
    },
    // Duration: 1e5 cycles is 6.3e8 steps at Δτ = 0.001, close to the
    // 1e9-step cap on one run.
    Field {
        key: "cycles",
        symbol: "cycles",
        ascii: "cycles",
        meaning: "excitation cycles",
        group: Group::Setting,
        kind: Kind::Integer {
            min: 1,
            max: 100_000,
            get: |p| p.cycles,
            set: |p, n| p.cycles = n,
        },
        step: Step::Add(1.0),
    },
    // Δτ: at most 20 steps per excitation period ([`DT_MAX`]; the structural
    // periods are checked with the frequencies). At 1e-6 a cycle is 6.3e6
    // steps and round-off already shows (energy residual 3.5e-10 in one
    // cycle, against 1e-13 at 1e-3); `dt = 1e300` gave 0 steps, `dt = 60` one.
    Field {
        key: "dt",
        symbol: "Δτ",
        ascii: "dtau",
        meaning: "Newmark time step",
        group: Group::Setting,
        kind: Kind::Number {
            min: 1e-6,
            max: DT_MAX,
            inf: false,
            get: |p| p.dt,
            set: |p, v| p.dt = v,
        },
        step: Step::Add(0.0005),
    },
    // v₀ floor of the improved Kelvin element: above 0.1 it changes real
    // impacts (set 1's approach velocities are about 1: Π_u1 moves 1.2 % at a
    // floor of 1, 7 % at 10); below 1e-6 the damping 3(1−e)/(2e v₀) of a
    // grazing contact exceeds 1e6 k̄. From 1e-4 down a grazing contact of set 1
    // already pulls (f_p = −7.5e-6 against a peak of 4e-5), harmless to the peaks.
    Field {
        key: "min_impact_velocity",
        symbol: "v₀min",
        ascii: "v0min",
        meaning: "floor on approach velocity",
        group: Group::Setting,
        kind: Kind::Number {
            min: 1e-6,
            max: 0.1,
            inf: false,
            get: |p| p.min_impact_velocity,
            set: |p, v| p.min_impact_velocity = v,
        },
        step: Step::Add(1e-4),
    },
];

/// The row of a key.
pub fn field(key: &str) -> Option<&'static Field> {
    FIELDS.iter().find(|f| f.key == key)
}

/// Every key, in display order.
pub fn keys() -> impl Iterator<Item = &'static str> {
    FIELDS.iter().map(|f| f.key)
}

/// Is `key` one of the Π-groups of SPEC §1?
pub fn is_pi(key: &str) -> bool {
    field(key).is_some_and(|f| f.group == Group::Pi)
}
