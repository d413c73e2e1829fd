//! The event-driven run: from rest to τ_end, one segment at a time.
//!
//! Each pass of the loop
//! 1. expands the motion about the current instant as Taylor series
//!    ([`super::dynamics`]): each structure alone out of contact, both
//!    together with the pounding force in contact;
//! 2. chooses the segment length: a fixed reach of the fastest free rate out
//!    of contact, where the series is the closed-form response summed to
//!    round-off; from the size of the last terms in contact, relative to the
//!    contact's own scale δ ~ v₀/Π_ωcon;
//! 3. finds the earliest event in the segment on the series
//!    ([`super::roots`]): contact onset (δ = 0, rising), separation (δ = 0,
//!    falling), yield (|z| reaches Π_uy) and unloading (ẋ changes sign while
//!    yielded) of either structure, and cuts the segment there;
//! 4. raises the peaks to the true maxima on the segment (Π_u at zeros of ẋ,
//!    Π_v at zeros of ẍ, and an impact's penetration and force at zeros of
//!    their rates), hands the observer its samples, and switches branch or
//!    contact at the event.
//!
//! The state is checked for non-finite values at every segment, and caps on
//! segments and events turn a runaway (chatter, a Zeno cascade of impacts)
//! into a reported stop.

// Comparisons are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::model::contact::ContactConstants;
use crate::model::{ContactLaw, Excitation, Method, Params};

use super::super::observer::{Observer, Sample};
use super::super::result::{FinalSpring, Impact, RunResult, Stop, StopReason};
use super::acceleration::{self, push, raise_absolute_acceleration};
use super::contact_rk::ContactSystem;
use super::dynamics::{Branch, ContactRecurrence, Structure, free_series, step_for};
use super::energy::Work;
use super::peaks::{raise_abs_max, raise_max};
use super::quiet::{Bands, Majorants, QuietStep, stays_below};
use super::roots::{fires_at_start, first_crossing};
use super::sample::{self, Limits, SampleMajorants, SampleMap};
use super::sample_peaks::{IntervalSeries, raise_relative};
use super::sample_run::{Pair, Peaks, Watch};
use super::sample_work::{DampingSums, PairWork};
use super::segment::{Event, Segment};
use super::series::{MAX_DEGREE, Series};
use crate::solver::SolverOptions;

/// Degree of the series out of contact.
const FREE_DEGREE: usize = 20;
/// Degree of a free series over a segment of Ω L = `reach` ≤ 1 (in units
/// of [`FREE_REACH`]/Ω): the least n at which the first term left out,
/// about (Ω L)^{n+1}/(n+1)! of the motion, is below 3e-18 (Ω L ≤ 1/8: 10;
/// ≤ 1/4: 12; ≤ 1/2: 15), else [`FREE_DEGREE`]. Used where a record's
/// sample intervals cut the segments short (the ground series is then of
/// degree 1).
fn short_free_degree(reach: f64) -> usize {
    if reach <= 0.125 {
        10
    } else if reach <= 0.25 {
        12
    } else if reach <= 0.5 {
        15
    } else {
        FREE_DEGREE
    }
}

/// Segment length out of contact in units of 1/Ω, Ω the fastest free rate
/// (structures and excitation): the last term is then about 1/21! ≈ 2e-20 of
/// the motion, below round-off.
const FREE_REACH: f64 = 1.0;
/// Quiet segments are this fraction of a free segment: short enough that the
/// swing bounds of [`Transition::swing`] and the cubic majorants clear most
/// of a cycle, long enough that few are needed. Measured on the presets and
/// on a 146 × 91 region map, 0.5 costs less than 0.25 and 1.0.
const QUIET_FRACTION: f64 = 0.5;
/// Where one structure is this much faster than the other (and than the
/// excitation), quiet segments are first tried at the same fraction of the
/// slower one's free segment: the fast one, bounded by its steady response
/// and the energy of its free vibration, rarely limits them. Measured: on a
/// 146 × 91 (Π_ω1, μ) map this takes a tenth off the time at 2, 3 or 4
/// alike, while at 2 the presets (μ = 2.25) lose 8–15 %.
const LONG_QUIET_RATIO: f64 = 4.0;
/// After a long quiet segment fails (the slow structure nears a peak or an
/// event, or the fast one still rings), it is not tried again for this many
/// of its lengths: on a 146 × 91 region map that costs least of 0, 1 and 2.
const LONG_QUIET_RETRY: f64 = 2.0;
/// Rotations of the quiet segments' phasor between evaluations of sin_cos.
const PHASOR_TURNS: u32 = 16;
/// Longest contact segment, in units of 1/Π_ωcon (the contact's own rate),
/// as [`FREE_REACH`] out of contact: over about a radian the bounds that clear
/// events and peaks stay tight. A linear law's series would otherwise reach
/// about 1.7 rad at the tolerance, and its searches over those long segments
/// cost more than the segments saved (set 1 with Kelvin: 73 → 60 µs, the
/// error unchanged at 5e-14). Improved Kelvin's steps are shorter anyway.
const CONTACT_REACH: f64 = 1.0;
/// Degree of the series in contact.
const CONTACT_DEGREE: usize = 20;
/// Events (onsets, separations, yields, unloadings) allowed per cycle of the
/// run, beyond a fixed allowance: a physical run has a few per cycle.
const EVENTS_PER_CYCLE: usize = 1_000;
const EVENT_ALLOWANCE: usize = 10_000;
/// Samples of a record cleared together by one test where nothing comes
/// near a peak or an event ([`super::sample_run::Pair::block`]).
const BLOCK: usize = 16;

/// How often (in segments) the observer is asked whether to go on.
const POLL_EVERY: usize = 256;

/// What a run may use besides the Π-groups.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactOptions {
    pub excitation: Excitation,
    pub initial_displacement: [f64; 2],
    pub initial_velocity: [f64; 2],
    /// Integrate the work terms of SPEC §6 (Gauss–Legendre on each segment).
    /// Costs about as much as the motion itself; spectra and maps skip it.
    pub energy: bool,
    /// Cap on events (onsets, separations, yields, unloadings) before the
    /// run stops with [`StopReason::EventCap`]; `None`: 10,000 plus 1,000
    /// per cycle, far above any physical run (a few per cycle).
    pub max_events: Option<usize>,
    /// Size allowed to each of the last two terms of a contact series,
    /// relative to the contact scale δ ~ v₀/Π_ωcon (the method's one knob;
    /// a parameter set's `contact_tolerance`).
    pub contact_tolerance: f64,
    /// Which extremes of the pounding force and penetration to locate.
    pub extremes: ContactExtremes,
    /// Locate each structure's peak absolute acceleration A_i = max |ẍ_i + g|
    /// (SPEC §6, demands) on the segments' series. Measured, it adds 15–20 %
    /// to a peaks-only run of the presets (more with improved Kelvin at a
    /// loose contact tolerance), so spectra, maps and the peaks-only bench
    /// skip it; A_i is then NaN in the result, never a value that looks measured.
    pub absolute_acceleration: bool,
    /// Advance the quiet sample intervals of a record (and of its free tail)
    /// by the linear map of [`super::sample`] where bounds show nothing can
    /// happen in them. Off, every interval takes the segments' series: the
    /// same results to round-off, kept so that tests can compare the two.
    pub quiet_samples: bool,
}

