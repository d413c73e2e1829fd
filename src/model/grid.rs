//! The Π_ω1 grid of a spectrum (SPEC §7), written `START:STOP:STEP`
//! (the default `0.1:3.0:0.01` has 291 points, both ends included).

use std::fmt;
use std::str::FromStr;

use super::params::{echo, field};

/// Most points one grid may have: keeps a typo (`0:3:1e-9`) from asking for
/// billions of runs.
pub const MAX_GRID_POINTS: usize = 100_000;

/// An evenly spaced grid of Π_ω1 values, START to STOP inclusive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    pub start: f64,
    pub stop: f64,
    pub step: f64,
}

impl Default for Grid {
    /// The paper's spectra: Π_ω1 from 0.1 to 3.0 by 0.01.
    fn default() -> Self {
        Grid {
            start: 0.1,
            stop: 3.0,
            step: 0.01,
        }
    }
}

/// Why a grid text was refused: a one-line message naming the value and the allowed form.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`omega1` grid = {text}: {allowed}")]
pub struct GridError {
    /// The grid as written, cut and escaped for one line.
    pub text: String,
    pub allowed: String,
}

impl Grid {
    /// Checks the ranges: START ≤ STOP both within `omega1`'s range of the
    /// parameter table, STEP > 0, at most [`MAX_GRID_POINTS`] points.
    pub fn new(start: f64, stop: f64, step: f64) -> Result<Grid, GridError> {
        let g = Grid { start, stop, step };
        let bad = |allowed: &str| GridError {
            text: g.to_string(),
            allowed: allowed.to_string(),
        };
        if !(start.is_finite() && stop.is_finite() && step.is_finite()) {
            return Err(bad("START, STOP and STEP must be finite numbers"));
        }
        if stop < start {
            return Err(bad("must have START <= STOP"));
        }
        let omega1 = field("omega1").expect("omega1 is a key");
        if omega1.check_number(start).is_err() || omega1.check_number(stop).is_err() {
            return Err(bad(&format!(
                "START and STOP are values of omega1, which {}",
                omega1.allowed()
            )));
        }
        if step <= 0.0 {
            return Err(bad("STEP must be > 0"));
        }
        if (stop - start) / step + 1.0 > MAX_GRID_POINTS as f64 {
            return Err(bad("has more than 100000 points"));
        }
        Ok(g)
    }

    /// Number of points: ⌊(STOP − START)/STEP⌉ + 1, the end kept when it
    /// lies on the grid to within round-off.
    pub fn len(&self) -> usize {
        ((self.stop - self.start) / self.step + 1e-9).floor() as usize + 1
    }

    pub fn is_empty(&self) -> bool {
        false
    }

    /// The Π_ω1 values, START + i·STEP, rounded to 12 decimals so that
    /// `0.1 + 2·0.01` reads as 0.12 in every output.
    pub fn values(&self) -> Vec<f64> {
        (0..self.len())
            .map(|i| ((self.start + i as f64 * self.step) * 1e12).round() / 1e12)
            .collect()
    }
}

impl fmt::Display for Grid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}",
            echo::number(self.start),
            echo::number(self.stop),
            echo::number(self.step)
        )
    }
}

impl FromStr for Grid {
    type Err = GridError;

    fn from_str(text: &str) -> Result<Grid, GridError> {
        let bad = |allowed: &str| GridError {
            text: echo::text(text),
            allowed: allowed.to_string(),
        };
        let parts: Vec<&str> = text.split(':').map(str::trim).collect();
        let [start, stop, step] = parts[..] else {
            return Err(bad("expected START:STOP:STEP, e.g. 0.1:3.0:0.01"));
        };
        let num = |s: &str| {
            s.parse::<f64>()
                .map_err(|_| bad("START, STOP and STEP must be numbers"))
        };
        Grid::new(num(start)?, num(stop)?, num(step)?).map_err(|e| GridError {
            text: echo::text(text),
            ..e
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_grid_has_291_points() {
        let g: Grid = "0.1:3.0:0.01".parse().unwrap();
        assert_eq!(g, Grid::default());
        let v = g.values();
        assert_eq!(v.len(), 291);
        assert_eq!(v[0], 0.1);
        assert_eq!(v[2], 0.12);
        assert_eq!(v[290], 3.0);
    }

    #[test]
    fn refuses_bad_grids() {
        for text in [
            "1:0:0.1",
            "0:1:0",
            "0:1",
            "a:1:0.1",
            "0:1e9:1e-9",
            "-1:1:0.1",
            "0:inf:1",
            "1e300:1e300:1",
        ] {
            let e = text.parse::<Grid>().unwrap_err();
            assert!(
                e.to_string()
                    .starts_with(&format!("`omega1` grid = {text}:")),
                "{e}"
            );
        }
        assert_eq!("2:2:0.5".parse::<Grid>().unwrap().values(), vec![2.0]);
    }
}
