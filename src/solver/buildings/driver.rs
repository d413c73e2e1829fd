//! The loop of the exact method for a row (SPEC §13): ground pieces, cut
//! into equal sub-steps no longer than one radian of the fastest mode; each
//! sub-step out of contact by the cached linear map when nothing can happen
//! inside it, and otherwise by Taylor steps from event to event.
//!
//! Events (each the first instant a polynomial turns positive):
//! - an elastic storey yields: |Δ − p| reaches Δ_y (SPEC §3);
//! - a yielding storey unloads: Δ̇ changes sign against z; then p = Δ − z;
//! - a floor pair touches: δ = u_A − u_B − d turns positive; v₀ = δ̇ there;
//! - a pair separates: δ returns to 0;
//! - under the Jankowski law, a closed pair's δ̇ turns negative (its
//!   damping switches off there);
//! - a storey of a building with P-Δ reaches its collapse drift,
//!   |Δ| = collapse_drift_ratio · h (SPEC §15): the run stops there;
//! - a fluid viscous damper's Δv changes sign (SPEC §14, [`super::damper`]).
//!
//! While a pair under a Hertz-type law is closed the steps are those of the
//! Runge–Kutta pair of [`super::contact_rk`] instead of the series. A row
//! with a fluid viscous damper takes no map step: each step is the series
//! with the dampers' forces in it where that reaches as far as the
//! collocated step of [`super::damper_collocation`] would, else that
//! collocated step (`driver/damped.rs`).
//!
//! A sub-step is quiet when, on rigorous ranges of every watched quantity
//! and of its rate over the sub-step ([`super::bound`]: the cubic Hermite
//! interpolant widened by a bound on its error from the whole state), no
//! event function reaches zero and no quantity can pass its running peak
//! inside; a quiet sub-step's interior then holds no event and no new
//! peak, so its end is all that is recorded. Where a cubic's range cannot
//! clear a floor pair's gap, an elastic storey's yield drift or a running
//! peak, the quintic Hermite through q, q̇ and q̈ at both ends, widened by
//! its own bound ([`super::quintic`]), is asked before the sub-step goes by
//! the series.
//!
//! A run can keep its state just before its first contact onset, from which
//! the run of the same buildings apart continues instead of repeating the
//! motion up to there ([`Checkpoint`], [`run_row_keeping`], [`run_row_from`]).

use std::cell::RefCell;
use std::collections::HashMap;
use std::time::Instant;

use crate::model::buildings::contact::element_law;
use crate::model::buildings::ground::Piece;
use crate::model::buildings::{Ground, Row};
use crate::numerics::extremes::largest;

use super::bound::{Rest, Stack, Watch};
use super::config::{Branch, Closed, Config};
use super::contact_rk::{self, Contact, Taken, by_steps};
use super::damper;
use super::damper_collocation::Collocation;
use super::energy::RowEnergy;
use super::event_function::EventFunction;
use super::layout::Layout;
use super::link::{self, LinkResult};
use super::link_peaks;
use super::peaks::{Envelope, raise};
use super::poly;
use super::profile::{Cause, CollocationSteps, RowProfile};
use super::propagator::{Propagator, apply};
use super::reach::Reach;
use super::result::{Collapse, FloorPeaks, ForceHistory, PairImpact, PairResult, RowRun, RowTrace};
use super::system::System;
use super::taylor::Series;

#[cfg(test)]
mod cache_check;
mod checkpoint;
mod damped;
#[cfg(test)]
mod damped_check;
#[cfg(test)]
mod event_check;
#[cfg(test)]
mod quiet_check;
mod ranges;
mod rising;
mod watch_pass;
mod work;
#[cfg(test)]
mod work_check;

pub use checkpoint::Checkpoint;
use checkpoint::Snapshot;
use ranges::{Ends, Probe};
use watch_pass::WatchPass;
use work::Balance;

/// Knobs of a row run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowOptions {
    /// Length of the run (s).
    pub duration: f64,
    /// Longest sub-step (s); default one radian of the fastest mode out of contact.
    pub max_substep: Option<f64>,
    /// Take the energy balance ([`super::energy`]): its integrals are taken
    /// on every step, by quadrature on the series and in closed form on the
    /// maps ([`super::propagator::WorkForms`]), so the run takes the same
    /// steps as without it.
    pub energy: bool,
    /// Take every sub-step by the series, never by the cached map: the
    /// reference the map path is checked against (slower, and the same
    /// motion to round-off).
    pub series_only: bool,
    /// Keep every floor's displacement at the end of every sub-step
    /// ([`super::result::RowTrace`]), for drawing the row in time.
    pub trace: bool,
    /// Keep every floor pair's contact force over time
    /// ([`super::result::ForceHistory`]), for drawing the impacts.
    pub forces: bool,
    /// Measure the time in map steps, series steps and matrix exponentials
    /// ([`super::profile::RowProfile`]); the counts are always kept.
    pub profile: bool,
}

impl RowOptions {
    /// A run of `duration` seconds with the default sub-steps, peaks only.
    pub fn lasting(duration: f64) -> RowOptions {
        RowOptions {
            duration,
            max_substep: None,
            energy: false,
            series_only: false,
            trace: false,
            forces: false,
            profile: false,
        }
    }
}

/// A run that cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RowError {
    #[error("the run stopped at t = {0} s: more than 10⁸ events or series steps")]
    Runaway(f64),
    /// Newmark's Newton iteration (SPEC §13) found no displacement that
    /// balances the step: a singular tangent, or no convergence within its
    /// iteration limit.
    #[error(
        "Newmark's iteration did not converge at t = {0} s (singular tangent or no convergence in 100 iterations); try a smaller --dt"
    )]
    Unconverged(f64),
}

/// Sub-steps a configuration takes by the series before its map is made
/// (or taken from the cache): a yielding storey's configuration often
/// lasts only a few, and its map costs some 1.2 million instructions at
/// block-and-frame's 22 states. Counted in instructions under
/// synthetic:2000, 16 takes 1.6 to 2.1 % fewer than 8 where the frame
/// yields (scales 2 and 3, both laws) and the same at scale 1, and 2 %
/// fewer over an IDA whose runs share their maps; 4 takes 1.7 % more at
/// scale 3 and 2.3 % more over the IDA.
/// The count is of this run's requests alone, so that a run takes the
/// same steps whatever maps earlier runs left in the cache.
pub const FRESH: usize = 16;

/// Most series steps in one run.
const MAX_SERIES_STEPS: usize = 100_000_000;

/// Ground (a, ȧ) at time t on `piece` (ä = σa: a line or a sine).
fn ground_at(piece: &Piece, t: f64) -> (f64, f64) {
    let s = t - piece.t0;
    if piece.sigma == 0.0 {
        (piece.a + piece.rate * s, piece.rate)
    } else {
        let w = (-piece.sigma).sqrt();
        let (sn, cs) = (w * s).sin_cos();
        (
            piece.a * cs + piece.rate / w * sn,
            -piece.a * w * sn + piece.rate * cs,
        )
    }
}

