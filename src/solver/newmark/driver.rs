//! The state of a run in progress, from rest to τ_end (SPEC §2–6): the loop
//! over phases, the run's clock, and where it stops.

use crate::model::Params;

use super::caps::RunCaps;
use super::options::SolverOptions;
use super::peaks::resolved_steps;
use super::policy::{Policy, contact_law};
use super::step::{Phase, State, System};
use crate::model::Method;
use crate::solver::observer::Observer;
use crate::solver::result::{EnergyBalance, FinalSpring, RunResult, Stop, StopReason};

/// How often (in accepted steps) the observer is asked whether to go on,
/// the excitation phasor is re-evaluated from τ and the step cap is checked.
pub const POLL_EVERY: usize = 1024;

/// Step sizes and the end of the run.
#[derive(Debug, Clone, Copy)]
pub struct Clock {
    pub tau_end: f64,
    /// Δτ, the step out of contact.
    pub dt: f64,
    /// Δτ/n, the step in contact.
    pub contact_dt: f64,
    /// A step shorter than this at the end is merged into the one before.
    pub end_slack: f64,
}

impl Clock {
    fn new(p: &Params, substeps: u32) -> Self {
        let tau_end = p.tau_end();
        Clock {
            tau_end,
            dt: p.dt,
            contact_dt: p.dt / substeps as f64,
            end_slack: 1e-9 * p.dt.min(tau_end),
        }
    }

    /// Whether the run has reached τ_end (up to the slack); a NaN τ has.
    #[inline]
    #[allow(clippy::neg_cmp_op_on_partial_ord, reason = "a NaN must compare false")]
    pub fn done(&self, tau: f64) -> bool {
        !(tau < self.tau_end - self.end_slack)
    }

    /// The step from τ: `base`, or the rest of the run when that is shorter
    /// than `base` plus the slack; halved `halvings` times.
    #[inline]
    pub fn step_from(&self, tau: f64, base: f64, halvings: u32) -> f64 {
        let remaining = self.tau_end - tau;
        let h = if remaining < base + self.end_slack {
            remaining
        } else {
            base
        };
        if halvings == 0 {
            h
        } else {
            h / f64::from(1u32 << halvings.min(30))
        }
    }
}

/// The state of a run in progress.
pub struct Driver<'a> {
    pub p: &'a Params,
    pub options: &'a SolverOptions,
    pub system: System,
    pub clock: Clock,
    pub caps: RunCaps,
    pub state: State,
    pub phase: Phase,
    /// Index into `result.impacts` of the open contact.
    pub open_impact: Option<usize>,
    pub result: RunResult,
    /// Running work integrals (SPEC §6).
    pub energy: EnergyBalance,
    /// Per structure, the largest step whose interpolant is trusted for peaks.
    pub resolved_step: [f64; 2],
    /// The next τ where g changes formula ([`Excitation::next_break`]): a
    /// step ends there rather than crossing it, since a step across a jump
    /// of g (a pulse's end, a record's last sample) is first order.
    ///
    /// [`Excitation::next_break`]: crate::model::Excitation::next_break
    pub next_break: f64,
}

impl<'a> Driver<'a> {
    /// The run at τ = 0, its initial state recorded.
    #[allow(clippy::neg_cmp_op_on_partial_ord, reason = "a NaN must compare false")]
    pub fn new<O: Observer>(p: &'a Params, options: &'a SolverOptions, observer: &mut O) -> Self {
        let substeps = options.substeps(p);
        let clock = Clock::new(p, substeps);
        let system =
            System::new(p, options.excitation.clone()).with_steps([clock.dt, clock.contact_dt]);
        let x = options.initial_displacement;
        let v = options.initial_velocity;
        let mut d = Driver {
            p,
            options,
            system,
            clock,
            caps: options.caps(p),
            state: State::default(),
            phase: Phase::Free,
            open_impact: None,
            result: RunResult {
                completed: true,
                method: Method::Newmark,
                ..RunResult::default()
            },
            energy: EnergyBalance::default(),
            resolved_step: resolved_steps([p.omega1, p.omega2]),
            next_break: options.excitation.next_break(0.0),
        };
        d.result.impacts.reserve(32);
        // Starting in contact: v₀ is the initial δ̇.
        let in_contact = d.system.penetration(x) > 0.0;
        if in_contact {
            d.phase = Phase::Contact(contact_law(p, v[0] - v[1]));
        }
        d.state = d.system.initial_state(x, v, &d.phase);
        if !is_finite(&d.state) {
            d.halt(StopReason::NonFinite);
            return d;
        }
        if in_contact {
            // A cap of zero impacts stops the run here (the driver loop checks).
            d.open_impact(v[0] - v[1]);
        }
        d.track();
        d.record(observer);
        // A step that τ_end + Δτ/n rounds back to τ_end cannot advance τ near
        // the end: the run would need more than 2⁵² steps and never finish.
        if !(clock.tau_end + clock.contact_dt > clock.tau_end) {
            d.halt(StopReason::StepCap);
        }
        d
    }

