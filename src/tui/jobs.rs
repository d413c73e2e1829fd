//! The computations behind the screen: what was asked for last, the runs
//! and spectrum points that came back, a small cache so that switching back
//! to a scene or set costs nothing, and which results are current.

use super::risk_job::{RiskOutput, RiskSpec};
use super::row_job::{RowOutput, RowSpec};
use super::worker::{Job, MapSpec, Output, RunOutput, RunSpec, Slot, SpectrumSpec};
use crate::analysis::map::MapCell;
use crate::analysis::risk::RiskPicture;
use crate::analysis::spectrum::SpectrumPoint;

/// Results kept for reuse (switching scenes or sets back does not recompute).
const CACHE: usize = 12;
/// Row results kept (each holds its traces).
const ROW_CACHE: usize = 4;

/// The runs, the spectrum, the map and the risk picture a scene needs.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Need {
    pub runs: Vec<RunSpec>,
    pub spectrum: Option<SpectrumSpec>,
    pub map: Option<MapSpec>,
    pub risk: Option<RiskSpec>,
    pub row: Option<RowSpec>,
}

impl Need {
    /// Runs alone.
    pub fn runs(runs: Vec<RunSpec>) -> Need {
        Need {
            runs,
            ..Need::default()
        }
    }
}

/// Progressive risk picture: the latest pass's picture, whether it is the
/// full one, or why there is none.
#[derive(Debug, Clone, PartialEq)]
pub struct RiskState {
    pub spec: RiskSpec,
    pub picture: Option<RiskPicture>,
    /// The picture covers every record at every level.
    pub full: bool,
    /// The picture is of an earlier spec (shown until the new one's first pass).
    pub stale: bool,
    pub error: Option<String>,
}

impl RiskState {
    /// Whether nothing more will come for this spec.
    pub fn finished(&self) -> bool {
        self.full || self.error.is_some()
    }
}

/// Progressive map: the cells computed so far, row-major from the lowest y.
#[derive(Debug, Clone, PartialEq)]
pub struct MapState {
    pub spec: MapSpec,
    pub cells: Vec<Option<MapCell>>,
    /// Why the map cannot be computed, when it cannot.
    pub error: Option<String>,
}

impl MapState {
    pub fn done(&self) -> usize {
        self.cells.iter().filter(|c| c.is_some()).count()
    }

    /// The cell (column, row from the lowest y), or the nearest computed one
    /// in its column (the coarse picture while the rows between fill in).
    pub fn cell(&self, col: usize, row: usize) -> Option<&MapCell> {
        let (nx, ny) = (self.spec.columns(), self.spec.rows());
        if col >= nx || row >= ny {
            return None;
        }
        (0..ny).find_map(|d| {
            [row.checked_sub(d), Some(row + d)]
                .into_iter()
                .flatten()
                .filter(|&r| r < ny)
                .find_map(|r| self.cells[r * nx + col].as_ref())
        })
    }
}

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
    pub map: Option<MapState>,
    pub risk: Option<RiskState>,
    /// The buildings scene's finished runs, newest last (a few kept).
    pub rows: Vec<RowOutput>,
    /// The last row spec the solver refused, and its one line.
    pub row_error: Option<(RowSpec, String)>,
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
        let Need {
            runs,
            spectrum,
            map,
            risk,
            row,
        } = need;
        let row = row.filter(|r| {
            !self.rows.iter().any(|o| o.spec == *r)
                && !self.row_error.as_ref().is_some_and(|(s, _)| s == r)
        });
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
        let map = map.filter(|m| {
            !self.map.as_ref().is_some_and(|st| {
                st.spec == *m && (st.done() == st.cells.len() || st.error.is_some())
            })
        });
        if let Some(m) = &map {
            let cells = vec![None; m.columns() * m.rows()];
            match &mut self.map {
                // The same map again (a cancelled one): keep what is there.
                Some(st) if st.spec == *m => {}
                _ => {
                    self.map = Some(MapState {
                        spec: m.clone(),
                        cells,
                        error: None,
                    })
                }
            }
        }
        // A finished picture of the same spec is kept; another spec starts
        // afresh (the previous picture stays on screen, marked, until the
        // first pass of the new one arrives).
        let risk = risk.filter(|r| {
            !self
                .risk
                .as_ref()
                .is_some_and(|st| st.spec == *r && st.finished())
        });
        if let Some(r) = &risk {
            match &mut self.risk {
                Some(st) if st.spec == *r => {}
                Some(st) => {
                    st.spec = r.clone();
                    st.full = false;
                    st.stale = st.picture.is_some();
                    st.error = None;
                }
                None => {
                    self.risk = Some(RiskState {
                        spec: r.clone(),
                        picture: None,
                        full: false,
                        stale: false,
                        error: None,
                    })
                }
            }
        }
        self.computing = !runs.is_empty()
            || spectrum.is_some()
            || map.is_some()
            || risk.is_some()
            || row.is_some();
        if !self.computing {
            return None;
        }
        Some(Job {
            generation: self.generation,
            runs,
            spectrum,
            map,
            risk,
            row,
        })
    }

    /// The row runs to show: those asked for if computed, else the latest
    /// (shown while the new ones compute, or when they were refused).
    pub fn shown_row(&self) -> Option<&RowOutput> {
        let asked = self.requested.as_ref().and_then(|n| n.row.as_ref());
        asked
            .and_then(|r| self.rows.iter().rev().find(|o| o.spec == *r))
            .or_else(|| self.rows.last())
    }

    /// The solver's line on the row asked for, when it refused it.
    pub fn row_refusal(&self) -> Option<&str> {
        let asked = self.requested.as_ref().and_then(|n| n.row.as_ref())?;
        self.row_error
            .as_ref()
            .filter(|(s, _)| s == asked)
            .map(|(_, e)| e.as_str())
    }

    fn cached(&self, spec: &RunSpec) -> Option<&RunOutput> {
        self.results.iter().rev().find(|o| o.spec == *spec)
    }

    fn requested_spec(&self, slot: Slot) -> Option<&RunSpec> {
        self.requested
            .as_ref()
            .and_then(|need| need.runs.iter().find(|s| s.slot == slot))
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
            Output::MapRows { rows, .. } => {
                if let Some(m) = self.map.as_mut() {
                    let nx = m.spec.columns();
                    for (r, cells) in rows {
                        for (slot, c) in m.cells[r * nx..].iter_mut().zip(cells) {
                            *slot = Some(c);
                        }
                    }
                }
            }
            Output::MapError { message, .. } => {
                if let Some(m) = self.map.as_mut() {
                    m.error = Some(message);
                }
            }
            Output::Risk { output, .. } => {
                if let Some(st) = self.risk.as_mut() {
                    match output {
                        RiskOutput::Picture { picture, full } => {
                            st.picture = Some(*picture);
                            st.full = full;
                            st.stale = false;
                        }
                        RiskOutput::Error(message) => st.error = Some(message),
                    }
                }
            }
            Output::Row { output, .. } => match output {
                Ok(output) => {
                    self.rows.retain(|o| o.spec != output.spec);
                    self.rows.push(*output);
                    if self.rows.len() > ROW_CACHE {
                        self.rows.remove(0);
                    }
                }
                Err(refused) => self.row_error = Some(refused),
            },
            Output::Done { .. } => self.computing = false,
        }
    }
}