/// The extremes of each contact a run locates besides the four peaks.
///
/// Each is the maximum of a series over the contact's segments, found as
/// the peaks are, and in a contact-heavy run they cost a fifth of its time
/// (set 2, improved Kelvin). A quantity not located is NaN in the result,
/// never a value that looks measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum ContactExtremes {
    /// Neither: each impact's peak force and maximum penetration, and the
    /// run's largest and smallest force, are NaN once it has an impact.
    None,
    /// Each impact's peak force and the run's largest and smallest force
    /// (what a map reports); each impact's maximum penetration is NaN.
    Forces,
    /// The forces and each impact's maximum penetration.
    All,
}

impl Default for ExactOptions {
    fn default() -> Self {
        ExactOptions {
            excitation: Excitation::Sine,
            initial_displacement: [0.0; 2],
            initial_velocity: [0.0; 2],
            energy: true,
            max_events: None,
            contact_tolerance: crate::model::params::CONTACT_TOLERANCE,
            extremes: ContactExtremes::All,
            absolute_acceleration: true,
            quiet_samples: true,
        }
    }
}

impl ExactOptions {
    /// The exact method's options for a run of `p` that Newmark makes with
    /// `o`: the same ground motion and initial state, and the set's
    /// contact tolerance.
    pub fn matching(p: &Params, o: &SolverOptions) -> Self {
        ExactOptions {
            excitation: o.excitation.clone(),
            initial_displacement: o.initial_displacement,
            initial_velocity: o.initial_velocity,
            contact_tolerance: p.contact_tolerance,
            ..ExactOptions::default()
        }
    }
}

/// Runs `p` (which must have passed [`Params::validate`]) with the exact method.
pub fn simulate<O: Observer>(p: &Params, options: &ExactOptions, observer: &mut O) -> RunResult {
    let mut run = Run::new(p, options);
    run.sample_now(observer);
    run.time_loop(observer);
    run.finish()
}

struct Run<'a> {
    p: &'a Params,
    options: &'a ExactOptions,
    structures: [Structure; 2],
    tau: f64,
    x: [f64; 2],
    v: [f64; 2],
    branch: [Branch; 2],
    /// Q/m of each structure's branch (SPEC §3), for the quiet segments.
    loads: [f64; 2],
    contact: Option<ContactLaw>,
    /// The open impact, an index into `result.impacts`.
    open_impact: Option<usize>,
    /// Length of a free segment.
    free_step: f64,
    /// Output grid spacing for observers (Δτ of the parameter set).
    sample_step: f64,
    /// Index of the next output instant k · Δτ.
    next_sample: u64,
    events: usize,
    /// Segments taken (the run's `steps`).
    segments: usize,
    /// The segment count at which the observer is next polled.
    next_poll: usize,
    max_events: usize,
    max_segments: usize,
    work: Work,
    /// max over τ of x1 − x2 so far (SPEC §11).
    max_relative_displacement: f64,
    /// The quiet segments, longest first: one of `QUIET_FRACTION` of a free
    /// segment, and before it a longer one where one structure is far
    /// faster than the other; none where the excitation is not a sine.
    quiet: [Option<QuietStep>; 2],
    /// (sin τ, cos τ) at `phasor_tau`, carried across quiet segments by
    /// rotation through each segment's angle.
    phasor: [f64; 2],
    phasor_tau: f64,
    /// The record's quiet-sample maps, per structure and branch kind, where
    /// the excitation is a record sampled finely enough ([`SampleMap::new`]).
    samples: Option<[[SampleMap; 2]; 2]>,
    /// (τ, k): the instant at which the last quiet sample ended and the
    /// sample interval k that starts there.
    sample_cursor: (f64, usize),
    /// The long quiet segment is not tried again before this instant after it failed.
    long_quiet_from: f64,
    /// Rotations since the phasor was last taken from sin_cos.
    turns: u32,
    /// The contact recurrence's constants, made at the first analytic
    /// contact segment (a run without one never needs them).
    recurrence: std::cell::OnceCell<Box<ContactRecurrence>>,
    /// Next step of a Hertz-type contact phase (0: not yet chosen).
    rk_step: std::cell::Cell<f64>,
    result: RunResult,
}

impl<'a> Run<'a> {
    fn new(p: &'a Params, options: &'a ExactOptions) -> Self {
        let structures = Structure::pair(p);
        let [x1, x2] = options.initial_displacement;
        let [v1, v2] = options.initial_velocity;
        let rate = structures[0].rate.max(structures[1].rate).max(1.0);
        let free_step = FREE_REACH / rate;
        let tau_end = p.tau_end();
        let mut run = Run {
            p,
            options,
            structures,
            tau: 0.0,
            x: [x1, x2],
            v: [v1, v2],
            branch: [
                structures[0].initial_branch(x1, v1),
                structures[1].initial_branch(x2, v2),
            ],
            loads: [0.0; 2],
            contact: None,
            open_impact: None,
            free_step,
            sample_step: p.dt,
            next_sample: 1,
            events: 0,
            segments: 0,
            next_poll: POLL_EVERY,
            max_events: options
                .max_events
                .unwrap_or(EVENT_ALLOWANCE + EVENTS_PER_CYCLE * p.cycles as usize),
            // Free segments needed, times a margin for events and contact segments.
            max_segments: 1_000_000 + (100.0 * tau_end / free_step).min(1e9) as usize,
            work: Work::default(),
            max_relative_displacement: x1 - x2,
            quiet: if matches!(options.excitation, Excitation::Sine | Excitation::None) {
                let slower = structures[0].rate.min(structures[1].rate).max(1.0);
                let short = QUIET_FRACTION * free_step;
                let long = QUIET_FRACTION / slower;
                [
                    (long >= LONG_QUIET_RATIO * short)
                        .then(|| QuietStep::new(&structures, long, FREE_DEGREE)),
                    Some(QuietStep::new(&structures, short, FREE_DEGREE)),
                ]
            } else {
                [None, None]
            },
            samples: match &options.excitation {
                Excitation::Record(m) if options.quiet_samples => {
                    let h = m.record.dt * m.omega;
                    // A peak inside a sample is located on the series a free
                    // segment over the sample would take, of its degree.
                    let series_degree = short_free_degree(h / free_step);
                    let map = |s: &Structure, k: f64| {
                        SampleMap::new(s, k, h, FREE_DEGREE, options.energy).map(|mut m| {
                            m.series_degree = series_degree;
                            m
                        })
                    };
                    let maps =
                        structures.map(|s| [map(&s, s.stiffness), map(&s, s.alpha * s.stiffness)]);
                    match maps {
                        [[Some(a), Some(b)], [Some(c), Some(d)]] => Some([[a, b], [c, d]]),
                        _ => None,
                    }
                }
                _ => None,
            },
            sample_cursor: (f64::NAN, 0),
            phasor: [0.0, 1.0],
            phasor_tau: f64::NAN,
            long_quiet_from: 0.0,
            turns: 0,
            recurrence: std::cell::OnceCell::new(),
            rk_step: std::cell::Cell::new(0.0),
            result: RunResult {
                completed: true,
                method: Method::Exact,
                ..RunResult::default()
            },
        };
        run.result.impacts.reserve(32);
        run.update_loads();
        for i in 0..2 {
            let peaks = run.result.structure_mut(i);
            peaks.peak_displacement = run.x[i].abs();
            peaks.peak_velocity = run.v[i].abs();
            peaks.yielded = matches!(run.branch[i], Branch::Yielded { .. });
        }
        let delta = x1 - x2 - p.gap;
        if delta > 0.0 || (delta == 0.0 && v1 > v2) {
            run.begin_contact();
        }
        for (i, a) in run.absolute_accelerations().into_iter().enumerate() {
            run.result.structure_mut(i).raise_absolute_acceleration(a);
        }
        run
    }

