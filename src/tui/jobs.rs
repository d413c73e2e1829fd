//! The computations behind the screen: what was asked for last, the runs
//! and spectrum points that came back, a small cache so that switching back
//! to a scene or set costs nothing, and which results are current.

use super::worker::{Job, Output, RunOutput, RunSpec, Slot, SpectrumSpec};
use crate::analysis::spectrum::SpectrumPoint;

/// Results kept for reuse (switching scenes or sets back does not recompute).
const CACHE: usize = 12;

/// The runs and the spectrum a scene needs.
pub type Need = (Vec<RunSpec>, Option<SpectrumSpec>);

/// Progressive spectrum: the grid and the points computed so far.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumState {
    pub spec: SpectrumSpec,
    pub points: Vec<Option<SpectrumPoint>>,
}

impl SpectrumState {
    pub fn done(&self) -> usize {
        self.points.iter().filter(|p| p.is_some()).count()
    }
}

#[derive(Debug, Default)]
pub struct Jobs {
    /// Generation of the newest job; older outputs are dropped.
    pub generation: u64,
    /// What the newest job was asked for (the whole need, cached parts included).
    requested: Option<Need>,
    /// Whether the newest job is still running.
    pub computing: bool,
    /// Finished runs, newest last.
    pub results: Vec<RunOutput>,
    pub spectrum: Option<SpectrumState>,
}

impl Jobs {
    /// A new job when `need` changed since the last request; parts already
    /// computed are left out. Bumps the generation.
    pub fn job(&mut self, need: Need) -> Option<Job> {
        if self.requested.as_ref() == Some(&need) {
            return None;
        }
        self.generation += 1;
        self.requested = Some(need.clone());
        let (runs, spectrum) = need;
        let runs: Vec<RunSpec> = runs
            .into_iter()
            .filter(|s| self.cached(s).is_none())
            .collect();
        let spectrum = spectrum.filter(|s| {
            !self
                .spectrum
                .as_ref()
                .is_some_and(|st| st.spec == *s && st.done() == st.points.len())
        });
        if let Some(s) = &spectrum {
            if self.spectrum.as_ref().is_none_or(|st| st.spec != *s) {
                self.spectrum = Some(SpectrumState {
                    spec: s.clone(),
                    points: vec![None; s.grid.len()],
                });
            } else if let Some(st) = &mut self.spectrum {
                st.points.iter_mut().for_each(|p| *p = None);
            }
        }
        self.computing = !runs.is_empty() || spectrum.is_some();
        if !self.computing {
            return None;
        }
        Some(Job {
            generation: self.generation,
            runs,
            spectrum,
        })
    }

    fn cached(&self, spec: &RunSpec) -> Option<&RunOutput> {
        self.results.iter().rev().find(|o| o.spec == *spec)
    }

    fn requested_spec(&self, slot: Slot) -> Option<&RunSpec> {
        self.requested
            .as_ref()
            .and_then(|(runs, _)| runs.iter().find(|s| s.slot == slot))
    }

    /// The run to show for a slot: the one asked for if computed, else the
    /// latest of that slot (shown, marked stale, while the new one computes).
    pub fn shown(&self, slot: Slot) -> Option<&RunOutput> {
        self.requested_spec(slot)
            .and_then(|s| self.cached(s))
            .or_else(|| self.results.iter().rev().find(|o| o.spec.slot == slot))
    }

    /// Whether the run shown for `slot` is the one asked for.
    pub fn is_current(&self, slot: Slot) -> bool {
        self.requested_spec(slot)
            .is_some_and(|s| self.cached(s).is_some())
    }

    /// Takes a worker output; those of an older generation are dropped.
    pub fn on_output(&mut self, out: Output) {
        if out.generation() != self.generation {
            return;
        }
        match out {
            Output::Run { output, .. } => {
                self.results.retain(|o| o.spec != output.spec);
                self.results.push(*output);
                if self.results.len() > CACHE {
                    self.results.remove(0);
                }
            }
            Output::Points { start, points, .. } => {
                if let Some(s) = self.spectrum.as_mut() {
                    for (slot, p) in s.points.iter_mut().skip(start).zip(points) {
                        *slot = Some(p);
                    }
                }
            }
            Output::Done { .. } => self.computing = false,
        }
    }
}
