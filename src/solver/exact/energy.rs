//! The energy balance of SPEC §6 for the event-driven method.
//!
//! Each work term is the integral over a segment of a smooth integrand built
//! from the segment's series (the branch and the contact law are fixed inside
//! a segment), taken by 8-point Gauss–Legendre quadrature. A segment spans at
//! most about one radian of the fastest motion, so the rule (exact for
//! degree 15) leaves an error near round-off. The balance is then an
//! independent check of the motion: nothing in it is a state function of
//! the solver's own bookkeeping.

use super::super::result::EnergyBalance;
use super::dynamics::{Branch, Structure};
use super::segment::Segment;
use super::series::Series;

/// Gauss–Legendre nodes and weights on [0, 1], 8 points (written to 17
/// digits, one more than f64 holds, as tabulated).
#[allow(clippy::excessive_precision)]
const NODES: [f64; 8] = [
    0.019_855_071_751_231_856,
    0.101_666_761_293_186_63,
    0.237_233_795_041_835_5,
    0.408_282_678_752_175_1,
    0.591_717_321_247_824_9,
    0.762_766_204_958_164_5,
    0.898_333_238_706_813_4,
    0.980_144_928_248_768_2,
];
#[allow(clippy::excessive_precision)]
const WEIGHTS: [f64; 8] = [
    0.050_614_268_145_188_13,
    0.111_190_517_226_687_24,
    0.156_853_322_938_943_64,
    0.181_341_891_689_180_99,
    0.181_341_891_689_180_99,
    0.156_853_322_938_943_64,
    0.111_190_517_226_687_24,
    0.050_614_268_145_188_13,
];

/// Running work integrals.
#[derive(Debug, Clone, Copy, Default)]
pub struct Work {
    input: f64,
    damping: f64,
    /// ∫ f_s,i ẋ_i dτ of each structure.
    spring: [f64; 2],
    contact: f64,
    max_input: f64,
}

impl Work {
    /// Adds the work done over [0, length] of `segment`, whose ground
    /// acceleration is the series `ground` (exact over the segment: it
    /// never crosses a change of the excitation's formula).
    pub fn add(
        &mut self,
        structures: &[Structure; 2],
        branch: [Branch; 2],
        segment: &Segment,
        ground: &Series,
        length: f64,
    ) {
        if length <= 0.0 {
            return;
        }
        // Every series at the eight nodes at once: x and ẋ of both
        // structures, g and, in contact, f_p.
        let t = NODES.map(|node| node * length);
        let g = ground.values_at(&t);
        let x = [segment.x[0].values_at(&t), segment.x[1].values_at(&t)];
        let v = [segment.v[0].values_at(&t), segment.v[1].values_at(&t)];
        let (mut input, mut damping, mut spring, mut contact) = (0.0, 0.0, [0.0; 2], 0.0);
        for i in 0..2 {
            let s = &structures[i];
            for n in 0..NODES.len() {
                let (w, vi) = (WEIGHTS[n], v[i][n]);
                input -= w * s.mass * vi * g[n];
                damping += w * s.damping * vi * vi;
                spring[i] += w * s.spring_force(branch[i], x[i][n]) * vi;
            }
        }
        if let Some(f) = segment.force() {
            let f = f.values_at(&t);
            for n in 0..NODES.len() {
                contact += WEIGHTS[n] * f[n] * (v[0][n] - v[1][n]);
            }
        }
        self.input += input * length;
        self.damping += damping * length;
        for (total, w) in self.spring.iter_mut().zip(spring) {
            *total += w * length;
        }
        self.contact += contact * length;
        self.max_input = self.max_input.max(self.input.abs());
    }

    /// Adds the input and spring work of both structures over a quiet
    /// sample interval in the tight loop ([`super::sample_work::PairWork`]),
    /// whose damping work comes later by [`Work::add_damping`].
    #[inline(always)]
    pub fn add_input_and_spring(&mut self, [a, b]: [[f64; 2]; 2]) {
        self.input += a[0] + b[0];
        self.spring[0] += a[1];
        self.spring[1] += b[1];
        self.max_input = self.max_input.max(self.input.abs());
    }

    /// Adds both structures' damping work over a run of quiet samples.
    pub fn add_damping(&mut self, [a, b]: [f64; 2]) {
        self.damping += a + b;
    }

    /// Adds the work of both structures over a quiet sample interval, each
    /// [input, damping, spring] from [`super::sample::work`].
    pub fn add_quiet(&mut self, terms: [[f64; 3]; 2]) {
        let [a, b] = terms;
        self.input += a[0] + b[0];
        self.damping += a[1] + b[1];
        self.spring[0] += a[2];
        self.spring[1] += b[2];
        self.max_input = self.max_input.max(self.input.abs());
    }

    /// The balance at the end of the run, with final velocities `v` and the
    /// kinetic energy `initial` the run started with.
    pub fn balance(&self, mass: [f64; 2], v: [f64; 2], initial: f64) -> EnergyBalance {
        let kinetic = 0.5 * (mass[0] * v[0] * v[0] + mass[1] * v[1] * v[1]);
        let spring = self.spring[0] + self.spring[1];
        let imbalance = kinetic + self.damping + spring + self.contact - self.input - initial;
        let scale = self.max_input.max(initial);
        EnergyBalance {
            input: self.input,
            kinetic,
            damping: self.damping,
            spring,
            spring_by_structure: self.spring,
            contact: self.contact,
            max_input: self.max_input,
            residual: if scale > 0.0 {
                imbalance.abs() / scale
            } else {
                imbalance.abs()
            },
        }
    }
}