    fn stop(&mut self, reason: StopReason) {
        self.result.completed = false;
        self.result.stop = Some(Stop {
            tau: self.tau,
            reason,
        });
    }

    fn time_loop<O: Observer>(&mut self, observer: &mut O) {
        let tau_end = self.p.tau_end();

        let mut ground = Series {
            degree: CONTACT_DEGREE.max(FREE_DEGREE),
            ..Series::default()
        };
        // Rebuilt in place by each segment that needs series.
        let mut segment = Segment::default();
        while self.tau < tau_end {
            self.segments += 1;
            let segments = self.segments;
            if segments >= self.next_poll {
                self.next_poll = segments + POLL_EVERY;
                observer.reached(self.tau);
                if !observer.keep_going() {
                    self.stop(StopReason::Cancelled);
                    return;
                }
            }
            if segments > self.max_segments {
                self.stop(StopReason::StepCap);
                return;
            }
            if !(self.x[0] + self.x[1] + self.v[0] + self.v[1]).is_finite() {
                self.stop(StopReason::NonFinite);
                return;
            }
            // Borrowed for the run (`options` outlives it): no count per segment.
            let options = self.options;
            let excitation = &options.excitation;
            let to_end = tau_end - self.tau;
            // With no samples to hand over, a quiet free segment needs no
            // series; nor, with its work in closed form, a record's quiet sample.
            if !O::RECORDS && self.contact.is_none() {
                let quiet = if self.samples.is_some() {
                    self.quiet_sample(to_end)
                } else {
                    !self.options.energy
                        && (self.quiet_segment::<0>(to_end) || self.quiet_segment::<1>(to_end))
                };
                if quiet {
                    continue;
                }
            }
            let reach = (tau_end - self.tau).min(excitation.next_break(self.tau) - self.tau);
            excitation.taylor(self.tau, &mut ground.c[..=ground.degree]);
            match self.contact {
                None => self.free_segment(&ground, reach, &mut segment),
                Some(law) => self.contact_segment(&law, &ground, reach, &mut segment),
            }
            let (length, event) = segment.end;
            self.account(&segment, &ground, length, observer);
            self.advance(&segment, length);
            if let Some(event) = event {
                self.events += 1;
                if self.events > self.max_events {
                    self.stop(StopReason::EventCap);
                    return;
                }
                self.switch(event);
                if O::RECORDS {
                    observer.record(&self.sample(self.tau));
                }
            }
            if event.is_none() && length >= to_end {
                // The last segment lands exactly on τ_end.
                self.tau = tau_end;
            }
        }
    }

    /// Advances one free segment by the transition matrices if bounds show
    /// that no event can happen in it and no peak can rise; returns whether it did.
    ///
    /// Each test tries the plain swing bound first (|q − q₀| ≤ swing) and
    /// then the cubic majorant of [`Majorants`], which also clears the
    /// segments near an extremum that the swing cannot: a displacement near
    /// its running peak, a spring near yield, a gap closing and reopening.
    /// `level` indexes `quiet`; a segment that would pass `to_end` is not taken.
    #[inline(always)]
    fn quiet_segment<const LEVEL: usize>(&mut self, to_end: f64) -> bool {
        let h = match &self.quiet[LEVEL] {
            Some(q) if to_end > q.length && (LEVEL > 0 || self.tau >= self.long_quiet_from) => {
                q.length
            }
            _ => return false,
        };
        let quiet = self.quiet_advance::<LEVEL>();
        if !quiet && LEVEL == 0 {
            self.long_quiet_from = self.tau + LONG_QUIET_RETRY * h;
        }
        quiet
    }

