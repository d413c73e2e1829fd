//! Suite maps: a study over two quantities of the buildings (SPEC §12).
//! Each cell of the plane (x, y) is the subject with both quantities set,
//! run under every record of a suite scaled as the suite asks, with
//! contact and with every joint open, as `pounding suite` runs it. Axes
//! are physical because a suite is: every record shakes the same buildings.
//!
//! The cells are planned, run and sharded over any [`Subject`], written
//! once here; what a cell reports from its records' runs is the
//! subject's ([`MapSubject::cell`]):
//!
//! - the physical pair ([`pair`]): the keys of its `[physical]` table, and
//!   P(pounding), the median amplification u1/u1,free of the left
//!   building's drift and the median Π_d,min;
//! - a row ([`row`]): any key `--set` takes (`joint1.gap`, `link1.damping`,
//!   `joint1.bumper.stiffness`, `frame.damping`, …), and P(pounding) per
//!   joint, the median peak drift ratio and floor acceleration per
//!   building and the median peak force per link: what a retrofit buys.

pub mod pair;
pub mod row;

use serde::Serialize;
use serde::de::DeserializeOwned;

use super::ida::over_levels;
use super::subject::Subject;
use super::suite::{Scaling, scales};
use crate::model::params::echo;
use crate::model::suite::SuiteMember;

pub use pair::{KEYS, PhysicalAxis, SuiteMapCell, cell_cases, set};
pub use row::{RowMapCell, row_axis};

/// Most points on one axis, and most cells × records of one map.
pub const MAX_AXIS_POINTS: usize = 1000;
pub const MAX_RUNS: usize = 10_000_000;

/// One axis: a key over an even grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MapAxis {
    pub key: String,
    pub values: Vec<f64>,
}

impl MapAxis {
    /// Parses `KEY=START:STOP:STEP` given to `flag`: finite START ≤ STOP,
    /// STEP > 0, at most [`MAX_AXIS_POINTS`] values. `key` checks the key
    /// (and returns why not), `hint` ends every message: what KEY may be.
    /// The values are START + k·STEP rounded to twelve significant digits,
    /// so that 0.1 + 2 × 0.1 is 0.3.
    pub fn parse(
        flag: &str,
        text: &str,
        hint: &str,
        key: impl Fn(&str) -> Result<(), String>,
    ) -> Result<MapAxis, String> {
        let bad = |why: &str| {
            format!(
                "{flag} `{}`: {why}; write KEY=START:STOP:STEP with KEY {hint}",
                echo::text(text)
            )
        };
        let (name, grid) = text.split_once('=').ok_or_else(|| bad("no `=`"))?;
        let name = name.trim();
        key(name).map_err(|why| bad(&why))?;
        let parts: Vec<Option<f64>> = grid.split(':').map(|t| t.trim().parse().ok()).collect();
        let [Some(start), Some(stop), Some(step)] = parts[..] else {
            return Err(bad("expected three numbers"));
        };
        if !(start.is_finite() && stop.is_finite() && step.is_finite())
            || step <= 0.0
            || stop < start
        {
            return Err(bad("needs finite START <= STOP and STEP > 0"));
        }
        let count = ((stop - start) / step + 1e-9).floor() + 1.0;
        if count > MAX_AXIS_POINTS as f64 {
            return Err(bad(&format!("more than {MAX_AXIS_POINTS} points")));
        }
        let values = (0..count as usize)
            .map(|k| {
                let v = start + k as f64 * step;
                format!("{v:.11e}").parse().unwrap_or(v)
            })
            .collect();
        Ok(MapAxis {
            key: name.to_string(),
            values,
        })
    }
}

/// A subject a map can be drawn over: what one cell reads of each
/// record's runs, and reports of them.
pub trait MapSubject: Subject + Clone + std::fmt::Debug {
    /// What a cell reads of one planned record: the pair's run with and
    /// without contact; of a row, the run with contact alone (every
    /// quantity its cell reports is of that run).
    type Sample: Send;
    /// What a worker keeps from record to record.
    type MapCaches: Default + Send;
    /// One cell's results, as the map reports and a shard's part carries them.
    type Cell: Clone + std::fmt::Debug + Serialize + DeserializeOwned + Send;

