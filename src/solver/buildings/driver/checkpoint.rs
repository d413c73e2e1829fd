//! A run's state just before its first contact onset, from which the run of
//! the same buildings apart continues (SPEC §13).
//!
//! Until the first onset of any contact element (a joint's floor pair or a
//! bumper, SPEC §14) no contact force acts, and the row obeys
//!
//! ```text
//! M ü + C u̇ + f_s(u, z) − K_G u + f_l(Δu, Δv) = −M 1 ü_g(t)
//! ```
//!
//! (the storeys' bilinear shear of SPEC §3 with P-Δ of §15, the links of
//! §14), in which no gap appears. The same buildings with every joint open
//! ([`Row::apart`]) obey the same equations from the same start, so up to
//! the first onset t_c the two runs have the same motion. The run apart need
//! not be made again over [0, t_c]: it starts from the run with contact's
//! state there ([`Checkpoint`]): the floors' (u, u̇), every storey's branch
//! and plastic offset, the envelopes so far (floors, storeys, facing floor
//! pairs, links), the energy integrals and the histories when kept, the
//! quiet test's count of each configuration's requests ([`super::FRESH`]),
//! and the run's counters.
//!
//! The continuation takes the sub-step in which t_c fell by the series from
//! t_c, and every later sub-step as the run from t = 0 would. The two differ
//! by rounding only: before t_c the run with contact takes by the series some
//! sub-steps the run apart takes by its map (where a gap may close), and the
//! continuation splits one sub-step at t_c.
//!
//! **When it holds**, as the driver states it: a checkpoint is kept only for
//! a row without fluid viscous dampers (their Runge–Kutta steps are sized by
//! an error estimate, and steps cut at different events differ by the step
//! tolerance, not by rounding), and continues only a row whose equations out
//! of contact are those of the checkpoint's row (`twin.apart() ==
//! row.apart()`), which has no contact element of its own (one could close
//! before t_c), under the same ground and options ([`Checkpoint::fits`]).
//! Any other run starts from t = 0.

use std::collections::HashMap;

use crate::model::buildings::ground::Piece;
use crate::model::buildings::{Ground, Row};

use super::super::config::Branch;
use super::super::link::LinkResult;
use super::super::peaks::Envelope;
use super::super::profile::{Cause, RowProfile};
use super::super::result::RowTrace;
use super::work::Balance;
use super::{RowOptions, Run, ground_at};

/// The state of a run just before its first contact onset, and what it
/// holds for ([`Checkpoint::fits`]).
#[derive(Debug, Clone)]
pub struct Checkpoint {
    /// The row's buildings apart ([`Row::apart`]), the ground and the
    /// options of the run it was taken in.
    apart: Row,
    ground: Ground,
    options: RowOptions,
    state: Snapshot,
}

/// What a run carries from one sub-step to the next that its results
/// depend on, at the instant `time`.
#[derive(Debug, Clone)]
pub(super) struct Snapshot {
    pub(super) time: f64,
    u: Vec<f64>,
    v: Vec<f64>,
    branch: Vec<Branch>,
    plastic: Vec<f64>,
    envelope: Envelope,
    links: Vec<LinkResult>,
    energy: Option<Balance>,
    /// Every link's force history, when kept.
    link_forces: Option<Vec<Vec<(f64, f64)>>>,
    /// The trace up to the start of the sub-step holding `time`, when kept
    /// (filled in by the loop, which holds the trace).
    pub(super) trace: Option<RowTrace>,
    configurations: HashMap<Vec<u8>, usize>,
    seen: Option<Vec<u8>>,
    requests: usize,
    series_steps: usize,
    /// Maps made and map steps taken (and seconds in exponentials) so far.
    maps: (usize, usize, f64),
    profile: RowProfile,
}

impl Checkpoint {
    /// The instant of the first onset, t_c (s).
    pub fn time(&self) -> f64 {
        self.state.time
    }

    /// Whether a run of `twin` under `ground` with `options` has the motion
    /// of the checkpoint's run up to t_c: the same equations out of contact,
    /// no contact element of its own, the same ground and options.
    pub fn fits(&self, twin: &Row, ground: &Ground, options: &RowOptions) -> bool {
        twin.contact_elements().is_empty()
            && *options == self.options
            && *ground == self.ground
            && twin.apart() == self.apart
    }

    pub(super) fn new(row: &Row, ground: &Ground, options: &RowOptions, state: Snapshot) -> Self {
        Checkpoint {
            apart: row.apart(),
            ground: ground.clone(),
            options: *options,
            state,
        }
    }

    pub(super) fn state(&self) -> &Snapshot {
        &self.state
    }
}

impl Run<'_> {
    /// The state now, at an onset about to be applied, when a checkpoint is
    /// asked for and none is kept yet.
    pub(super) fn keep_before_onset(&mut self) {
        if !self.keep || self.snapshot.is_some() || !self.layout.dampers.is_empty() {
            return;
        }
        self.snapshot = Some(Snapshot {
            time: self.t,
            u: self.u.clone(),
            v: self.v.clone(),
            branch: self.config.branch.clone(),
            plastic: self.config.plastic.clone(),
            envelope: self.envelope.clone(),
            links: self.links.clone(),
            energy: self.energy.clone(),
            link_forces: self.forces.as_ref().map(|f| f.links.clone()),
            trace: None,
            configurations: self.configurations.clone(),
            seen: self.seen.clone(),
            requests: self.requests,
            series_steps: self.series_steps,
            maps: self.maps_so_far(),
            profile: self.profile,
        });
    }

    /// Takes up the state of `s` (a run of the same equations out of
    /// contact), and records its point with the acceleration of this row.
    pub(super) fn resume(&mut self, s: &Snapshot, piece: &Piece) {
        self.t = s.time;
        self.u.clone_from(&s.u);
        self.v.clone_from(&s.v);
        self.config.branch.clone_from(&s.branch);
        self.config.plastic.clone_from(&s.plastic);
        self.system = self.propagator.systems.of(&self.layout, &self.config);
        self.envelope = s.envelope.clone();
        self.links.clone_from(&s.links);
        if self.energy.is_some() {
            self.energy.clone_from(&s.energy);
        }
        if let (Some(f), Some(links)) = (self.forces.as_mut(), &s.link_forces) {
            f.links.clone_from(links);
        }
        self.configurations.clone_from(&s.configurations);
        self.seen.clone_from(&s.seen);
        self.requests = s.requests;
        self.series_steps = s.series_steps;
        self.carried = s.maps;
        self.profile = s.profile;
        // The series steps of the sub-step holding t_c, taken before it,
        // are the continued sub-step's.
        let unassigned = s.series_steps - s.profile.series.total();
        self.profile.series.add(Cause::Continued, unassigned);
        self.record_here(ground_at(piece, self.t).0);
    }
}
