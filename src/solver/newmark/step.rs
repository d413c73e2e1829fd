//! One Newmark-β step (γ = 1/2, β = 1/4, SPEC §5) of the two-structure system
//!
//! ```text
//! M ẍ + C ẋ + f_s(x) + B f_p(δ, δ̇) = −M g(τ),   B = (1, −1)ᵀ,
//! ```
//!
//! with M = diag(Π_m, 1), C = diag(2Π_ξΠ_mΠ_ω1, 2Π_ξΠ_ω2) (SPEC §2).
//! The average-acceleration rule writes the end-of-step velocity and
//! acceleration in terms of the unknown displacement x = x_n + Δ:
//!
//! ```text
//! ẋ = 2Δ/h − ẋ_n,     ẍ = 4Δ/h² − 4ẋ_n/h − ẍ_n.
//! ```
//!
//! Out of contact the two structures are uncoupled and each spring is
//! piecewise affine in Δ (elastic or on one of the two yield branches), so
//! each structure's step is solved exactly, branch by branch, without
//! iteration. In contact the system is coupled and the improved Kelvin force
//! is nonlinear, so Newton–Raphson runs on the 2×2 residual with the
//! consistent tangent
//!
//! ```text
//! J = 4M/h² + 2C/h + diag(k_t) + (∂f_p/∂δ + 2/h ∂f_p/∂δ̇) B Bᵀ.
//! ```

use nalgebra::{Matrix2, Vector2};

use crate::model::{Bilinear, ContactLaw, Excitation, Params, Rotation, SpringState};

/// The constant coefficients of the equations of motion (SPEC §2–3).
#[derive(Debug, Clone)]
pub struct System {
    /// Diagonal of M: (Π_m, 1).
    pub mass: [f64; 2],
    /// Diagonal of C: (2Π_ξΠ_mΠ_ω1, 2Π_ξΠ_ω2).
    pub damping: [f64; 2],
    /// Springs with k1 = Π_m Π_ω1², k2 = Π_ω2² (SPEC §3).
    pub springs: [Bilinear; 2],
    /// Π_d (infinite: no pounding).
    pub gap: f64,
    pub excitation: Excitation,
    /// Phasor rotations for the run's usual step sizes (Δτ and the contact sub-step).
    pub rotations: [Rotation; 2],
}

/// The full state at one instant: what Newmark needs to take the next step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct State {
    pub tau: f64,
    pub x: [f64; 2],
    pub v: [f64; 2],
    pub a: [f64; 2],
    pub springs: [SpringState; 2],
    pub fs: [f64; 2],
    pub fp: f64,
    /// Ground acceleration g(τ) at this instant (cached: it is needed twice per step).
    pub g: f64,
    /// dg/dτ at this instant, so that the next g comes by a rotation.
    pub g_rate: f64,
    /// Whether each spring's last step ended on a yield branch.
    pub plastic: [bool; 2],
}

/// How contact enters a step: not at all, or through a contact law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Phase {
    Free,
    Contact(ContactLaw),
}

/// `[f(0), f(1)]`: one value per structure, written out so the hot path
/// compiles to straight-line code.
#[inline(always)]
fn pair<T>(f: impl Fn(usize) -> T) -> [T; 2] {
    [f(0), f(1)]
}

/// Largest Newton iteration count before a contact step is declared unconverged.
pub const MAX_NEWTON: usize = 40;

impl System {
    pub fn new(p: &Params, excitation: Excitation) -> Self {
        let spring = |k: f64, uy: f64| Bilinear {
            stiffness: k,
            yield_displacement: uy,
            alpha: p.alpha,
        };
        System {
            mass: [p.mass_ratio, 1.0],
            damping: [
                2.0 * p.damping * p.mass_ratio * p.omega1,
                2.0 * p.damping * p.omega2,
            ],
            springs: [
                spring(p.mass_ratio * p.omega1 * p.omega1, p.yield1),
                spring(p.omega2 * p.omega2, p.yield2),
            ],
            gap: p.gap,
            excitation,
            rotations: [Rotation::new(p.dt); 2],
        }
    }

    /// Sets the step sizes whose phasor rotations are precomputed.
    pub fn with_steps(mut self, steps: [f64; 2]) -> Self {
        self.rotations = steps.map(Rotation::new);
        self
    }

    /// (g, dg/dτ) at τ + h from the state's phasor: a rotation for the usual
    /// step sizes under the sine, a fresh evaluation otherwise (pulses and
    /// records are not rotations: a pulse stops, a record is piecewise linear).
    /// The fresh value is the limit from the left: a step that ends on a jump
    /// of g integrates the formula before it (the driver switches the state
    /// to the value after, see `Driver::pass_break`).
    #[inline(always)]
    fn excitation_after(&self, s: &State, h: f64) -> [f64; 2] {
        if self.excitation.rotates() {
            for r in &self.rotations {
                if r.step == h {
                    return r.advance([s.g, s.g_rate]);
                }
            }
        }
        self.excitation.phasor_before(s.tau + h)
    }

