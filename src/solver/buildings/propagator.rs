//! The closed-form map over one sub-step out of contact (SPEC §13), cached
//! by (configuration, h, σ), and the systems of the configurations out of
//! contact ([`Systems`]).
//!
//! With w = (u, u̇, a_g, ȧ_g, M⁻¹q) the motion is w' = 𝒜w,
//!
//! ```text
//! 𝒜 = [ 0      I      0   0  0 ]
//!     [ −M⁻¹K  −M⁻¹C  −1  0  I ]
//!     [ 0      0      0   1  0 ]
//!     [ 0      0      σ   0  0 ]
//!     [ 0      0      0   0  0 ],
//! ```
//!
//! so w(h) = e^{𝒜h} w(0) exactly; the map keeps the rows of (u, u̇), made
//! with the bounds of the quiet test ([`Bounds::with_map`]). The
//! plastic offsets only enter through M⁻¹q, a part of the state, so one map
//! serves every configuration with the same branches. The bounds of the
//! quiet test ([`super::bound`]) depend on the same data and are cached
//! with it, and so does the stack's response to a jump of the ground
//! ([`GroundJump`]), which carries a sub-step's end stack into the next
//! piece. A run that takes its energy balance asks, beside, for the
//! quadratic forms of its integrals over the step ([`WorkForms`]), made on
//! first request and kept with the map.

use std::collections::HashMap;
use std::time::Instant;

use nalgebra::DMatrix;

use super::bound::{Bounds, GroundJump, Watch};
use super::layout::Layout;
use super::system::{System, Systems};

mod energy;
mod map;

pub use energy::{DAMPING, FIRST_LINK, INPUT, WorkForms};
pub use map::{Map, apply};

/// Cache key: the branches, h and σ (as bits).
pub type Key = (Vec<u8>, u64, u64);

/// The cache of linear maps with their quiet-test bounds and ground jumps,
/// and how it was used.
#[derive(Debug, Default)]
pub struct Propagator {
    /// Where each key's map is in `entries`.
    index: HashMap<Key, usize>,
    entries: Vec<(Map, Bounds, GroundJump)>,
    /// The energy's forms of each entry, once asked for.
    work_forms: Vec<Option<WorkForms>>,
    /// The key asked for last and its entry: a run asks for the same map
    /// sub-step after sub-step, which then costs a comparison of a few
    /// bytes instead of hashing the key.
    last: Option<(Key, usize)>,
    /// Maps made (matrix exponentials computed).
    pub made: usize,
    /// Sub-steps taken with a cached map.
    pub used: usize,
    /// Seconds spent making maps and their bounds, and the energy's forms.
    pub seconds: f64,
    /// The systems of the configurations met out of contact ([`Systems`]),
    /// which events switch to.
    pub systems: Systems,
}

/// The augmented matrix 𝒜 of `system` (no contact) on a piece with σ.
pub fn augmented(system: &System, sigma: f64) -> DMatrix<f64> {
    let n = system.load.len();
    let d = 3 * n + 2;
    let mut a = DMatrix::<f64>::zeros(d, d);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -system.stiffness[(i, j)];
            a[(n + i, n + j)] = -system.damping[(i, j)];
        }
        a[(n + i, 2 * n)] = -1.0;
        a[(n + i, 2 * n + 2 + i)] = 1.0;
    }
    a[(2 * n, 2 * n + 1)] = 1.0;
    a[(2 * n + 1, 2 * n)] = sigma;
    a
}

impl Propagator {
    /// The map of `system` (no contact) over h on a piece with σ, the
    /// bounds of the quantities `watch` over it ([`Bounds`], scaled by the
    /// row's fastest rate `rate`), and the configuration's [`GroundJump`].
    pub fn map(
        &mut self,
        branches: &[u8],
        system: &System,
        (h, sigma): (f64, f64),
        rate: f64,
        watch: &[Watch],
    ) -> (&Map, &Bounds, &GroundJump) {
        let n = system.load.len();
        self.used += 1;
        let bits = (h.to_bits(), sigma.to_bits());
        let at = match &self.last {
            Some(((b, hb, sb), at)) if b == branches && (*hb, *sb) == bits => *at,
            _ => {
                let key = (branches.to_vec(), bits.0, bits.1);
                let at = match self.index.get(&key) {
                    Some(&at) => at,
                    None => {
                        self.made += 1;
                        let clock = Instant::now();
                        let a = augmented(system, sigma);
                        let (bounds, map) = Bounds::with_map(&a, n, h, rate, watch);
                        self.seconds += clock.elapsed().as_secs_f64();
                        let jump = GroundJump::of(&system.columns, n);
                        self.entries.push((Map::of(&map), bounds, jump));
                        self.index.insert(key.clone(), self.entries.len() - 1);
                        self.entries.len() - 1
                    }
                };
                self.last = Some((key, at));
                at
            }
        };
        let (map, bounds, jump) = &self.entries[at];
        (map, bounds, jump)
    }

    /// The energy balance's forms ([`WorkForms`]) over the step of the map
    /// asked for last ([`Propagator::map`], for `system`), made on first
    /// request.
    pub fn last_work_forms(&mut self, system: &System, layout: &Layout) -> &WorkForms {
        let ((_, h, sigma), at) = self.last.as_ref().expect("a map asked for first");
        let at = *at;
        if self.work_forms.len() < self.entries.len() {
            self.work_forms.resize(self.entries.len(), None);
        }
        if self.work_forms[at].is_none() {
            let clock = Instant::now();
            let a = augmented(system, f64::from_bits(*sigma));
            let forms = WorkForms::of(&a, layout, f64::from_bits(*h), layout.rate);
            self.seconds += clock.elapsed().as_secs_f64();
            self.work_forms[at] = Some(forms);
        }
        self.work_forms[at].as_ref().expect("made above")
    }

    /// Distinct maps held.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
}