/// Ground (a, ȧ, σ) at time t on `piece`.
fn ground_triple(piece: &Piece, t: f64) -> (f64, f64, f64) {
    let (a, rate) = ground_at(piece, t);
    (a, rate, piece.sigma)
}

/// The quantities the quiet test watches, as combinations of the augmented
/// state (u, u̇, a_g, ȧ_g, M⁻¹q) of [`super::propagator`], in this order:
/// u_i, u̇_i and ü_i + a_g of every floor, every storey's drift, the
/// relative displacement u_A − u_B of every facing pair, then of every
/// contact element, then Δu and Δv of every link (SPEC §14).
fn watched(layout: &Layout) -> Vec<Probe> {
    let n = layout.dofs;
    let mut w = Vec::new();
    for order in 0..3 {
        w.extend((0..n).map(|i| Probe::new(order, i, None)));
    }
    for s in &layout.storeys {
        w.push(Probe::new(0, s.upper, s.lower));
    }
    for p in layout.facing.iter().chain(&layout.pairs) {
        w.push(Probe::new(0, p.left_dof, Some(p.right_dof)));
    }
    for l in &layout.links {
        for order in 0..2 {
            w.push(Probe::new(order, l.pair.left_dof, Some(l.pair.right_dof)));
        }
    }
    w
}

enum Event {
    Yield(usize, Branch),
    Unload(usize),
    Onset(usize),
    Separation(usize),
    /// δ̇ of a closed Jankowski pair turns negative.
    Turn,
    /// A storey reaches its building's collapse drift (SPEC §15).
    Collapse(usize),
    /// A fluid viscous damper's Δv changes sign (SPEC §14), by its index
    /// among the dampers.
    Reversal(usize),
}

struct Run<'a> {
    row: &'a Row,
    layout: Layout,
    config: Config,
    system: System,
    u: Vec<f64>,
    v: Vec<f64>,
    t: f64,
    envelope: Envelope,
    pairs: Vec<PairResult>,
    propagator: &'a mut Propagator,
    /// Maps made and used before this run (a cache kept across runs), and
    /// the seconds spent making them.
    counts_before: (usize, usize, f64),
    /// Maps made and used, and seconds spent, by the run a continuation
    /// starts from before its checkpoint ([`checkpoint`]).
    carried: (usize, usize, f64),
    /// Whether to keep the state before the first onset, and that state.
    keep: bool,
    snapshot: Option<Snapshot>,
    series_steps: usize,
    /// Each configuration met, with the quiet tests it asked for ([`FRESH`]).
    configurations: HashMap<Vec<u8>, usize>,
    /// The branches of the current sub-step ([`Config::key_into`]), and the
    /// last ones met, with their count of requests so far.
    key: Vec<u8>,
    seen: Option<Vec<u8>>,
    requests: usize,
    buf: Vec<f64>,
    buf2: Vec<f64>,
    /// A closed pair's contact force polynomial on the current series step.
    force: Vec<f64>,
    /// ü at a series step's end, reused from step to step.
    point_acceleration: Vec<f64>,
    /// How far each floor moves over the current series step.
    reach: Reach,
    /// Every floor's absolute acceleration polynomial on a series step,
    /// order by order, and their bounds.
    accelerations: Accelerations,
    /// The last Taylor step's series, its vectors reused by the next.
    spare_series: Series,
    /// The quantities of the quiet test ([`watched`]), and each as read
    /// from a stack.
    watch: Vec<Watch>,
    probes: Vec<Probe>,
    /// The quiet test's first pass over them all ([`watch_pass`]).
    pass: WatchPass,
    /// The stack at the end of the last quiet sub-step, with its ground
    /// (a, ȧ, σ); dropped whenever the state moves otherwise.
    stack: Option<((f64, f64, f64), Stack)>,
    /// The rest point the quiet test and the energy balance's forms
    /// measure the state from ([`Rest`]).
    rest: Rest,
    energy: Option<Balance>,
    /// Suggested length of the next Runge–Kutta step in contact (0: none yet).
    next_contact_step: f64,
    /// The pairs' forces over time, when asked for.
    forces: Option<ForceHistory>,
    /// Set at a collapse, where the run stops.
    collapse: Option<Collapse>,
    profile: RowProfile,
    /// Whether to measure times into `profile`.
    timed: bool,
    /// Buffers of the map steps, reused: the next (u, u̇) and spare stacks.
    next: (Vec<f64>, Vec<f64>),
    spare: Vec<Stack>,
    /// Every link's peaks and energy (SPEC §14).
    links: Vec<LinkResult>,
    /// The sign of each damper's Δv in its current phase (0 until it has
    /// one): its reversal is watched against it ([`super::damper`]).
    damper_signs: Vec<f64>,
    /// The responses of the dampers' collocated steps, by configuration
    /// and length ([`super::damper_collocation`]), and their counts.
    collocation: RefCell<Collocation>,
}

/// Runs the exact method on `row` under `ground`.
pub fn run_row(row: &Row, ground: &Ground, options: &RowOptions) -> Result<RowRun, RowError> {
    run_row_cached(row, ground, options, &mut MapCache::default())
}

/// [`run_row_cached`], keeping the state just before the first contact
/// onset ([`Checkpoint`]; none when no contact closed, or the row has a
/// fluid viscous damper): the run is the same to the bit.
pub fn run_row_keeping(
    row: &Row,
    ground: &Ground,
    options: &RowOptions,
    cache: &mut MapCache,
) -> Result<(RowRun, Option<Checkpoint>), RowError> {
    let (run, snapshot) = drive(row, ground, options, cache, (true, None))?;
    let checkpoint = snapshot.map(|s| Checkpoint::new(row, ground, options, s));
    Ok((run, checkpoint))
}

/// [`run_row_cached`] of `twin` continued from `from`, a checkpoint of a run
/// of the same buildings with contact ([`Checkpoint`]), when it fits
/// ([`Checkpoint::fits`]), else from t = 0: the same results to rounding.
pub fn run_row_from(
    twin: &Row,
    ground: &Ground,
    options: &RowOptions,
    cache: &mut MapCache,
    from: Option<&Checkpoint>,
) -> Result<RowRun, RowError> {
    let from = from.filter(|c| c.fits(twin, ground, options));
    let resume = from.map(Checkpoint::state);
    Ok(drive(twin, ground, options, cache, (false, resume))?.0)
}

/// Every floor's |ü + ü_g| polynomial on a series step, order by order
/// ([`Series::absolute_accelerations`]), each floor's bound on it over the
/// step, and [`poly::bound_lanes`]' chains: buffers reused from step to
/// step.
#[derive(Default)]
struct Accelerations {
    orders: Vec<f64>,
    bounds: Vec<f64>,
    chains: Vec<f64>,
}

