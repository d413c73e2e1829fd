//! The one place where a step's result enters the run's account (SPEC §6):
//! every accepted state, in either phase and under either policy, passes
//! through [`Driver::accept`].

use super::driver::{Driver, POLL_EVERY, is_finite};
use super::peaks::hermite_extremum;
use super::policy::Event;
use super::step::{Phase, State};
use crate::solver::observer::{Observer, Sample};
use crate::solver::result::{Impact, StopReason};

impl Driver<'_> {
    /// Accepts `next` as the state after `start`, in this order:
    /// 1. the phase switch `event` is worked out: the new phase, and the
    ///    state in it (at a located crossing the force may jump, x and ẋ do not);
    /// 2. a non-finite state, before or after the switch, stops the run at
    ///    `start` instead, with nothing of the step accounted;
    /// 3. work integrals and peaks inside the step, over the step as taken
    ///    (before any force jump at its end);
    /// 4. the switch, which may open or close an impact;
    /// 5. peaks, yielding and force extremes at the new state, and the observer;
    /// 6. every [`POLL_EVERY`] steps, the checkpoint (cancel, step cap).
    ///
    /// Returns whether the run goes on.
    #[inline(always)]
    pub fn accept<O: Observer>(
        &mut self,
        observer: &mut O,
        start: &State,
        next: &State,
        event: Event,
    ) -> bool {
        let mut state = *next;
        let switch = match event {
            Event::None => None,
            Event::Onset { law, rephase, .. } => Some((Phase::Contact(law), rephase)),
            Event::Separation { rephase } => Some((Phase::Free, rephase)),
        };
        if let Some((phase, true)) = switch {
            self.system.rephase(&mut state, &phase);
        }
        if !(is_finite(next) && is_finite(&state)) {
            self.halt(StopReason::NonFinite);
            return false;
        }
        self.add_work(start, next);
        self.peaks_within(start, next);
        if switch.is_some() {
            // Where f_p jumps (a Kelvin onset or separation), ẍ + g has two
            // one-sided values: the one before the switch counts here, the
            // one after it in `track`.
            for (i, peaks) in [&mut self.result.left, &mut self.result.right]
                .into_iter()
                .enumerate()
            {
                peaks.raise_absolute_acceleration(next.a[i] + next.g);
            }
        }
        self.state = state;
        if let Some((phase, _)) = switch {
            self.phase = phase;
        }
        // Only an onset can meet a cap here (the impact cap).
        let going = match event {
            Event::None => true,
            Event::Onset {
                approach_velocity, ..
            } => self.open_impact(approach_velocity),
            Event::Separation { .. } => {
                self.close_impact();
                true
            }
        };
        self.track();
        self.record(observer);
        self.result.steps += 1;
        if self.result.steps.is_multiple_of(POLL_EVERY) && !self.checkpoint(observer) {
            return false;
        }
        going
    }

    /// Opens an impact at the current state (SPEC §6). Past the impact cap
    /// the run stops; returns whether it goes on.
    pub fn open_impact(&mut self, approach_velocity: f64) -> bool {
        self.result.impacts.push(Impact {
            start: self.state.tau,
            end: self.state.tau,
            approach_velocity,
            separation_velocity: 0.0,
            restitution: 0.0,
            peak_force: 0.0,
            max_penetration: 0.0,
            ended: false,
        });
        self.open_impact = Some(self.result.impacts.len() - 1);
        if self.result.impacts.len() > self.caps.impacts {
            self.halt(StopReason::EventCap);
            return false;
        }
        true
    }

    /// Closes the open impact at the current state: separation velocity −δ̇
    /// and achieved restitution (separation over approach velocity).
    fn close_impact(&mut self) {
        if let Some(i) = self.open_impact.take() {
            let s = &self.state;
            self.result.impacts[i].close(s.tau, s.v[0] - s.v[1]);
        }
    }

    /// Work of every force over the step start → next (SPEC §6): the mean of
    /// the force at both ends times the displacement increment. With the
    /// average-acceleration rule, Δ(½mẋ²) equals the sum of these exactly.
    #[inline(always)]
    fn add_work(&mut self, start: &State, next: &State) {
        let sys = &self.system;
        let dx = [next.x[0] - start.x[0], next.x[1] - start.x[1]];
        let g = 0.5 * (start.g + next.g);
        let e = &mut self.energy;
        e.input -= g * (sys.mass[0] * dx[0] + sys.mass[1] * dx[1]);
        for (i, dx) in dx.into_iter().enumerate() {
            e.damping += sys.damping[i] * 0.5 * (start.v[i] + next.v[i]) * dx;
            e.spring_by_structure[i] += 0.5 * (start.fs[i] + next.fs[i]) * dx;
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
    ///
    /// [`RESOLVED_PHASE`]: super::peaks::RESOLVED_PHASE
    #[inline(always)]
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

    /// Peaks (Π_u, Π_v and the absolute acceleration A), yielding, force
    /// extremes and the open impact's maxima at the current state.
    #[inline(always)]
    pub fn track(&mut self) {
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
            // ẍ + g (SPEC §6, demands) at the accepted state.
            peaks.raise_absolute_acceleration(s.a[i] + s.g);
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

    /// Tells the observer the current state.
    #[inline(always)]
    pub fn record<O: Observer>(&self, observer: &mut O) {
        let s = &self.state;
        observer.record(&Sample {
            tau: s.tau,
            x: s.x,
            v: s.v,
            a: s.a,
            fs: s.fs,
            fp: s.fp,
            in_contact: matches!(self.phase, Phase::Contact(_)),
        });
    }
}
