//! Bilinear hysteresis with kinematic hardening (SPEC §3), as OpenSees `Steel01`
//! with b = Π_α.
//!
//! f_s = Π_α k x + (1 − Π_α) k z with |z| ≤ Π_uy; ż = ẋ while |z| < Π_uy or
//! z ẋ < 0, else ż = 0. Over a step the update is a return map: the elastic
//! predictor z* = z_n + (x − x_n), then the plastic corrector z = Π_uy sign z*
//! where |z*| > Π_uy.

/// Constants of one structure's spring.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bilinear {
    /// Elastic stiffness k (k1 = Π_m Π_ω1², k2 = Π_ω2²).
    pub stiffness: f64,
    /// Yield displacement Π_uy (may be infinite: elastic).
    pub yield_displacement: f64,
    /// Post-yield stiffness ratio Π_α.
    pub alpha: f64,
}

/// The history variable of one spring at an accepted state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpringState {
    /// Displacement x at which `z` was reached.
    pub x: f64,
    /// Elastic part z, |z| ≤ Π_uy.
    pub z: f64,
}

/// Result of the return map at a trial displacement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringResponse {
    pub force: f64,
    /// Consistent tangent ∂f_s/∂x: k elastic, Π_α k plastic.
    pub tangent: f64,
    pub state: SpringState,
    pub plastic: bool,
}

impl Bilinear {
    /// Return map from the accepted state `from` to trial displacement `x`.
    #[inline]
    pub fn respond(&self, from: SpringState, x: f64) -> SpringResponse {
        let trial = from.z + (x - from.x);
        let uy = self.yield_displacement;
        let (z, plastic) = if trial.abs() > uy {
            (uy.copysign(trial), true)
        } else {
            (trial, false)
        };
        let k = self.stiffness;
        SpringResponse {
            force: self.alpha * k * x + (1.0 - self.alpha) * k * z,
            tangent: if plastic { self.alpha * k } else { k },
            state: SpringState { x, z },
            plastic,
        }
    }

    /// Force at an accepted state.
    #[inline]
    pub fn force(&self, s: SpringState) -> f64 {
        self.alpha * self.stiffness * s.x + (1.0 - self.alpha) * self.stiffness * s.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loop_follows_kinematic_hardening() {
        let b = Bilinear {
            stiffness: 2.0,
            yield_displacement: 1.0,
            alpha: 0.1,
        };
        let s0 = SpringState::default();
        let r = b.respond(s0, 0.5);
        assert!(!r.plastic && (r.force - 1.0).abs() < 1e-15);
        let r = b.respond(r.state, 2.0); // yields at x = 1, force 2 + 0.1*2*1
        assert!(r.plastic && (r.force - 2.2).abs() < 1e-12);
        let r = b.respond(r.state, 1.5); // unloads elastically by k
        assert!(!r.plastic && (r.force - 1.2).abs() < 1e-12);
        let r = b.respond(r.state, -1.0); // reverse yield after 2 u_y of travel
        assert!(r.plastic && (r.force - (-0.2 - 1.8)).abs() < 1e-12);
    }

    #[test]
    fn infinite_yield_is_elastic() {
        let b = Bilinear {
            stiffness: 3.0,
            yield_displacement: f64::INFINITY,
            alpha: 0.1,
        };
        let r = b.respond(SpringState::default(), 1e6);
        assert!(!r.plastic && (r.force - 3e6).abs() < 1e-6);
    }
}
