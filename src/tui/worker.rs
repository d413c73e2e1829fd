//! The solver on a background thread, latest wins (after gitui's
//! `AsyncSingleJob`): at most one job runs and at most one waits; a newer
//! request replaces the waiting one and cancels the running one (through the
//! observer's `keep_going`, and between chunks of spectrum points, map rows
//! and a risk picture's runs). Every output carries
//! its job's generation so the app can drop stale ones.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::risk_job::{RiskOutput, RiskSpec, run_risk};
use super::row_job::{self, RowOutput, RowSpec};
use super::trace::Trace;
use crate::analysis::gap::{MinimumGap, free_params, minimum_gap};
use crate::analysis::map::{MapCache, MapCell, MapPlan, compute_rows};
use crate::analysis::spectrum::{SpectrumPoint, point};
use crate::model::Method;
use crate::model::Params;
use crate::solver::{Observer, RunResult, Sample, error_vs_exact, solve};

/// Which run of the explorer a result belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Slot {
    /// Parameter set 0 (left pane) or 1 (right pane).
    Set(usize),
    /// The active set under another contact law (the laws compared).
    Law(crate::model::ContactModel),
}

/// One run to compute: its parameters and the history to keep.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSpec {
    pub slot: Slot,
    pub params: Params,
    /// Time buckets of the decimated history (chart width × 2 Braille dots).
    pub buckets: usize,
    /// The time window [τ0, τ1] the history covers (the whole run unless zoomed).
    pub window: [f64; 2],
}

/// A spectrum to compute point by point (SPEC §7).
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumSpec {
    /// Every parameter but Π_ω1, Π_ω2 (which the grid sets).
    pub params: Params,
    /// μ = Π_ω2/Π_ω1.
    pub mu: f64,
    /// Π_ω1 grid.
    pub grid: Vec<f64>,
}

/// A region map to compute row by row (SPEC §7): coarse rows first.
#[derive(Debug, Clone, PartialEq)]
pub struct MapSpec {
    /// The base set (exact method), μ and the axes; checked by the worker.
    pub plan: MapPlan,
}

impl MapSpec {
    pub fn columns(&self) -> usize {
        self.plan.x.len()
    }
    pub fn rows(&self) -> usize {
        self.plan.y.len()
    }
}

/// The order the rows of a map are computed in: every 8th row, then the
/// rows between them at 4, 2 and 1, so a coarse picture appears at once
/// and is refined in place.
pub fn row_order(rows: usize) -> Vec<usize> {
    let mut order = Vec::with_capacity(rows);
    let mut done = vec![false; rows];
    for stride in [8, 4, 2, 1] {
        for r in (0..rows).step_by(stride) {
            if !done[r] {
                done[r] = true;
                order.push(r);
            }
        }
    }
    order
}

/// What the visible scene needs.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Job {
    pub generation: u64,
    pub runs: Vec<RunSpec>,
    pub spectrum: Option<SpectrumSpec>,
    pub map: Option<MapSpec>,
    pub risk: Option<RiskSpec>,
    pub row: Option<RowSpec>,
}

/// A finished run.
#[derive(Debug, Clone)]
pub struct RunOutput {
    pub spec: RunSpec,
    pub result: RunResult,
    pub history: Trace,
    /// Wall time of the run in milliseconds.
    pub elapsed_ms: f64,
    /// Newmark's largest relative peak error against the exact method on the
    /// same parameters (None for an exact run).
    pub error_vs_exact: Option<f64>,
    /// The gap that prevents pounding for a parameter set's run (SPEC §11):
    /// Π_d,min = max over τ of x1 − x2 of the no-pounding run, beside the
    /// code rules. None for the other contact laws' runs.
    pub min_gap: Option<MinimumGap>,
}

/// Spectrum points computed between two cancellation checks.
const SPECTRUM_CHUNK: usize = 32;

/// The longest a filling spectrum waits before its points are shown.
const BATCH_INTERVAL: Duration = Duration::from_millis(200);

/// What the worker reports.
#[derive(Debug, Clone)]
pub enum Output {
    Run {
        generation: u64,
        output: Box<RunOutput>,
    },
    /// Consecutive spectrum points from grid index `start` on.
    Points {
        generation: u64,
        start: usize,
        points: Vec<SpectrumPoint>,
    },
    /// Whole map rows: (row index from the lowest y, its cells by x).
    MapRows {
        generation: u64,
        rows: Vec<(usize, Vec<MapCell>)>,
    },
    /// The map's parameters are refused (one line naming the value).
    MapError { generation: u64, message: String },
    /// A pass of the risk picture, or why there is none.
    Risk { generation: u64, output: RiskOutput },
    /// The buildings scene's runs, or the solver's one line on why not.
    Row {
        generation: u64,
        output: Result<Box<RowOutput>, (RowSpec, String)>,
    },
    /// The job ended, complete or cancelled by a newer one.
    Done { generation: u64, cancelled: bool },
}

