//! Contact phases of the Hertz-type laws in a row (SPEC §13 with §10), by
//! the embedded Runge–Kutta pair of [`crate::numerics::dopri5`], as the
//! pair's exact method carries them ([`crate::solver::exact::contact_rk`]).
//!
//! With f = βδ^{3/2}(1 + λδ̇) + ηδ^{1/4}δ̇⁺ and δ ≈ v₀t after onset, the motion
//! holds terms in t^{7/2}: it is not analytic at onset or separation, so the
//! Taylor series cannot carry it. While such a pair is closed, each step is
//! one accepted step of the Dormand–Prince 5(4) pair on y = (u, u̇),
//!
//! ```text
//! ü = −M⁻¹K u − M⁻¹C u̇ + M⁻¹q − 1 ü_g(t) − M⁻¹ Σ_p f_p(δ_p, δ̇_p) e_p
//!     − M⁻¹ Σ_d c_d |Δv_d|^α_d sgn(Δv_d) e_d,
//! ```
//!
//! (K, C and q of the configuration's storeys: a Hertz-type law puts
//! nothing into them; the last sum is the row's fluid viscous dampers,
//! SPEC §14, [`super::damper`], which put their springs alone into K, and
//! which keep a row off the maps for the whole run: out of Hertz-type
//! contact each step is [`damper_collocation`]'s instead, the linear motion
//! exact and only the nonlinear forces collocated, where the Taylor series
//! with the dampers' forces in it does not serve, near a reversal or where
//! a damper is stiff), its local error held below [`TOLERANCE`] of the
//! motion's scales (largest |u| for displacements, largest |u̇| for
//! velocities). On the accepted step each u_i is the quintic Hermite
//! polynomial through (u, u̇, ü) at both ends (error O(h⁶), the step's own
//! order) and u̇_i its derivative, written as a [`Series`], so that events
//! and peaks are found by the Taylor steps' own machinery; an event found
//! inside is then placed on the motion itself by Newton's method on its
//! function, each trial a step retaken from the start to that instant
//! ([`Contact::settle`]), its error held to the tolerance as an accepted
//! step's is ([`Contact::retake`]).

use std::cell::RefCell;

use crate::model::contact::Hertzian;
use crate::numerics::dopri5::{self, Step};
use crate::solver::exact::contact_rk::{equispaced_quintic, hermite_quintic};

use super::config::Config;
use super::damper::{self, Damper};
use super::damper_collocation::{self, Collocation};
use super::damper_radau;
use super::event_function::EventFunction;
use super::layout::Layout;
use super::system::System;
use super::taylor::{Series, ground_coefficients};

/// Local error asked of each step, relative to the motion's scales: the
/// pair's error per step then sits a decade below the 1e-9 to which the
/// row's peaks are checked.
pub const TOLERANCE: f64 = 1e-12;

/// The largest |d_i| / σ_i of a difference d of two motions of n floors,
/// d = (Δu₁ … Δu_n, Δu̇₁ … Δu̇_n), with σ_i = `scale`.0 for the
/// displacements and `scale`.1 for the velocities: the norm in which a
/// step's local error is held. A NaN never counts (`f64::max`).
pub(super) fn scaled_norm(d: impl IntoIterator<Item = f64>, n: usize, scale: (f64, f64)) -> f64 {
    d.into_iter()
        .enumerate()
        .map(|(i, e)| (e / if i < n { scale.0 } else { scale.1 }).abs())
        .fold(0.0, f64::max)
}

/// The motion's scales times [`TOLERANCE`]: the σ of [`scaled_norm`] in
/// which a step's error estimate is 1 at the tolerance.
fn tolerated(scale: (f64, f64)) -> (f64, f64) {
    (TOLERANCE * scale.0, TOLERANCE * scale.1)
}

#[cfg(test)]
thread_local! {
    /// Where a test sets it, each accepted collocated step's true local
    /// error over its tolerance ([`Contact::audit`]).
    pub static AUDIT: RefCell<Option<Vec<f64>>> = const { RefCell::new(None) };
}

/// Newton iterations at most when placing an event on the motion.
const NEWTON: usize = 8;

/// One closed pair under a Hertz-type law.
#[derive(Debug, Clone, Copy)]
struct HertzPair {
    left: usize,
    right: usize,
    gap: f64,
    law: Hertzian,
    /// 1/m_A and 1/m_B.
    left_rate: f64,
    right_rate: f64,
}

