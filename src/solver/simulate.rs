//! The run driver: the order of one run, from rest to τ_end (SPEC §2–6).
//!
//! Each pass of the loop
//! 1. takes a Newmark step (Δτ, or Δτ/n inside a contact phase),
//! 2. if δ changed side during it, locates the crossing, takes the shorter
//!    step to it instead and switches the phase there (so v₀ is the approach
//!    velocity at the true onset, SPEC §4–5),
//! 3. accepts the state: peaks, impacts, force extremes and energy work are
//!    updated, and the observer is told.

use crate::model::{ContactLaw, Excitation, Params};

use super::events::locate;
use super::newmark::{Phase, State, System};
use super::observer::{Observer, Sample};
use super::result::{EnergyBalance, Impact, RunResult, Stop, StopReason};

/// How many Newmark sub-steps each Δτ is cut into while the structures are in contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactSubsteps {
    /// n = ⌈Π_ωcon · 0.001 / [`AUTO_CONTACT_PHASE`]⌉ = ⌈Π_ωcon / 5⌉: at the
    /// default Δτ = 0.001 the contact step then has Π_ωcon · h ≤ 0.005, and the
    /// contact phase (a few per cent of a run) is integrated as accurately as
    /// the rest. n depends on the contact stiffness only, not on Δτ, so
    /// refining Δτ refines the whole scheme uniformly (second order).
    Auto,
    /// Exactly this many (1: the paper's plain Δτ throughout).
    Fixed(u32),
}

/// Largest Π_ωcon · h inside a contact under [`ContactSubsteps::Auto`].
/// Newmark's period error is (ωh)²/12, so 0.005 gives about 2e-6 per contact.
pub const AUTO_CONTACT_PHASE: f64 = 0.005;
/// The Δτ at which [`ContactSubsteps::Auto`] meets [`AUTO_CONTACT_PHASE`] (the paper's step).
const AUTO_REFERENCE_DT: f64 = 0.001;

/// Numerical choices of a run beyond the Π-groups. The defaults are the
/// project's accurate scheme; the paper's plain scheme is
/// [`SolverOptions::plain`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Locate contact onset and separation inside the step and split it there.
    /// Without it, a phase change is noticed at the end of the step and the step is redone in the new phase.
    pub locate_contact: bool,
    pub contact_substeps: ContactSubsteps,
    pub excitation: Excitation,
    /// x(0); the paper starts at rest.
    pub initial_displacement: [f64; 2],
    /// ẋ(0).
    pub initial_velocity: [f64; 2],
    /// Halvings of a step whose Newton iteration fails, before it is accepted unconverged.
    pub max_step_halvings: u32,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            locate_contact: true,
            contact_substeps: ContactSubsteps::Auto,
            excitation: Excitation::Sine,
            initial_displacement: [0.0; 2],
            initial_velocity: [0.0; 2],
            max_step_halvings: 20,
        }
    }
}

impl SolverOptions {
    /// The plain scheme: fixed Δτ, contact noticed at step ends only.
    pub fn plain() -> Self {
        SolverOptions {
            locate_contact: false,
            contact_substeps: ContactSubsteps::Fixed(1),
            ..Self::default()
        }
    }

    /// Located contact at the paper's Δτ throughout (no sub-steps in contact).
    pub fn located() -> Self {
        SolverOptions {
            contact_substeps: ContactSubsteps::Fixed(1),
            ..Self::default()
        }
    }

    /// Sub-steps per Δτ inside a contact for these parameters.
    pub fn substeps(&self, p: &Params) -> u32 {
        match self.contact_substeps {
            ContactSubsteps::Fixed(n) => n.max(1),
            ContactSubsteps::Auto => {
                let n = (p.contact_omega * AUTO_REFERENCE_DT / AUTO_CONTACT_PHASE).ceil();
                if n.is_finite() {
                    n.clamp(1.0, 1e6) as u32
                } else {
                    1
                }
            }
        }
    }
}

/// Runs the simulation with the default (accurate) options, peaks only.
pub fn run(p: &Params) -> RunResult {
    simulate(p, &SolverOptions::default(), &mut ())
}

