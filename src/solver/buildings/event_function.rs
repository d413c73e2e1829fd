//! An event's function (SPEC §13): a linear form in the state,
//!
//! ```text
//! g = Σ w_u,i u_i + Σ w_v,i u̇_i + c,   ġ = Σ w_u,i u̇_i + Σ w_v,i ü_i,
//! ```
//!
//! whose first rise through zero is the event: a storey's drift reaching
//! yield (Δ − p ∓ Δ_y), its rate changing sign (unloading), a floor pair's
//! penetration δ = u_A − u_B − d turning positive (onset) or negative
//! (separation), and its rate δ̇ turning negative (the Jankowski law's
//! switch at the deepest point). Each involves at most two floors.

use super::taylor::Series;

/// g of one event: (floor, weight) terms on u and on u̇ (weight 0: unused),
/// and the constant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EventFunction {
    pub on_u: [(usize, f64); 2],
    pub on_v: [(usize, f64); 2],
    pub constant: f64,
}

impl EventFunction {
    /// w (u_upper − u_lower) + c: a drift, the lower floor None at the ground.
    pub fn drift(upper: usize, lower: Option<usize>, w: f64, constant: f64) -> EventFunction {
        EventFunction {
            on_u: [(upper, w), lower.map_or((0, 0.0), |l| (l, -w))],
            on_v: [(0, 0.0); 2],
            constant,
        }
    }

    /// w (u̇_upper − u̇_lower): a drift's rate.
    pub fn drift_rate(upper: usize, lower: Option<usize>, w: f64) -> EventFunction {
        EventFunction {
            on_u: [(0, 0.0); 2],
            on_v: [(upper, w), lower.map_or((0, 0.0), |l| (l, -w))],
            constant: 0.0,
        }
    }

    /// g on `series`, coefficient by coefficient, into `out`.
    pub fn on(&self, series: &Series, out: &mut Vec<f64>) {
        series.combine(&self.on_u, &self.on_v, out);
        out[0] += self.constant;
    }

    /// Whether g reads a velocity (unloading, the Jankowski law's switch, a
    /// damper's reversal) rather than displacements alone.
    pub fn reads_velocities(&self) -> bool {
        self.on_v.iter().any(|&(_, w)| w != 0.0)
    }

    /// g at the state (u, u̇).
    pub fn value(&self, u: &[f64], v: &[f64]) -> f64 {
        let mut g = self.constant;
        for &(i, w) in &self.on_u {
            g += w * u[i];
        }
        for &(i, w) in &self.on_v {
            g += w * v[i];
        }
        g
    }

    /// (g, ġ) at the state (u, u̇, ü).
    pub fn at(&self, u: &[f64], v: &[f64], acc: &[f64]) -> (f64, f64) {
        let mut rate = 0.0;
        for &(i, w) in &self.on_u {
            rate += w * v[i];
        }
        for &(i, w) in &self.on_v {
            rate += w * acc[i];
        }
        (self.value(u, v), rate)
    }
}
