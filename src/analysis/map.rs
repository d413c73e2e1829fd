//! Region maps: the spectrum's question over two parameters at once
//! (SPEC §7). Each cell of the plane (x, y) is one parameter set, run with
//! pounding and without it (`gap = inf`); it reports the peaks of both
//! structures, their amplification ratios Π_u/Π_u,free, the left structure's
//! region, the impacts, the extreme pounding forces and, from the
//! no-pounding run, the gap that prevents pounding (SPEC §11).
//!
//! An axis is any Π key of the parameter table or `mu` = Π_ω2/Π_ω1. As in a
//! spectrum, Π_ω2 follows Π_ω1 at the frequency ratio μ (the base set's,
//! unless `mu` is an axis); an `omega2` axis sets Π_ω2 itself, and with
//! neither axis a frequency Π_ω2 keeps the base's value.
//!
//! The cells are computed as the spectrum engine computes points, as one
//! [`super::batch`]: the pounding runs and the baselines still missing, one
//! per distinct [`BaselineKey`], so an axis that the free motion does not
//! depend on (Π_d, Π_e, Π_ωcon) costs no baseline runs.

use std::collections::HashSet;
use std::fmt;

use serde::{Deserialize, Serialize};

use super::baseline::NewBaseline;
use super::baseline::{BaselineCache, BaselineKey, FreePeaks};
use super::batch::run_points;
use super::gap::from_max_relative;
use super::spectrum::{Region, eight_peaks};
use crate::model::family::MU;
use crate::model::grid::{Grid, MAX_GRID_POINTS};
use crate::model::params::{Kind, echo, field, is_pi};
use crate::model::{ParamError, Params};
use crate::solver::exact::ContactExtremes;
use crate::solver::{RunResult, StructurePeaks};

/// Most cells one map may have: the product of two long axes is refused
/// before any run (a map holds every cell in memory).
pub const MAX_CELLS: usize = 1_000_000;

/// A bad axis or map, as one line naming the flag, the value and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct MapError(pub String);

/// One axis of a map: a key (a Π key or `mu`) over an even grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    pub key: &'static str,
    pub grid: Grid,
}

impl Axis {
    /// Parses `KEY=START:STOP:STEP` as given to `flag` (`--x`, `--y`). Both
    /// ends must lie in the key's range (μ: finite and > 0), STEP > 0, at
    /// most [`MAX_GRID_POINTS`] values.
    pub fn parse(flag: &str, text: &str) -> Result<Axis, MapError> {
        let bad = |why: String| MapError(format!("{flag} `{}`: {why}", echo::text(text)));
        let form = "expected KEY=START:STOP:STEP, e.g. omega1=0.1:3.0:0.02";
        let (key, grid) = text.split_once('=').ok_or_else(|| bad(form.into()))?;
        let key = axis_key(key.trim()).ok_or_else(|| {
            bad(format!(
                "unknown axis `{}`; an axis is mu or a Π key: {}",
                echo::text(key.trim()),
                pi_keys().join(", ")
            ))
        })?;
        let parts: Vec<&str> = grid.split(':').map(str::trim).collect();
        let [start, stop, step] = parts[..] else {
            return Err(bad(form.into()));
        };
        let [Some(start), Some(stop), Some(step)] =
            [start, stop, step].map(|s| s.parse::<f64>().ok())
        else {
            return Err(bad("START, STOP and STEP must be numbers".into()));
        };
        if !(start.is_finite() && stop.is_finite() && step.is_finite()) {
            return Err(bad("START, STOP and STEP must be finite numbers".into()));
        }
        if stop < start {
            return Err(bad("must have START <= STOP".into()));
        }
        if let Some(allowed) = [start, stop]
            .into_iter()
            .find_map(|v| check_value(key, v).err())
        {
            return Err(bad(format!(
                "START and STOP are values of {key}, which {allowed}"
            )));
        }
        if step <= 0.0 {
            return Err(bad("STEP must be > 0".into()));
        }
        if (stop - start) / step + 1.0 > MAX_GRID_POINTS as f64 {
            return Err(bad(format!("has more than {MAX_GRID_POINTS} points")));
        }
        Ok(Axis {
            key,
            grid: Grid { start, stop, step },
        })
    }

    /// The axis values, START + i·STEP (rounded as a spectrum's Π_ω1 grid).
    pub fn values(&self) -> Vec<f64> {
        self.grid.values()
    }

    pub fn len(&self) -> usize {
        self.grid.len()
    }