/// Largest Π_ω h at which a step's Hermite interpolant is used for peaks:
/// its error is about (Π_ω h)⁴/384 of the amplitude, 1.6e-4 here.
pub const RESOLVED_PHASE: f64 = 0.5;

/// How often (in steps) the observer is asked whether to go on.
const POLL_EVERY: usize = 1024;

/// Runs one simulation of `p` (which must have passed [`Params::validate`]),
/// reporting every accepted state to `observer`.
pub fn simulate<O: Observer>(p: &Params, options: &SolverOptions, observer: &mut O) -> RunResult {
    let system =
        System::new(p, options.excitation).with_steps([p.dt, p.dt / options.substeps(p) as f64]);
    let mut run = Driver::new(p, options, system);
    run.record(observer);
    run.time_loop(observer);
    run.finish()
}

/// The state of a run in progress.
struct Driver<'a> {
    p: &'a Params,
    options: &'a SolverOptions,
    system: System,
    state: State,
    phase: Phase,
    /// Index into `result.impacts` of the open contact.
    open_impact: Option<usize>,
    result: RunResult,
    /// Running work integrals (SPEC §6).
    energy: EnergyBalance,
    /// Per structure, the largest step whose interpolant is trusted for peaks.
    resolved_step: [f64; 2],
}

impl<'a> Driver<'a> {
    fn new(p: &'a Params, options: &'a SolverOptions, system: System) -> Self {
        let x = options.initial_displacement;
        let v = options.initial_velocity;
        let mut d = Driver {
            p,
            options,
            system,
            state: State::default(),
            phase: Phase::Free,
            open_impact: None,
            result: RunResult {
                completed: true,
                ..RunResult::default()
            },
            energy: EnergyBalance::default(),
            resolved_step: [p.omega1, p.omega2].map(|w| {
                if w > 0.0 {
                    RESOLVED_PHASE / w
                } else {
                    f64::INFINITY
                }
            }),
        };
        d.result.impacts.reserve(32);
        if system.penetration(x) > 0.0 {
            d.phase = d.contact_law(v[0] - v[1]);
        }
        d.state = system.initial_state(x, v, &d.phase);
        let s = d.state;
        if matches!(d.phase, Phase::Contact(_)) {
            d.open_impact(&s);
        }
        d.track();
        d
    }

    fn contact_law(&self, approach_velocity: f64) -> Phase {
        let p = self.p;
        Phase::Contact(ContactLaw::new(
            p.model,
            p.mass_ratio,
            p.contact_omega,
            p.restitution,
            approach_velocity,
            p.min_impact_velocity,
        ))
    }

