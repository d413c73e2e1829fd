//! The reference run: adaptive DOPRI5 from event to event (SPEC §2–4).
//!
//! Each pass of the loop
//! 1. attempts a step; a step whose error estimate exceeds the tolerance is
//!    retried smaller (standard controller, exponent 1/5);
//! 2. evaluates every active event function at the step's end; if one turned
//!    positive, its zero is located on the dense output and the step is
//!    retaken exactly to the earliest one, where the mode switches;
//! 3. updates the peaks: at the step's end, and inside it where ẋᵢ = 0
//!    (a peak of |xᵢ|) or ẍᵢ = 0 (a peak of |ẋᵢ|), found on the dense output.
//!
//! Between events the right-hand side is smooth, so the method keeps its
//! order, and the peaks are the continuous maxima rather than the maxima over
//! step ends.

use crate::model::{Excitation, Params};

use super::dopri5::{self, Vector};
use super::events::{self, Event};
use super::system::{Branch, Mode, Structures};

/// Knobs of a reference run.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceOptions {
    /// Absolute and relative local error tolerance of each step.
    pub tolerance: f64,
    /// Largest step, so that no event or peak can hide inside one step.
    pub max_step: f64,
    /// Give up (result marked incomplete) after this many attempted steps.
    pub max_steps: usize,
    pub excitation: Excitation,
    pub initial_displacement: [f64; 2],
    pub initial_velocity: [f64; 2],
}

/// The tolerance the bench measures against.
pub const DEFAULT_TOLERANCE: f64 = 1e-13;

impl Default for ReferenceOptions {
    fn default() -> Self {
        ReferenceOptions {
            tolerance: DEFAULT_TOLERANCE,
            max_step: 0.05,
            max_steps: 50_000_000,
            excitation: Excitation::Sine,
            initial_displacement: [0.0; 2],
            initial_velocity: [0.0; 2],
        }
    }
}

impl ReferenceOptions {
    /// The set's own ground motion ([`Params::ground`]) and the initial
    /// velocity it imposes (the type B pulse's ẋ_i(0) = −1, SPEC §9).
    pub fn for_params(p: &Params, tolerance: f64) -> Self {
        let excitation = p.ground();
        ReferenceOptions {
            tolerance,
            initial_velocity: excitation.initial_velocity(),
            excitation,
            ..Self::default()
        }
    }

    pub fn with_tolerance(tolerance: f64) -> Self {
        ReferenceOptions {
            tolerance,
            ..Self::default()
        }
    }
}

/// One contact phase as the reference sees it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReferenceImpact {
    pub start: f64,
    pub end: f64,
    /// δ̇ at onset.
    pub approach_velocity: f64,
    /// −δ̇ at separation.
    pub separation_velocity: f64,
}

/// What a reference run reports.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ReferenceResult {
    /// [Π_u1, Π_v1, Π_u2, Π_v2]: continuous maxima of |x1|, |ẋ1|, |x2|, |ẋ2| (SPEC §6).
    pub peaks: [f64; 4],
    pub impacts: Vec<ReferenceImpact>,
    pub yielded: [bool; 2],
    /// Largest and smallest pounding force at the accepted points (step ends
    /// and events) in contact; below 0 the element pulls.
    pub max_force: f64,
    pub min_force: f64,
    /// The state at the end.
    pub final_state: [f64; 4],
    /// z of each spring at the end (SPEC §3), for the residual displacement
    /// (1 − Π_α)(x − z) of SPEC §6.
    pub final_elastic_part: [f64; 2],
    /// max |ẍ_i + g| of each structure (SPEC §6, demands) over the accepted
    /// points (step ends, and both sides of every event, where f_p may jump),
    /// and the τ at which each was reached: the true peak where it is reached
    /// at such a point (a Kelvin onset), a lower bound by O(h²) otherwise.
    pub peak_absolute_acceleration: [f64; 2],
    pub peak_absolute_acceleration_at: [f64; 2],
    pub tau_end: f64,
    pub accepted_steps: usize,
    pub rejected_steps: usize,
    pub events: usize,
    /// False if the run gave up (step size underflow or `max_steps`).
    pub completed: bool,
}

/// Integrates `p` from rest (or the given initial state) to τ_end = 2π·cycles.
pub fn reference(p: &Params, options: &ReferenceOptions) -> ReferenceResult {
    let system = Structures::new(p, options.excitation.clone());
    let mut run = Run::new(&system, options);
    run.integrate(p.tau_end());
    run.result
}