    /// Runs one planned record of the cell.
    fn sample(
        &self,
        member: &SuiteMember,
        plan: &Self::Plan,
        caches: &mut Self::MapCaches,
    ) -> Result<Self::Sample, Self::Error>;

    /// The cell at (x, y) from its samples, one per record in suite order.
    fn cell(&self, x: f64, y: f64, samples: &[Self::Sample]) -> Self::Cell;
}

/// The cells row after row (y), x along each row: `make(x, y)` is the
/// subject with both quantities set, or why it cannot be.
pub fn cells_of<S, E>(
    x: &MapAxis,
    y: &MapAxis,
    mut make: impl FnMut(f64, f64) -> Result<S, E>,
) -> Result<Vec<(f64, f64, S)>, E> {
    let mut cells = Vec::with_capacity(x.values.len() * y.values.len());
    for &yv in &y.values {
        for &xv in &x.values {
            cells.push((xv, yv, make(xv, yv)?));
        }
    }
    Ok(cells)
}

/// Every cell's plans, or the cell (x, y) whose record failed and why.
pub type CellPlans<S> = Result<Vec<Vec<<S as Subject>::Plan>>, (f64, f64, <S as Subject>::Error)>;

/// Plans every record in every cell before any run, so that a building
/// out of range (a Δτ too coarse for a short period, …) fails at once and
/// names the record and cell. Each record's scale is measured once for
/// every cell of one scaling: it depends on the records alone.
pub fn plan_cells<S: Subject>(cells: &[(f64, f64, S)], members: &[SuiteMember]) -> CellPlans<S> {
    let mut measured: Option<(Scaling, Vec<(f64, f64)>)> = None;
    let mut plans = Vec::with_capacity(cells.len());
    for (x, y, subject) in cells {
        let scaling = *subject.scaling();
        if measured.as_ref().is_none_or(|(s, _)| *s != scaling) {
            let at = scales(members, &scaling).map_err(|e| (*x, *y, e.into()))?;
            measured = Some((scaling, at));
        }
        let at = &measured.as_ref().expect("measured above").1;
        plans.push(
            members
                .iter()
                .zip(at)
                .map(|(m, &(scale, intensity))| subject.plan_at(m, scale, intensity))
                .collect::<Result<_, _>>()
                .map_err(|e| (*x, *y, e))?,
        );
    }
    Ok(plans)
}

/// Computes the cells `range` of a planned map, in order
/// ([`compute_listed`]).
pub fn compute_cells<S: MapSubject>(
    cells: &[(f64, f64, S)],
    plans: &[Vec<S::Plan>],
    members: &[SuiteMember],
    range: std::ops::Range<usize>,
    done: &(dyn Fn() + Sync),
) -> Result<Vec<S::Cell>, S::Error> {
    compute_listed(cells, plans, members, &range.collect::<Vec<_>>(), done)
}

/// The cells `list` (indices, any set, such as a shard's), in that order:
/// every record of each cell, in parallel over (cell, record) pairs as
/// one pool of work, each worker keeping its caches; or the first failed
/// run in that order. `done` is told of each finished record.
pub fn compute_listed<S: MapSubject>(
    cells: &[(f64, f64, S)],
    plans: &[Vec<S::Plan>],
    members: &[SuiteMember],
    list: &[usize],
    done: &(dyn Fn() + Sync),
) -> Result<Vec<S::Cell>, S::Error> {
    let runs = over_levels(
        list.len(),
        members.len(),
        S::MapCaches::default,
        |caches, l, j| {
            let c = list[l];
            let sample = cells[c].2.sample(&members[j], &plans[c][j], caches);
            done();
            sample
        },
    );
    list.iter()
        .zip(runs)
        .map(|(&c, at)| {
            let at: Vec<S::Sample> = at.into_iter().collect::<Result<_, _>>()?;
            let (x, y, subject) = &cells[c];
            Ok(subject.cell(*x, *y, &at))
        })
        .collect()
}
