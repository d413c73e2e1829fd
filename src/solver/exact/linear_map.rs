//! What the two linear maps of a quiet stretch share (SPEC §2–3): the sine's
//! segment map ([`super::quiet::Transition`]) and a record's sample map
//! ([`super::sample::SampleMap`]).
//!
//! Out of contact, on a fixed branch, a structure obeys
//! ẍ = Q/m − (c/m) ẋ − (K/m) x − g, so its state over a stretch is a sum of
//! five unit responses weighted by the stretch's inputs:
//!
//! ```text
//! y(t) = (x*, 0) + Σ_j input_j · u_j(t),
//! inputs = (x − x*, ẋ, γ₀, γ₁, Q/m),   x* = Q/K the branch's equilibrium,
//! ```
//!
//! where (γ₀, γ₁) are the ground's two inputs (sin τ₀ and cos τ₀ of the
//! sine; g_k and the slope s of a record's sample) and the load input is
//! used only where K = 0 and there is no equilibrium. Each map keeps the
//! unit responses' ends and swings; the inputs, the end state, the swing
//! bounds and the cubic majorants are computed here, once for both.

use super::series::Series;

/// Number of inputs: x − x*, ẋ, the ground's two, Q/m.
pub const INPUTS: usize = 5;

/// The ends (x, ẋ) at `h` and the swings (of x, of ẋ) over [0, h] of the
/// unit responses `units`; each rate's series is left in `rates`.
pub fn ends_and_swings(
    units: &[Series; INPUTS],
    h: f64,
    rates: &mut [Series; INPUTS],
) -> ([[f64; 2]; INPUTS], [[f64; 2]; INPUTS]) {
    let mut end = [[0.0; 2]; INPUTS];
    let mut swing = [[0.0; 2]; INPUTS];
    for (j, u) in units.iter().enumerate() {
        let du = &mut rates[j];
        let (sx, sv) = u.derivative_and_swings_into(h, du);
        end[j] = [u.value(h), du.value(h)];
        swing[j] = [sx, sv];
    }
    (end, swing)
}

/// The inputs of a stretch for a structure at (x, ẋ) with load Q/m on a
/// branch of K/m = `stiffness` (1/(K/m) = `inverse_stiffness`, 0 where
/// K = 0), and the equilibrium x* they were taken from (0 where K = 0, the
/// load then an input of its own). Where K > 0 the displacement is taken
/// from x*, so the large, cancelling parts of x and Q/m of a yielded
/// branch do not inflate the bounds.
#[inline(always)]
pub fn inputs(
    stiffness: f64,
    inverse_stiffness: f64,
    x: f64,
    v: f64,
    ground: [f64; 2],
    load: f64,
) -> ([f64; INPUTS], f64) {
    if stiffness > 0.0 {
        let equilibrium = load * inverse_stiffness;
        ([x - equilibrium, v, ground[0], ground[1], 0.0], equilibrium)
    } else {
        ([x, v, ground[0], ground[1], load], 0.0)
    }
}

/// (x, ẋ) at the stretch's end: (x*, 0) + Σ_j input_j · end_j.
#[inline(always)]
pub fn advance(end: &[[f64; 2]; INPUTS], inputs: &[f64; INPUTS], equilibrium: f64) -> [f64; 2] {
    let mut y = [equilibrium, 0.0];
    for (u, e) in inputs.iter().zip(end) {
        y[0] += u * e[0];
        y[1] += u * e[1];
    }
    y
}

/// Bounds of |x − x₀| and |ẋ − ẋ₀| over the stretch: Σ_j |input_j| swing_j.
#[inline(always)]
pub fn swing(swings: &[[f64; 2]; INPUTS], inputs: &[f64; INPUTS]) -> [f64; 2] {
    let mut s = [0.0; 2];
    for (u, w) in inputs.iter().zip(swings) {
        s[0] += u.abs() * w[0];
        s[1] += u.abs() * w[1];
    }
    // The bounds are sums of products: allow for their own round-off.
    s.map(|v| v * (1.0 + 1e-12))
}

/// The start and the bounds of the cubic majorants of x and ẋ over a
/// stretch: with ẍ = Q/m − (c/m) ẋ − (K/m) x − g (SPEC §2–3),
///
/// ```text
/// ẍ₀  = Q/m − (c/m) ẋ₀ − (K/m) x₀ − g₀,      x⁽³⁾₀ = −(c/m) ẍ₀ − (K/m) ẋ₀ − g₀'
/// |ẍ| ≤ A = (c/m) V + (K/m) X + G,   X ≥ |x − x*|, V ≥ |ẋ| on the stretch
/// |x⁽³⁾| ≤ J = (c/m) A + (K/m) V + G',   |x⁽⁴⁾| ≤ S = (c/m) J + (K/m) A + G''
/// ```
///
/// with G, G', G'' bounds of |g|, |g'|, |g''| on the stretch (`ground_bounds`)
/// and, where K = 0, |Q/m| joining A. `ground` is (g₀, g₀') at its start and
/// `swing` the swings of [`swing`]. Returns [ẍ₀, x⁽³⁾₀, J, S].
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn derivative_bounds(
    stiffness: f64,
    inverse_stiffness: f64,
    damping: f64,
    x: f64,
    v: f64,
    ground: [f64; 2],
    load: f64,
    swing: [f64; 2],
    ground_bounds: [f64; 3],
) -> [f64; 4] {
    let a0 = load - damping * v - stiffness * x - ground[0];
    let j0 = -damping * a0 - stiffness * v - ground[1];
    let (from_equilibrium, free_load) = if stiffness > 0.0 {
        ((x - load * inverse_stiffness).abs(), 0.0)
    } else {
        (0.0, load.abs())
    };
    let reach_x = from_equilibrium + swing[0];
    let reach_v = v.abs() + swing[1];
    let accel = damping * reach_v + stiffness * reach_x + free_load + ground_bounds[0];
    let jerk = damping * accel + stiffness * reach_v + ground_bounds[1];
    let snap = damping * jerk + stiffness * accel + ground_bounds[2];
    [a0, j0, jerk, snap]
}

/// The cubic majorants of x and ẋ from the start (x₀, ẋ₀, ẍ₀, x⁽³⁾₀) and the
/// bounds J ≥ |x⁽³⁾|, S ≥ |x⁽⁴⁾| (Taylor's theorem):
/// q(t) ≤ q₀ + q₁ t + q₂ t² + M t³ on the stretch, and −q likewise with q₀,
/// q₁, q₂ negated; M = J/6 for x and S/6 for ẋ.
#[inline(always)]
pub fn cubic_majorants(x: f64, v: f64, a0: f64, j0: f64, jerk: f64, snap: f64) -> [[f64; 4]; 2] {
    // The bounds are sums of products: allow for their own round-off.
    let margin = 1.0 + 1e-12;
    [
        [x, v, 0.5 * a0, margin * jerk / 6.0],
        [v, a0, 0.5 * j0, margin * snap / 6.0],
    ]
}