struct Run<'a> {
    system: &'a Structures,
    options: &'a ReferenceOptions,
    tau: f64,
    y: Vector,
    mode: Mode,
    /// The step starts at an event: event values at its start count as zero.
    fresh: bool,
    result: ReferenceResult,
}

impl<'a> Run<'a> {
    fn new(system: &'a Structures, options: &'a ReferenceOptions) -> Self {
        let [x1, x2] = options.initial_displacement;
        let [v1, v2] = options.initial_velocity;
        let y = [x1, v1, x2, v2];
        let spring = |i: usize, x: f64| {
            let uy = system.yield_displacement[i];
            if x.abs() > uy {
                Branch::Yielded { sign: x.signum() }
            } else {
                Branch::Elastic {
                    x_anchor: 0.0,
                    z_anchor: 0.0,
                }
            }
        };
        let mut mode = Mode {
            springs: [spring(0, x1), spring(1, x2)],
            contact: None,
        };
        let mut result = ReferenceResult {
            completed: true,
            ..Default::default()
        };
        if system.penetration(&y) > 0.0 {
            let rate = system.penetration_rate(&y);
            mode.contact = Some(system.contact_at_onset(rate));
            result.impacts.push(ReferenceImpact {
                start: 0.0,
                approach_velocity: rate,
                ..Default::default()
            });
        }
        let mut run = Run {
            system,
            options,
            tau: 0.0,
            y,
            mode,
            fresh: true,
            result,
        };
        run.track_point(&y);
        run
    }