/// The linear maps of one row's configurations, kept from run to run: a
/// study runs the same row under many records, whose configurations and
/// sub-step lengths recur. A map is a function of its key (configuration,
/// h, σ) and of the row alone, so a run takes bit for bit the steps it
/// takes with a fresh cache; only the count of maps it made is smaller.
/// Given another row, the cache starts afresh.
#[derive(Debug, Default)]
pub struct MapCache {
    row: Option<Row>,
    propagator: Propagator,
}

impl MapCache {
    /// The maps of `row`, emptied first if they were another row's.
    fn of(&mut self, row: &Row) -> &mut Propagator {
        if self.row.as_ref() != Some(row) {
            self.row = Some(row.clone());
            self.propagator = Propagator::default();
        }
        &mut self.propagator
    }
}

/// [`run_row`] with the maps of earlier runs of the same row ([`MapCache`]).
pub fn run_row_cached(
    row: &Row,
    ground: &Ground,
    options: &RowOptions,
    cache: &mut MapCache,
) -> Result<RowRun, RowError> {
    Ok(drive(row, ground, options, cache, (false, None))?.0)
}

/// The run, from t = 0 or from a snapshot of a run of the same equations
/// (`resume`), keeping the state before its first onset when asked to
/// (`keep`).
fn drive(
    row: &Row,
    ground: &Ground,
    options: &RowOptions,
    cache: &mut MapCache,
    (keep, resume): (bool, Option<&Snapshot>),
) -> Result<(RowRun, Option<Snapshot>), RowError> {
    let propagator = cache.of(row);
    let counts_before = (propagator.made, propagator.used, propagator.seconds);
    let layout = Layout::of(row);
    let n = layout.dofs;
    let config = Config::at_rest(layout.storeys.len(), layout.pairs.len());
    let system = System::of(&layout, &config);
    let h_max = options.max_substep.unwrap_or(1.0 / layout.rate);
    let probes = watched(&layout);
    // Every floor starts at rest on the ground, or against it when the
    // ground starts moving (SPEC §9, type B pulse): u̇_i(0) = −u̇_g(0).
    let v0 = vec![-ground.initial_velocity(); n];
    let n_pairs = layout.pairs.len();
    let layout_links = layout.links.len();
    let initial_kinetic = 0.5
        * layout
            .mass
            .iter()
            .zip(&v0)
            .map(|(m, v)| m * v * v)
            .sum::<f64>();
    let mut run = Run {
        row,
        envelope: Envelope::new(n, layout.storeys.len(), layout.facing.len()),
        pairs: vec![PairResult::default(); layout.pairs.len()],
        layout,
        config,
        system,
        u: vec![0.0; n],
        v: v0,
        t: 0.0,
        propagator,
        counts_before,
        carried: (0, 0, 0.0),
        keep,
        snapshot: None,
        series_steps: 0,
        configurations: HashMap::new(),
        key: Vec::new(),
        seen: None,
        requests: 0,
        buf: Vec::new(),
        buf2: Vec::new(),
        force: Vec::new(),
        point_acceleration: Vec::new(),
        reach: Reach::default(),
        accelerations: Accelerations::default(),
        spare_series: Series::default(),
        watch: probes.iter().map(Probe::watch).collect(),
        probes,
        pass: WatchPass::default(),
        stack: None,
        rest: Rest::default(),
        energy: options
            .energy
            .then(|| Balance::new(initial_kinetic, layout_links)),
        next_contact_step: 0.0,
        forces: options.forces.then(|| ForceHistory {
            pairs: vec![Vec::new(); n_pairs],
            ..ForceHistory::default()
        }),
        collapse: None,
        profile: RowProfile::default(),
        timed: options.profile,
        next: (Vec::new(), Vec::new()),
        spare: Vec::new(),
        links: vec![LinkResult::new(); layout_links],
        damper_signs: Vec::new(),
        collocation: RefCell::default(),
    };
    run.damper_signs = damper::signs(&run.layout.dampers, &run.v);
    run.pass = WatchPass::new(&run.layout);
    run.record_here(ground.at(0.0));
    let mut trace = options.trace.then(|| RowTrace::new(n));
    let mut resume = resume;
    'pieces: for piece in ground.pieces(options.duration) {
        let length = piece.length;
        if length <= 0.0 || resume.is_some_and(|s| piece.t1 < s.time) {
            continue;
        }
        let m = (length / h_max).ceil().max(1.0) as usize;
        let h = length / m as f64;
        for j in 0..m {
            let tb = if j + 1 == m {
                piece.t1
            } else {
                piece.t0 + (j + 1) as f64 * h
            };
            // A continuation skips the sub-steps before its snapshot's
            // instant, and takes the one holding it from there by the series
            // (nothing of it when the instant ends it).
            let mut continued = false;
            if let Some(s) = resume.take() {
                if tb < s.time {
                    resume = Some(s);
                    continue;
                }
                run.resume(s, &piece);
                trace.clone_from(&s.trace);
                continued = true;
            }
            let clock = run.timed.then(Instant::now);
            let cause = if continued {
                (run.t < tb).then_some(Cause::Continued)
            } else if run.config.any_contact() {
                Some(Cause::Contact)
            } else if !run.layout.dampers.is_empty() {
                Some(Cause::Damper)
            } else if options.series_only {
                Some(Cause::SeriesOnly)
            } else {
                run.quiet_step(&piece, h).err()
            };
            let mapped = run.timed.then(Instant::now);
            if let Some(cause) = cause {
                let before = run.series_steps;
                // Only a peak may rise: the bounds cleared every event.
                run.careful(&piece, tb, cause != Cause::Peak)?;
                run.profile.careful.add(cause, 1);
                run.profile.series.add(cause, run.series_steps - before);
            } else if !continued {
                run.profile.map_steps += 1;
            }
            if let (Some(c), Some(m)) = (clock, mapped) {
                let p = &mut run.profile;
                p.map_seconds += (m - c).as_secs_f64();
                p.series_seconds += m.elapsed().as_secs_f64();
            }
            // The trace a continuation starts from: up to this sub-step.
            if let (Some(s), Some(trace)) = (run.snapshot.as_mut(), &trace)
                && s.trace.is_none()
            {
                s.trace = Some(trace.clone());
            }
            if run.collapse.is_some() {
                if let Some(trace) = trace.as_mut() {
                    trace.push(run.t, &run.u);
                }
                break 'pieces;
            }
            run.t = tb;
            if let Some(trace) = trace.as_mut() {
                trace.push(tb, &run.u);
            }
        }
    }
    let snapshot = run.snapshot.take();
    let mut done = run.finish(options.duration);
    done.trace = trace;
    Ok((done, snapshot))
}

