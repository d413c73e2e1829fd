//! What a run reports (SPEC §6).

use serde::{Deserialize, Serialize};

use crate::model::Method;

/// Peak response of one structure: Π_u = max |x|, Π_v = max |ẋ| (SPEC §6),
/// and the demands of SPEC §6 "Demands for performance studies".
///
/// Two are equal when every number is: a quantity a run did not compute
/// (NaN) equals another not computed, so that two runs of a sweep, which
/// skips A and E_h, compare as the same result.
#[derive(Debug, Clone, Copy, Default, Serialize, Deserialize)]
pub struct StructurePeaks {
    pub peak_displacement: f64,
    pub peak_velocity: f64,
    /// A_i = max over the run of |ẍ_i + g(τ)|, the floor's absolute
    /// acceleration in a_p (SPEC §6, demands). By the equations of motion
    /// (SPEC §2), Π_m(ẍ1 + g) = −(2Π_ξΠ_mΠ_ω1 ẋ1 + f_s1 + f_p) and
    /// ẍ2 + g = −(2Π_ξΠ_ω2 ẋ2 + f_s2 − f_p): a function of the state and the
    /// pounding force, so it does not jump where g does; it jumps where f_p
    /// does (a Kelvin contact's onset and separation), and both one-sided
    /// values count. NaN where a run did not locate it (an exact run with
    /// `absolute_acceleration: false`, as sweeps make).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub peak_absolute_acceleration: f64,
    /// μ_i = Π_u,i / Π_uy,i (SPEC §6, demands); ∞ for an elastic structure
    /// (Π_uy = ∞), written `inf`.
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub ductility: f64,
    /// r_i = (1 − Π_α)(x_i − z_i) at τ_end (SPEC §6, demands, with SPEC §3's
    /// split f_s = Π_α k x + (1 − Π_α) k z): the displacement at which the
    /// spring force vanishes when unloaded elastically from the final state.
    /// Signed; exactly 0 for an elastic structure.
    pub residual_displacement: f64,
    /// E_h,i = ∫ f_s,i ẋ_i dτ − f_s,i(τ_end)²/(2 k_i) (SPEC §6, demands),
    /// k1 = Π_m Π_ω1², k2 = Π_ω2², per m2 a_p²/ω_p²: the spring's work less
    /// the elastic energy it stores at the end. NaN where the run did not
    /// integrate the work (an exact run with `energy: false`, as sweeps make).
    #[serde(serialize_with = "crate::output::report::float_or_inf")]
    pub hysteretic_energy: f64,
    /// Whether the spring left its elastic range at any time.
    pub yielded: bool,
}

/// One spring at the end of a run, from which the end-of-run demands of
/// SPEC §6 follow ([`StructurePeaks::settle`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FinalSpring {
    /// Elastic stiffness k (k1 = Π_m Π_ω1², k2 = Π_ω2²).
    pub stiffness: f64,
    /// Π_uy (∞: elastic).
    pub yield_displacement: f64,
    /// Π_α.
    pub alpha: f64,
    /// x at τ_end.
    pub displacement: f64,
    /// z at τ_end (SPEC §3).
    pub elastic_part: f64,
    /// f_s at τ_end.
    pub force: f64,
    /// ∫ f_s ẋ dτ over the run; NaN where it was not integrated.
    pub work: f64,
}

impl PartialEq for StructurePeaks {
    fn eq(&self, other: &Self) -> bool {
        let same = |a: f64, b: f64| a == b || (a.is_nan() && b.is_nan());
        same(self.peak_displacement, other.peak_displacement)
            && same(self.peak_velocity, other.peak_velocity)
            && same(
                self.peak_absolute_acceleration,
                other.peak_absolute_acceleration,
            )
            && same(self.ductility, other.ductility)
            && same(self.residual_displacement, other.residual_displacement)
            && same(self.hysteretic_energy, other.hysteretic_energy)
            && self.yielded == other.yielded
    }
}

