//! The floor a row run is measured against (SPEC §13): the row's elastic
//! motion out of contact, advanced over the ground's pieces by one dense
//! state map per piece, written as plainly as C would be, with the sampled
//! peaks of every floor's |u| and |u̇|. No events, no contact, nothing
//! located between samples: [`super::floor`]'s pass with the row's 2n
//! states in place of a pair's 2 + 2. A run's time over this pass's is its
//! overhead.
//!
//! With x = (u, u̇) and the ground linear on a sample interval of length h,
//! ü_g = g_k + (g_{k+1} − g_k) s/h, the exact map of the augmented system
//! of [`crate::solver::buildings::propagator`] (load 0 at rest) gives
//!
//! ```text
//! x_{k+1} = A x_k + b₀ g_k + b₁ g_{k+1},
//! A = (e^{𝒜h})_{x,x},  b₁ = (e^{𝒜h})_{x,ȧ}/h,  b₀ = (e^{𝒜h})_{x,a} − b₁.
//! ```
//!
//! A piece of another length or with σ ≠ 0 (a sine, a record's last short
//! interval) takes its own map, made before the pass is timed. A line
//! longer than the record's interval (the free tail after a record) is cut
//! into equal parts no longer than it, as [`super::floor`]'s pass takes
//! its tail at the record's own interval.

use nalgebra::DMatrix;

use crate::model::buildings::ground::Piece;
use crate::model::buildings::{Ground, Row};
use crate::solver::buildings::config::Config;
use crate::solver::buildings::layout::Layout;
use crate::solver::buildings::propagator::augmented;
use crate::solver::buildings::system::System;

/// One dense map: A (2n × 2n, row-major) and the ground columns
/// (e^{𝒜h})_{x,a} and (e^{𝒜h})_{x,ȧ}, applied to a piece's (a, ȧ).
#[derive(Debug, Clone)]
struct DenseMap {
    /// (h, σ) as bits.
    key: (u64, u64),
    a: Vec<f64>,
    ground: [Vec<f64>; 2],
}

/// The dense pass of a row's elastic motion over its ground's pieces.
#[derive(Debug, Clone)]
pub struct RowFloor {
    states: usize,
    maps: Vec<DenseMap>,
    /// Per piece: its map and its start (a, ȧ).
    pieces: Vec<(usize, (f64, f64))>,
}

impl RowFloor {
    /// For `row` under `ground` over [0, `duration`]: every storey elastic,
    /// every joint open. Pieces of the same length and σ share one map, as
    /// a C pass would precompute it.
    pub fn new(row: &Row, ground: &Ground, duration: f64) -> RowFloor {
        let layout = Layout::of(row);
        let n = layout.dofs;
        let system = System::of(&layout, &Config::at_rest(layout.storeys.len(), 0));
        let mut maps: Vec<DenseMap> = Vec::new();
        let mut pieces = Vec::new();
        let all = ground.pieces(duration);
        // The record's interval: the shortest piece but the last.
        let interval = all[..all.len().saturating_sub(1)]
            .iter()
            .map(|p| p.length)
            .fold(f64::INFINITY, f64::min);
        let cut = all.into_iter().flat_map(|p| {
            let parts = if p.sigma == 0.0 && p.length > interval {
                (p.length / interval).ceil() as usize
            } else {
                1
            };
            let length = p.length / parts as f64;
            (0..parts).map(move |k| {
                let s = k as f64 * length;
                Piece {
                    length: if parts == 1 { p.length } else { length },
                    a: p.a + p.rate * s,
                    ..p
                }
            })
        });
        for piece in cut {
            if piece.length <= 0.0 {
                continue;
            }
            let key = (piece.length.to_bits(), piece.sigma.to_bits());
            let at = match maps.iter().position(|m| m.key == key) {
                Some(at) => at,
                None => {
                    let map: DMatrix<f64> = (augmented(&system, piece.sigma) * piece.length).exp();
                    let a = (0..2 * n)
                        .flat_map(|r| (0..2 * n).map(move |c| (r, c)))
                        .map(|(r, c)| map[(r, c)])
                        .collect();
                    let col = |c: usize| (0..2 * n).map(|r| map[(r, c)]).collect::<Vec<_>>();
                    maps.push(DenseMap {
                        key,
                        a,
                        ground: [col(2 * n), col(2 * n + 1)],
                    });
                    maps.len() - 1
                }
            };
            pieces.push((at, (piece.a, piece.rate)));
        }
        RowFloor {
            states: 2 * n,
            maps,
            pieces,
        }
    }

    /// Pieces the pass takes.
    pub fn intervals(&self) -> usize {
        self.pieces.len()
    }

    /// States of the map (2n).
    pub fn states(&self) -> usize {
        self.states
    }

    /// The sampled peaks of |u_i| then |u̇_i| of every floor, from rest.
    pub fn peaks(&self) -> Vec<f64> {
        let d = self.states;
        let mut x = vec![0.0; d];
        let mut y = vec![0.0; d];
        let mut peaks = vec![0.0f64; d];
        for &(at, (a, rate)) in &self.pieces {
            let p = &self.maps[at];
            for (r, y) in y.iter_mut().enumerate() {
                let row = &p.a[r * d..(r + 1) * d];
                let mut s = p.ground[0][r] * a + p.ground[1][r] * rate;
                for (m, x) in row.iter().zip(&x) {
                    s += m * x;
                }
                *y = s;
            }
            std::mem::swap(&mut x, &mut y);
            for (peak, x) in peaks.iter_mut().zip(&x) {
                *peak = peak.max(x.abs());
            }
        }
        peaks
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::buildings;
    use crate::solver::buildings::{RowOptions, run_row};

    /// With every joint open and every storey elastic, the sampled peaks
    /// lie below the exact method's true peaks, and within what a sample
    /// can miss of them.
    #[test]
    fn the_row_floor_samples_the_exact_elastic_response() {
        let mut row = buildings::load("block-and-frame").expect("shipped");
        for j in &mut row.joints {
            j.gap = f64::INFINITY;
        }
        for b in &mut row.buildings {
            for y in &mut b.yield_drift {
                *y = f64::INFINITY;
            }
        }
        let samples: Vec<f64> = (0..600)
            .map(|k| 2.0 * (0.31 * k as f64).sin() * (-(k as f64 - 200.0).powi(2) / 9e3).exp())
            .collect();
        let ground = Ground::Samples {
            dt: 0.01,
            acceleration: samples,
        };
        let duration = ground.end();
        let floor = RowFloor::new(&row, &ground, duration).peaks();
        let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).expect("runs");
        let n = floor.len() / 2;
        let flat: Vec<_> = exact.floors.iter().flatten().collect();
        assert_eq!(flat.len(), n);
        for (i, f) in flat.iter().enumerate() {
            for (sampled, true_peak) in [(floor[i], f.displacement), (floor[n + i], f.velocity)] {
                assert!(
                    sampled <= true_peak * (1.0 + 1e-12) && sampled >= 0.95 * true_peak,
                    "floor {i}: {sampled} vs {true_peak}"
                );
            }
        }
    }
}
