//! The cases: the corners of the parameter space (stiff and soft contact,
//! extreme restitution and mass ratio, grazing, long runs, every range
//! limit), then seeded random valid parameter sets.

use crate::model::{ContactModel, Excitation, Params, SET1};
use crate::solver::{FullHistory, SolverOptions, simulate};

use super::super::random::SplitMix64;

/// What a case checks beyond the invariants every case keeps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Expect {
    /// The invariants only.
    Invariants,
    /// Linear, undamped, free: |x_i| never exceeds the exact amplitude
    /// √(x₀² + (v₀/ω)²) by more than [`AMPLITUDE_TOLERANCE`] (average
    /// acceleration conserves the discrete energy of a linear undamped system
    /// at any Δτ, which the energy residual shows exactly; the solver's peaks
    /// come from a cubic interpolant inside each step, which may overshoot the
    /// state's amplitude by its interpolation error: 1.5e-6 at Π_ω·Δτ = 0.12).
    AmplitudeBound([f64; 2]),
    /// A long run with the peaks-only observer: resident memory must not grow
    /// by more than this many bytes.
    MemoryBound(usize),
    /// Contact deliberately under-resolved (flagged): it must stay finite,
    /// converged and energy-consistent, but accuracy properties (no tension)
    /// are reported as degradation, not failure.
    UnderResolved,
}

/// Allowed relative overshoot of the amplitude by the interpolated peaks.
pub const AMPLITUDE_TOLERANCE: f64 = 1e-3;

/// One run to check.
#[derive(Debug, Clone)]
pub struct Case {
    pub name: String,
    pub params: Params,
    pub options: SolverOptions,
    pub expect: Expect,
}

fn case(name: impl Into<String>, params: Params) -> Case {
    Case {
        name: name.into(),
        params,
        options: SolverOptions::default(),
        expect: Expect::Invariants,
    }
}

fn with(key: &str, value: f64) -> Params {
    let mut p = SET1;
    p.set(key, &value.to_string())
        .expect("corner values are valid");
    p
}

const MODELS: [ContactModel; 2] = ContactModel::PAPER;

/// The corners, each a departure from set 1.
pub fn corner_cases() -> Vec<Case> {
    let mut out = Vec::new();
    for w in [1.0, 10.0, 100.0, 1e3, 1e4] {
        out.push(case(format!("contact_omega={w}"), with("contact_omega", w)));
    }
    // Under-resolved contact (Π_ωcon·Δτ = 10) without sub-steps: must stay finite and be flagged.
    out.push(Case {
        options: SolverOptions::located(),
        expect: Expect::UnderResolved,
        ..case(
            "contact_omega=1e4 located, no sub-steps",
            with("contact_omega", 1e4),
        )
    });
    for e in [1e-3, 1e-2, 0.1, 0.4, 0.7, 1.0] {
        for model in MODELS {
            let p = Params {
                model,
                ..with("restitution", e)
            };
            out.push(case(format!("restitution={e} {model}"), p));
        }
    }
    for gap in [0.0, 10.0] {
        for model in MODELS {
            out.push(case(
                format!("gap={gap} {model}"),
                Params {
                    model,
                    ..with("gap", gap)
                },
            ));
        }
    }
    for m in [1e-3, 1e-2, 10.0, 1e3] {
        out.push(case(format!("mass_ratio={m}"), with("mass_ratio", m)));
    }
    for a in [0.0, 1.0] {
        out.push(case(format!("alpha={a}"), with("alpha", a)));
    }
    for uy in [1e-4, f64::INFINITY] {
        let p = Params {
            yield1: uy,
            yield2: uy,
            ..SET1
        };
        out.push(case(format!("yield={uy}"), p));
    }
    out.push(case("damping=0", with("damping", 0.0)));
    for dt in [1e-5, 1e-4, 0.01, 0.05] {
        for model in MODELS {
            out.push(case(
                format!("dt={dt} {model}"),
                Params {
                    model,
                    ..with("dt", dt)
                },
            ));
        }
    }
    out.extend(stability_cases());
    out.push(Case {
        expect: Expect::MemoryBound(16 << 20),
        ..case(
            "cycles=1000 peaks-only memory",
            Params {
                cycles: 1000,
                ..SET1
            },
        )
    });
    out.extend(grazing_cases());
    out.extend(range_limit_cases());
    out
}

