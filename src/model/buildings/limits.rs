//! The bounds a row's contact elements are held to (SPEC §13, §14): the
//! least restitution and the stiffest contact per kilogram of reduced mass
//! that the solvers resolve, shared by the joints' own elements and the
//! bumpers'.

/// Least coefficient of restitution (as the pair's `restitution`).
pub const MIN_RESTITUTION: f64 = 1e-3;

/// Most a joint's stiffness k̄ (N/m, the Kelvin family) may be per
/// kilogram of the reduced mass m̄ of any floor pair it joins (1/s²): the
/// contact frequency √(k̄/m̄) ≤ 1e5 rad/s, a contact lasting π/ω̄ ≥ 31 μs.
/// The block-and-frame row (m̄ = 1.7e5 to 1.9e5 kg) runs its sine in
/// 0.05 s at k̄ = 1e13 N/m, in 38 s with 241 impacts and floor
/// accelerations of 7e7 g at 1e17 N/m, and not at all at 1e19; 1e300 gives
/// 300-digit accelerations and a NaN energy balance.
pub const MAX_CONTACT_STIFFNESS_PER_MASS: f64 = 1e10;

/// The same for β (N/m^1.5) of the Hertz-type laws, in 1/(s²·√m): their
/// tangent stiffness 1.5β√δ grows with the penetration δ, and at δ = 1 mm
/// this bound gives √(1.5β√δ/m̄) ≤ 2.2e5 rad/s. The block-and-frame row
/// runs its sine at β = 1e17 N/m^1.5 in 0.8 s, and not at all at 1e19.
pub const MAX_HERTZ_STIFFNESS_PER_MASS: f64 = 1e12;