/// The row's motion through Hertz-type contact phases, and with its fluid
/// viscous dampers, in one configuration.
pub struct Contact<'a, G: Fn(f64) -> f64> {
    system: &'a System,
    pairs: Vec<HertzPair>,
    dampers: &'a [Damper],
    /// The floors' masses (kg).
    mass: &'a [f64],
    /// ü_g at offset s from the step's start.
    ground: G,
    /// Where set, the steps of a row with dampers and no Hertz-type pair
    /// are [`damper_collocation`]'s, with its cache and the ground
    /// (a_g, ȧ_g, σ) at offset s.
    collocation: Option<(&'a RefCell<Collocation>, &'a GroundAt<'a>)>,
}

/// Ground (a_g, ȧ_g, σ) at offset s from a step's start.
pub type GroundAt<'a> = dyn Fn(f64) -> (f64, f64, f64) + 'a;

/// One accepted step with where it started: y₀ = (u, u̇), ẏ₀, the step.
pub type Taken = (Vec<f64>, Vec<f64>, Step<Vec<f64>>);

/// Whether the row's motion in `config` goes by these steps: a closed pair
/// is under a Hertz-type law, or the row has a fluid viscous damper.
pub fn by_steps(layout: &Layout, config: &Config) -> bool {
    !layout.dampers.is_empty()
        || config
            .contact
            .iter()
            .flatten()
            .any(|c| !c.law.is_analytic())
}

impl<'a, G: Fn(f64) -> f64> Contact<'a, G> {
    pub fn new(layout: &'a Layout, config: &Config, system: &'a System, ground: G) -> Self {
        let pairs = layout
            .pairs
            .iter()
            .zip(&layout.gaps)
            .zip(&config.contact)
            .filter_map(|((p, &gap), closed)| {
                let law = closed.as_ref()?.law.hertzian?;
                Some(HertzPair {
                    left: p.left_dof,
                    right: p.right_dof,
                    gap,
                    law,
                    left_rate: 1.0 / layout.mass[p.left_dof],
                    right_rate: 1.0 / layout.mass[p.right_dof],
                })
            })
            .collect();
        Contact {
            system,
            pairs,
            dampers: &layout.dampers,
            mass: &layout.mass,
            ground,
            collocation: None,
        }
    }

    /// The same, its steps by exponential collocation where it applies
    /// (a row with dampers and no pair closed under a Hertz-type law), with the cache `cache` and the ground
    /// (a_g, ȧ_g, σ) at offset s.
    pub fn with_collocation(self, cache: &'a RefCell<Collocation>, ground: &'a GroundAt) -> Self {
        Contact {
            collocation: Some((cache, ground)),
            ..self
        }
    }

    /// Whether the steps go by [`damper_collocation`]: the row has a
    /// damper, no pair is closed under a Hertz-type law (whose force is
    /// not a polynomial's in time near onset), and a cache was given.
    fn collocates(&self) -> bool {
        self.collocation.is_some() && self.pairs.is_empty() && !self.dampers.is_empty()
    }

    /// The cache and what a collocated step needs of the row, with the
    /// motion's scales `scale`; None where the steps do not collocate.
    fn collocation_row(
        &self,
        scale: (f64, f64),
    ) -> Option<(&'a RefCell<Collocation>, damper_collocation::Row<'_>)> {
        let (cache, ground) = self.collocation.filter(|_| self.collocates())?;
        let row = damper_collocation::Row {
            system: self.system,
            dampers: self.dampers,
            mass: self.mass,
            ground,
            scale,
        };
        Some((cache, row))
    }

    /// The step of length h from y0 by [`damper_collocation`], as a step
    /// of the pair with f at its end, its error estimate, and as
    /// its dense output the line from y0 to y1 (its own series left in the
    /// cache where `dense`); None where it does not apply or its Newton's
    /// method fails ([`Collocation::step`]).
    fn collocated(
        &self,
        (y0, _): (&Vec<f64>, &Vec<f64>),
        (h, dense): (f64, bool),
        scale: (f64, f64),
    ) -> Option<Step<Vec<f64>>> {
        let (cache, row) = self.collocation_row(scale)?;
        let (y1, error) = cache.borrow_mut().step(&row, y0, (h, dense))?;
        let f1 = self.rate(h, &y1);
        Some(Step::linear(h, y0, y1, f1, error))
    }

