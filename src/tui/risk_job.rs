//! The risk scene's computation on the worker thread: the active set's
//! buildings over a suite ([`crate::analysis::risk`]), in two passes. A
//! coarse pass (the first [`COARSE_RECORDS`] records at
//! [`COARSE_LEVELS`] of the levels) appears within a fraction of a
//! second of a key, then the whole suite at every level; a newer job
//! stops either pass between two runs (as the spectrum stops between
//! chunks of points).

use std::cell::RefCell;

use super::physical::Base;
use crate::analysis::fragility::bridging_levels;
use crate::analysis::risk::{Kept, RiskPicture, RowRiskCase, risk, row_risk};
use crate::analysis::suite::{Scaling, SuiteCase};
use crate::model::buildings::Row;
use crate::model::buildings::matrices::periods;
use crate::model::intensity::IntensityMeasure;
use crate::model::physical::{G, Physical};
use crate::model::suite::{SuiteMember, SuiteSpec};
use crate::model::{Method, Params};

/// The suite the risk scene runs.
pub const SUITE: &str = "synthetic:20";

/// The base at which the Π-groups of a set without a `[physical]` table
/// become buildings: a_p = 0.5 g, ω_p = 2π rad/s, m2 = 1e6 kg (those of
/// the preset two-buildings).
pub const REFERENCE: Base = Base {
    ap: 0.5 * G,
    omega_p: std::f64::consts::TAU,
    m2: 1e6,
};

/// The design level at start, its step and its range (g).
pub const DESIGN_LEVEL: f64 = 0.3;
pub const DESIGN_STEP: f64 = 0.05;
pub const DESIGN_RANGE: [f64; 2] = [0.05, 2.0];

/// The IDA's levels: k/5 of the design level, k = 1 … 10 (the design
/// level is the fifth), each rounded to 12 significant digits as
/// `--levels` rounds its grid.
pub fn levels(design_level: f64) -> Vec<f64> {
    (1..=10)
        .map(|k| {
            let x = design_level * k as f64 / 5.0;
            format!("{x:.11e}").parse().unwrap_or(x)
        })
        .collect()
}

/// The design level one step up (`up`) or down, within [`DESIGN_RANGE`].
pub fn stepped(level: f64, up: bool) -> f64 {
    let steps = (level / DESIGN_STEP).round() + if up { 1.0 } else { -1.0 };
    let x = (steps * DESIGN_STEP).clamp(DESIGN_RANGE[0], DESIGN_RANGE[1]);
    format!("{x:.11e}").parse().unwrap_or(x)
}

/// Sa at the left building's period T1 = 2π/ω1, rounded to 0.01 s (as
/// `--im sa:0.95` names it), within (0, 10] s.
pub fn measure_of(physical: &Physical) -> IntensityMeasure {
    let t1 = std::f64::consts::TAU / physical.omega[0];
    let period = ((t1 * 100.0).round() / 100.0).clamp(0.01, 10.0);
    IntensityMeasure::Sa { period }
}

/// The risk picture of a set: its buildings are the preset's base (a_p,
/// ω_p, m2 of `[physical]`) applied to the set's current Π-groups, so a
/// nudged gap, period or mass moves them; without a base, [`REFERENCE`].
/// Records are scaled to Sa(T1) ([`measure_of`]), or to their PGA with `pga`.
pub fn spec_of(params: &Params, base: Option<Base>, design_level: f64, pga: bool) -> RiskSpec {
    let physical = base.unwrap_or(REFERENCE).physical(params);
    let measure = if pga {
        IntensityMeasure::Pga
    } else {
        measure_of(&physical)
    };
    RiskSpec {
        suite: SUITE.to_string(),
        physical,
        reference: base.is_none(),
        settings: params.clone(),
        measure,
        design_level,
        levels: levels(design_level),
        row: None,
    }
}

/// The risk picture of joint `joint` (0-based) of `row`: pounding counted
/// at that joint, the drift of its taller building followed, records
/// scaled to Sa at that building's T1 (rounded to 0.01 s) or to their PGA.
pub fn row_spec(row: &Row, joint: usize, design_level: f64, pga: bool) -> RiskSpec {
    let building = RowRiskCase::taller_of(row, joint);
    let t1 = periods(&row.buildings[building])[0];
    let measure = if pga {
        IntensityMeasure::Pga
    } else {
        IntensityMeasure::Sa {
            period: ((t1 * 100.0).round() / 100.0).clamp(0.01, 10.0),
        }
    };
    let mut spec = spec_of(&Params::default(), None, design_level, pga);
    spec.reference = false;
    spec.measure = measure;
    spec.row = Some(RowRiskCase {
        row: row.clone(),
        joint,
        building,
        measure,
    });
    spec
}

/// Records of the coarse pass.
pub const COARSE_RECORDS: usize = 6;
/// Indices into the levels of the coarse pass (those that exist).
pub const COARSE_LEVELS: [usize; 4] = [1, 4, 7, 9];