    pub fn is_empty(&self) -> bool {
        false
    }

    /// The paper's symbol of the key.
    pub fn symbol(&self) -> &'static str {
        if self.key == MU {
            "μ"
        } else {
            field(self.key).map_or(self.key, |f| f.symbol)
        }
    }
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}={}", self.key, self.grid)
    }
}

/// The Π keys that are numbers, in table order.
fn pi_keys() -> Vec<&'static str> {
    crate::model::params::FIELDS
        .iter()
        .filter(|f| is_pi(f.key) && matches!(f.kind, Kind::Number { .. }))
        .map(|f| f.key)
        .collect()
}

/// `key` as an axis key, if it is one.
fn axis_key(key: &str) -> Option<&'static str> {
    if key == MU {
        return Some(MU);
    }
    pi_keys().into_iter().find(|k| *k == key)
}

/// Checks one axis value against its key's range; the error says what is allowed.
fn check_value(key: &str, v: f64) -> Result<(), String> {
    if key == MU {
        return (v.is_finite() && v > 0.0)
            .then_some(())
            .ok_or_else(|| "must be a finite number > 0".to_string());
    }
    let f = field(key).expect("an axis key is a table key");
    f.check_number(v).map(|_| ()).map_err(|_| f.allowed())
}

/// Sets a numeric key of `p`.
fn set_number(p: &mut Params, key: &str, v: f64) {
    if let Some(f) = field(key)
        && let Kind::Number { set, .. } = f.kind
    {
        set(p, v);
    }
}

/// `base` with each axis key set to its value. Where Π_ω1 or μ is an axis,
/// Π_ω2 = μ Π_ω1 (μ = `mu` unless it is an axis); an `omega2` axis sets Π_ω2
/// itself, and otherwise Π_ω2 keeps the base's value, bit for bit.
pub fn set_axes(base: &Params, mu: f64, values: &[(&str, f64)]) -> Params {
    let mut p = base.clone();
    let mut mu = mu;
    let mut follows = false;
    for &(key, v) in values {
        match key {
            MU => {
                mu = v;
                follows = true;
            }
            "omega1" => {
                p.omega1 = v;
                follows = true;
            }
            _ => set_number(&mut p, key, v),
        }
    }
    if follows && !values.iter().any(|(k, _)| *k == "omega2") {
        p.omega2 = mu * p.omega1;
    }
    p
}

/// The parameter sets along one axis from `base` (Π_ω2 = μ Π_ω1 where
/// Π_ω1 is the axis, as in a map), each validated as a whole.
pub fn line(base: &Params, mu: f64, axis: &Axis) -> Result<Vec<(f64, Params)>, MapError> {
    axis.values()
        .into_iter()
        .map(|v| {
            let p = set_axes(base, mu, &[(axis.key, v)]);
            p.validate().map(|()| (v, p)).map_err(|e: ParamError| {
                MapError(format!("at {} = {}: {e}", axis.key, echo::number(v)))
            })
        })
        .collect()
}

/// What a map is asked for: the base parameters, the frequency ratio μ
/// (Π_ω2 = μ Π_ω1 where Π_ω1 is an axis and μ is not) and the two axes.
#[derive(Debug, Clone, PartialEq)]
pub struct MapPlan {
    pub base: Params,
    /// μ of the cells when `mu` is not an axis.
    pub mu: f64,
    pub x: Axis,
    pub y: Axis,
}

impl MapPlan {
    /// Checks the axes against each other and every cell's parameters
    /// (validated as a whole, so Δτ resolves the highest frequency).
    pub fn new(base: Params, mu: f64, x: Axis, y: Axis) -> Result<MapPlan, MapError> {
        if x.key == y.key {
            return Err(MapError(format!(
                "--x {x} and --y {y}: the two axes must be different keys"
            )));
        }
        let keys = [x.key, y.key];
        if keys.contains(&MU) && keys.contains(&"omega2") {
            return Err(MapError(format!(
                "--x {x} and --y {y}: mu and omega2 cannot both be axes \
                 (omega2 = mu·omega1); sweep omega1 and mu, or omega1 and omega2"
            )));
        }
        let cells = x.len().saturating_mul(y.len());
        if cells > MAX_CELLS {
            return Err(MapError(format!(
                "--x {x} and --y {y}: {} × {} = {cells} cells; at most {MAX_CELLS} are allowed",
                x.len(),
                y.len()
            )));
        }
        let plan = MapPlan { base, mu, x, y };
        if keys.contains(&"omega1") && !keys.contains(&MU) {
            check_value(MU, mu)
                .map_err(|allowed| MapError(format!("mu = {}: {allowed}", echo::number(mu))))?;
        }
        for yv in y.values() {
            for xv in x.values() {
                plan.at(xv, yv).validate().map_err(|e: ParamError| {
                    MapError(format!(
                        "at {} = {}, {} = {} of the map: {e}",
                        x.key,
                        echo::number(xv),
                        y.key,
                        echo::number(yv)
                    ))
                })?;
            }
        }
        Ok(plan)
    }

