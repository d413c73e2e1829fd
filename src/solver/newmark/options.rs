//! The numerical choices of a Newmark run beyond the Π-groups (SPEC §5).

use crate::model::{Excitation, Params};

use super::caps::RunCaps;

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
/// Most sub-steps per Δτ under [`ContactSubsteps::Auto`] (Π_ωcon = 5e6).
const MAX_AUTO_SUBSTEPS: f64 = 1e6;

/// Numerical choices of a run beyond the Π-groups. The defaults are the
/// project's accurate scheme; the paper's plain scheme is
/// [`SolverOptions::plain`].
#[derive(Debug, Clone, PartialEq)]
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
    /// Limits on steps, impacts and retries; `None`: [`RunCaps::for_run`].
    pub caps: Option<RunCaps>,
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
            caps: None,
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
                    n.clamp(1.0, MAX_AUTO_SUBSTEPS) as u32
                } else {
                    1
                }
            }
        }
    }

    /// The caps of a run of `p` under these options.
    pub fn caps(&self, p: &Params) -> RunCaps {
        self.caps
            .unwrap_or_else(|| RunCaps::for_run(p, self.substeps(p)))
    }
}