/// A risk picture to compute (SPEC §11, §12).
#[derive(Debug, Clone, PartialEq)]
pub struct RiskSpec {
    /// The suite, as `--suite` takes it (`synthetic:20`).
    pub suite: String,
    /// The buildings in SI.
    pub physical: Physical,
    /// Whether the buildings are the set's Π-groups at the reference base
    /// (the set's preset has no `[physical]` table).
    pub reference: bool,
    /// Contact law, Δτ, free cycles… of the set (the method is exact).
    pub settings: Params,
    pub measure: IntensityMeasure,
    /// The design level X (g) of the P(pounding) curve.
    pub design_level: f64,
    /// The IDA's levels (g), ascending.
    pub levels: Vec<f64>,
    /// A joint of a row of buildings instead of the pair (SPEC §13).
    pub row: Option<RowRiskCase>,
}

impl RiskSpec {
    /// The levels of the coarse pass.
    pub fn coarse_levels(&self) -> Vec<f64> {
        COARSE_LEVELS
            .iter()
            .filter_map(|&i| self.levels.get(i).copied())
            .collect()
    }
}

/// What a pass reports.
#[derive(Debug, Clone)]
pub enum RiskOutput {
    /// A picture: `full` once every record ran at every level.
    Picture {
        picture: Box<RiskPicture>,
        full: bool,
    },
    /// Why there is no picture (one line).
    Error(String),
}

thread_local! {
    /// The last suite loaded on this thread: a suite is read once, not per key.
    static MEMBERS: RefCell<Option<(String, Vec<SuiteMember>)>> = const { RefCell::new(None) };
}

/// The members of `suite`, loaded once per thread.
fn members(suite: &str) -> Result<Vec<SuiteMember>, String> {
    MEMBERS.with_borrow_mut(|cache| {
        if let Some((name, m)) = cache.as_ref()
            && name == suite
        {
            return Ok(m.clone());
        }
        let m = SuiteSpec::parse(suite)
            .and_then(|s| s.load())
            .map_err(|e| e.to_string())?;
        *cache = Some((suite.to_string(), m.clone()));
        Ok(m)
    })
}

/// The passes of `spec` (coarse, full, and the full one again with
/// bridging levels when its fit needs them) while `current()` holds; false if stopped.
pub fn run_risk(spec: &RiskSpec, current: &dyn Fn() -> bool, send: &dyn Fn(RiskOutput)) -> bool {
    let members = match members(&spec.suite) {
        Ok(m) => m,
        Err(e) => {
            send(RiskOutput::Error(e));
            return true;
        }
    };
    let case = SuiteCase {
        physical: spec.physical,
        settings: Params {
            method: Method::Exact,
            ..spec.settings.clone()
        },
        scaling: Scaling {
            measure: spec.measure,
            level: None,
            collective: false,
        },
    };
    let coarse = members.len() > COARSE_RECORDS || spec.levels.len() > COARSE_LEVELS.len();
    let passes = [
        coarse.then(|| {
            let few = &members[..COARSE_RECORDS.min(members.len())];
            (few, spec.coarse_levels(), false)
        }),
        Some((&members[..], spec.levels.clone(), true)),
    ];
    // Each pass runs only what the passes before it did not ([`Kept`]).
    let (mut row_kept, mut pair_kept) = (Kept::default(), Kept::default());
    for (members, levels, full) in passes.into_iter().flatten() {
        if !current() {
            return false;
        }
        let mut pass = |levels: &[f64]| {
            let design = spec.design_level;
            match &spec.row {
                Some(row) => row_risk(row, members, design, levels, current, &mut row_kept)
                    .map_err(|e| e.to_string()),
                None => risk(&case, members, design, levels, current, &mut pair_kept)
                    .map_err(|e| e.to_string()),
            }
        };
        let fit = match pass(&levels) {
            Ok(Some(picture)) => {
                let fit = picture.fragility;
                send(RiskOutput::Picture {
                    picture: Box::new(picture),
                    full,
                });
                fit
            }
            Ok(None) => return false,
            Err(e) => {
                send(RiskOutput::Error(e));
                return true;
            }
        };
        // Outcomes that flip between two levels leave the fit without a β:
        // the full pass runs once more with levels inside that bracket
        // (SPEC §12), and its picture replaces the first.
        let bridging = bridging_levels(&levels, &fit, BRIDGING_LEVELS);
        if full && !bridging.is_empty() {
            let mut more = levels.clone();
            more.extend(bridging);
            more.sort_by(f64::total_cmp);
            more.dedup();
            match pass(&more) {
                Ok(Some(picture)) => send(RiskOutput::Picture {
                    picture: Box::new(picture),
                    full,
                }),
                Ok(None) => return false,
                Err(e) => send(RiskOutput::Error(e)),
            }
        }
    }
    true
}

/// Levels added inside the bracket where the outcomes flip.
pub const BRIDGING_LEVELS: usize = 6;
