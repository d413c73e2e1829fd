//! Exact solutions of the linear, contact-free case (yield = inf, gap = inf),
//! the yardstick the reference and the Newmark solver are both checked against.
//!
//! Each structure is then the damped oscillator (SPEC §2 divided by its mass)
//!
//! ```text
//! ẍ + 2ζω ẋ + ω² x = −s sin τ,   x(0) = x₀, ẋ(0) = v₀,
//! ```
//!
//! with ω = Π_ωi, ζ = Π_ξ and s = 1 (sine excitation) or 0 (free motion).
//! Its solution is the steady state x_p = A sin τ + B cos τ with
//! A = −(ω² − 1)s/D, B = 2ζω s/D, D = (ω² − 1)² + (2ζω)², plus the transient
//! e^{−ζωτ}(C cos ω_d τ + E sin ω_d τ), ω_d = ω√(1 − ζ²), C = x₀ − B,
//! E = (v₀ + ζωC − A)/ω_d. Valid for 0 ≤ ζ < 1, ω > 0 and (ω, ζ) ≠ (1, 0).

/// One linear oscillator's exact response.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearOscillator {
    omega: f64,
    zeta: f64,
    damped_omega: f64,
    a: f64,
    b: f64,
    c: f64,
    e: f64,
}

impl LinearOscillator {
    /// `forcing` is s: 1 for g = sin τ, 0 for free motion.
    pub fn new(omega: f64, zeta: f64, forcing: f64, x0: f64, v0: f64) -> Self {
        let detune = omega * omega - 1.0;
        let d = detune * detune + (2.0 * zeta * omega).powi(2);
        let a = -detune * forcing / d;
        let b = 2.0 * zeta * omega * forcing / d;
        let damped_omega = omega * (1.0 - zeta * zeta).sqrt();
        let c = x0 - b;
        let e = (v0 + zeta * omega * c - a) / damped_omega;
        LinearOscillator {
            omega,
            zeta,
            damped_omega,
            a,
            b,
            c,
            e,
        }
    }

    /// x(τ).
    pub fn displacement(&self, tau: f64) -> f64 {
        let decay = (-self.zeta * self.omega * tau).exp();
        let (s, c) = (self.damped_omega * tau).sin_cos();
        self.a * tau.sin() + self.b * tau.cos() + decay * (self.c * c + self.e * s)
    }

    /// ẋ(τ).
    pub fn velocity(&self, tau: f64) -> f64 {
        let decay = (-self.zeta * self.omega * tau).exp();
        let (s, c) = (self.damped_omega * tau).sin_cos();
        let wd = self.damped_omega;
        let sigma = self.zeta * self.omega;
        self.a * tau.cos() - self.b * tau.sin()
            + decay * ((self.e * wd - sigma * self.c) * c - (self.c * wd + sigma * self.e) * s)
    }
}

/// max |f| over [0, τ_end]: a fine scan, then golden-section refinement of
/// the best sample's neighbourhood (f smooth, its peaks ≫ 1/samples apart).
pub fn peak(f: impl Fn(f64) -> f64, tau_end: f64) -> f64 {
    let n = 200_000;
    let dt = tau_end / n as f64;
    let (mut best, mut best_i) = (f(0.0).abs(), 0);
    for i in 1..=n {
        let v = f(i as f64 * dt).abs();
        if v > best {
            (best, best_i) = (v, i);
        }
    }
    let (mut lo, mut hi) = (
        (best_i as f64 - 1.0).max(0.0) * dt,
        ((best_i + 1) as f64 * dt).min(tau_end),
    );
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let m1 = hi - ratio * (hi - lo);
        let m2 = lo + ratio * (hi - lo);
        if f(m1).abs() < f(m2).abs() {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    best.max(f(0.5 * (lo + hi)).abs()).max(f(tau_end).abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form satisfies its own differential equation and initial conditions.
    #[test]
    fn satisfies_equation_of_motion() {
        let o = LinearOscillator::new(2.36, 0.05, 1.0, 0.1, -0.2);
        assert!((o.displacement(0.0) - 0.1).abs() < 1e-14);
        assert!((o.velocity(0.0) + 0.2).abs() < 1e-14);
        let h = 1e-4;
        for k in 1..50 {
            let t = 0.37 * k as f64;
            let acc = (o.velocity(t + h) - o.velocity(t - h)) / (2.0 * h);
            let vel = (o.displacement(t + h) - o.displacement(t - h)) / (2.0 * h);
            let residual = acc
                + 2.0 * 0.05 * 2.36 * o.velocity(t)
                + 2.36f64.powi(2) * o.displacement(t)
                + t.sin();
            assert!(residual.abs() < 1e-6, "t={t}: {residual}");
            assert!((vel - o.velocity(t)).abs() < 1e-7);
        }
    }
}
