//! What the driver does with a step across δ = 0 (SPEC §4–5): the plain
//! scheme notices the change at the step's end, the located scheme finds the
//! instant inside the step. Either way the answer is a [`Crossing`]: the
//! state to accept and the phase switch to make there, which the driver
//! applies in its one `accept`.

use crate::model::{ContactLaw, Params};

use super::locate::locate;
use super::step::{Phase, State, System};

/// The state to accept after a step that crossed δ = 0, and what happens there.
#[derive(Debug, Clone, Copy)]
pub struct Crossing {
    pub state: State,
    /// Newton converged in every contact step taken to find `state`.
    pub converged: bool,
    pub event: Event,
}

/// A phase switch at an accepted state.
#[derive(Debug, Clone, Copy)]
pub enum Event {
    None,
    /// Contact begins under `law`, with approach velocity v₀ = δ̇ at onset (SPEC §4).
    Onset {
        law: ContactLaw,
        approach_velocity: f64,
        /// The state was computed out of contact: recompute its force and
        /// acceleration under `law` (the force may jump; x and ẋ do not).
        rephase: bool,
    },
    /// Contact ends.
    Separation {
        /// The state was computed in contact: recompute it without the force.
        rephase: bool,
    },
}

/// How a step across δ = 0 is handled.
pub trait Policy {
    /// A free step of size `h` from `start` ended at `next` with δ > 0.
    fn onset(&self, system: &System, p: &Params, start: &State, next: State, h: f64) -> Crossing;

    /// A contact step of size `h` from `start` under `phase` ended at `next` with δ ≤ 0.
    fn separation(
        &self,
        system: &System,
        start: &State,
        next: State,
        h: f64,
        phase: &Phase,
    ) -> Crossing;
}

/// The paper's scheme: the phase changes at the end of the step that crossed,
/// and that step is redone in the new phase. v₀ is δ̇ at the end of the free
/// step, up to one step past the true onset.
pub struct Plain;

/// Onset and separation located inside the step (regula falsi on δ of a
/// Newmark step of variable length, SPEC §5); the step is cut there, so v₀ is
/// the approach velocity at the true onset and the scheme stays second order.
pub struct Located;

/// The contact law of an onset with approach velocity v₀ (SPEC §4).
pub fn contact_law(p: &Params, approach_velocity: f64) -> ContactLaw {
    crate::model::contact::ContactConstants::of(p).law(approach_velocity)
}

impl Policy for Plain {
    fn onset(&self, system: &System, p: &Params, start: &State, next: State, h: f64) -> Crossing {
        let approach_velocity = next.v[0] - next.v[1];
        let law = contact_law(p, approach_velocity);
        let (state, converged) = system.step(start, h, &Phase::Contact(law));
        Crossing {
            state,
            converged,
            event: Event::Onset {
                law,
                approach_velocity,
                rephase: false,
            },
        }
    }

    fn separation(&self, system: &System, start: &State, _: State, h: f64, _: &Phase) -> Crossing {
        Crossing {
            state: system.free_step(start, h),
            converged: true,
            event: Event::Separation { rephase: false },
        }
    }
}

impl Policy for Located {
    fn onset(&self, system: &System, p: &Params, start: &State, next: State, h: f64) -> Crossing {
        let found = locate(system, start, next, h, &Phase::Free, |d| d > 0.0);
        let approach_velocity = found.state.v[0] - found.state.v[1];
        Crossing {
            state: found.state,
            converged: found.converged,
            event: Event::Onset {
                law: contact_law(p, approach_velocity),
                approach_velocity,
                rephase: true,
            },
        }
    }

    fn separation(
        &self,
        system: &System,
        start: &State,
        next: State,
        h: f64,
        phase: &Phase,
    ) -> Crossing {
        // δ ≤ 0 is the far side; a NaN δ never gets here (the driver stops on it).
        let found = locate(system, start, next, h, phase, |d| d <= 0.0);
        Crossing {
            state: found.state,
            converged: found.converged,
            event: Event::Separation { rephase: true },
        }
    }
}