    /// ẏ at offset s, y = (u, u̇) (the equation above). It takes the
    /// pair's own state type, a vector.
    #[allow(clippy::ptr_arg)]
    pub fn rate(&self, s: f64, y: &Vec<f64>) -> Vec<f64> {
        let n = y.len() / 2;
        let (u, v) = y.split_at(n);
        let mut out = vec![0.0; 2 * n];
        out[..n].copy_from_slice(v);
        self.acceleration(s, u, v, &mut out[n..]);
        out
    }

    /// ü at offset s into `acc`: the second half of [`Contact::rate`].
    pub fn acceleration(&self, s: f64, u: &[f64], v: &[f64], acc: &mut [f64]) {
        self.hertz_acceleration(s, u, v, acc);
        for d in self.dampers {
            d.add_to(v, acc);
        }
    }

    /// ü at offset s without the dampers' forces: the linear system's and
    /// the closed Hertz-type pairs'.
    fn hertz_acceleration(&self, s: f64, u: &[f64], v: &[f64], acc: &mut [f64]) {
        self.system.acceleration(u, v, (self.ground)(s), acc);
        for p in &self.pairs {
            let delta = u[p.left] - u[p.right] - p.gap;
            let f = p.law.force(delta, v[p.left] - v[p.right]).force;
            acc[p.left] -= p.left_rate * f;
            acc[p.right] += p.right_rate * f;
        }
    }

    /// Whether some damper is stiff over a step of length h from y0
    /// ([`Damper::stiff`]): the step is then the implicit one.
    fn stiff(&self, y0: &[f64], h: f64) -> bool {
        let n = y0.len() / 2;
        self.dampers.iter().any(|d| d.stiff(d.rate(&y0[n..]), h))
    }

    /// The implicit step of length h from y0 ([`damper_radau`]), as a
    /// step of the pair with f at its end, its error by step doubling, and
    /// as its dense output the line from y0 to y1; `speed` is the motion's
    /// velocity scale. Where Newton's method fails on it (a damper so weak
    /// that its inverse law overflows), the explicit step instead.
    fn implicit(&self, (y0, f0): (&Vec<f64>, &Vec<f64>), h: f64, speed: f64) -> Step<Vec<f64>> {
        let n = y0.len() / 2;
        let acceleration = |s: f64, u: &[f64], v: &[f64], f: &[f64], acc: &mut [f64]| {
            self.hertz_acceleration(s, u, v, acc);
            for (d, &f) in self.dampers.iter().zip(f) {
                acc[d.left] -= d.left_rate * f;
                acc[d.right] += d.right_rate * f;
            }
        };
        let row = damper_radau::Row {
            acceleration: &acceleration,
            stiffness: &self.system.stiffness,
            damping: &self.system.damping,
            dampers: self.dampers,
        };
        let forces = |y: &[f64]| -> Vec<f64> {
            self.dampers
                .iter()
                .map(|d| d.force(d.rate(&y[n..])))
                .collect()
        };
        let whole = damper_radau::step(&row, y0, &forces(y0), h, speed);
        let half = damper_radau::step(&row, y0, &forces(y0), 0.5 * h, speed);
        let twice = half.as_ref().and_then(|y| {
            // The second half starts at h/2: the ground is shifted there.
            let shifted = |s: f64, u: &[f64], v: &[f64], f: &[f64], acc: &mut [f64]| {
                acceleration(0.5 * h + s, u, v, f, acc)
            };
            let row = damper_radau::Row {
                acceleration: &shifted,
                ..row
            };
            damper_radau::step(&row, y, &forces(y), 0.5 * h, speed)
        });
        let (Some(y1), Some(twice)) = (whole, twice) else {
            return dopri5::step(&|s, y| self.rate(s, y), 0.0, y0, f0, h);
        };
        let error = y1.iter().zip(&twice).map(|(a, b)| (a - b) / 31.0).collect();
        let f1 = self.rate(h, &y1);
        Step::linear(h, y0, y1, f1, error)
    }