    /// The parameters of the cell (x, y).
    pub fn at(&self, x: f64, y: f64) -> Params {
        set_axes(&self.base, self.mu, &[(self.x.key, x), (self.y.key, y)])
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.x.len() * self.y.len()
    }
}

/// One cell of a map.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MapCell {
    /// The values of the x and y axes.
    pub x: f64,
    pub y: f64,
    pub omega1: f64,
    pub omega2: f64,
    /// With pounding.
    pub left: StructurePeaks,
    pub right: StructurePeaks,
    /// The no-pounding run (`gap = inf`).
    pub free_left: StructurePeaks,
    pub free_right: StructurePeaks,
    /// Π_u1/Π_u1,free.
    pub left_amplification: f64,
    /// Π_u2/Π_u2,free.
    pub right_amplification: f64,
    /// The left structure's region (SPEC §7).
    pub region: Region,
    pub impacts: usize,
    /// Largest pounding force (0 without contact).
    pub max_force: f64,
    /// Smallest pounding force (below 0: the element pulled).
    pub min_force: f64,
    /// Π_d,min of the no-pounding run (SPEC §11); `None` with Newmark.
    pub min_gap: Option<f64>,
    /// False when either run stopped before τ_end.
    pub completed: bool,
}

impl MapCell {
    /// The eight peaks with and without pounding, in the order of [`eight_peaks`].
    pub fn peaks(&self) -> [f64; 8] {
        eight_peaks(
            [&self.left, &self.right],
            [&self.free_left, &self.free_right],
        )
    }

    /// Combines a pounding run with its baseline (SPEC §7).
    pub fn combine(
        x: f64,
        y: f64,
        p: &Params,
        with: &RunResult,
        without: &FreePeaks,
        free_completed: bool,
    ) -> MapCell {
        let ratio =
            |a: &StructurePeaks, b: &StructurePeaks| a.peak_displacement / b.peak_displacement;
        MapCell {
            x,
            y,
            omega1: p.omega1,
            omega2: p.omega2,
            left: with.left,
            right: with.right,
            free_left: without.left,
            free_right: without.right,
            left_amplification: ratio(&with.left, &without.left),
            right_amplification: ratio(&with.right, &without.right),
            region: Region::classify(with.left.peak_displacement, without.left.peak_displacement),
            impacts: with.impacts.len(),
            max_force: with.max_force,
            min_force: with.min_force,
            min_gap: without.max_relative_displacement.map(from_max_relative),
            completed: with.completed && free_completed,
        }
    }
}

/// Computes the rows of the map at the y values `ys` (every x of each),
/// row after row, reusing and filling `cache`.
pub fn compute_rows(plan: &MapPlan, ys: &[f64], cache: &mut MapCache) -> Vec<MapCell> {
    let xs = plan.x.values();
    let at: Vec<(f64, f64)> = ys
        .iter()
        .flat_map(|&y| xs.iter().map(move |&x| (x, y)))
        .collect();
    compute_cells(plan, &at, cache)
}

/// Computes the cells at the axis values `at` (x, y), in that order,
/// reusing and filling `cache`: any set of cells, such as a shard's.
pub fn compute_cells(plan: &MapPlan, at: &[(f64, f64)], cache: &mut MapCache) -> Vec<MapCell> {
    let cells: Vec<(f64, f64, Params)> = at.iter().map(|&(x, y)| (x, y, plan.at(x, y))).collect();

    let points: Vec<Params> = cells.iter().map(|(_, _, q)| q.clone()).collect();
    let batch = run_points(&points, ContactExtremes::Forces, |q| {
        cache.baselines.contains(q)
    });
    for b in &batch.baselines {
        cache.insert(&points[b.point], b);
    }
    let pounding = batch.pounding;

    cells
        .iter()
        .zip(pounding)
        .map(|((x, y, q), with)| {
            let (free, free_completed) = match &with {
                // A pounding run with no impact is its own baseline, bit for bit.
                Some(r) if r.impacts.is_empty() => (FreePeaks::of(r), r.completed),
                _ => cache.get(q),
            };
            let with = with.unwrap_or_else(|| free.as_run());
            MapCell::combine(*x, *y, q, &with, &free, free_completed)
        })
        .collect()
}