    /// Re-evaluates the state's phasor from τ (removes the rotations' drift).
    pub fn resync(&self, s: &mut State) {
        [s.g, s.g_rate] = self.excitation.phasor(s.tau);
    }

    /// Penetration δ = x1 − x2 − Π_d (SPEC §4).
    #[inline]
    pub fn penetration(&self, x: [f64; 2]) -> f64 {
        x[0] - x[1] - self.gap
    }

    /// Pounding force of a state under a phase (0 when free).
    #[inline]
    pub fn contact_force(&self, phase: &Phase, x: [f64; 2], v: [f64; 2]) -> f64 {
        match phase {
            Phase::Free => 0.0,
            Phase::Contact(law) => law.force(self.penetration(x), v[0] - v[1]).force,
        }
    }

    /// Accelerations from the equations of motion at a state (SPEC §2).
    #[inline]
    pub fn acceleration(&self, g: f64, v: [f64; 2], fs: [f64; 2], fp: f64) -> [f64; 2] {
        let sign = [1.0, -1.0];
        pair(|i| (-self.damping[i] * v[i] - fs[i] - sign[i] * fp) / self.mass[i] - g)
    }

    /// A state at rest or with given initial conditions, its acceleration in equilibrium.
    pub fn initial_state(&self, x: [f64; 2], v: [f64; 2], phase: &Phase) -> State {
        let springs = pair(|i| self.springs[i].respond(SpringState::default(), x[i]));
        let fs = pair(|i| springs[i].force);
        let fp = self.contact_force(phase, x, v);
        let [g, g_rate] = self.excitation.phasor(0.0);
        State {
            tau: 0.0,
            x,
            v,
            a: self.acceleration(g, v, fs, fp),
            g,
            g_rate,
            springs: pair(|i| springs[i].state),
            fs,
            fp,
            plastic: pair(|i| springs[i].plastic),
        }
    }

    /// Recomputes the force and acceleration of a state under a new phase
    /// (at a contact onset or separation the force may jump; x and ẋ do not).
    pub fn rephase(&self, s: &mut State, phase: &Phase) {
        s.fp = self.contact_force(phase, s.x, s.v);
        s.a = self.acceleration(s.g, s.v, s.fs, s.fp);
    }

    /// One Newmark step of size `h` from `s`. Returns the new state and
    /// whether Newton converged (always true out of contact).
    #[inline(always)]
    pub fn step(&self, s: &State, h: f64, phase: &Phase) -> (State, bool) {
        match phase {
            Phase::Free => (self.free_step(s, h), true),
            Phase::Contact(law) => self.contact_step(s, h, law),
        }
    }

    /// Builds the end-of-step state from the displacement increment.
    #[inline(always)]
    fn finish(
        &self,
        s: &State,
        h: f64,
        inv_h: f64,
        [g, g_rate]: [f64; 2],
        dx: [f64; 2],
        fp: impl Fn([f64; 2], [f64; 2]) -> f64,
    ) -> State {
        let tau = s.tau + h;
        let x = [s.x[0] + dx[0], s.x[1] + dx[1]];
        let v = pair(|i| 2.0 * dx[i] * inv_h - s.v[i]);
        let r = pair(|i| self.springs[i].respond(s.springs[i], x[i]));
        let fs = pair(|i| r[i].force);
        let fp = fp(x, v);
        State {
            tau,
            x,
            v,
            // Newmark's own acceleration; equal to the equation-of-motion one at convergence.
            a: pair(|i| 4.0 * inv_h * (dx[i] * inv_h - s.v[i]) - s.a[i]),
            springs: pair(|i| r[i].state),
            fs,
            fp,
            g,
            g_rate,
            plastic: pair(|i| r[i].plastic),
        }
    }

    /// Uncoupled step: per structure, the residual
    /// R(Δ) = (4m/h² + 2c/h) Δ + r₀ + f_s(x_n + Δ) is continuous, increasing
    /// and affine on each spring branch, so its root is found exactly.
    #[inline(always)]
    pub fn free_step(&self, s: &State, h: f64) -> State {
        let phasor = self.excitation_after(s, h);
        let g = phasor[0];
        let inv_h = 1.0 / h;
        let dx = pair(|i| {
            let (m, c, spring) = (self.mass[i], self.damping[i], &self.springs[i]);
            let k_eff = (4.0 * m * inv_h + 2.0 * c) * inv_h;
            let r0 = m * (-4.0 * s.v[i] * inv_h - s.a[i]) - c * s.v[i] + m * g;
            solve_bilinear(k_eff, r0, spring, s.springs[i], s.fs[i])
        });
        self.finish(s, h, inv_h, phasor, dx, |_, _| 0.0)
    }