    /// One accepted step from y0 (f0 = ẏ there), at most `h_max` long,
    /// from the suggestion `h_try`, shrunk until the error is within
    /// [`TOLERANCE`] of `scale` = (displacement, velocity); steps below
    /// `h_min` are accepted (round-off floor). A step rejected while some
    /// damper's Δv changes sign inside it is retried to that reversal, as
    /// its dense output places it ([`damper::first_reversal`]): its error
    /// came from the kink, which no step should straddle. The next length
    /// is h·0.9 err^(−1/p) (within 0.2 h and 5 h), p the order of the
    /// error estimate in h: 2S for a collocated step, whose estimate is
    /// O(h^(2S)) where the force is smooth (with 1/5 there, a step after a
    /// small error grew past the tolerance: 2,333 of 11,132 rejected on
    /// block-and-frame-retrofit at α = 0.35 under synthetic:2000, 1,522 of
    /// 10,656 with 1/8), 5 for the Dormand–Prince pair and the implicit
    /// step. Returns the step and the suggested length of the next.
    pub fn step(
        &self,
        (y0, f0): (&Vec<f64>, &Vec<f64>),
        (h_try, h_max, h_min): (f64, f64, f64),
        scale: (f64, f64),
    ) -> (Step<Vec<f64>>, f64) {
        let n = y0.len() / 2;
        let mut h = h_try.min(h_max);
        // Whether the length is h_max's, not the controller's.
        let mut cut = h_try > h_max;
        loop {
            let collocated = self.collocated((y0, f0), (h, true), scale);
            // The order of the error estimate in h: 2S for a collocated
            // step (its end's error where the force is smooth), 5 for the
            // Dormand–Prince pair's and the implicit step's.
            let collocates = collocated.is_some();
            let order = if collocates {
                2 * damper_collocation::STAGES
            } else {
                5
            };
            let step = match collocated {
                Some(step) => step,
                None if self.stiff(y0, h) => self.implicit((y0, f0), h, scale.1),
                None => dopri5::step(&|s, y| self.rate(s, y), 0.0, y0, f0, h),
            };
            let err = scaled_norm(step.error.iter().copied(), n, tolerated(scale));
            let factor = if err > 0.0 {
                (0.9 * err.powf(-1.0 / order as f64)).clamp(0.2, 5.0)
            } else {
                5.0
            };
            let accepted = err <= 1.0 || h <= h_min;
            if let Some((cache, _)) = self.collocation {
                let mut cache = cache.borrow_mut();
                if accepted {
                    cache.accepted += 1;
                } else {
                    cache.rejected += 1;
                }
            }
            #[cfg(test)]
            if accepted && collocates {
                self.audit(y0, &step, scale);
            }
            if accepted {
                // A step cut short by h_max says nothing against h_try;
                // one shrunk after a rejection does.
                let next = if cut {
                    h_try.max(h * factor)
                } else {
                    h * factor
                };
                return (step, next);
            }
            let reversal =
                damper::first_reversal(self.dampers, h, &y0[n..], &step.y1[n..], |theta| {
                    step.at(theta)
                });
            cut = false;
            h *= match reversal {
                Some(theta) if theta < 0.999 => theta.max(1e-6),
                _ => factor.min(0.9),
            };
        }
    }

    /// Records an accepted collocated step's true local error over its
    /// tolerance in [`AUDIT`] (where a test has set it): its end's distance
    /// from sixteen collocated steps of a sixteenth of its length, in the
    /// motion's scales.
    #[cfg(test)]
    fn audit(&self, y0: &[f64], step: &Step<Vec<f64>>, scale: (f64, f64)) {
        if AUDIT.with(|a| a.borrow().is_none()) {
            return;
        }
        let Some((cache, row)) = self.collocation_row(scale) else {
            return;
        };
        let n = y0.len() / 2;
        let Some(reference) = cache.borrow_mut().substepped(&row, y0, step.h, 16) else {
            return;
        };
        let ratio = scaled_norm(
            step.y1.iter().zip(&reference).map(|(a, b)| a - b),
            n,
            tolerated(scale),
        );
        AUDIT.with(|a| a.borrow_mut().as_mut().map(|r| r.push(ratio)));
    }