    fn rhs(&self) -> impl Fn(f64, &Vector) -> Vector + '_ {
        let mode = self.mode;
        move |t, y| self.system.derivative(&mode, t, y)
    }

    fn integrate(&mut self, tau_end: f64) {
        let tol = self.options.tolerance;
        let mut h = 1e-3f64.min(self.options.max_step);
        let mut f0 = self.rhs()(self.tau, &self.y);
        let mut attempts = 0usize;
        while self.tau < tau_end {
            attempts += 1;
            if attempts > self.options.max_steps || h < 1e-15 * (1.0 + self.tau) {
                self.result.completed = false;
                break;
            }
            // A step ends where g changes formula (a pulse's end, a record's
            // sample), so that the right-hand side is smooth inside it.
            let stop = tau_end.min(self.system.excitation.next_break(self.tau));
            let last = stop - self.tau <= h * (1.0 + 1e-12);
            let hs = if last { stop - self.tau } else { h };
            let y0 = self.y;
            let step = dopri5::step(&self.rhs(), self.tau, &y0, &f0, hs);
            let err = step.error_norm(&y0, tol);
            let factor = if err > 0.0 {
                (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
            } else {
                5.0
            };
            if err > 1.0 {
                self.result.rejected_steps += 1;
                h = hs * factor.min(1.0);
                continue;
            }
            self.result.accepted_steps += 1;
            match self.first_event(&step) {
                None => {
                    self.track_inside(&step, 1.0, &f0);
                    self.tau = if last { stop } else { self.tau + hs };
                    self.y = step.y1;
                    // g may jump at a break: the next step starts from f there.
                    f0 = if last && stop < tau_end {
                        self.rhs()(self.tau, &self.y)
                    } else {
                        step.f1
                    };
                    self.fresh = false;
                    self.track_point(&self.y.clone());
                }
                Some((event, theta)) => {
                    self.track_inside(&step, theta, &f0);
                    let short = dopri5::step(&self.rhs(), self.tau, &y0, &f0, theta * hs);
                    self.tau += theta * hs;
                    self.y = short.y1;
                    self.track_point(&self.y.clone());
                    self.switch(event);
                    // The other side of the event: f_p may have jumped.
                    self.track_accelerations(&self.y.clone());
                    self.result.events += 1;
                    self.fresh = true;
                    f0 = self.rhs()(self.tau, &self.y);
                }
            }
            h = (hs * factor)
                .min(self.options.max_step)
                .max(if last { h } else { 0.0 });
            if last && self.tau >= tau_end {
                break;
            }
        }
        if let Some(open) = self.result.impacts.last_mut().filter(|i| i.end == 0.0) {
            open.end = self.tau;
        }
        self.result.tau_end = self.tau;
        self.result.final_state = self.y;
        for i in 0..2 {
            self.result.final_elastic_part[i] =
                self.system
                    .elastic_part(i, self.mode.springs[i], self.y[2 * i]);
        }
    }

    /// The earliest active event whose function turned positive within the step.
    fn first_event(&self, step: &dopri5::Step) -> Option<(Event, f64)> {
        let (list, n) = events::active(self.system, &self.mode);
        let mut best: Option<(Event, f64)> = None;
        for &event in &list[..n] {
            let g = |y: &Vector| events::value(self.system, &self.mode, event, y);
            let g1 = g(&step.y1);
            let mut g0 = g(&self.y);
            if self.fresh {
                g0 = g0.min(0.0);
            }
            if !(g1 > 0.0 && g0 <= 0.0) {
                continue;
            }
            let theta = events::locate(|th| g(&step.at(th)), 0.0, g0, 1.0, g1);
            if best.is_none_or(|(_, t)| theta < t) {
                best = Some((event, theta));
            }
        }
        best
    }

    /// Changes the mode at an event located at the current state.
    fn switch(&mut self, event: Event) {
        let y = self.y;
        match event {
            Event::Onset => {
                let rate = self.system.penetration_rate(&y);
                self.mode.contact = Some(self.system.contact_at_onset(rate));
                self.result.impacts.push(ReferenceImpact {
                    start: self.tau,
                    approach_velocity: rate,
                    ..Default::default()
                });
            }
            Event::Separation => {
                self.mode.contact = None;
                if let Some(open) = self.result.impacts.last_mut() {
                    open.end = self.tau;
                    open.separation_velocity = -self.system.penetration_rate(&y);
                }
            }
            Event::Yield { spring, sign } => {
                self.mode.springs[spring] = Branch::Yielded { sign };
                self.result.yielded[spring] = true;
            }
            Event::Unload { spring } => {
                if let Branch::Yielded { sign } = self.mode.springs[spring] {
                    self.mode.springs[spring] = Branch::Elastic {
                        x_anchor: y[2 * spring],
                        z_anchor: sign * self.system.yield_displacement[spring],
                    };
                }
            }
        }
    }

    fn track_point(&mut self, y: &Vector) {
        if self.mode.contact.is_some() {
            let f = self.system.pounding_force(&self.mode, y);
            self.result.max_force = self.result.max_force.max(f);
            self.result.min_force = self.result.min_force.min(f);
        }
        self.track_peaks(y);
        self.track_accelerations(y);
    }

    /// Raises each peak absolute acceleration to its value at state `y` and the current τ.
    fn track_accelerations(&mut self, y: &Vector) {
        let a = self.system.absolute_acceleration(&self.mode, y);
        let r = &mut self.result;
        let peaks = r
            .peak_absolute_acceleration
            .iter_mut()
            .zip(&mut r.peak_absolute_acceleration_at);
        for (a, (peak, at)) in a.iter().zip(peaks) {
            if a.abs() > *peak {
                *peak = a.abs();
                *at = self.tau;
            }
        }
    }

    fn track_peaks(&mut self, y: &Vector) {
        for (peak, value) in self.result.peaks.iter_mut().zip(y) {
            *peak = peak.max(value.abs());
        }
    }

    /// Interior peaks on θ ∈ (0, θ_end) of the step's dense output: |xᵢ| where
    /// ẋᵢ changes sign, |ẋᵢ| where ẍᵢ does.
    fn track_inside(&mut self, step: &dopri5::Step, theta_end: f64, f0: &Vector) {
        let y_end = step.at(theta_end);
        let f = self.rhs();
        let f_end = f(step.t0 + theta_end * step.h, &y_end);
        let mut found = [0.0f64; 4];
        for i in 0..2 {
            let (x, v) = (2 * i, 2 * i + 1);
            // ẋᵢ = 0: peak of |xᵢ|.
            let (v0, v1) = (self.y[v], y_end[v]);
            if v0 * v1 < 0.0 {
                let sign = v1.signum();
                let th = events::locate(
                    |th| sign * step.at(th)[v],
                    0.0,
                    sign * v0,
                    theta_end,
                    sign * v1,
                );
                found[x] = step.at(th)[x].abs();
            }
            // ẍᵢ = 0: peak of |ẋᵢ|.
            let (a0, a1) = (f0[v], f_end[v]);
            if a0 * a1 < 0.0 {
                let sign = a1.signum();
                let accel = |th: f64| sign * f(step.t0 + th * step.h, &step.at(th))[v];
                let th = events::locate(accel, 0.0, sign * a0, theta_end, sign * a1);
                found[v] = step.at(th)[v].abs();
            }
        }
        drop(f);
        self.track_peaks(&found);
    }
}