impl StructurePeaks {
    /// Sets the demands that follow from the peaks and the final state
    /// (SPEC §6, demands): μ = Π_u/Π_uy (∞ when elastic), r = (1 − Π_α)(x − z)
    /// (0 when elastic), E_h = ∫ f_s ẋ dτ − f_s²/(2k) (0 for a spring that
    /// never yielded).
    pub fn settle(&mut self, end: &FinalSpring) {
        let elastic = !end.yield_displacement.is_finite();
        self.ductility = if elastic {
            f64::INFINITY
        } else {
            self.peak_displacement / end.yield_displacement
        };
        self.residual_displacement = if elastic {
            0.0
        } else {
            (1.0 - end.alpha) * (end.displacement - end.elastic_part)
        };
        // A spring that never left its elastic range is conservative: its
        // work is exactly the energy it stores, f_s²/(2k), so E_h = 0; the
        // difference of the two computed terms would be round-off noise
        // (±1e-14 of the input), whose sign and logarithm mean nothing.
        self.hysteretic_energy = if self.yielded || end.work.is_nan() {
            end.work - end.force * end.force / (2.0 * end.stiffness)
        } else {
            0.0
        };
    }

    /// Raises A to |a| for an absolute acceleration a = ẍ + g at an instant.
    #[inline(always)]
    pub fn raise_absolute_acceleration(&mut self, a: f64) {
        self.peak_absolute_acceleration = self.peak_absolute_acceleration.max(a.abs());
    }
}

/// One contact phase, from the located onset to the located separation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Impact {
    /// τ at which contact began.
    pub start: f64,
    /// τ at which contact ended (the run's end if it had not).
    pub end: f64,
    /// δ̇ at onset, v₀ (before the floor of the improved Kelvin law).
    pub approach_velocity: f64,
    /// −δ̇ at separation.
    pub separation_velocity: f64,
    /// Achieved restitution: separation / approach velocity.
    pub restitution: f64,
    /// Largest f_p and δ of the contact; NaN where an exact run did not
    /// locate them ([`ContactExtremes`](crate::solver::exact::ContactExtremes)).
    pub peak_force: f64,
    pub max_penetration: f64,
    /// False when the run ended during this contact.
    pub ended: bool,
}

impl Impact {
    /// Closes the contact at τ with penetration rate δ̇ = `rate` (negative at
    /// separation): separation velocity −δ̇ and the achieved restitution,
    /// separation over approach velocity.
    pub fn close(&mut self, tau: f64, rate: f64) {
        self.end = tau;
        self.separation_velocity = -rate;
        self.restitution = if self.approach_velocity > 0.0 {
            self.separation_velocity / self.approach_velocity
        } else {
            0.0
        };
        self.ended = true;
    }
}

/// Energy balance of SPEC §6, in units of m2 a_p²/ω_p².
///
/// Every work term is accumulated per Newmark step as the mean of its force
/// at the two ends times the displacement increment; with the average
/// acceleration rule this is the step's exact discrete work, so the balance
/// closes to the Newton tolerance and round-off.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct EnergyBalance {
    /// E_in = −∫ (Π_m ẋ1 + ẋ2) g dτ.
    pub input: f64,
    /// E_kin = ½ Π_m ẋ1² + ½ ẋ2² at the end.
    pub kinetic: f64,
    /// E_damp = ∫ (2Π_ξΠ_mΠ_ω1 ẋ1² + 2Π_ξΠ_ω2 ẋ2²) dτ.
    pub damping: f64,
    /// E_spring = ∫ (f_s1 ẋ1 + f_s2 ẋ2) dτ (stored plus dissipated by yielding).
    pub spring: f64,
    /// The spring work of each structure, [∫ f_s1 ẋ1 dτ, ∫ f_s2 ẋ2 dτ]; its
    /// sum is `spring` (SPEC §6, demands: the hysteretic energy's first term).
    pub spring_by_structure: [f64; 2],
    /// E_contact = ∫ f_p δ̇ dτ.
    pub contact: f64,
    /// max |E_in| over the run.
    pub max_input: f64,
    /// |E_kin + E_damp + E_spring + E_contact − E_in| / max |E_in|.
    pub residual: f64,
}