    /// Steps from the current state to τ_end, phase after phase, unless a stop comes first.
    pub fn run<P: Policy, O: Observer>(&mut self, policy: &P, observer: &mut O) {
        while self.running() {
            match self.phase {
                Phase::Free => self.free_phase(policy, observer),
                Phase::Contact(_) => self.contact_phase(policy, observer),
            }
        }
        if let Some(i) = self.open_impact {
            self.result.impacts[i].end = self.state.tau;
        }
    }

    /// Neither stopped nor at τ_end.
    #[inline]
    pub fn running(&self) -> bool {
        self.result.stop.is_none() && !self.clock.done(self.state.tau)
    }

    /// Ends the run early at the current state, for `reason`.
    #[cold]
    pub fn halt(&mut self, reason: StopReason) {
        self.result.completed = false;
        self.result.stop = Some(Stop {
            tau: self.state.tau,
            reason,
        });
    }

    /// Every [`POLL_EVERY`] accepted steps: the observer may cancel, the step
    /// cap is checked, and the excitation phasor is re-evaluated from τ (the
    /// rotations' drift stays at round-off). Returns whether to go on.
    #[cold]
    #[inline(never)]
    pub fn checkpoint<O: Observer>(&mut self, observer: &mut O) -> bool {
        if !observer.keep_going() {
            self.halt(StopReason::Cancelled);
            return false;
        }
        if self.result.steps >= self.caps.steps {
            self.halt(StopReason::StepCap);
            return false;
        }
        self.system.resync(&mut self.state);
        true
    }

    /// The step `h` from τ, shortened to end exactly on the next break of g
    /// when it would reach or cross it: break − τ, rounded down until τ + h
    /// does not pass the break in floating point.
    #[inline]
    pub fn to_break(&self, tau: f64, h: f64) -> f64 {
        if tau + h < self.next_break {
            return h;
        }
        let mut h = self.next_break - tau;
        // break − τ is exact when τ ≥ break/2; otherwise step down until τ + h ≤ break.
        while tau + h > self.next_break && h > 0.0 {
            h = f64::from_bits(h.to_bits() - 1);
        }
        h
    }

    /// At a break of g reached by a step: the state takes g's value after the
    /// break (the step ended with the one before) and the acceleration of the
    /// equations of motion with it (SPEC §2: ẍ jumps with g, x and ẋ do not);
    /// the next break is looked up.
    #[allow(clippy::neg_cmp_op_on_partial_ord, reason = "a NaN must compare false")]
    pub fn pass_break(&mut self) {
        // A step aimed at the break may stop an ulp or so short of it ([`Driver::to_break`]).
        // (Breaks are at τ > 0; none ahead is an infinite break, never reached.)
        if !(self.state.tau >= self.next_break * (1.0 - 4.0 * f64::EPSILON)) {
            return;
        }
        let s = &mut self.state;
        s.tau = self.next_break;
        self.system.resync(s);
        s.a = self.system.acceleration(s.g, s.v, s.fs, s.fp);
        self.next_break = self.options.excitation.next_break(s.tau);
    }

    /// Counts a retry at half size; false (and a stop) past the retry cap.
    #[cold]
    pub fn retry(&mut self) -> bool {
        self.result.step_retries += 1;
        if self.result.step_retries > self.caps.retries {
            self.halt(StopReason::RetryCap);
            return false;
        }
        true
    }

    /// The energy balance (SPEC §6) and the run's end.
    pub fn finish(mut self) -> RunResult {
        let s = self.state;
        let m = self.system.mass;
        let e = &mut self.energy;
        e.kinetic = 0.5 * (m[0] * s.v[0] * s.v[0] + m[1] * s.v[1] * s.v[1]);
        e.spring = e.spring_by_structure[0] + e.spring_by_structure[1];
        let imbalance = e.kinetic + e.damping + e.spring + e.contact - e.input;
        // A run with no input (free motion) is measured against its initial energy instead.
        let initial = 0.5
            * (m[0] * self.options.initial_velocity[0].powi(2)
                + m[1] * self.options.initial_velocity[1].powi(2));
        let scale = e.max_input.max(initial);
        e.residual = if scale > 0.0 {
            (imbalance - initial).abs() / scale
        } else {
            imbalance.abs()
        };
        self.result.energy = self.energy;
        for i in 0..2 {
            let spring = &self.system.springs[i];
            let end = FinalSpring {
                stiffness: spring.stiffness,
                yield_displacement: spring.yield_displacement,
                alpha: spring.alpha,
                displacement: s.x[i],
                elastic_part: s.springs[i].z,
                force: s.fs[i],
                work: self.energy.spring_by_structure[i],
            };
            self.result.structure_mut(i).settle(&end);
        }
        self.result.tau_end = s.tau;
        self.result
    }
}

/// Whether every number of a state is finite: one test on their sum, since
/// a NaN or an infinity anywhere makes the sum NaN or infinite (a sum of
/// finite values overflows only near 1e308, far past any physical state).
#[inline(always)]
pub fn is_finite(s: &State) -> bool {
    // Summed per structure first: two short chains instead of one long one.
    let per = [0, 1].map(|i| (s.x[i] + s.v[i]) + (s.a[i] + s.fs[i]));
    (per[0] + per[1] + s.fp).is_finite()
}