    fn quiet_advance<const LEVEL: usize>(&mut self) -> bool {
        let phasor = self.quiet_phasor();
        let Some(QuietStep {
            length: h,
            turn,
            transitions,
        }) = &self.quiet[LEVEL]
        else {
            return false;
        };
        let (h, turn) = (*h, *turn);
        let mut next = [[0.0; 2]; 2];
        let mut local = [None; 2];
        let mut swings = [[0.0; 2]; 2];
        for i in 0..2 {
            let load = self.loads[i];
            let t = &transitions[i][self.branch[i].kind()];
            let (x, v) = (self.x[i], self.v[i]);
            let (inputs, equilibrium) = t.inputs(x, v, phasor, load);
            let [sx, sv] = t.swing(&inputs);
            if !(sx + sv).is_finite() {
                return false;
            }
            let peaks = self.result.structure(i);
            let (px, pv) = (peaks.peak_displacement, peaks.peak_velocity);
            // Without A to locate, its test always passes.
            let pa = if self.options.absolute_acceleration {
                peaks.peak_absolute_acceleration
            } else {
                f64::INFINITY
            };
            let bands = Bands::new(
                self.branch[i],
                self.structures[i].yield_displacement,
                px,
                pv,
                pa,
            );
            // The swing bounds first; the majorants only where they fail.
            // ẍ + g = Q/m − (c/m) ẋ − (K/m) x within its running peak.
            let accel = load - t.damping * v - t.stiffness * x;
            let within_a = accel.abs() + t.damping * sv + t.stiffness * sx < pa;
            if !(within_a && bands.hold_by_swings(x, v, [sx, sv])) {
                let m = Majorants::new(t, x, v, phasor, load, [sx, sv]);
                let a = (!within_a)
                    .then(|| acceleration::majorant(&m.x, &m.v, t.stiffness, t.damping, load));
                if !bands.hold_by_majorants(&m.x, &m.v, a, h) {
                    return false;
                }
                local[i] = Some(m.x);
            }
            swings[i] = [sx, sv];
            next[i] = t.advance(&inputs, equilibrium);
        }
        // x1 − x2 must stay below the gap (no onset) and, until a first
        // impact, below its running maximum (the minimum gap of SPEC §11).
        let ceiling = if self.result.impacts.is_empty() {
            self.p.gap.min(self.max_relative_displacement)
        } else {
            self.p.gap
        };
        let relative = self.x[0] - self.x[1];
        if !(relative + swings[0][0] + swings[1][0] < ceiling) {
            let [a, b] = [0, 1].map(|i| {
                local[i].unwrap_or_else(|| {
                    let t = &transitions[i][self.branch[i].kind()];
                    let (x, v) = (self.x[i], self.v[i]);
                    Majorants::new(t, x, v, phasor, self.loads[i], swings[i]).x
                })
            });
            let gap_majorant = [a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] + b[3]];
            if !stays_below(&gap_majorant, ceiling, h) {
                return false;
            }
        }
        self.x = next.map(|y| y[0]);
        self.v = next.map(|y| y[1]);
        self.tau += h;
        // sin(τ + h) and cos(τ + h) by the angle-sum rule.
        let ([s, c], [sh, ch]) = (phasor, turn);
        self.phasor = [s * ch + c * sh, c * ch - s * sh];
        self.phasor_tau = self.tau;
        self.turns += 1;
        true
    }

    /// Advances one sample interval of a record [τ_k, τ_{k+1}] (or an interval
    /// of the same length in the free tail after it) by the maps of
    /// [`super::sample`] if bounds show that no event can happen in it and
    /// no peak can rise; returns whether it did. Only from a sample: an
    /// interval begun elsewhere (after an event) is left to the series.
    fn quiet_sample(&mut self, to_end: f64) -> bool {
        let Some(maps) = &self.samples else {
            return false;
        };
        let h = maps[0][0].length;
        let options = self.options;
        let Excitation::Record(motion) = &options.excitation else {
            return false;
        };
        // Sample k of the record: known where the last quiet sample ended,
        // else located (and g then taken at τ itself).
        let at_cursor = self.tau == self.sample_cursor.0;
        let k = if at_cursor {
            self.sample_cursor.1
        } else {
            motion.interval(self.tau)
        };
        let (end, ground, next_k) = match motion.at_sample(k) {
            Some((next, ground)) => {
                // The interval's length is h to the rounding of τ: a longer or
                // shorter one (begun after an event) is not this map's.
                if !((next - self.tau - h).abs() <= 8.0 * f64::EPSILON * next) {
                    return false;
                }
                let ground = if at_cursor {
                    ground
                } else {
                    self.options.excitation.phasor(self.tau)
                };
                (next, ground, k + 1)
            }
            // The free tail after the record: g = 0.
            None => (self.tau + h, [0.0; 2], k),
        };
        if !(end - self.tau < to_end) {
            return false;
        }
        if !self.sample_interval(end, ground, next_k) {
            return false;
        }
        self.quiet_run(to_end - h);
        true
    }

    /// One sample interval from τ to `end` under g = g_k + s t (`ground`),
    /// `next_k` the interval after it, by the map if [`sample::clear`]
    /// clears both structures (peaks inside located) and x1 − x2 stays
    /// below the gap; returns whether it did.
    fn sample_interval(&mut self, end: f64, ground: [f64; 2], next_k: usize) -> bool {
        self.sample_interval_from(end, ground, next_k, [None; 2], None)
    }

    /// [`Run::sample_interval`] with what the tight loop's bounds already
    /// cleared: a structure's part (`known`) and the running maximum of
    /// x1 − x2 where x1 − x2 cleared (`relative`), taken as they are.
    fn sample_interval_from(
        &mut self,
        end: f64,
        ground: [f64; 2],
        next_k: usize,
        known: [Option<sample::Cleared>; 2],
        relative: Option<f64>,
    ) -> bool {
        let Some(maps) = &self.samples else {
            return false;
        };
        let h = maps[0][0].length;
        let mut cleared = known;
        for i in 0..2 {
            if cleared[i].is_some() {
                continue;
            }
            let peaks = self.result.structure(i);
            let limits = Limits {
                displacement: peaks.peak_displacement,
                velocity: peaks.peak_velocity,
                absolute_acceleration: if self.options.absolute_acceleration {
                    peaks.peak_absolute_acceleration
                } else {
                    f64::INFINITY
                },
                branch: self.branch[i],
                yield_displacement: self.structures[i].yield_displacement,
            };
            let map = &maps[i][self.branch[i].kind()];
            match sample::clear(map, self.x[i], self.v[i], ground, self.loads[i], &limits) {
                Some(c) => cleared[i] = Some(c),
                None => return false,
            }
        }
        let [Some(a), Some(b)] = cleared else {
            return false;
        };
        // x1 − x2 must stay below the gap (no onset) and, until a first
        // impact, below its running maximum (the minimum gap of SPEC §11).
        let ceiling = if self.result.impacts.is_empty() {
            self.p.gap.min(self.max_relative_displacement)
        } else {
            self.p.gap
        };
        let relative_now = self.x[0] - self.x[1];
        let mut max_relative = self.max_relative_displacement;
        let rate = self.v[0] - self.v[1];
        if let Some(top) = relative {
            if self.result.impacts.is_empty() {
                max_relative = top;
            }
        } else if relative_now + a.swing[0] + b.swing[0] < ceiling {
            // Clear by the swings.
        } else if rate.abs() > a.swing[1] + b.swing[1] {
            // x1 − x2 monotone: its largest value is at an end, below the gap,
            // and it raises Π_d,min there.
            let top = relative_now.max(a.end[0] - b.end[0]);
            if !sample::below(top, self.p.gap) {
                return false;
            }
            if self.result.impacts.is_empty() {
                max_relative = max_relative.max(top);
            }
        } else {
            let [ma, mb] = [(0, a), (1, b)].map(|(i, c)| {
                c.majorant_x.unwrap_or_else(|| {
                    let map = &maps[i][self.branch[i].kind()];
                    SampleMajorants::new(
                        map,
                        self.x[i],
                        self.v[i],
                        ground,
                        self.loads[i],
                        map.swing(&map.inputs(self.x[i], self.v[i], ground, self.loads[i]).0),
                    )
                    .x
                })
            });
            let gap_majorant = [ma[0] - mb[0], ma[1] - mb[1], ma[2] - mb[2], ma[3] + mb[3]];
            if !stays_below(&gap_majorant, ceiling, h) {
                // Below the gap, only Π_d,min's running maximum may rise:
                // it is located on the two structures' series, as a
                // segment would locate it.
                if !(ceiling < self.p.gap && stays_below(&gap_majorant, self.p.gap, h)) {
                    return false;
                }
                let [sa, sb] = [0, 1].map(|i| {
                    let map = &maps[i][self.branch[i].kind()];
                    IntervalSeries::new(
                        map.stiffness,
                        map.damping,
                        self.loads[i],
                        [self.x[i], self.v[i]],
                        ground,
                        map.series_degree,
                    )
                });
                let swing = a.swing[0] + b.swing[0];
                raise_relative([&sa, &sb], h, swing, &mut max_relative);
            }
        }
        if self.options.energy {
            let terms = [(0, a), (1, b)].map(|(i, c)| {
                let map = &maps[i][self.branch[i].kind()];
                sample::work(
                    map,
                    self.structures[i].mass,
                    &c.inputs,
                    self.loads[i],
                    [self.x[i], c.end[0]],
                )
            });
            self.work.add_quiet(terms);
        }
        self.max_relative_displacement = max_relative;
        for (i, c) in [(0, a), (1, b)] {
            let peaks = self.result.structure_mut(i);
            peaks.peak_displacement = c.peaks[0];
            peaks.peak_velocity = c.peaks[1];
            if self.options.absolute_acceleration {
                peaks.peak_absolute_acceleration = c.peaks[2];
            }
        }
        self.x = [a.end[0], b.end[0]];
        self.v = [a.end[1], b.end[1]];
        self.tau = end;
        self.sample_cursor = (end, next_k);
        true
    }

    /// After a quiet sample, the samples that follow it while the bounds of
    /// [`super::sample_run`] clear them, in one tight loop: each of x, ẋ,
    /// |ẍ + g| and x1 − x2 either stays inside its band by its chord margin
    /// or is monotone over the interval with its end inside the event band,
    /// and then raises its running peak at that end; where nothing comes
    /// near a peak or an event, [`BLOCK`] samples at a time. The branches
    /// stand still, so the event bands are made once. A sample these bounds
    /// do not clear is settled in the loop where only an extremum near its
    /// running peak stood in the way ([`super::sample_settle`]); else it is
    /// taken by [`Run::sample_interval`] (majorants, peaks located inside);
    /// if that fails too (an event), it is left to the series. Stops at the next poll of the
    /// observer (a block may pass it by fewer than [`BLOCK`] samples).
    fn quiet_run(&mut self, to_end: f64) {
        match (self.options.absolute_acceleration, self.options.energy) {
            (false, false) => self.quiet_run_with::<false, false>(to_end),
            (false, true) => self.quiet_run_with::<false, true>(to_end),
            (true, false) => self.quiet_run_with::<true, false>(to_end),
            (true, true) => self.quiet_run_with::<true, true>(to_end),
        }
    }

    /// [`Run::quiet_run`] with |ẍ + g| held to its running peak where
    /// `ACCEL` and the work integrated where `ENERGY`. g_k and the slope s
    /// are taken from the record by products with its factor and the
    /// factor over h (a unit in the last place from
    /// [`crate::model::RecordMotion::at_sample`]'s quotients).
    ///
    /// x1 − x2 must stay below the gap (no onset) and, until a first
    /// impact, its running maximum (the minimum gap of SPEC §11) is raised
    /// where it is monotone; after one, that maximum no longer moves (it is
    /// carried as ∞ in the loop and not written back).
    fn quiet_run_with<const ACCEL: bool, const ENERGY: bool>(&mut self, to_end: f64) {
        let options = self.options;
        let (Some(maps), Excitation::Record(motion)) = (&self.samples, &options.excitation) else {
            return;
        };
        let tau_end = self.tau + to_end;
        let h = maps[0][0].length;
        let [m0, m1] = [0, 1].map(|i| maps[i][self.branch[i].kind()]);
        let loads = self.loads;
        let lanes = [m0.lane(loads[0]), m1.lane(loads[1])];
        let watch =
            [0, 1].map(|i| Watch::new(self.branch[i], self.structures[i].yield_displacement));
        let pair = Pair::new(lanes, watch, h, self.p.gap);
        let degree = m0.series_degree;
        let masses = [self.structures[0].mass, self.structures[1].mass];
        let pair_work = PairWork::new([&m0, &m1], [&lanes[0], &lanes[1]], masses);
        let track_relative = self.result.impacts.is_empty();
        let record = &motion.record.acceleration;
        let factor = motion.scale / motion.amplitude;
        let per_step = factor / h;
        let (mut x, mut v, mut tau) = (self.x, self.v, self.tau);
        let mut peaks = self.running_peaks::<ACCEL>(track_relative);
        // The work integrals in a local copy, the same sums in the same
        // order, so that they do not wait on memory from one sample to the next.
        let mut work = self.work;
        let mut sums = DampingSums::default();
        let (mut k, mut taken) = (self.sample_cursor.1, 0);
        // Samples up to the next poll; the last block may pass it by up to
        // BLOCK − 1, and the poll then comes with the next segment.
        let budget = self.next_poll.saturating_sub(self.segments + 1);
        // Samples to take one by one before the next block is tried.
        let mut single = 0;
        let mut ends = [[[0.0; 2]; 2]; BLOCK];
        let mut grounds = [[0.0; 2]; BLOCK];
        while taken < budget {
            // A block of samples by one test, wholly inside the record or
            // wholly in its free tail.
            if single == 0 {
                let block = if let Some(a) = record.get(k..k + BLOCK + 1) {
                    for (j, ground) in grounds.iter_mut().enumerate() {
                        *ground = [a[j] * factor, (a[j + 1] - a[j]) * per_step];
                    }
                    Some(((k + BLOCK) as f64 * h, k + BLOCK))
                } else if k + 2 > record.len() {
                    grounds = [[0.0; 2]; BLOCK];
                    Some(((0..BLOCK).fold(tau, |t, _| t + h), k))
                } else {
                    None
                };
                if let Some((end, next_k)) = block
                    && end < tau_end
                {
                    if pair.block::<ACCEL, BLOCK>(x, v, &grounds, &peaks, &mut ends) {
                        if ENERGY {
                            let mut start = [x, v];
                            for (&ground, end) in grounds.iter().zip(&ends) {
                                let [x, v] = start;
                                let terms = pair_work.terms(&mut sums, x, v, ground, end[0]);
                                work.add_input_and_spring(terms);
                                start = *end;
                            }
                        }
                        [x, v] = ends[BLOCK - 1];
                        (tau, k) = (end, next_k);
                        taken += BLOCK;
                        continue;
                    }
                    single = BLOCK;
                }
            }
            single = single.saturating_sub(1);
            // Inside the record τ = k h and the interval ends at (k + 1) h:
            // the cursor stands on a sample (quiet_sample checked it).
            let (end, ground, next_k) = match record.get(k..k + 2) {
                Some(&[a0, a1]) => (
                    (k + 1) as f64 * h,
                    [a0 * factor, (a1 - a0) * per_step],
                    k + 1,
                ),
                // The free tail after the record: g = 0.
                _ => (tau + h, [0.0; 2], k),
            };
            if !(end < tau_end) {
                break;
            }
            let mut step = pair.step::<ACCEL>(x, v, ground, &peaks);
            if !step.clear
                && let Some(settled) = pair.settle::<ACCEL>(x, v, ground, &peaks, degree)
            {
                step = settled;
            }
            if !step.clear {
                // Not cleared: the full tests of one sample (majorants, peaks
                // located inside), on the same branches; if they clear it,
                // the run goes on from the peaks they raised.
                if ENERGY {
                    work.add_damping(pair_work.damping(&sums));
                    sums = DampingSums::default();
                }
                (self.x, self.v, self.tau, self.work) = (x, v, tau, work);
                self.sample_cursor = (tau, k);
                self.set_running_peaks::<ACCEL>(&peaks, track_relative);
                let known = [0, 1].map(|i| {
                    step.cleared[i].then(|| {
                        let map = if i == 0 { &m0 } else { &m1 };
                        let inputs = lanes[i].inputs(x[i], v[i], ground);
                        sample::Cleared {
                            end: [step.x[i], step.v[i]],
                            inputs,
                            swing: map.swing(&inputs),
                            majorant_x: None,
                            peaks: [step.peaks.x[i], step.peaks.v[i], step.peaks.a[i]],
                        }
                    })
                });
                let relative = step.cleared[2].then_some(step.peaks.relative);
                if self.sample_interval_from(end, ground, next_k, known, relative) {
                    (x, v, tau, k, work) = (self.x, self.v, self.tau, next_k, self.work);
                    peaks = self.running_peaks::<ACCEL>(track_relative);
                    taken += 1;
                    continue;
                }
                self.segments += taken;
                return;
            }
            if ENERGY {
                work.add_input_and_spring(pair_work.terms(&mut sums, x, v, ground, step.x));
            }
            (x, v, peaks) = (step.x, step.v, step.peaks);
            tau = end;
            k = next_k;
            taken += 1;
        }
        if ENERGY {
            work.add_damping(pair_work.damping(&sums));
        }
        self.x = x;
        self.v = v;
        self.tau = tau;
        self.work = work;
        self.set_running_peaks::<ACCEL>(&peaks, track_relative);
        self.sample_cursor = (tau, k);
        self.segments += taken;
    }

    /// Both structures' running peaks of |x|, |ẋ| and, where `ACCEL`,
    /// |ẍ + g| (∞ where it is not located, so that it never binds), and,
    /// where `track_relative`, the running maximum of x1 − x2 (else ∞).
    fn running_peaks<const ACCEL: bool>(&self, track_relative: bool) -> Peaks {
        let [l, r] = [0, 1].map(|i| self.result.structure(i));
        Peaks {
            x: [l.peak_displacement, r.peak_displacement],
            v: [l.peak_velocity, r.peak_velocity],
            a: if ACCEL {
                [l.peak_absolute_acceleration, r.peak_absolute_acceleration]
            } else {
                [f64::INFINITY; 2]
            },
            relative: if track_relative {
                self.max_relative_displacement
            } else {
                f64::INFINITY
            },
        }
    }

    /// The inverse of [`Run::running_peaks`].
    fn set_running_peaks<const ACCEL: bool>(&mut self, peaks: &Peaks, track_relative: bool) {
        for i in 0..2 {
            let p = self.result.structure_mut(i);
            p.peak_displacement = peaks.x[i];
            p.peak_velocity = peaks.v[i];
            if ACCEL {
                p.peak_absolute_acceleration = peaks.a[i];
            }
        }
        if track_relative {
            self.max_relative_displacement = peaks.relative;
        }
    }

    /// The excitation's phasor at τ for a quiet segment: rotated on from the
    /// last quiet segment when this one follows it, else evaluated afresh
    /// (and afresh every [`PHASOR_TURNS`] rotations, which bounds the
    /// rotations' round-off to a few units in the last place).
    #[inline]
    fn quiet_phasor(&mut self) -> [f64; 2] {
        if self.phasor_tau != self.tau || self.turns >= PHASOR_TURNS {
            self.phasor = self.options.excitation.phasor(self.tau);
            self.phasor_tau = self.tau;
            self.turns = 0;
        }
        self.phasor
    }

    /// Both structures out of contact, each on its own branch.
    fn free_segment(&self, ground: &Series, reach: f64, segment: &mut Segment) {
        let length = self.free_step.min(reach);
        // A record's sample intervals are short: their series need fewer terms.
        let degree = if self.samples.is_some() {
            short_free_degree(length / self.free_step)
        } else {
            FREE_DEGREE
        };
        free_series(
            &self.structures,
            self.branch,
            self.x,
            self.v,
            ground,
            degree,
            &mut segment.x,
        );
        segment.open(length, false);
        if self.p.gap.is_finite() {
            let delta0 = self.x[0] - self.x[1] - self.p.gap;
            if delta0 + segment.swing[0] + segment.swing[1] >= 0.0 {
                segment.write_gap_function(self.p.gap, 1.0);
                cut(&mut segment.end, &segment.gap_function, Event::Onset);
            }
        }
        self.spring_events(segment);
    }

    /// Both structures coupled through the contact law.
    fn contact_segment(
        &self,
        law: &ContactLaw,
        ground: &Series,
        reach: f64,
        segment: &mut Segment,
    ) {
        if !law.is_analytic() {
            return self.contact_rk_segment(law, ground, reach, segment);
        }
        let recurrence = self
            .recurrence
            .get_or_init(|| Box::new(ContactRecurrence::new(&self.structures)));
        recurrence.series(
            &self.structures,
            self.branch,
            self.x,
            self.v,
            self.p.gap,
            law,
            ground,
            CONTACT_DEGREE,
            &mut segment.x,
            &mut segment.force,
        );
        let impact = &self.result.impacts[self.open_impact.expect("contact has an impact")];
        let scale = impact
            .approach_velocity
            .abs()
            .max(self.p.min_impact_velocity)
            / self.p.contact_omega;
        let h = step_for(
            &[&segment.x[0], &segment.x[1]],
            self.options.contact_tolerance * scale,
        )
        .min(CONTACT_REACH / self.p.contact_omega)
        .min(self.free_step)
        .min(reach);
        segment.open(h, true);
        self.contact_events(segment);
    }

    /// A Hertz-type contact: one Runge–Kutta step ([`super::contact_rk`]).
    fn contact_rk_segment(
        &self,
        law: &ContactLaw,
        ground: &Series,
        reach: f64,
        segment: &mut Segment,
    ) {
        let impact = &self.result.impacts[self.open_impact.expect("contact has an impact")];
        let v0 = impact
            .approach_velocity
            .abs()
            .max(self.p.min_impact_velocity);
        let system = ContactSystem {
            structures: &self.structures,
            branch: self.branch,
            gap: self.p.gap,
            law,
            ground,
        };
        let guess = match self.rk_step.get() {
            h if h > 0.0 => h,
            _ => 0.01 / self.p.contact_omega,
        };
        let piece = system.step(
            self.x,
            self.v,
            guess,
            self.free_step.min(reach),
            self.options.contact_tolerance,
            v0 / self.p.contact_omega,
            v0,
        );
        self.rk_step.set(piece.next);
        segment.x = piece.x;
        segment.force = piece.force;
        segment.open(piece.h, true);
        self.contact_events(segment);
    }

    /// The events of a contact segment: separation (δ falls to 0) and the
    /// springs'. Keeps the opening (−δ) for the impact's extremes.
    fn contact_events(&self, segment: &mut Segment) {
        segment.write_gap_function(self.p.gap, -1.0);
        cut(&mut segment.end, &segment.gap_function, Event::Separation);
        self.spring_events(segment);
    }

    fn spring_events(&self, segment: &mut Segment) {
        for i in 0..2 {
            match self.branch[i] {
                Branch::Elastic { offset } => {
                    let uy = self.structures[i].yield_displacement;
                    let z0 = self.x[i] - offset;
                    // Each side of the yield surface only where z can reach it.
                    let swing = segment.swing[i];
                    let (up, down) = (z0 + swing >= uy, -z0 + swing >= uy);
                    if uy.is_finite() && (up || down) {
                        let z = segment.x[i].shifted(offset);
                        if up {
                            segment.consider(&z.shifted(uy), Event::Yield(i, 1.0));
                        }
                        if down {
                            segment.consider(&z.scaled(-1.0).shifted(uy), Event::Yield(i, -1.0));
                        }
                    }
                }
                Branch::Yielded { sign } => {
                    if -sign * self.v[i] + segment.swing[2 + i] >= 0.0 {
                        let back = segment.v[i].scaled(-sign);
                        segment.consider(&back, Event::Unload(i));
                    }
                }
            }
        }
    }

    /// Peaks, impact extremes, work and samples over [0, length] of the segment.
    fn account<O: Observer>(
        &mut self,
        segment: &Segment,
        ground: &Series,
        length: f64,
        observer: &mut O,
    ) {
        for i in 0..2 {
            let peaks = self.result.structure_mut(i);
            raise_abs_max(
                &segment.x[i],
                Some(&segment.v[i]),
                length,
                segment.swing[i],
                &mut peaks.peak_displacement,
            );
            // ẍ's series only where a walk for ẋ's peak needs it.
            raise_abs_max(
                &segment.v[i],
                None,
                length,
                segment.swing[2 + i],
                &mut peaks.peak_velocity,
            );
        }
        let force = self
            .options
            .absolute_acceleration
            .then(|| segment.force().map(|f| (f, f.swing(length))));
        for i in 0..2 {
            let Some(force) = force else { break };
            raise_absolute_acceleration(
                &self.structures[i],
                self.branch[i],
                i,
                &segment.x[i],
                &segment.v[i],
                [segment.swing[i], segment.swing[2 + i]],
                force,
                length,
                &mut self.result.structure_mut(i).peak_absolute_acceleration,
            );
        }
        // Until a first impact the run is the no-pounding run, and the maximum
        // of x1 − x2 is the gap that would prevent pounding (SPEC §11); it
        // can rise only where its bound does. After an impact it means nothing.
        if self.result.impacts.is_empty()
            && self.x[0] - self.x[1] + segment.swing[0] + segment.swing[1]
                > self.max_relative_displacement
        {
            let relative = segment.x[0].minus(&segment.x[1]);
            raise_max(
                &relative,
                None,
                1.0,
                length,
                relative.swing(length),
                &mut self.max_relative_displacement,
            );
        }
        let extremes = self.options.extremes;
        if extremes > ContactExtremes::None
            && let (Some(force), Some(k)) = (segment.force(), self.open_impact)
        {
            let r = &mut self.result;
            let imp = &mut r.impacts[k];
            // Each extreme is searched only where its bound can beat it; the
            // penetration's swing is at most the sum of the two displacements'.
            if extremes == ContactExtremes::All {
                let swing = segment.swing[0] + segment.swing[1];
                // δ = −opening.
                raise_max(
                    &segment.gap_function,
                    None,
                    -1.0,
                    length,
                    swing,
                    &mut imp.max_penetration,
                );
            }
            let force_swing = force.swing(length);
            raise_max(force, None, 1.0, length, force_swing, &mut imp.peak_force);
            r.max_force = r.max_force.max(imp.peak_force);
            let mut pull = -r.min_force;
            raise_max(force, None, -1.0, length, force_swing, &mut pull);
            // A pull within round-off of zero (δ ≈ ±1e-17 at a located onset) is no pull.
            if pull > 1e-9 * r.max_force {
                r.min_force = -pull;
            }
        }
        if self.options.energy {
            self.work
                .add(&self.structures, self.branch, segment, ground, length);
        }
        if O::RECORDS {
            let end = self.tau + length;
            loop {
                let t = self.next_sample as f64 * self.sample_step;
                if t >= end {
                    break;
                }
                observer.record(&segment.sample(self, t - self.tau, t));
                self.next_sample += 1;
            }
        }
    }

    fn advance(&mut self, segment: &Segment, length: f64) {
        for i in 0..2 {
            let (x, v) = segment.x[i].value_slope(length);
            self.x[i] = x;
            self.v[i] = v;
        }
        self.tau += length;
    }

    fn switch(&mut self, event: Event) {
        match event {
            Event::Onset => self.begin_contact(),
            Event::Separation => {
                self.contact = None;
                if let Some(k) = self.open_impact.take() {
                    self.result.impacts[k].close(self.tau, self.v[0] - self.v[1]);
                }
            }
            Event::Yield(i, sign) => {
                self.branch[i] = Branch::Yielded { sign };
                self.result.structure_mut(i).yielded = true;
            }
            Event::Unload(i) => {
                if let Branch::Yielded { sign } = self.branch[i] {
                    let uy = self.structures[i].yield_displacement;
                    let x = self.x[i];
                    // The spring turns back at ẋ = 0 with z = σΠ_uy. The state
                    // reached carries round-off of both: an ẋ a few 1e-18 on
                    // the loading side, or x − p one bit past Π_uy, would
                    // yield again at once and unload again after 1e-17.
                    // Both are set to the located values.
                    if sign * self.v[i] > 0.0 {
                        self.v[i] = 0.0;
                    }
                    let mut offset = x - sign * uy;
                    for _ in 0..4 {
                        if !(sign * (x - offset) > uy) {
                            break;
                        }
                        offset = if sign > 0.0 {
                            offset.next_up()
                        } else {
                            offset.next_down()
                        };
                    }
                    self.branch[i] = Branch::Elastic { offset };
                }
            }
        }
        self.update_loads();
    }

    /// Q/m of each branch, after a change of branch.
    fn update_loads(&mut self) {
        for i in 0..2 {
            let s = &self.structures[i];
            self.loads[i] = s.affine(self.branch[i]).1 / s.mass;
        }
    }

    /// Onset at the current instant: v₀ = δ̇ here (SPEC §4).
    fn begin_contact(&mut self) {
        let p = self.p;
        let rate = self.v[0] - self.v[1];
        let law = ContactConstants::of(p).law(rate);
        self.contact = Some(law);
        self.rk_step.set(0.0);
        let delta = self.x[0] - self.x[1] - p.gap;
        let extremes = self.options.extremes;
        let force = match extremes {
            ContactExtremes::None => f64::NAN,
            _ => law.force(delta.max(0.0), rate).force,
        };
        self.result.impacts.push(Impact {
            start: self.tau,
            end: self.tau,
            approach_velocity: rate,
            separation_velocity: 0.0,
            restitution: 0.0,
            peak_force: force,
            max_penetration: match extremes {
                ContactExtremes::All => delta.max(0.0),
                _ => f64::NAN,
            },
            ended: false,
        });
        if extremes == ContactExtremes::None {
            self.result.max_force = f64::NAN;
            self.result.min_force = f64::NAN;
        } else {
            self.result.max_force = self.result.max_force.max(force);
            self.result.min_force = self.result.min_force.min(force);
        }
        self.open_impact = Some(self.result.impacts.len() - 1);
    }

    fn sample_now<O: Observer>(&self, observer: &mut O) {
        if O::RECORDS {
            observer.record(&self.sample(self.tau));
        }
    }

    /// f_p at the current state (0 out of contact).
    fn contact_force(&self) -> f64 {
        let delta = self.x[0] - self.x[1] - self.p.gap;
        let rate = self.v[0] - self.v[1];
        match &self.contact {
            Some(law) => law.force(delta, rate).force,
            None => 0.0,
        }
    }

    /// ẍ_i + g of each structure at the current state, (∓f_p − c ẋ − f_s)/m
    /// (SPEC §2), with the force of the contact now open.
    fn absolute_accelerations(&self) -> [f64; 2] {
        let fp = self.contact_force();
        [0, 1].map(|i| {
            let s = &self.structures[i];
            let fs = s.spring_force(self.branch[i], self.x[i]);
            (push(i) * fp - s.damping * self.v[i] - fs) / s.mass
        })
    }

    /// The state at the current instant, for observers.
    fn sample(&self, tau: f64) -> Sample {
        let fs = [0, 1].map(|i| self.structures[i].spring_force(self.branch[i], self.x[i]));
        let fp = self.contact_force();
        let g = self.options.excitation.at(tau);
        let a = self.absolute_accelerations().map(|a| a - g);
        Sample {
            tau,
            x: self.x,
            v: self.v,
            a,
            fs,
            fp,
            in_contact: self.contact.is_some(),
        }
    }

    fn finish(mut self) -> RunResult {
        if let Some(k) = self.open_impact {
            self.result.impacts[k].end = self.tau;
        }
        if self.options.energy {
            let m = [self.structures[0].mass, self.structures[1].mass];
            let initial = 0.5
                * (m[0] * self.options.initial_velocity[0].powi(2)
                    + m[1] * self.options.initial_velocity[1].powi(2));
            self.result.energy = self.work.balance(m, self.v, initial);
        }
        for i in 0..2 {
            let s = &self.structures[i];
            let end = FinalSpring {
                stiffness: s.stiffness,
                yield_displacement: s.yield_displacement,
                alpha: s.alpha,
                displacement: self.x[i],
                elastic_part: s.elastic_part(self.branch[i], self.x[i]),
                force: s.spring_force(self.branch[i], self.x[i]),
                work: if self.options.energy {
                    self.result.energy.spring_by_structure[i]
                } else {
                    f64::NAN
                },
            };
            let peaks = self.result.structure_mut(i);
            peaks.settle(&end);
            if !self.options.absolute_acceleration {
                peaks.peak_absolute_acceleration = f64::NAN;
            }
        }
        self.result.tau_end = self.tau;
        self.result.steps = self.segments;
        self.result.max_relative_displacement = self
            .result
            .impacts
            .is_empty()
            .then_some(self.max_relative_displacement);
        self.result
    }
}