impl Run<'_> {
    /// Tries the sub-step to t + h by the cached map; keeps it and returns
    /// true when it is quiet: on the rigorous ranges of [`super::bound`]
    /// (the Hermite cubic of each watched quantity widened by its error
    /// bound), no storey reaches yield or unloads, no floor pair closes,
    /// and no quantity can pass its running peak inside unless it is
    /// monotone there (then its extremes are the ends, which are recorded);
    /// a gap, a yield drift or a peak the cubic cannot clear is asked again
    /// of the quintic through q, q̇, q̈ at both ends ([`super::quintic`]).
    // Out of line, so that a profile shows a map step's cost apart from
    // the loop's (one call per sub-step).
    #[inline(never)]
    fn quiet_step(&mut self, piece: &Piece, h: f64) -> Result<(), Cause> {
        let n = self.layout.dofs;
        let (a0, r0) = ground_at(piece, self.t);
        let (a1, r1) = ground_at(piece, self.t + h);
        self.config.key_into(&mut self.key);
        if self.seen.as_deref() != Some(&self.key[..]) {
            if let Some(seen) = self.seen.take() {
                self.configurations.insert(seen, self.requests);
            }
            let met = self.configurations.entry(self.key.clone()).or_insert(0);
            self.requests = *met;
            self.seen = Some(self.key.clone());
        }
        self.requests += 1;
        if self.requests < FRESH {
            return Err(Cause::Fresh);
        }
        let (map, bounds, jump) = self.propagator.map(
            &self.key,
            &self.system,
            (h, piece.sigma),
            self.layout.rate,
            &self.watch,
        );
        let (mut u1, mut v1) = std::mem::take(&mut self.next);
        u1.resize(n, 0.0);
        v1.resize(n, 0.0);
        apply(
            map,
            (&self.u, &self.v),
            (a0, r0),
            &self.system.load,
            (&mut u1, &mut v1),
        );
        let sigma = piece.sigma;
        // The end of a quiet sub-step is the start of the next one: its
        // stack is kept while the state is the same, and carried to a new
        // ground piece by the ground's jump ([`super::bound::GroundJump`]).
        let mut start = match self.stack.take() {
            Some((g, stack)) if g == (a0, r0, sigma) => stack,
            Some((_, mut stack)) => {
                stack.reground(jump, (a0, r0, sigma));
                stack
            }
            None => {
                let mut stack = self.spare.pop().unwrap_or_default();
                stack.set_to_jerk(&self.system, (&self.u, &self.v), (a0, r0, sigma));
                stack
            }
        };
        let mut end = self.spare.pop().unwrap_or_default();
        end.set_to_jerk(&self.system, (&u1, &v1), (a1, r1, sigma));
        let size = bounds.size(
            (&self.u, &self.v),
            (a0, r0),
            &self.system.load,
            (&self.key, &mut self.rest),
        );
        // What the first pass clears, the per-quantity tests would clear.
        let (value, rate) = bounds.unit_errors();
        let pass = &mut self.pass;
        pass.ask(
            (&start, &end),
            (value, rate, size),
            h,
            (&self.config, &self.envelope),
        );
        let pass = &self.pass;
        // The rate of ü + a_g's cubic is read from u⁗ for what the pass leaves.
        if (0..n).any(|i| !pass.floor(2, i)) {
            start.make_snap(&self.system);
            end.make_snap(&self.system);
        }
        let ends = |k: usize| Ends {
            start: self.probes[k].at(&start),
            end: self.probes[k].at(&end),
            errors: bounds.errors(k, size),
            h,
        };
        // Whether quantity k (its ends `q`, already made for its cubic),
        // measured from `offset`, stays strictly inside `limits` on its
        // quintic ([`super::quintic`]), asked where its cubic's range
        // cannot tell.
        let quintic_cleared = std::cell::Cell::new(false);
        let quintic_clears = |(k, mut q): (usize, Ends), offset: f64, limits: (f64, f64)| {
            q.start[0] -= offset;
            q.end[0] -= offset;
            let clears = q.quintic_within(bounds.quintic_error(k, size), limits);
            quintic_cleared.set(quintic_cleared.get() || clears);
            clears
        };
        // Quantities whose peak may rise inside, located after the events clear.
        let mut rising = Vec::new();
        let verdict = (|| {
            let base = 3 * n + self.layout.storeys.len() + self.layout.facing.len();
            for (k, &d) in self.layout.gaps.iter().enumerate() {
                if pass.open(k) {
                    continue;
                }
                let q = ends(base + k);
                if !q.clears(0, |(_, hi)| hi < d)
                    && !quintic_clears((base + k, q), 0.0, (f64::NEG_INFINITY, d))
                {
                    return Err(Cause::Onset);
                }
            }
            let env = &self.envelope;
            let base = 3 * n;
            for (k, s) in self.layout.storeys.iter().enumerate() {
                // Below its running peak (and so its collapse drift, which
                // it has not reached), nothing more to ask.
                let peak = env.drift[k];
                if pass.storey_quiet(k) && pass.drift_below(k) && peak < s.collapse_drift {
                    continue;
                }
                let q = ends(base + k);
                let (quiet, cause) = match self.config.branch[k] {
                    Branch::Elastic => {
                        let (p, dy) = (self.config.plastic[k], s.yield_drift);
                        let within = |(lo, hi): (f64, f64)| (lo - p).abs().max((hi - p).abs()) < dy;
                        let quiet =
                            q.clears(0, within) || quintic_clears((base + k, q), p, (-dy, dy));
                        (quiet, Cause::Yield)
                    }
                    Branch::Plus => (q.clears(1, |(lo, _)| lo > 0.0), Cause::Unload),
                    Branch::Minus => (q.clears(1, |(_, hi)| hi < 0.0), Cause::Unload),
                };
                if !quiet {
                    return Err(cause);
                }
                if peak < s.collapse_drift && q.clears(0, |(lo, hi)| lo.abs().max(hi.abs()) <= peak)
                {
                    continue;
                }
                let (lo, hi) = q.range(0);
                let extreme = lo.abs().max(hi.abs());
                if extreme >= s.collapse_drift {
                    return Err(Cause::Collapse);
                }
                if extreme > peak && !q.monotone() {
                    rising.push(base + k);
                }
            }
            let floors = [&env.displacement, &env.velocity, &env.acceleration];
            for (order, peaks) in floors.into_iter().enumerate() {
                for (i, &peak) in peaks.iter().enumerate() {
                    let k = order * n + i;
                    if !pass.floor(order, i) && !ends(k).below(peak) {
                        rising.push(k);
                    }
                }
            }
            let base = base + self.layout.storeys.len();
            for k in 0..self.layout.facing.len() {
                if pass.relative_below(k) {
                    continue;
                }
                let q = ends(base + k);
                let peak = env.relative[k];
                if !q.clears(0, |(_, hi)| hi <= peak) && !q.monotone() {
                    rising.push(base + k);
                }
            }
            let base = base + self.layout.facing.len() + self.layout.pairs.len();
            for (l, (link, peaks)) in self.layout.links.iter().zip(&self.links).enumerate() {
                let (du, dv) = (ends(base + 2 * l), ends(base + 2 * l + 1));
                let stroke = (du.range(0), du.monotone());
                let rate = (dv.range(0), dv.monotone());
                if !link::quiet(link, peaks, stroke, rate) {
                    return Err(Cause::Peak);
                }
            }
            Ok(())
        })();
        // A peak that may rise on the cubics' ranges but that the quintic of
        // its ends holds within its running value ([`super::quintic`])
        // cannot rise after all.
        if verdict.is_ok() && !rising.is_empty() {
            let counts = (n, self.layout.storeys.len());
            rising.retain(|&k| {
                let (&mut peak, signed) = rising::peak_of(&mut self.envelope, k, counts);
                !quintic_clears(
                    (k, ends(k)),
                    0.0,
                    (if signed { f64::NEG_INFINITY } else { -peak }, peak),
                )
            });
        }
        if verdict.is_ok() && rising.is_empty() && quintic_cleared.get() {
            self.profile.held += 1;
        }
        // Every event cleared: the peaks that may rise are located on the
        // sub-step's closed form ([`rising`]), unless its series falls short.
        let verdict = verdict.and_then(|()| {
            #[cfg(test)]
            let before = self.envelope.clone();
            if rising.is_empty() {
                return Ok(());
            }
            if !self.locate_rising(piece, h, &rising, (&mut u1, &mut v1)) {
                return Err(Cause::Peak);
            }
            end.set_to_jerk(&self.system, (&u1, &v1), (a1, r1, sigma));
            self.profile.located += 1;
            #[cfg(test)]
            self.check_located(piece, h, &before);
            Ok(())
        });
        if let Err(cause) = verdict {
            self.spare.extend([start, end]);
            self.next = (u1, v1);
            return Err(cause);
        }
        #[cfg(test)]
        self.check_quiet(piece, h, (&u1, &v1));
        self.work_on_map(piece, h, &u1);
        self.spare.push(start);
        self.next = (
            std::mem::replace(&mut self.u, u1),
            std::mem::replace(&mut self.v, v1),
        );
        self.record_point(&end.rates[2], a1);
        self.stack = Some(((a1, r1, sigma), end));
        Ok(())
    }

    /// Peaks at the current point under ground acceleration `a`, with ü
    /// of the configuration in force out of contact: at the start (the
    /// floors' initial velocity, and the acceleration its damping force
    /// gives; 0 from rest), and where a continuation takes up its state.
    fn record_here(&mut self, a: f64) {
        let mut acc = vec![0.0; self.layout.dofs];
        self.system.acceleration(&self.u, &self.v, a, &mut acc);
        self.record_point(&acc, a);
    }

    /// Peaks at the current point, with ü already known.
    fn record_point(&mut self, acc: &[f64], a: f64) {
        let n = self.layout.dofs;
        let env = &mut self.envelope;
        // raise() of each floor's |u|, |u̇|, |ü + a_g|, as one comparison
        // and an unconditional store, which the compiler makes vector
        // operations.
        let (u, v, acc) = (&self.u[..n], &self.v[..n], &acc[..n]);
        let displacement = &mut env.displacement[..n];
        let velocity = &mut env.velocity[..n];
        let acceleration = &mut env.acceleration[..n];
        for i in 0..n {
            displacement[i] = largest(u[i].abs(), displacement[i]);
            velocity[i] = largest(v[i].abs(), velocity[i]);
            acceleration[i] = largest((acc[i] + a).abs(), acceleration[i]);
        }
        for (k, s) in self.layout.storeys.iter().enumerate() {
            raise(&mut env.drift[k], self.layout.drift(s, &self.u));
        }
        for (k, p) in self.layout.facing.iter().enumerate() {
            env.relative[k] = env.relative[k].max(self.u[p.left_dof] - self.u[p.right_dof]);
        }
        link::record_point(&self.layout.links, &self.u, &self.v, &mut self.links);
        if let Some(history) = self.forces.as_mut() {
            history.links.resize(self.layout.links.len(), Vec::new());
            for (l, h) in self.layout.links.iter().zip(&mut history.links) {
                let (a, b) = (l.pair.left_dof, l.pair.right_dof);
                h.push((
                    self.t,
                    l.force(self.u[a] - self.u[b], self.v[a] - self.v[b]),
                ));
            }
        }
    }

    /// The sub-step to `tb` by Taylor steps from event to event; with
    /// `events` false, the quiet test has cleared every event function over
    /// it, and the steps only locate peaks.
    fn careful(&mut self, piece: &Piece, tb: f64, events: bool) -> Result<(), RowError> {
        if let Some((_, stack)) = self.stack.take() {
            self.spare.push(stack);
        }
        let n = self.layout.dofs;
        // The map steps' buffers of the next state, and of ü at each point.
        let (mut un, mut vn) = std::mem::take(&mut self.next);
        un.resize(n, 0.0);
        vn.resize(n, 0.0);
        let mut acc = std::mem::take(&mut self.point_acceleration);
        // Whether `acc` is ü at the current point (recorded in this loop,
        // on this piece, in the configuration in force).
        let mut known = false;
        while self.t < tb {
            self.series_steps += 1;
            if self.series_steps > MAX_SERIES_STEPS {
                return Err(RowError::Runaway(self.t));
            }
            let rem = tb - self.t;
            let (a, rate) = ground_at(piece, self.t);
            let su = self.u.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
            let sv = self.v.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
            let ground = (a, rate, piece.sigma);
            // Whether the step is the series with the dampers' forces in it.
            let mut damped = false;
            // Whether the series is the quintic through a Runge–Kutta
            // step's ends, not a collocated step's own motion.
            let mut quintic = false;
            let (series, mut rk) = if by_steps(&self.layout, &self.config) {
                match self.damped_series(rem, ground, (su, sv)) {
                    Some(series) => {
                        damped = true;
                        (series, None)
                    }
                    None => {
                        let known = known.then_some(&acc[..]);
                        let (series, step, own) =
                            self.contact_step(piece, (rem, known), ground, (su, sv));
                        quintic = !own;
                        (series, Some(step))
                    }
                }
            } else {
                let mut series = std::mem::take(&mut self.spare_series);
                series.fill_over(&self.system, (&self.u, &self.v), ground, (su, sv), rem);
                (series, None)
            };
            let whole = rem.min(series.radius);
            let mut end = whole;
            let mut event = None;
            // The functions whose root on a Runge–Kutta step's polynomial
            // the motion does not reach ([`Contact::settle`]): the events
            // are looked for again without them.
            let mut unreached = Vec::new();
            if events {
                self.find_events(&series, &mut end, &mut event, &unreached);
            }
            while let (Some((y0, f0, step)), Some((_, g))) = (&mut rk, &event)
                && end < step.h
            {
                let t = self.t;
                let ground = |s: f64| ground_triple(piece, t + s);
                let contact = Contact::new(&self.layout, &self.config, &self.system, |s| {
                    ground_at(piece, t + s).0
                })
                .with_collocation(&self.collocation, &ground);
                match contact.settle((y0, f0), g, (end, step.h), sv) {
                    Some(settled) => {
                        *step = settled;
                        end = step.h;
                    }
                    None => {
                        unreached.push(*g);
                        (end, event) = (whole, None);
                        self.find_events(&series, &mut end, &mut event, &unreached);
                    }
                }
            }
            #[cfg(test)]
            if damped {
                self.check_damped(&series, end);
            }
            #[cfg(not(test))]
            let _ = damped;
            // The events' search left the reach over [0, whole] of this series.
            let reached = events && end == whole;
            self.peaks_on(&series, end, quintic.then_some(piece), reached);
            if self.energy.is_some() {
                self.work_on(&series, end);
            }
            match &rk {
                Some((_, _, step)) => {
                    un.copy_from_slice(&step.y1[..n]);
                    vn.copy_from_slice(&step.y1[n..]);
                    self.collocation.borrow_mut().recycle(series);
                }
                None => {
                    series.state(end, &mut un, &mut vn);
                    self.spare_series = series;
                }
            }
            std::mem::swap(&mut self.u, &mut un);
            std::mem::swap(&mut self.v, &mut vn);
            self.t = if end >= rem { tb } else { self.t + end };
            if let Some((e, g)) = event {
                #[cfg(test)]
                self.check_event(&g, (su, sv));
                #[cfg(not(test))]
                let _ = g;
                self.apply(e);
            }
            // A damper that had no sign (from rest), or whose crossings
            // were not watched (stiff), takes Δv's sign now.
            let h = self.next_contact_step;
            for (sign, d) in self.damper_signs.iter_mut().zip(&self.layout.dampers) {
                let rate = d.rate(&self.v);
                if *sign == 0.0 || d.stiff(rate, h) {
                    *sign = damper::sign(rate);
                }
            }
            // The point itself, with ü of the configuration now in force.
            let (a1, _) = ground_at(piece, self.t);
            self.acceleration(piece, (self.t, 0.0), (&self.u, &self.v), &mut acc);
            known = true;
            self.record_point(&acc, a1);
            if self.collapse.is_some() {
                break;
            }
        }
        self.next = (un, vn);
        self.point_acceleration = acc;
        Ok(())
    }

    /// ü at (u, u̇) at time t + s on `piece` in the configuration in force,
    /// into `out` (its vector reused): the linear system's, and where the
    /// row goes by steps the force of every pair closed under a Hertz-type
    /// law and of every fluid viscous damper ([`Contact::acceleration`]),
    /// which the system leaves out.
    fn acceleration(
        &self,
        piece: &Piece,
        (t, s): (f64, f64),
        (u, v): (&[f64], &[f64]),
        out: &mut Vec<f64>,
    ) {
        out.resize(self.layout.dofs, 0.0);
        if by_steps(&self.layout, &self.config) {
            let contact = Contact::new(&self.layout, &self.config, &self.system, |s| {
                ground_at(piece, t + s).0
            });
            contact.acceleration(s, u, v, out);
        } else {
            self.system
                .acceleration(u, v, ground_at(piece, t + s).0, out);
        }
    }

    /// One Runge–Kutta step of a Hertz-type contact phase
    /// ([`super::contact_rk`]) from the current state, at most `rem` long,
    /// as a series on its length, with its start (y, ẏ), the step, and
    /// whether the series is the step's own (a collocated step's motion)
    /// rather than the quintic through its ends. `known`: ü at the current
    /// state on `piece` in the configuration in force, where the point was
    /// just recorded ([`Run::acceleration`], the same sum as ẏ's).
    fn contact_step(
        &mut self,
        piece: &Piece,
        (rem, known): (f64, Option<&[f64]>),
        ground: (f64, f64, f64),
        scale: (f64, f64),
    ) -> (Series, Taken, bool) {
        let t = self.t;
        let at = |s: f64| ground_triple(piece, t + s);
        let contact = Contact::new(&self.layout, &self.config, &self.system, |s| {
            ground_at(piece, t + s).0
        })
        .with_collocation(&self.collocation, &at);
        let y0: Vec<f64> = self.u.iter().chain(&self.v).copied().collect();
        let f0 = match known {
            Some(acc) => self.v.iter().chain(acc).copied().collect(),
            None => contact.rate(0.0, &y0),
        };
        let fastest = 1.0 / self.layout.rate;
        let guess = match self.next_contact_step {
            h if h > 0.0 => h,
            _ => 1e-3 * fastest,
        };
        // A series left by an earlier settling is not this step's.
        self.collocation.borrow_mut().last = None;
        let (step, next) = contact.step((&y0, &f0), (guess, rem, 1e-12 * fastest), scale);
        self.next_contact_step = next;
        // A collocated step's own series, else the quintic through its ends.
        let (series, own) = match self.collocation.borrow_mut().last.take() {
            Some(series) => (series, true),
            None => (contact_rk::series((&y0, &f0), &step, ground), false),
        };
        (series, (y0, f0, step), own)
    }

    /// Each event that can happen from the current configuration, with its
    /// function ([`EventFunction`]).
    fn watched_events(&self, mut each: impl FnMut(Event, EventFunction)) {
        for (k, s) in self.layout.storeys.iter().enumerate() {
            if s.collapse_drift.is_finite() {
                // Δ − Δ_c and −Δ − Δ_c: the drift reaches the collapse drift either way.
                let c = s.collapse_drift;
                each(
                    Event::Collapse(k),
                    EventFunction::drift(s.upper, s.lower, 1.0, -c),
                );
                each(
                    Event::Collapse(k),
                    EventFunction::drift(s.upper, s.lower, -1.0, -c),
                );
            }
            match self.config.branch[k] {
                Branch::Elastic => {
                    if !s.yield_drift.is_finite() {
                        continue;
                    }
                    // z − Δ_y and −z − Δ_y, z = Δ − p.
                    let (p, dy) = (self.config.plastic[k], s.yield_drift);
                    let up = EventFunction::drift(s.upper, s.lower, 1.0, -p - dy);
                    each(Event::Yield(k, Branch::Plus), up);
                    let down = EventFunction::drift(s.upper, s.lower, -1.0, p - dy);
                    each(Event::Yield(k, Branch::Minus), down);
                }
                sign => {
                    let w = if sign == Branch::Plus { -1.0 } else { 1.0 };
                    each(
                        Event::Unload(k),
                        EventFunction::drift_rate(s.upper, s.lower, w),
                    );
                }
            }
        }
        for (pi, (p, &d)) in self.layout.pairs.iter().zip(&self.layout.gaps).enumerate() {
            let closed = &self.config.contact[pi];
            let (a, b) = (p.left_dof, p.right_dof);
            match closed {
                None => each(Event::Onset(pi), EventFunction::drift(a, Some(b), 1.0, -d)),
                Some(c) => {
                    each(
                        Event::Separation(pi),
                        EventFunction::drift(a, Some(b), -1.0, d),
                    );
                    let jankowski = c.law.hertzian.is_some_and(|h| h.approach_damping > 0.0);
                    if jankowski && self.v[a] - self.v[b] > 0.0 {
                        each(Event::Turn, EventFunction::drift_rate(a, Some(b), -1.0));
                    }
                }
            }
        }
        // A damper's reversal, unless it is stiff over the next step.
        let h = self.next_contact_step;
        for (k, (d, &sign)) in self
            .layout
            .dampers
            .iter()
            .zip(&self.damper_signs)
            .enumerate()
        {
            if sign != 0.0 && !d.stiff(d.rate(&self.v), h) {
                // g = −σΔv: Δv leaves the sign σ of its phase.
                each(
                    Event::Reversal(k),
                    EventFunction::drift_rate(d.left, Some(d.right), -sign),
                );
            }
        }
    }

    /// The first event on `series` over [0, `end`] (`end` moved to it),
    /// of the functions [`Run::watched_events`] gives but `unreached`.
    fn find_events(
        &mut self,
        series: &Series,
        end: &mut f64,
        event: &mut Option<(Event, EventFunction)>,
        unreached: &[EventFunction],
    ) {
        let mut c = std::mem::take(&mut self.buf);
        // The reach over the whole step holds over any shorter part of it.
        let mut reach = std::mem::take(&mut self.reach);
        reach.set(series, *end);
        self.watched_events(|e, g| {
            if unreached.contains(&g) {
                return;
            }
            // g cannot turn positive on the step: first_rise finds nothing.
            if reach.upper((&g.on_u, &g.on_v), g.constant) < 0.0 {
                return;
            }
            g.on(series, &mut c);
            if let Some(s) = poly::first_rise(&c, *end)
                && (s < *end || event.is_none())
            {
                *end = s;
                *event = Some((e, g));
            }
        });
        self.reach = reach;
        self.buf = c;
    }

    /// Turning points on [0, end] that may raise a peak (Σ|c_k|s^k above it),
    /// and the force and penetration of closed pairs.
    ///
    /// On a Runge–Kutta step (`rk`: its ground piece) the quintic through
    /// both ends carries u and u̇ to the step's order, but its second
    /// derivative holds the rounding of u magnified by 1/h², which on the
    /// shortest steps (near an event) swamps ü: there the acceleration's
    /// largest point is located on the polynomial and its value taken from
    /// the equation of motion at the interpolated state; the ends are the
    /// recorded points. A collocated step's own series is not such a
    /// quintic (`rk` None): its ü is the linear motion's under the
    /// collocated forces, where the equation of motion at an interpolated
    /// state would take a damper's force from the law at its Δv, which
    /// is ill-conditioned where the damper all but locks (F = c|Δv|^α
    /// moves by α ε/|Δv| of itself for an error ε in Δv, and Δv is the
    /// collocation's algebraic part). With `reached`, the run's reach
    /// already holds that of `series` over [0, end].
    fn peaks_on(&mut self, series: &Series, end: f64, rk: Option<&Piece>, reached: bool) {
        let mut c = std::mem::take(&mut self.buf);
        let n = self.layout.dofs;
        if !reached {
            self.reach.set(series, end);
        }
        // Every floor's |ü + ü_g| polynomial, formed in one pass, and its
        // bound over the step, all floors side by side.
        let mut accelerations = std::mem::take(&mut self.accelerations);
        let Accelerations {
            orders,
            bounds,
            chains,
        } = &mut accelerations;
        series.absolute_accelerations(orders);
        bounds.resize(n, 0.0);
        poly::magnitude_bound_lanes(orders, end, chains, bounds);
        for i in 0..n {
            let env = &mut self.envelope;
            // |u_i| and |u̇_i| cannot pass their peaks on the step ([`Reach`]),
            // or their polynomials' bounds decide (on a copy of the floor's
            // coefficients, taken only then).
            if self.reach.magnitude(&[(i, 1.0)]) > env.displacement[i] {
                series.displacement_into(i, &mut c);
                if poly::magnitude_bound(&c, end) > env.displacement[i] {
                    raise(&mut env.displacement[i], poly::max_abs(&c, end));
                }
            }
            if self.reach.speed(i) > env.velocity[i] {
                series.velocity_into(i, &mut c);
                if poly::magnitude_bound(&c, end) > env.velocity[i] {
                    raise(&mut env.velocity[i], poly::max_abs(&c, end));
                }
            }
            // |ü_i + ü_g| likewise, its polynomial gathered only then.
            if bounds[i] > env.acceleration[i] {
                Series::gather(orders, n, i, &mut c);
                let Some(piece) = rk else {
                    raise(&mut env.acceleration[i], poly::max_abs(&c, end));
                    continue;
                };
                let (at, _) = poly::argmax_abs(&c, end);
                if at > 0.0 && at < end {
                    let (mut us, mut vs) = (vec![0.0; n], vec![0.0; n]);
                    series.state(at, &mut us, &mut vs);
                    let mut acc = Vec::new();
                    self.acceleration(piece, (self.t, at), (&us, &vs), &mut acc);
                    let a = acc[i] + ground_at(piece, self.t + at).0;
                    raise(&mut self.envelope.acceleration[i], a);
                }
            }
        }
        self.accelerations = accelerations;
        link_peaks::peaks_on(
            &self.layout.links,
            series,
            end,
            &mut self.links,
            (&mut c, &mut self.buf2),
        );
        let c = &mut c;
        let env = &mut self.envelope;
        let reach = &self.reach;
        for (k, s) in self.layout.storeys.iter().enumerate() {
            let du = [(s.upper, 1.0), (s.lower.unwrap_or(s.upper), -1.0)];
            let terms = if s.lower.is_some() { &du[..] } else { &du[..1] };
            // |Δ| cannot pass its peak on the step ([`Reach`]).
            if reach.magnitude(terms) <= env.drift[k] {
                continue;
            }
            series.combine(terms, &[], c);
            if poly::magnitude_bound(c, end) > env.drift[k] {
                raise(&mut env.drift[k], poly::max_abs(c, end));
            }
        }
        for (k, p) in self.layout.facing.iter().enumerate() {
            let terms = [(p.left_dof, 1.0), (p.right_dof, -1.0)];
            if reach.upper((&terms, &[]), 0.0) <= env.relative[k] {
                continue;
            }
            series.combine(&terms, &[], c);
            if poly::upper_bound(c, end) > env.relative[k] {
                env.relative[k] = env.relative[k].max(poly::max(c, end));
            }
        }
        for (pi, (p, &d)) in self.layout.pairs.iter().zip(&self.layout.gaps).enumerate() {
            let Some(closed) = &self.config.contact[pi] else {
                continue;
            };
            let (a, b) = (p.left_dof, p.right_dof);
            series.combine(&[(a, 1.0), (b, -1.0)], &[], c);
            c[0] -= d;
            // Without a force history, a step's largest penetration and
            // force are located only where their upper bounds on the step
            // (the quadratic part exactly, the rest by Σ|c_k|s^k) pass the
            // impact's peaks so far.
            let last = self.pairs[pi]
                .impacts
                .last()
                .filter(|_| self.forces.is_none());
            let passes = |p: &[f64], peak: fn(&PairImpact) -> f64| {
                last.is_none_or(|last| poly::upper_bound(p, end) > peak(last))
            };
            let penetration = if passes(c, |l| l.max_penetration) {
                poly::max(c, end)
            } else {
                f64::NEG_INFINITY
            };
            let dd = &mut self.buf2;
            series.combine(&[], &[(a, 1.0), (b, -1.0)], dd);
            let law = &closed.law;
            let force = &mut self.force;
            force.clear();
            match &law.hertzian {
                Some(h) => force.extend(contact_rk::force_polynomial(h, c, dd, end)),
                None => force.extend((0..c.len()).map(|k| {
                    // Σ_j δ_j δ̇_{k−j}.
                    let conv = poly::product_coefficient(&c[..=k], &dd[..=k]);
                    law.stiffness * c[k] + law.linear_damping * dd[k] + law.hertz_damping * conv
                })),
            }
            let force = &self.force[..];
            let (at, f) = if passes(force, |l| l.max_force) {
                poly::argmax(force, end)
            } else {
                (0.0, f64::NEG_INFINITY)
            };
            if let Some(history) = self.forces.as_mut() {
                // The step's start, its largest force, its end.
                history.push(pi, self.t, force[0]);
                if at > 0.0 && at < end {
                    history.push(pi, self.t + at, f);
                }
                history.push(pi, self.t + end, poly::eval(force, end));
            }
            if let Some(last) = self.pairs[pi].impacts.last_mut() {
                last.max_penetration = last.max_penetration.max(penetration);
                last.max_force = last.max_force.max(f);
            }
        }
        self.buf = std::mem::take(c);
    }

    fn apply(&mut self, event: Event) {
        if let Event::Onset(_) = event {
            self.keep_before_onset();
        }
        let events = &mut self.profile.events;
        match &event {
            Event::Yield(..) => events.yields += 1,
            Event::Unload(_) => events.unloads += 1,
            Event::Onset(_) => events.onsets += 1,
            Event::Separation(_) => events.separations += 1,
            Event::Turn => events.turns += 1,
            Event::Collapse(_) => events.collapses += 1,
            Event::Reversal(_) => events.reversals += 1,
        }
        match event {
            Event::Yield(k, branch) => self.config.branch[k] = branch,
            Event::Unload(k) => {
                let s = &self.layout.storeys[k];
                let z = self.config.z(k, 0.0, s.yield_drift);
                self.config.plastic[k] = self.layout.drift(s, &self.u) - z;
                self.config.branch[k] = Branch::Elastic;
            }
            Event::Onset(pi) => {
                let p = self.layout.pairs[pi];
                let v0 = self.v[p.left_dof] - self.v[p.right_dof];
                self.config.contact[pi] = Some(Closed {
                    law: element_law(self.row, &self.layout.elements[pi], v0),
                    approach_velocity: v0,
                });
                if let Some(history) = self.forces.as_mut() {
                    history.push(pi, self.t, 0.0);
                }
                self.pairs[pi].impacts.push(PairImpact {
                    start: self.t,
                    end: f64::NAN,
                    approach_velocity: v0,
                    separation_velocity: f64::NAN,
                    max_force: 0.0,
                    max_penetration: 0.0,
                });
            }
            Event::Turn => return,
            // Only the sign the next reversal is watched against changes.
            Event::Reversal(k) => {
                self.damper_signs[k] = -self.damper_signs[k];
                return;
            }
            Event::Collapse(k) => {
                let (building, storey) = self.layout.building_storey(k);
                self.collapse = Some(Collapse {
                    building,
                    storey,
                    time: self.t,
                });
                return;
            }
            Event::Separation(pi) => {
                let p = self.layout.pairs[pi];
                self.config.contact[pi] = None;
                if let Some(history) = self.forces.as_mut() {
                    history.push(pi, self.t, 0.0);
                }
                if let Some(last) = self.pairs[pi].impacts.last_mut() {
                    last.end = self.t;
                    last.separation_velocity = -(self.v[p.left_dof] - self.v[p.right_dof]);
                }
            }
        }
        self.system = self.propagator.systems.of(&self.layout, &self.config);
    }

    /// Maps made and map steps taken by this run so far (those of the run
    /// a continuation took up included), and the seconds spent making maps.
    fn maps_so_far(&self) -> (usize, usize, f64) {
        let (before, carried, p) = (self.counts_before, self.carried, &self.propagator);
        (
            carried.0 + p.made - before.0,
            carried.1 + p.used - before.1,
            carried.2 + p.seconds - before.2,
        )
    }

    fn finish(mut self, duration: f64) -> RowRun {
        let (maps_made, map_steps, exponential_seconds) = self.maps_so_far();
        self.profile.maps_made = maps_made;
        let c = self.collocation.borrow();
        self.profile.collocation = CollocationSteps {
            accepted: c.accepted,
            rejected: c.rejected,
            solves: c.solves,
            newton: c.newton,
            responses: c.made,
            series: self.profile.collocation.series,
        };
        drop(c);
        if self.timed {
            self.profile.exponential_seconds = exponential_seconds;
        }
        let mut floors = Vec::new();
        let mut k = 0;
        for (b, &o) in self.row.buildings.iter().zip(&self.row.offsets()) {
            let mut list = Vec::new();
            for i in 0..b.storeys() {
                let s = &self.layout.storeys[k];
                let drift = self.envelope.drift[k];
                let now = self.layout.drift(s, &self.u);
                let z = self.config.z(k, now, s.yield_drift);
                list.push(FloorPeaks {
                    displacement: self.envelope.displacement[o + i],
                    velocity: self.envelope.velocity[o + i],
                    absolute_acceleration: self.envelope.acceleration[o + i],
                    drift,
                    drift_ratio: drift / s.height,
                    ductility: drift / s.yield_drift,
                    residual_drift: (1.0 - s.alpha) * (now - z),
                });
                k += 1;
            }
            floors.push(list);
        }
        let energy = self.energy.as_ref().map(|b| RowEnergy {
            kinetic: 0.5
                * self
                    .layout
                    .mass
                    .iter()
                    .zip(&self.v)
                    .map(|(m, v)| m * v * v)
                    .sum::<f64>(),
            ..b.sums
        });
        let (mut pairs, mut forces) = (self.pairs, self.forces);
        let bumpers = pairs.split_off(self.layout.hard);
        if let Some(f) = forces.as_mut() {
            f.bumpers = f.pairs.split_off(self.layout.hard);
        }
        RowRun {
            energy,
            max_relative: self.envelope.relative.clone(),
            floors,
            pairs,
            bumpers,
            links: self.links,
            duration,
            final_displacement: self.u,
            final_velocity: self.v,
            maps_made,
            map_steps,
            series_steps: self.series_steps,
            configurations: self.configurations.len(),
            trace: None,
            forces,
            collapse: self.collapse,
            profile: self.profile,
        }
    }
}