    /// Coupled step in contact: Newton–Raphson from the constant-acceleration predictor.
    #[inline]
    fn contact_step(&self, s: &State, h: f64, law: &ContactLaw) -> (State, bool) {
        let phasor = self.excitation_after(s, h);
        let g = phasor[0];
        let m = Vector2::from(self.mass);
        let c = Vector2::from(self.damping);
        let k_dyn = m * (4.0 / (h * h)) + c * (2.0 / h);
        // Constant-acceleration predictor.
        let mut dx = Vector2::new(
            s.v[0] * h + 0.5 * h * h * s.a[0],
            s.v[1] * h + 0.5 * h * h * s.a[1],
        );
        let scale = 1e-13 * (1.0 + s.x[0].abs() + s.x[1].abs());
        for _ in 0..MAX_NEWTON {
            let x = [s.x[0] + dx[0], s.x[1] + dx[1]];
            let r = pair(|i| self.springs[i].respond(s.springs[i], x[i]));
            let v = pair(|i| 2.0 * dx[i] / h - s.v[i]);
            let a = pair(|i| 4.0 * dx[i] / (h * h) - 4.0 * s.v[i] / h - s.a[i]);
            let f = law.force(self.penetration(x), v[0] - v[1]);
            let residual = Vector2::new(
                m[0] * (a[0] + g) + c[0] * v[0] + r[0].force + f.force,
                m[1] * (a[1] + g) + c[1] * v[1] + r[1].force - f.force,
            );
            let kc = f.d_penetration + 2.0 / h * f.d_rate;
            let jacobian = Matrix2::new(
                k_dyn[0] + r[0].tangent + kc,
                -kc,
                -kc,
                k_dyn[1] + r[1].tangent + kc,
            );
            let Some(step) = jacobian.try_inverse().map(|inv| -(inv * residual)) else {
                break;
            };
            dx += step;
            if step.amax() <= scale {
                let state = self.finish(s, h, 1.0 / h, phasor, [dx[0], dx[1]], |x, v| {
                    law.force(self.penetration(x), v[0] - v[1]).force
                });
                return (state, true);
            }
        }
        let state = self.finish(s, h, 1.0 / h, phasor, [dx[0], dx[1]], |x, v| {
            law.force(self.penetration(x), v[0] - v[1]).force
        });
        (state, false)
    }
}

/// Root of k_eff Δ + r₀ + f_s(x_n + Δ) = 0 for a bilinear spring (SPEC §3).
///
/// On the elastic branch f_s = f_s,n + kΔ; on the yield branch of sign σ,
/// f_s = Π_α k (x_n + Δ) + σ (1 − Π_α) k Π_uy. The residual is continuous and
/// increasing, so exactly one branch holds its root: try elastic first, then
/// the branch on the side the elastic trial overshot to.
#[inline(always)]
fn solve_bilinear(k_eff: f64, r0: f64, spring: &Bilinear, from: SpringState, fs_n: f64) -> f64 {
    let k = spring.stiffness;
    let uy = spring.yield_displacement;
    let elastic = -(r0 + fs_n) / (k_eff + k);
    let trial = from.z + elastic;
    if trial.abs() <= uy {
        return elastic;
    }
    let sign = trial.signum();
    let plastic = -(r0 + spring.alpha * k * from.x + sign * (1.0 - spring.alpha) * k * uy)
        / (k_eff + spring.alpha * k);
    // The plastic root lies beyond the yield point on the same side (monotone residual).
    if sign * (from.z + plastic) >= uy {
        plastic
    } else {
        // Only reachable by round-off at the kink: the root is the yield point itself.
        sign * uy - from.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    /// A free step must satisfy the equation of motion at its end.
    #[test]
    fn free_step_satisfies_equation_of_motion() {
        let mut p = SET1;
        p.yield1 = 0.01; // force yielding within a few steps
        let sys = System::new(&p, Excitation::Sine);
        let mut s = sys.initial_state([0.0; 2], [0.5, -0.3], &Phase::Free);
        for _ in 0..200 {
            s = sys.free_step(&s, 0.01);
            let a = sys.acceleration(s.g, s.v, s.fs, 0.0);
            assert!(
                (a[0] - s.a[0]).abs() < 1e-9 && (a[1] - s.a[1]).abs() < 1e-9,
                "{a:?} vs {:?}",
                s.a
            );
        }
        assert!(s.plastic[0] || s.springs[0].z.abs() <= 0.01 + 1e-15);
    }
}