    /// The step of length s from y0, taken again (the implicit one where a
    /// damper is stiff over it; `speed` the motion's velocity scale), to
    /// place an event on it ([`Contact::settle`]), its error held to
    /// [`TOLERANCE`] as an accepted step's is: where the one step's
    /// estimate misses it, accepted steps carry the motion over s instead
    /// (`Contact::carried`). A retake is shorter than the step it was
    /// found on, but its estimate need not be smaller: a collocated step
    /// whose defect model failed was doubled, while the retake, its
    /// model passing, may return an end corrected by an estimate far past
    /// the tolerance. Taken as it came, such an end once moved a locked
    /// damper's stroke by 7.5e-10 m in 2.6 ms (block-and-frame-retrofit in
    /// Kelvin contact, α = 0.2, c = 1e7, under synthetic:2000: 18 of 626
    /// retakes missed the tolerance), and the runs at the tolerance and at
    /// a hundredth of it stood 1.3e-9 m apart from 0.79 s on; with the
    /// check they agree to 2.5e-12 m.
    pub fn retake(&self, (y0, f0): (&Vec<f64>, &Vec<f64>), s: f64, speed: f64) -> Step<Vec<f64>> {
        let n = y0.len() / 2;
        let size = y0[..n].iter().fold(1e-6f64, |m, x| m.max(x.abs()));
        let scale = (size, speed);
        let step = if let Some(step) = self.collocated((y0, f0), (s, false), scale) {
            step
        } else if self.stiff(y0, s) {
            self.implicit((y0, f0), s, speed)
        } else {
            dopri5::step(&|t, y| self.rate(t, y), 0.0, y0, f0, s)
        };
        if scaled_norm(step.error.iter().copied(), n, tolerated(scale)) <= 1.0 {
            return step;
        }
        self.carried((y0, f0), s, scale)
    }

    /// The motion from y0 over s by accepted steps ([`Contact::step`], its
    /// error held to [`TOLERANCE`] of `scale`), each from its own start
    /// under the ground from there, as one step of length s. A step a
    /// thousandth of s long is accepted whatever its estimate, so that an
    /// estimate that cannot meet the tolerance (round-off) ends the walk
    /// in at most some thousand steps rather than never. A walk takes a
    /// few: on the run of [`Contact::retake`]'s doc, 74 steps for the 18
    /// retakes that missed.
    fn carried(
        &self,
        (y0, f0): (&Vec<f64>, &Vec<f64>),
        s: f64,
        scale: (f64, f64),
    ) -> Step<Vec<f64>> {
        let (mut y, mut f) = (y0.clone(), f0.clone());
        let mut error = vec![0.0; y0.len()];
        let (mut covered, mut h_try) = (0.0, s);
        loop {
            let rest = s - covered;
            let triple = |t: f64| {
                self.collocation
                    .map_or((0.0, 0.0, 0.0), |(_, ground)| ground(covered + t))
            };
            let from = Contact {
                system: self.system,
                pairs: self.pairs.clone(),
                dampers: self.dampers,
                mass: self.mass,
                ground: |t: f64| (self.ground)(covered + t),
                collocation: self
                    .collocation
                    .map(|(cache, _)| (cache, &triple as &GroundAt)),
            };
            let (step, next) = from.step((&y, &f), (h_try, rest, 1e-3 * s), scale);
            for (e, d) in error.iter_mut().zip(&step.error) {
                *e += d;
            }
            (y, f) = (step.y1, step.f1);
            if step.h >= rest {
                break;
            }
            covered += step.h;
            h_try = next;
        }
        Step::linear(s, y0, y, f, error)
    }