    fn time_loop<O: Observer>(&mut self, observer: &mut O) {
        let tau_end = self.p.tau_end();
        let dt = self.p.dt;
        let contact_dt = dt / self.options.substeps(self.p) as f64;
        // A step shorter than this at the end is merged into the one before.
        let end_slack = 1e-9 * dt;
        let mut halvings = 0u32;
        let mut iterations = 0usize;
        while self.state.tau < tau_end - end_slack {
            iterations += 1;
            if iterations.is_multiple_of(POLL_EVERY) {
                if !observer.keep_going() {
                    self.result.completed = false;
                    self.result.stop = Some(Stop {
                        tau: self.state.tau,
                        reason: StopReason::Cancelled,
                    });
                    break;
                }
                self.system.resync(&mut self.state);
            }
            let base = if matches!(self.phase, Phase::Contact(_)) {
                contact_dt
            } else {
                dt
            };
            let remaining = tau_end - self.state.tau;
            let mut h = if remaining < base + end_slack {
                remaining
            } else {
                base
            };
            if halvings > 0 {
                h /= f64::from(1u32 << halvings.min(30));
            }
            if h == dt && matches!(self.phase, Phase::Free) {
                if !self.free_flight(observer, dt, tau_end - end_slack) {
                    break;
                }
                if self.state.tau + dt + end_slack > tau_end {
                    continue;
                }
            }
            let start = self.state;
            let (next, converged) = self.system.step(&start, h, &self.phase);
            if !converged && halvings < self.options.max_step_halvings {
                halvings += 1;
                self.result.step_retries += 1;
                continue;
            }
            let level = halvings;
            halvings = 0;
            if !converged {
                self.result.unconverged_steps += 1;
            }
            let pen = self.system.penetration(next.x);
            match (self.phase, self.options.locate_contact) {
                (Phase::Free, true) if pen > 0.0 => {
                    let found = locate(&self.system, &start, next, h, &Phase::Free, |d| d > 0.0);
                    self.accept(observer, &start, found.state, |d| d.begin_contact());
                }
                (Phase::Contact(_), true) if pen <= 0.0 => {
                    let found = locate(&self.system, &start, next, h, &self.phase, |d| d <= 0.0);
                    // A contact trial step inside the location failed: retry the whole step smaller.
                    if !found.converged && level < self.options.max_step_halvings {
                        halvings = level + 1;
                        self.result.step_retries += 1;
                        continue;
                    }
                    if !found.converged {
                        self.result.unconverged_steps += 1;
                    }
                    self.accept(observer, &start, found.state, |d| d.end_contact());
                }
                (Phase::Free, false) if pen > 0.0 => {
                    // Plain scheme: contact noticed at the step's end; v₀ from that end state.
                    self.phase = self.contact_law(next.v[0] - next.v[1]);
                    let (redo, ok) = self.system.step(&start, h, &self.phase);
                    if !ok {
                        self.result.unconverged_steps += 1;
                    }
                    self.open_impact(&next);
                    self.accept(observer, &start, redo, |_| {});
                }
                (Phase::Contact(_), false) if pen <= 0.0 => {
                    let (redo, _) = self.system.step(&start, h, &Phase::Free);
                    self.phase = Phase::Free;
                    self.accept(observer, &start, redo, |d| d.close_impact());
                }
                _ => self.accept(observer, &start, next, |_| {}),
            }
        }
        if let Some(i) = self.open_impact {
            self.result.impacts[i].end = self.state.tau;
        }
    }

    /// The hot path: whole steps of Δτ out of contact, up to [`POLL_EVERY`]
    /// of them, until a step would start a contact or the run's last step is
    /// due; then the general loop takes over (and redoes that one step with
    /// event location). The same step and the same accounting as
    /// [`Driver::accept`], with the state kept in locals. Returns false when
    /// the observer asked to stop.
    fn free_flight<O: Observer>(&mut self, observer: &mut O, dt: f64, tau_end: f64) -> bool {
        if !observer.keep_going() {
            self.result.completed = false;
            self.result.stop = Some(Stop {
                tau: self.state.tau,
                reason: StopReason::Cancelled,
            });
            return false;
        }
        self.system.resync(&mut self.state);
        let mut current = self.state;
        for _ in 0..POLL_EVERY {
            if current.tau + dt > tau_end {
                break;
            }
            let next = self.system.free_step(&current, dt);
            if self.system.penetration(next.x) > 0.0 {
                break;
            }
            self.add_work(&current, &next);
            self.peaks_within(&current, &next);
            track_peaks(&mut self.result, &next);
            observer.record(&sample(&next, false));
            self.result.steps += 1;
            current = next;
        }
        self.state = current;
        true
    }

    /// Accepts `next` as the state after `start`: work integrals, then the
    /// phase switch `switch` (if any), then peaks and the observer.
    fn accept<O: Observer>(
        &mut self,
        observer: &mut O,
        start: &State,
        next: State,
        switch: impl FnOnce(&mut Self),
    ) {
        self.add_work(start, &next);
        self.peaks_within(start, &next);
        self.state = next;
        switch(self);
        self.track();
        self.record(observer);
        self.result.steps += 1;
    }

    /// Onset located at the current state: v₀ = δ̇ here (SPEC §4).
    fn begin_contact(&mut self) {
        let rate = self.state.v[0] - self.state.v[1];
        self.phase = self.contact_law(rate);
        self.system.rephase(&mut self.state, &self.phase);
        let s = self.state;
        self.open_impact(&s);
    }