impl Segment {
    /// Starts a segment of length h on the series of x already in place
    /// (and of f_p, in contact): the velocities' series, the swings, and
    /// no event yet.
    fn open(&mut self, h: f64, contact: bool) {
        let [v0, v1] = &mut self.v;
        let (sx0, sv0) = self.x[0].derivative_and_swings_into(h, v0);
        let (sx1, sv1) = self.x[1].derivative_and_swings_into(h, v1);
        self.swing = [sx0, sx1, sv0, sv1];
        self.contact = contact;
        self.end = (h, None);
    }

    /// f_p's series, in contact.
    pub fn force(&self) -> Option<&Series> {
        self.contact.then_some(&self.force)
    }

    /// Writes σ(x1 − x2 − Π_d) (SPEC §4, σ = ±1) into `gap_function` from
    /// the series of x in one pass, in place: the penetration δ for σ = 1,
    /// the opening −δ for σ = −1 (each exactly the negative of the other:
    /// rounding is symmetric).
    fn write_gap_function(&mut self, gap: f64, sign: f64) {
        let [x1, x2] = &self.x;
        let (a, b) = if sign > 0.0 { (x1, x2) } else { (x2, x1) };
        for (e, (p, q)) in self.gap_function.c.iter_mut().zip(a.c.iter().zip(&b.c)) {
            *e = p - q;
        }
        self.gap_function.c[0] -= sign * gap;
        self.gap_function.degree = x1.degree.max(x2.degree);
    }