    /// The event of function `g`, found near `s` on the polynomials, placed
    /// on the motion: Newton's method s ← s − g/ġ, with g and ġ from a step
    /// retaken to each trial, until the update is a few ulps; then moved
    /// just past the root (g > 0), so that the event is applied on its far
    /// side, as on the series. Every trial stays within the accepted step
    /// the event was found on, of length `within`: where ġ is all but zero
    /// at the root, Newton's update would otherwise leave it (a retake
    /// a second long is no step of this motion).
    ///
    /// A trial on the root within rounding of a function of the
    /// displacements alone (onset, separation, yield, collapse: g = 0, or
    /// |g| within 4ε of its terms' sum and past the root) ends the search:
    /// there s moved by an ulp moves no displacement by one, and the walk
    /// on past the root took all its sixteen trials, as many retaken
    /// steps, for nearly every event of a Hertz contact (on block-and-frame
    /// under synthetic:2000 at twice its scale, 1,135 trials for 81 events;
    /// 356 so). A function of the velocities (unloading, the Jankowski
    /// law's switch, a damper's reversal) still walks on to g > 0: a
    /// locked damper's reversal is ill-conditioned, and where in the last
    /// ulps it lands shows in the link's energy at 1e-9.
    ///
    /// None where the last trial leaves g below zero and not rising: the
    /// motion moves away from the root the polynomials put there, which
    /// was their rounding. So it is where a storey has just unloaded at
    /// its yield drift: its yield function starts at zero with zero slope
    /// and falls, and the quintic's rounding can put a root a hair past
    /// the start. Such an event, applied at the step's end as it once was
    /// (g = −2.2e-7 m there, on block-and-frame-retrofit in Hertz contact
    /// under a ten-cycle sine), put the storey on the plastic branch it was
    /// leaving for a whole step, and the run's peaks 3.5e-6 from runs at
    /// other tolerances. (A root placed exactly, g = 0, or one the last
    /// trial falls a rounding short of while g rises, is the motion's.)
    pub fn settle(
        &self,
        start: (&Vec<f64>, &Vec<f64>),
        g: &EventFunction,
        (mut s, within): (f64, f64),
        speed: f64,
    ) -> Option<Step<Vec<f64>>> {
        let n = start.0.len() / 2;
        let value = |step: &Step<Vec<f64>>| {
            let (u, v) = step.y1.split_at(n);
            g.at(u, v, &step.f1[n..])
        };
        // Past the root, or on it where g reads the displacements alone.
        let displacements = !g.reads_velocities();
        let past = |gs: f64| gs > 0.0 || (displacements && gs == 0.0);
        let resolved = |step: &Step<Vec<f64>>, gs: f64| {
            let (u, _) = step.y1.split_at(n);
            let size = g
                .on_u
                .iter()
                .fold(g.constant.abs(), |m, &(i, w)| m + (w * u[i]).abs());
            displacements && gs.abs() <= 4.0 * f64::EPSILON * size
        };
        let mut step = self.retake(start, s, speed);
        for _ in 0..NEWTON {
            let (gs, rate) = value(&step);
            let ds = -gs / rate;
            if !ds.is_finite() || rate <= 0.0 || s + ds < 0.0 || s + ds > within {
                break;
            }
            if past(gs) && (ds.abs() <= 4.0 * f64::EPSILON * s || resolved(&step, gs)) {
                break;
            }
            s = (s + ds).max(if gs <= 0.0 { s.next_up() } else { 0.0 });
            step = self.retake(start, s, speed);
        }
        for _ in 0..NEWTON {
            let (gs, rate) = value(&step);
            if past(gs) {
                break;
            }
            let ds = if rate > 0.0 { -gs / rate } else { 0.0 };
            let next = (s + 2.0 * ds).max(s.next_up().next_up()).min(within);
            if next <= s {
                break;
            }
            s = next;
            step = self.retake(start, s, speed);
        }
        let (gs, rate) = value(&step);
        (gs >= 0.0 || rate > 0.0).then_some(step)
    }
}

/// u on the accepted `step` from y0 (f0 = ẏ there) as the quintic Hermite
/// polynomial through (u, u̇, ü) at both ends, u̇ as its derivative, with
/// the ground (a, ȧ, σ) at the start: a [`Series`] on [0, h].
pub fn series(
    (y0, f0): (&Vec<f64>, &Vec<f64>),
    step: &Step<Vec<f64>>,
    ground: (f64, f64, f64),
) -> Series {
    let n = y0.len() / 2;
    let mut u = vec![0.0; 6 * n];
    let mut v = vec![0.0; 6 * n];
    let (y1, f1) = (&step.y1, &step.f1);
    for i in 0..n {
        let q = hermite_quintic(
            [y0[i], y0[n + i], f0[n + i]],
            [y1[i], y1[n + i], f1[n + i]],
            step.h,
        );
        let at = i * 6;
        u[at..at + 6].copy_from_slice(&q.c[..6]);
        for k in 0..5 {
            v[at + k] = (k + 1) as f64 * q.c[k + 1];
        }
    }
    let mut series = Series::from_floors(n, 5, (&u, &v));
    series.ground = ground_coefficients(ground);
    series.radius = step.h;
    series
}

/// f = law(δ, δ̇) on [0, end] as the quintic through six equally spaced
/// values, δ and δ̇ the polynomials `delta` and `rate`: the contact force's
/// peak is its largest value.
pub fn force_polynomial(law: &Hertzian, delta: &[f64], rate: &[f64], end: f64) -> Vec<f64> {
    let values = std::array::from_fn(|j| {
        let s = end * j as f64 / 5.0;
        law.force(super::poly::eval(delta, s), super::poly::eval(rate, s))
            .force
    });
    equispaced_quintic(&values, end).c[..=5].to_vec()
}

#[cfg(test)]
mod tests;