    /// Separation located at the current state.
    fn end_contact(&mut self) {
        self.phase = Phase::Free;
        self.system.rephase(&mut self.state, &self.phase);
        self.close_impact();
    }

    fn open_impact(&mut self, s: &State) {
        self.result.impacts.push(Impact {
            start: s.tau,
            end: s.tau,
            approach_velocity: s.v[0] - s.v[1],
            separation_velocity: 0.0,
            restitution: 0.0,
            peak_force: 0.0,
            max_penetration: 0.0,
            ended: false,
        });
        self.open_impact = Some(self.result.impacts.len() - 1);
    }

    fn close_impact(&mut self) {
        if let Some(i) = self.open_impact.take() {
            let s = &self.state;
            let imp = &mut self.result.impacts[i];
            imp.end = s.tau;
            imp.separation_velocity = -(s.v[0] - s.v[1]);
            imp.restitution = if imp.approach_velocity > 0.0 {
                imp.separation_velocity / imp.approach_velocity
            } else {
                0.0
            };
            imp.ended = true;
        }
    }

    /// Work of every force over the step start → next (SPEC §6): the mean of
    /// the force at both ends times the displacement increment. With the
    /// average-acceleration rule, Δ(½mẋ²) equals the sum of these exactly.
    fn add_work(&mut self, start: &State, next: &State) {
        let sys = &self.system;
        let dx = [next.x[0] - start.x[0], next.x[1] - start.x[1]];
        let g = 0.5 * (start.g + next.g);
        let e = &mut self.energy;
        e.input -= g * (sys.mass[0] * dx[0] + sys.mass[1] * dx[1]);
        for i in 0..2 {
            e.damping += sys.damping[i] * 0.5 * (start.v[i] + next.v[i]) * dx[i];
            e.spring += 0.5 * (start.fs[i] + next.fs[i]) * dx[i];
        }
        e.contact += 0.5 * (start.fp + next.fp) * (dx[0] - dx[1]);
        e.max_input = e.max_input.max(e.input.abs());
    }

    /// Peaks reached between two accepted states: where ẋ_i (or ẍ_i) changes
    /// sign inside the step, the extremum of x_i (or ẋ_i) is taken from the
    /// cubic Hermite interpolant of the step's end values and slopes, so that
    /// Π_u and Π_v are the peaks of the trajectory, not of its samples
    /// (sampling alone would add an erratic O(h²) error).
    ///
    /// The interpolant is trusted only where the step resolves the
    /// structure's own oscillation (Π_ωi h ≤ [`RESOLVED_PHASE`]); on coarser
    /// steps its overshoot could exceed the motion, and the step ends alone count.
    #[inline]
    fn peaks_within(&mut self, start: &State, next: &State) {
        let h = next.tau - start.tau;
        let r = &mut self.result;
        for (peaks, i) in [(&mut r.left, 0), (&mut r.right, 1)] {
            if h > self.resolved_step[i] {
                continue;
            }
            if start.v[i] * next.v[i] < 0.0 {
                let x = hermite_extremum(start.x[i], next.x[i], start.v[i], next.v[i], h);
                peaks.peak_displacement = peaks.peak_displacement.max(x.abs());
            }
            if start.a[i] * next.a[i] < 0.0 {
                let v = hermite_extremum(start.v[i], next.v[i], start.a[i], next.a[i], h);
                peaks.peak_velocity = peaks.peak_velocity.max(v.abs());
            }
        }
    }

    /// Peaks, yielding, force extremes and the open impact's maxima.
    fn track(&mut self) {
        let Driver {
            result: r,
            state: s,
            open_impact,
            system,
            ..
        } = self;
        for (peaks, i) in [(&mut r.left, 0), (&mut r.right, 1)] {
            peaks.peak_displacement = peaks.peak_displacement.max(s.x[i].abs());
            peaks.peak_velocity = peaks.peak_velocity.max(s.v[i].abs());
            peaks.yielded |= s.plastic[i];
        }
        if let Some(i) = *open_impact {
            r.max_force = r.max_force.max(s.fp);
            r.min_force = r.min_force.min(s.fp);
            let imp = &mut r.impacts[i];
            imp.peak_force = imp.peak_force.max(s.fp);
            imp.max_penetration = imp.max_penetration.max(system.penetration(s.x));
        }
    }