    /// Cuts the segment at `event` if `e` turns positive before its current end.
    fn consider(&mut self, e: &Series, event: Event) {
        cut(&mut self.end, e, event);
    }

    /// The state at offset t into the segment (τ = `tau`), for observers.
    fn sample(&self, run: &Run, t: f64, tau: f64) -> Sample {
        let x = [self.x[0].value(t), self.x[1].value(t)];
        let (v0, a0) = self.v[0].value_slope(t);
        let (v1, a1) = self.v[1].value_slope(t);
        let fs = [0, 1].map(|i| run.structures[i].spring_force(run.branch[i], x[i]));
        Sample {
            tau,
            x,
            v: [v0, v1],
            a: [a0, a1],
            fs,
            fp: self.force().map_or(0.0, |f| f.value(t)),
            in_contact: self.contact,
        }
    }
}

/// [`Segment::consider`] on the segment's `end` alone, for an event function
/// that the segment itself holds (its gap function) and so cannot be lent to it.
fn cut(end: &mut (f64, Option<Event>), e: &Series, event: Event) {
    if end.0 == 0.0 {
        return;
    }
    if fires_at_start(e) {
        *end = (0.0, Some(event));
    } else if let Some(t) = first_crossing(e, 0.0, end.0) {
        *end = (t, Some(event));
    }
}