/// Every bound of the parameter table, at its limit (each case runs with
/// both methods, see `checks`): the ends of the accepted ranges must give
/// finite, balanced, agreeing results.
fn range_limit_cases() -> Vec<Case> {
    let mut out = Vec::new();
    for model in MODELS {
        for (key, value) in [
            ("contact_omega", 1e5),
            ("contact_omega", 1e6),
            ("restitution", 1e-3),
            ("mass_ratio", 1e-3),
            ("mass_ratio", 1e3),
        ] {
            out.push(case(
                format!("limit {key}={value} {model}"),
                Params {
                    model,
                    ..with(key, value)
                },
            ));
        }
    }
    for (key, value) in [
        ("damping", 1.0),
        ("gap", 1e6),
        ("yield1", 1e6),
        ("min_impact_velocity", 1e-6),
        ("min_impact_velocity", 0.1),
    ] {
        out.push(case(format!("limit {key}={value}"), with(key, value)));
    }
    // The fastest structures the table accepts, with the largest Δτ it allows for them.
    let mut stiff = SET1;
    for (key, value) in [
        ("omega1", "1000"),
        ("omega2", "1000"),
        ("dt", "6e-6"),
        ("cycles", "1"),
    ] {
        stiff.set(key, value).expect("limit values are valid");
    }
    out.push(case("limit omega1=omega2=1000, dt=6e-6", stiff));
    out
}

/// Linear, undamped, free vibration from ẋ = (1, −1) at Δτ up to 10
/// (Π_ω2·Δτ = 23.6): the amplitude must stay at 1/Π_ωi.
fn stability_cases() -> Vec<Case> {
    [0.05, 1.0, 10.0]
        .into_iter()
        .map(|dt| {
            let p = Params {
                yield1: f64::INFINITY,
                yield2: f64::INFINITY,
                gap: f64::INFINITY,
                damping: 0.0,
                dt,
                ..SET1
            };
            Case {
                name: format!("linear free vibration dt={dt}"),
                options: SolverOptions {
                    excitation: Excitation::None,
                    initial_velocity: [1.0, -1.0],
                    ..SolverOptions::default()
                },
                expect: Expect::AmplitudeBound([1.0 / p.omega1, 1.0 / p.omega2]),
                params: p,
            }
        })
        .collect()
}

/// Contacts whose approach velocity v₀ is below `min_impact_velocity` (1e-3):
/// a touch from rest-like motion, and a sine-driven run whose gap is a hair
/// under the largest separation closure of the no-pounding run.
fn grazing_cases() -> Vec<Case> {
    let mut out = Vec::new();
    for model in MODELS {
        let p = Params {
            gap: 0.0,
            model,
            cycles: 2,
            ..SET1
        };
        out.push(Case {
            name: format!("grazing v0=5e-4 {model}"),
            options: SolverOptions {
                excitation: Excitation::None,
                initial_velocity: [5e-4, 0.0],
                ..SolverOptions::default()
            },
            ..case("", p)
        });
        let mut free = FullHistory::default();
        simulate(
            &Params {
                gap: f64::INFINITY,
                ..SET1
            },
            &SolverOptions::default(),
            &mut free,
        );
        let closest = free
            .samples
            .iter()
            .map(|s| s.x[0] - s.x[1])
            .fold(f64::NEG_INFINITY, f64::max);
        out.push(case(
            format!("grazing gap=max(x1-x2)-1e-9 {model}"),
            Params {
                gap: closest - 1e-9,
                model,
                ..SET1
            },
        ));
    }
    out
}

/// A random valid parameter set: every Π log-uniform over a wide range,
/// yield and gap sometimes infinite.
pub fn random_params(rng: &mut SplitMix64) -> Params {
    let maybe_inf = |rng: &mut SplitMix64, lo: f64, hi: f64| {
        if rng.chance(0.15) {
            f64::INFINITY
        } else {
            rng.log_uniform(lo, hi)
        }
    };
    Params {
        mass_ratio: rng.log_uniform(1e-2, 1e2),
        omega1: rng.log_uniform(0.2, 5.0),
        omega2: rng.log_uniform(0.2, 10.0),
        yield1: maybe_inf(rng, 1e-2, 10.0),
        yield2: maybe_inf(rng, 1e-2, 10.0),
        damping: rng.uniform(0.0, 0.2),
        alpha: rng.uniform(0.0, 1.0),
        contact_omega: rng.log_uniform(5.0, 2000.0),
        restitution: rng.uniform(0.05, 1.0),
        gap: if rng.chance(0.1) {
            f64::INFINITY
        } else {
            rng.uniform(0.0, 2.0)
        },
        model: if rng.chance(0.5) {
            ContactModel::Kelvin
        } else {
            ContactModel::ImprovedKelvin
        },
        method: crate::model::Method::Newmark,
        cycles: 2 + (rng.next_u64() % 7) as u32,
        dt: 0.001,
        min_impact_velocity: 1e-3,
        ..SET1
    }
}

/// `count` random cases from `seed`, each named by its seed and index so it can be rerun.
pub fn random_cases(count: usize, seed: u64) -> Vec<Case> {
    let mut rng = SplitMix64::new(seed);
    (0..count)
        .map(|i| {
            case(
                format!("random #{i} (seed {seed})"),
                random_params(&mut rng),
            )
        })
        .collect()
}