/// The summary of one run.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct RunResult {
    pub left: StructurePeaks,
    pub right: StructurePeaks,
    pub impacts: Vec<Impact>,
    /// Largest pounding force (0 without contact; NaN after an impact where
    /// an exact run did not locate the forces).
    pub max_force: f64,
    /// Smallest pounding force: below 0 means the element pulled (tension).
    /// NaN as `max_force`.
    pub min_force: f64,
    /// max over τ of x1 − x2, the left structure's largest excursion towards
    /// the right one. In a run without contact the smallest gap that
    /// prevents pounding is Π_d,min = max(0, this) (SPEC §11). Tracked on
    /// the motion's own series by the exact method, in a run that had no
    /// impact (which is its own no-pounding run); `None` after an impact
    /// and from Newmark.
    pub max_relative_displacement: Option<f64>,
    pub energy: EnergyBalance,
    /// τ reached (τ_end unless stopped early).
    pub tau_end: f64,
    /// Accepted Newmark steps, counting split and contact sub-steps.
    pub steps: usize,
    /// Steps retried at a smaller size because Newton did not converge.
    pub step_retries: usize,
    /// Steps accepted although Newton had not converged at the smallest size.
    pub unconverged_steps: usize,
    /// False when the run stopped before τ_end (see `stop`).
    pub completed: bool,
    /// Why and where the run stopped early; `None` when it reached τ_end.
    pub stop: Option<Stop>,
    /// The integrator that produced this result.
    pub method: Method,
}

/// Why a run ended before τ_end.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StopReason {
    /// The observer asked to stop (a superseded explorer job).
    Cancelled,
    /// A state variable or force became NaN or infinite.
    NonFinite,
    /// The run took more steps than its cap.
    StepCap,
    /// The run met more events (impacts, yields, unloadings) than its cap: chatter or Zeno.
    EventCap,
    /// Too many steps had to be retried at a smaller size.
    RetryCap,
}

impl StopReason {
    pub fn describe(self) -> &'static str {
        match self {
            StopReason::Cancelled => "cancelled",
            StopReason::NonFinite => "the state became non-finite (NaN or infinite)",
            StopReason::StepCap => "the step cap was reached",
            StopReason::EventCap => "the event cap was reached (chattering contact)",
            StopReason::RetryCap => "the retry cap was reached (the step would not converge)",
        }
    }
}

/// Where (τ) and why a run stopped early.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Stop {
    pub tau: f64,
    pub reason: StopReason,
}

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "run stopped at τ = {:.6}: {}",
            self.tau,
            self.reason.describe()
        )
    }
}

/// Largest energy residual (SPEC §6) of a run whose numbers are trusted.
/// Both methods close the balance to about 1e-10 on every accepted case;
/// a residual above this means the step did not resolve the motion.
pub const ENERGY_TOLERANCE: f64 = 1e-4;

impl RunResult {
    /// The peaks of structure `i` (0 left, 1 right).
    pub fn structure(&self, i: usize) -> &StructurePeaks {
        if i == 0 { &self.left } else { &self.right }
    }

    /// The peaks of structure `i` (0 left, 1 right), to update.
    pub fn structure_mut(&mut self, i: usize) -> &mut StructurePeaks {
        if i == 0 {
            &mut self.left
        } else {
            &mut self.right
        }
    }

    /// Peaks of the four headline numbers [Π_u1, Π_v1, Π_u2, Π_v2].
    pub fn peaks(&self) -> [f64; 4] {
        [
            self.left.peak_displacement,
            self.left.peak_velocity,
            self.right.peak_displacement,
            self.right.peak_velocity,
        ]
    }

    /// Why this result should not be trusted, or `None` when it may be:
    /// it stopped early (other than by cancellation, which callers discard),
    /// a number is not finite, or the energy residual exceeds [`ENERGY_TOLERANCE`].
    pub fn unreliable(&self) -> Option<String> {
        if let Some(stop) = self.stop {
            return Some(stop.to_string());
        }
        if !self.is_finite() {
            return Some("a result is not finite".into());
        }
        if self.energy.residual > ENERGY_TOLERANCE {
            return Some(format!(
                "energy residual {:.3e} exceeds {:.0e}",
                self.energy.residual, ENERGY_TOLERANCE
            ));
        }
        None
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.peaks().iter().all(|v| v.is_finite())
            && self.max_force.is_finite()
            && self.min_force.is_finite()
            && self.energy.residual.is_finite()
    }
}