const _: () = assert!(CONTACT_DEGREE <= MAX_DEGREE && FREE_DEGREE <= MAX_DEGREE);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SET1;

    /// A spring turning back at ẋ = 0, z = Π_uy, reached with the round-off
    /// of the located root (ẋ = +1e-18 on the loading side, x − p one bit
    /// past Π_uy), starts its elastic branch inside the yield surface and
    /// not moving out of it: the next segment does not yield again at once.
    #[test]
    fn an_unloading_with_round_off_does_not_yield_again_at_once() {
        let p = Params {
            gap: f64::INFINITY,
            ..SET1
        };
        let options = ExactOptions {
            energy: false,
            ..ExactOptions::default()
        };
        let uy = p.yield1;
        // A displacement at which x − (x − Π_uy) rounds above Π_uy.
        let x = (1..10_000)
            .map(|k| k as f64 * 1.37e-4)
            .find(|&x| x - (x - uy) > uy)
            .expect("some x rounds past the yield surface");
        let mut run = Run::new(&p, &options);
        run.x = [x, 0.0];
        run.v = [1e-18, 0.0];
        run.branch[0] = Branch::Yielded { sign: 1.0 };
        run.update_loads();
        run.switch(Event::Unload(0));
        let Branch::Elastic { offset } = run.branch[0] else {
            panic!("unloading leaves the spring elastic");
        };
        assert!(x - offset <= uy, "z = {} > Π_uy = {uy}", x - offset);
        assert!((x - offset - uy).abs() <= 4.0 * f64::EPSILON * uy);
        assert_eq!(run.v[0], 0.0);
        let mut ground = Series {
            degree: FREE_DEGREE,
            ..Series::default()
        };
        options
            .excitation
            .taylor(run.tau, &mut ground.c[..=FREE_DEGREE]);
        let mut segment = Segment::default();
        run.free_segment(&ground, 1.0, &mut segment);
        assert!(segment.end.0 > 1e-3, "next event after {:?}", segment.end);
    }
}