impl Output {
    pub fn generation(&self) -> u64 {
        match self {
            Output::Run { generation, .. }
            | Output::Points { generation, .. }
            | Output::MapRows { generation, .. }
            | Output::MapError { generation, .. }
            | Output::Risk { generation, .. }
            | Output::Row { generation, .. }
            | Output::Done { generation, .. } => *generation,
        }
    }
}

/// The waiting place: at most one job.
#[derive(Debug, Default)]
pub struct Pending {
    waiting: Option<Job>,
    shutdown: bool,
}

impl Pending {
    /// Puts a job in the waiting place, returning the one it replaced.
    pub fn put(&mut self, job: Job) -> Option<Job> {
        self.waiting.replace(job)
    }
}

struct Shared {
    pending: Mutex<Pending>,
    wake: Condvar,
    /// Generation of the newest request; a job of an older one stops.
    latest: AtomicU64,
}

/// The background solver thread.
pub struct Worker {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the thread; `send` receives every output.
    pub fn start(send: impl Fn(Output) + Send + 'static) -> Worker {
        let shared = Arc::new(Shared {
            pending: Mutex::new(Pending::default()),
            wake: Condvar::new(),
            latest: AtomicU64::new(0),
        });
        let inner = Arc::clone(&shared);
        let thread = std::thread::Builder::new()
            .name("pounding-solver".into())
            .spawn(move || worker_loop(&inner, &send))
            .ok();
        Worker { shared, thread }
    }

    /// Requests a job: it replaces any waiting job, and the running one stops.
    pub fn submit(&self, job: Job) {
        self.shared.latest.store(job.generation, Ordering::SeqCst);
        if let Ok(mut p) = self.shared.pending.lock() {
            p.put(job);
        }
        self.shared.wake.notify_one();
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.shared.latest.store(u64::MAX, Ordering::SeqCst);
        if let Ok(mut p) = self.shared.pending.lock() {
            p.shutdown = true;
        }
        self.shared.wake.notify_one();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

fn worker_loop(shared: &Shared, send: &dyn Fn(Output)) {
    loop {
        let job = {
            let Ok(mut p) = shared.pending.lock() else {
                return;
            };
            loop {
                if p.shutdown {
                    return;
                }
                if let Some(job) = p.waiting.take() {
                    break job;
                }
                p = match shared.wake.wait(p) {
                    Ok(p) => p,
                    Err(_) => return,
                };
            }
        };
        let current = || shared.latest.load(Ordering::SeqCst) == job.generation;
        let cancelled = !run_job(&job, &current, send);
        send(Output::Done {
            generation: job.generation,
            cancelled,
        });
    }
}

/// Runs every part of a job while `current()` holds; false if it stopped early.
pub fn run_job(job: &Job, current: &dyn Fn() -> bool, send: &dyn Fn(Output)) -> bool {
    if let Some(spec) = &job.row {
        let output = row_job::run(spec)
            .map(Box::new)
            .map_err(|e| (spec.clone(), e));
        if !current() {
            return false;
        }
        send(Output::Row {
            generation: job.generation,
            output,
        });
    }
    for spec in &job.runs {
        if !current() {
            return false;
        }
        let output = compute_run(spec, current);
        if !output.result.completed || !current() {
            return false;
        }
        send(Output::Run {
            generation: job.generation,
            output: Box::new(output),
        });
    }
    if let Some(s) = &job.spectrum {
        // A spectrum runs many cases: the exact method, whatever the set's own.
        let params = crate::model::Params {
            method: Method::Exact,
            ..s.params.clone()
        };
        // Points are computed in parallel, a chunk at a time so that a newer
        // job cancels within one chunk, and sent in batches a few times per
        // second (or once, when the whole spectrum is quick), so the screen
        // is redrawn per batch, not per point.
        let mut batch_start = 0;
        let mut batch = Vec::new();
        let mut sent = Instant::now();
        for (k, chunk) in s.grid.chunks(SPECTRUM_CHUNK).enumerate() {
            if !current() {
                return false;
            }
            batch.par_extend(chunk.par_iter().map(|&omega1| point(&params, omega1, s.mu)));
            let last = (k + 1) * SPECTRUM_CHUNK >= s.grid.len();
            if last || sent.elapsed() >= BATCH_INTERVAL {
                let points = std::mem::take(&mut batch);
                let start = batch_start;
                batch_start += points.len();
                sent = Instant::now();
                send(Output::Points {
                    generation: job.generation,
                    start,
                    points,
                });
            }
        }
    }
    if let Some(m) = &job.map
        && !run_map(job.generation, m, current, send)
    {
        return false;
    }
    if let Some(r) = &job.risk {
        let generation = job.generation;
        return run_risk(r, current, &|output| {
            send(Output::Risk { generation, output })
        });
    }
    true
}

/// Rows of a map computed between two cancellation checks.
const MAP_CHUNK: usize = 4;

/// Computes a map's rows in [`row_order`], a few at a time so that a newer
/// job cancels within one chunk; the first chunk is sent at once (the
/// coarse picture), the rest in batches a few times per second.
fn run_map(
    generation: u64,
    m: &MapSpec,
    current: &dyn Fn() -> bool,
    send: &dyn Fn(Output),
) -> bool {
    let p = &m.plan;
    let plan = match MapPlan::new(p.base.clone(), p.mu, p.x, p.y) {
        Ok(plan) => plan,
        Err(e) => {
            send(Output::MapError {
                generation,
                message: e.to_string(),
            });
            return true;
        }
    };
    let ys = plan.y.values();
    let nx = plan.x.len();
    let mut cache = MapCache::default();
    let mut batch = Vec::new();
    let mut sent: Option<Instant> = None;
    let order = row_order(ys.len());
    let chunks: Vec<&[usize]> = order.chunks(MAP_CHUNK).collect();
    for (k, chunk) in chunks.iter().enumerate() {
        if !current() {
            return false;
        }
        let values: Vec<f64> = chunk.iter().map(|&r| ys[r]).collect();
        let cells = compute_rows(&plan, &values, &mut cache);
        for (i, &r) in chunk.iter().enumerate() {
            batch.push((r, cells[i * nx..(i + 1) * nx].to_vec()));
        }
        let last = k + 1 == chunks.len();
        if last || sent.is_none_or(|t| t.elapsed() >= BATCH_INTERVAL) {
            sent = Some(Instant::now());
            send(Output::MapRows {
                generation,
                rows: std::mem::take(&mut batch),
            });
        }
    }
    true
}

/// A decimated history that stops when its job is superseded.
struct Cancellable<'a> {
    history: Trace,
    current: &'a dyn Fn() -> bool,
}

impl Observer for Cancellable<'_> {
    #[inline]
    fn record(&mut self, sample: &Sample) {
        self.history.record(sample);
    }
    fn keep_going(&mut self) -> bool {
        (self.current)()
    }
}

