//! Self-similarity (SPEC §8): the same spectrum at several excitation
//! levels a_p, in physical units and on the dimensionless master curve.
//!
//! Each level is converted to Π-groups on its own ([`Physical::to_params`])
//! and swept on its own, so the agreement of the dimensionless curves is
//! computed, not assumed. Dimensional peaks are X_max = Π_u a_p/ω_p² and
//! Ẋ_max = Π_v a_p/ω_p.

use super::baseline::BaselineCache;
use super::sweep::{Curve, CurveSpec, sweep};
use crate::model::physical::Physical;
use crate::model::{ParamError, Params};

/// One excitation level: its physical system, Π-groups and spectrum.
#[derive(Debug, Clone, PartialEq)]
pub struct Level {
    pub physical: Physical,
    pub params: Params,
    pub curve: Curve,
}

impl Level {
    /// Metres per unit of Π_u at this level.
    pub fn length_scale(&self) -> f64 {
        self.physical.length_scale()
    }

    /// Metres per second per unit of Π_v at this level.
    pub fn velocity_scale(&self) -> f64 {
        self.physical.velocity_scale()
    }
}

/// Computes the spectrum of `physical` at each amplitude of `levels` (m/s²)
/// on the Π_ω1 grid `omega1` with frequency ratio `mu`; `similar` scales
/// yield displacements and gap with a_p (see [`Physical::at_level`]).
pub fn study(
    physical: &Physical,
    settings: &Params,
    levels: &[f64],
    omega1: &[f64],
    mu: f64,
    similar: bool,
) -> Result<Vec<Level>, ParamError> {
    let systems: Vec<(Physical, Params)> = levels
        .iter()
        .map(|&ap| {
            let phys = physical.at_level(ap, similar);
            phys.to_params(settings).map(|p| (phys, p))
        })
        .collect::<Result<_, _>>()?;
    let specs: Vec<CurveSpec> = systems
        .iter()
        .map(|(_, p)| CurveSpec {
            member: None,
            params: p.clone(),
            mu,
        })
        .collect();
    let curves = sweep(&specs, omega1, &mut BaselineCache::new());
    Ok(systems
        .into_iter()
        .zip(curves)
        .map(|((physical, params), curve)| Level {
            physical,
            params,
            curve,
        })
        .collect())
}

/// Largest relative difference of any dimensionless peak between any level
/// and the first (the master curve): round-off when the levels are similar.
pub fn master_curve_spread(levels: &[Level]) -> f64 {
    let Some(master) = levels.first() else {
        return 0.0;
    };
    let mut spread: f64 = 0.0;
    for level in &levels[1..] {
        for (a, b) in master.curve.points.iter().zip(&level.curve.points) {
            for (x, y) in a.peaks().iter().zip(b.peaks()) {
                spread = spread.max((x - y).abs() / x.abs().max(y.abs()).max(f64::MIN_POSITIVE));
            }
        }
    }
    spread
}