/// The whole map in one pass, row-major (y outer, x inner).
pub fn compute(plan: &MapPlan) -> (Vec<MapCell>, MapCache) {
    let mut cache = MapCache::default();
    let cells = compute_rows(plan, &plan.y.values(), &mut cache);
    (cells, cache)
}

/// The baselines of a map, and which of them did not reach τ_end.
#[derive(Debug, Clone, Default)]
pub struct MapCache {
    pub baselines: BaselineCache,
    incomplete: HashSet<BaselineKey>,
}

impl MapCache {
    /// Records the baseline of `p` from a run without contact: a pounding
    /// run that had no impact (`from_pounding`), or a no-pounding run.
    fn insert(&mut self, p: &Params, b: &NewBaseline) {
        if self.baselines.contains(p) {
            return;
        }
        if !b.completed {
            self.incomplete.insert(BaselineKey::of(p));
        }
        self.baselines.record(p, b);
    }

    fn get(&self, p: &Params) -> (FreePeaks, bool) {
        (
            self.baselines.get(p).unwrap_or_default(),
            !self.incomplete.contains(&BaselineKey::of(p)),
        )
    }
}

/// The left structure's regions along one row of a map (fixed y), as
/// maximal runs over x.
pub fn row_regions(row: &[MapCell]) -> Vec<super::spectrum::RegionRange> {
    super::spectrum::region_runs(row.iter().map(|c| (c.x, c.region)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    #[test]
    fn axes_parse_and_refuse() {
        let a = Axis::parse("--x", "omega1=0.1:3.0:0.02").unwrap();
        assert_eq!((a.key, a.len()), ("omega1", 146));
        assert_eq!(Axis::parse("--y", "mu=1:10:0.1").unwrap().len(), 91);
        let msg = |t: &str| Axis::parse("--x", t).unwrap_err().to_string();
        assert!(
            msg("bogus=1:2:1").contains("unknown axis `bogus`"),
            "{}",
            msg("bogus=1:2:1")
        );
        assert!(msg("model=1:2:1").contains("unknown axis"));
        assert!(msg("omega1=1:2").contains("expected KEY=START:STOP:STEP"));
        assert!(msg("omega1=2:1:0.1").contains("START <= STOP"));
        assert!(msg("omega1=1:2:0").contains("STEP must be > 0"));
        assert!(msg("mu=0:2:1").contains("must be a finite number > 0"));
        assert!(msg("restitution=0.5:2:0.5").contains("[0.001, 1]"));
        assert!(msg("gap=0:1:1e-9").contains("more than"));
    }

    #[test]
    fn cells_follow_mu() {
        let x = Axis::parse("--x", "omega1=0.5:1:0.5").unwrap();
        let y = Axis::parse("--y", "mu=2:3:1").unwrap();
        let plan = MapPlan::new(SET1, SET1.mu(), x, y).unwrap();
        let p = plan.at(0.5, 3.0);
        assert_eq!((p.omega1, p.omega2), (0.5, 1.5));
        // Without a mu axis, the base set's μ holds.
        let y = Axis::parse("--y", "gap=0.1:0.2:0.1").unwrap();
        let plan = MapPlan::new(SET1, SET1.mu(), x, y).unwrap();
        let p = plan.at(1.0, 0.1);
        assert_eq!((p.omega2, p.gap), (SET1.mu(), 0.1));
        // Neither frequency an axis: Π_ω2 is the base's, bit for bit.
        let gap = Axis::parse("--x", "gap=0.1:0.2:0.1").unwrap();
        let e = Axis::parse("--y", "restitution=0.5:0.6:0.1").unwrap();
        let p = MapPlan::new(SET1, SET1.mu(), gap, e).unwrap().at(0.2, 0.6);
        assert_eq!(
            (p.omega1, p.omega2, p.gap, p.restitution),
            (1.05, 2.36, 0.2, 0.6)
        );
        let bad = MapPlan::new(SET1, SET1.mu(), x, x).unwrap_err().to_string();
        assert!(bad.contains("different keys"), "{bad}");
    }
}