/// One run with the default (accurate) solver options and a decimated history.
pub fn compute_run(spec: &RunSpec, current: &dyn Fn() -> bool) -> RunOutput {
    let start = Instant::now();
    let mut observer = Cancellable {
        history: Trace::new(spec.buckets, spec.window).with_contact(spec.params.gap),
        current,
    };
    let result = solve(&spec.params, &mut observer);
    let elapsed_ms = start.elapsed().as_secs_f64() * 1e3;
    // A few per cent of a Newmark run: its actual error, shown beside it.
    let error_vs_exact = (spec.params.method == Method::Newmark && result.completed)
        .then(|| error_vs_exact(&spec.params, &result));
    let min_gap = matches!(spec.slot, Slot::Set(_)).then(|| gap_of(&spec.params, &result));
    RunOutput {
        spec: spec.clone(),
        result,
        history: observer.history,
        elapsed_ms,
        error_vs_exact,
        min_gap,
    }
}

/// Parameter sets whose minimum gap is kept (both panes, and a few more).
const GAP_CACHE: usize = 4;

thread_local! {
    /// Minimum gaps by parameter set, newest last: a zoom or a scene switch
    /// re-runs the history but not the no-pounding run.
    static GAPS: std::cell::RefCell<Vec<(Params, MinimumGap)>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// The minimum gap of `p` (SPEC §11). An exact run without impacts is its
/// own no-pounding twin (the contact never acted), and the solver reports
/// its x1 − x2 peak, which is used as is; otherwise one extra exact run
/// without contact, cached.
pub fn gap_of(p: &Params, run: &RunResult) -> MinimumGap {
    if let Some(g) = MinimumGap::from_free_run(&free_params(p), run) {
        return g;
    }
    GAPS.with_borrow_mut(|cache| {
        if let Some((_, g)) = cache.iter().find(|(q, _)| q == p) {
            return *g;
        }
        let g = minimum_gap(p);
        if cache.len() == GAP_CACHE {
            cache.remove(0);
        }
        cache.push((p.clone(), g));
        g
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::preset::builtin;

    fn run_of(params: Params) -> RunOutput {
        let spec = RunSpec {
            slot: Slot::Set(0),
            buckets: 100,
            window: [0.0, params.tau_end()],
            params,
        };
        compute_run(&spec, &|| true)
    }

    #[test]
    fn the_minimum_gap_is_the_librarys_whether_the_set_pounds_or_not() {
        let set1 = builtin("set1").unwrap().params;
        let exact = minimum_gap(&set1).exact;
        // Set 1 pounds (its Π_d is below Π_d,min): one extra run.
        let pounding = run_of(set1.clone());
        assert!(!pounding.result.impacts.is_empty());
        assert!(set1.gap < exact);
        assert_eq!(pounding.min_gap.unwrap().exact, exact);
        // A gap a little above Π_d,min, exact method: no impact, and the
        // run is its own no-pounding twin.
        let clear = run_of(Params {
            gap: exact + 1e-6,
            method: Method::Exact,
            ..set1.clone()
        });
        assert!(clear.result.max_relative_displacement.is_some());
        assert!(clear.result.impacts.is_empty());
        let own = clear.min_gap.unwrap().exact;
        assert!(
            (own - exact).abs() <= 1e-9 * exact.max(1.0),
            "{own} {exact}"
        );
    }
}