    #[inline]
    fn record<O: Observer>(&self, observer: &mut O) {
        observer.record(&sample(
            &self.state,
            matches!(self.phase, Phase::Contact(_)),
        ));
    }

    fn finish(mut self) -> RunResult {
        let s = self.state;
        let m = self.system.mass;
        let e = &mut self.energy;
        e.kinetic = 0.5 * (m[0] * s.v[0] * s.v[0] + m[1] * s.v[1] * s.v[1]);
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
        self.result.tau_end = s.tau;
        self.result
    }
}

/// Peaks and yielding at an accepted state.
#[inline]
fn track_peaks(r: &mut RunResult, s: &State) {
    for (peaks, i) in [(&mut r.left, 0), (&mut r.right, 1)] {
        peaks.peak_displacement = peaks.peak_displacement.max(s.x[i].abs());
        peaks.peak_velocity = peaks.peak_velocity.max(s.v[i].abs());
        peaks.yielded |= s.plastic[i];
    }
}

/// What an observer sees of a state.
#[inline]
fn sample(s: &State, in_contact: bool) -> Sample {
    Sample {
        tau: s.tau,
        x: s.x,
        v: s.v,
        a: s.a,
        fs: s.fs,
        fp: s.fp,
        in_contact,
    }
}

/// The value at the interior extremum of the cubic Hermite interpolant with
/// end values p0, p1 and end slopes m0, m1 (m0·m1 < 0) over a step of size h.
/// dp/ds = a s² + b s + c on s ∈ [0, 1], with a = 6(p0 − p1) + 3h(m0 + m1),
/// b = −6(p0 − p1) − h(4m0 + 2m1), c = h m0; its root in (0, 1) is unique
/// when the end slopes differ in sign.
fn hermite_extremum(p0: f64, p1: f64, m0: f64, m1: f64, h: f64) -> f64 {
    let (hm0, hm1) = (h * m0, h * m1);
    let a = 6.0 * (p0 - p1) + 3.0 * (hm0 + hm1);
    let b = -6.0 * (p0 - p1) - 4.0 * hm0 - 2.0 * hm1;
    let c = hm0;
    // Bisection-free root: the quadratic changes sign on [0, 1] (c and a + b + c = h m1 differ in sign).
    let s = if a.abs() < 1e-300 {
        -c / b
    } else {
        let disc = (b * b - 4.0 * a * c).max(0.0).sqrt();
        // Numerically stable pair of roots; take the one inside [0, 1].
        let q = -0.5 * (b + b.signum() * disc);
        let (r1, r2) = (q / a, if q != 0.0 { c / q } else { f64::NAN });
        if (0.0..=1.0).contains(&r1) { r1 } else { r2 }
    };
    let s = if s.is_finite() {
        s.clamp(0.0, 1.0)
    } else {
        0.5
    };
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * p0
        + (s3 - 2.0 * s2 + s) * hm0
        + (-2.0 * s3 + 3.0 * s2) * p1
        + (s3 - s2) * hm1
}

#[cfg(test)]
mod tests {
    use super::hermite_extremum;

    #[test]
    fn hermite_finds_the_peak_of_a_sine() {
        // sin on [1.5, 1.7]: peak 1 at π/2, cubic interpolation error O(h⁴).
        let (t0, t1) = (1.5f64, 1.7f64);
        let p = hermite_extremum(t0.sin(), t1.sin(), t0.cos(), t1.cos(), t1 - t0);
        assert!((p - 1.0).abs() < 1e-5, "{p}");
        // A parabola is reproduced exactly: p = 1 − (t − 0.3)², t ∈ [0, 1].
        let p = hermite_extremum(1.0 - 0.09, 1.0 - 0.49, 0.6, -1.4, 1.0);
        assert!((p - 1.0).abs() < 1e-14, "{p}");
    }
}
