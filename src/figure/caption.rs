//! The caption line: every Π-group, the contact law and the integrator, so
//! that a figure can be reproduced from itself.

use crate::model::{Method, Params};

/// The symbol of a parameter key as the paper writes it (SPEC §1).
pub fn symbol(key: &str) -> &str {
    match key {
        "mass_ratio" => "Π_m",
        "omega1" => "Π_ω1",
        "omega2" => "Π_ω2",
        "yield1" => "Π_uy1",
        "yield2" => "Π_uy2",
        "damping" => "Π_ξ",
        "alpha" => "Π_α",
        "contact_omega" => "Π_ωcon",
        "restitution" => "Π_e",
        "gap" => "Π_d",
        "mu" => "μ",
        other => other,
    }
}

/// A number as short as it is exact (`inf` for infinity).
pub fn num(v: f64) -> String {
    if v.is_infinite() {
        "inf".into()
    } else {
        format!("{v}")
    }
}

/// The ten Π-groups of `p` as `Π_m = 0.5, ...`, leaving out `skip` (swept or family keys).
pub fn params_text(p: &Params, skip: &[&str]) -> String {
    crate::model::params::keys()
        .filter(|k| crate::model::params::is_pi(k) && !skip.contains(k))
        .filter_map(|k| p.get(k).map(|v| format!("{} = {}", symbol(k), num(v))))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The integrator, its step and the duration.
pub fn method_text(p: &Params, method: Method) -> String {
    match method {
        Method::Newmark => format!(
            "Newmark-β (γ = 1/2, β = 1/4, located contact), Δτ = {}, {} cycles",
            p.dt, p.cycles
        ),
        Method::Exact => format!("exact (event-driven) method, {} cycles", p.cycles),
    }
}
