//! The first pass of the quiet test (SPEC §13) over the watched quantities
//! of [`super::watched`] at once: every floor's u, u̇ and ü + a_g, every
//! storey's drift (against its yield drift or, yielding, its rate against
//! unloading, and against its running peak), every facing pair's relative
//! displacement and every contact element's gap, each asked its question
//! on the widened hull of its Hermite cubic, straight from the two ends'
//! stacks, in plain loops over arrays that the compiler turns into vector
//! operations: the floors' questions read the stacks' rates in place, the
//! storeys' the drifts formed from them in one pass (storey k joins floor
//! k to floor k − 1 or the ground), the facing pairs' and the gaps' are
//! gathered first into one array per operand.
//!
//! Each question asks whether the rigorous range of q (or of q̇) lies
//! within limits. On the hull of the control points c ∈ {q0, q0 + d0h/3,
//! q1 − d1h/3, q1} of the cubic ([`super::super::hermite::hull`]), widened
//! by the error bound e of [`super::super::bound::Bounds::errors`] and
//! measured from an offset p (a storey's plastic drift, else 0), it is
//!
//! ```text
//! lower ≤ fl(fl(c − e) − p)   and   fl(fl(c + e) − p) ≤ upper   for all four c:
//! ```
//!
//! since rounding is monotone, min over c of fl(fl(c − e) − p) is
//! fl(fl(min c − e) − p), so the four comparisons are the hull's own, and
//! they are asked as two, of the least and the largest c (with each c
//! asked to be a number, as a comparison with a NaN would be false). A
//! strict limit x < d is x ≤ d⁻ (the float below d), which is the same
//! test for every float x; the questions become
//!
//! | quantity                  | offset | lower      | upper      |
//! |---------------------------|--------|------------|------------|
//! | |q| within its peak P     | 0      | −P         | P          |
//! | elastic drift, Δ_y        | p      | (−Δ_y)⁺    | Δ_y⁻       |
//! | yielding drift's rate     | 0      | 0⁺ or −∞   | ∞ or 0⁻    |
//! | gap d (no onset)          | 0      | −∞         | d⁻         |
//! | relative displacement     | 0      | −∞         | P          |
//!
//! A comparison with a NaN is false, so nothing a NaN touches is cleared.
//! On finite values the verdicts are those of [`super::ranges::Ends`]'s
//! hull, the first test [`super::ranges::Ends::clears`] asks, bit for bit
//! (the differences u_a − u_b are Probe::at's, up to the sign of a zero,
//! which no comparison sees): what this pass clears, the per-quantity
//! path clears, and only what it cannot clear goes on to that path and
//! its exact ranges.

use crate::numerics::extremes::{largest, least};

use super::super::bound::Stack;
use super::super::config::{Branch, Config};
use super::super::layout::Layout;
use super::super::peaks::Envelope;

/// A difference of two floors' rates, x_a − w·x_b (w = 0 for a storey on
/// the ground, whose drift is its floor's own u).
#[derive(Debug, Clone, Copy)]
struct Difference {
    a: usize,
    b: usize,
    w: f64,
}

impl Difference {
    /// (q, q̇) of x^(order) at the instant of `stack`.
    #[inline]
    fn at(self, stack: &Stack, order: usize) -> (f64, f64) {
        let (x, y) = (&stack.rates[order], &stack.rates[order + 1]);
        (
            x[self.a] - self.w * x[self.b],
            y[self.a] - self.w * y[self.b],
        )
    }
}

/// Whether the hull of the cubic through (q0, d0) and (q1, d1) over a
/// sub-step of length `h`, widened by `e` and measured from `p`, lies in
/// [lower, upper]: lower ≤ fl(fl(min c − e) − p) and fl(fl(max c + e) − p)
/// ≤ upper over its control points c, made as
/// [`super::super::hermite::hull`] makes them, each a number.
#[inline(always)]
fn clears(
    ((q0, d0), (q1, d1)): ((f64, f64), (f64, f64)),
    h: f64,
    (e, p): (f64, f64),
    (lower, upper): (f64, f64),
) -> bool {
    let (b1, b2) = (q0 + d0 * h / 3.0, q1 - d1 * h / 3.0);
    let low = least(least(q0, q1), least(b1, b2));
    let high = largest(largest(q0, q1), largest(b1, b2));
    let numbers = !q0.is_nan() & !q1.is_nan() & !b1.is_nan() & !b2.is_nan();
    numbers & (lower <= (low - e) - p) & ((high + e) - p <= upper)
}

/// Each storey's drift of floor rates `x` (order 0: u; 1: u̇; 2: ü) into
/// `out`: storey k's x_k − w_k x_b, b = k − 1 over a floor (w_k = 1) and
/// b = k on the ground (w_k = 0), as [`Difference::at`] forms it, with b
/// chosen by a select so that the loop runs as vector operations.
#[inline(always)]
fn storey_drifts(x: &[f64], grounds: &[f64], out: &mut [f64]) {
    let n = out.len();
    let (x, grounds) = (&x[..n], &grounds[..n]);
    if n == 0 {
        return;
    }
    out[0] = x[0] - grounds[0] * x[0];
    let (below, here) = (&x[..n - 1], &x[1..]);
    for (((o, &w), &xb), &xk) in out[1..].iter_mut().zip(&grounds[1..]).zip(below).zip(here) {
        let b = if w != 0.0 { xb } else { xk };
        *o = xk - w * b;
    }
}

/// The questions past the floors' and the storeys' (each facing pair's
/// peak, each gap), one array per operand: each one's q and its rate at
/// both ends, its error bound, offset and limits.
#[derive(Debug, Clone, Default)]
struct Questions {
    q0: Vec<f64>,
    d0: Vec<f64>,
    q1: Vec<f64>,
    d1: Vec<f64>,
    error: Vec<f64>,
    offset: Vec<f64>,
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl Questions {
    fn new(count: usize) -> Questions {
        let zeros = vec![0.0; count];
        Questions {
            q0: zeros.clone(),
            d0: zeros.clone(),
            q1: zeros.clone(),
            d1: zeros.clone(),
            error: zeros.clone(),
            offset: zeros.clone(),
            lower: zeros.clone(),
            upper: zeros,
        }
    }

    /// Question `j`: ((q0, q̇0), (q1, q̇1)), error, offset, (lower, upper).
    // Always inline: called once per question and sub-step (6 times a
    // map step in block-and-frame), its eight stores cost less than the
    // call that passes them, which a plain hint left out of line.
    #[inline(always)]
    fn set(
        &mut self,
        j: usize,
        ((q0, d0), (q1, d1)): ((f64, f64), (f64, f64)),
        (error, offset): (f64, f64),
        (lower, upper): (f64, f64),
    ) {
        self.q0[j] = q0;
        self.d0[j] = d0;
        self.q1[j] = q1;
        self.d1[j] = d1;
        self.error[j] = error;
        self.offset[j] = offset;
        self.lower[j] = lower;
        self.upper[j] = upper;
    }

    /// Each question's verdict ([`clears`]) over a sub-step of length `h`.
    fn verdicts(&self, h: f64, out: &mut [bool]) {
        let m = out.len();
        let (q0, d0, q1, d1) = (&self.q0[..m], &self.d0[..m], &self.q1[..m], &self.d1[..m]);
        let (error, offset) = (&self.error[..m], &self.offset[..m]);
        let (lower, upper) = (&self.lower[..m], &self.upper[..m]);
        for j in 0..m {
            out[j] = clears(
                ((q0[j], d0[j]), (q1[j], d1[j])),
                h,
                (error[j], offset[j]),
                (lower[j], upper[j]),
            );
        }
    }
}

/// The first pass: the watched quantities' differences, laid out once per
/// run, and each sub-step's verdicts.
#[derive(Debug, Default)]
pub(super) struct WatchPass {
    /// Floors n.
    dofs: usize,
    /// Storey k joins floor k to floor k − 1 (w_k = 1) or to the ground
    /// (w_k = 0, a building's first storey): its drift is x_k − w_k x_b
    /// with b = k − 1 or k ([`Difference`]'s form, read in one pass).
    grounds: Vec<f64>,
    /// Each storey's drift, its rate and its second rate at the start and
    /// at the end of the sub-step (orders 0 to 2 of [`storey_drifts`]).
    drifts: [[Vec<f64>; 3]; 2],
    facing: Vec<Difference>,
    gaps: Vec<Difference>,
    /// Each storey's limits while elastic, ((−Δ_y)⁺, Δ_y⁻), and each gap's
    /// d⁻: constants of the run, made once.
    yield_limits: Vec<(f64, f64)>,
    gap_limits: Vec<f64>,
    questions: Questions,
    /// Each question's verdict: the floors' 3n, then the others'.
    cleared: Vec<bool>,
}

impl WatchPass {
    pub fn new(layout: &Layout) -> WatchPass {
        let pair = |p: &crate::model::buildings::FloorPair| Difference {
            a: p.left_dof,
            b: p.right_dof,
            w: 1.0,
        };
        let n = layout.dofs;
        let storeys = layout.storeys.len();
        // Storey k is floor k's (Layout::of lays them out so), over floor
        // k − 1 or the ground.
        assert!(
            storeys == n
                && layout
                    .storeys
                    .iter()
                    .enumerate()
                    .all(|(k, s)| s.upper == k && s.lower.is_none_or(|lower| lower + 1 == k)),
            "storey k joins floor k to floor k − 1 or the ground"
        );
        let questions = layout.facing.len() + layout.pairs.len();
        let drift = || [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        WatchPass {
            dofs: n,
            grounds: layout
                .storeys
                .iter()
                .map(|s| if s.lower.is_some() { 1.0 } else { 0.0 })
                .collect(),
            drifts: [drift(), drift()],
            facing: layout.facing.iter().map(pair).collect(),
            gaps: layout.pairs.iter().map(pair).collect(),
            yield_limits: layout
                .storeys
                .iter()
                .map(|s| ((-s.yield_drift).next_up(), s.yield_drift.next_down()))
                .collect(),
            gap_limits: layout.gaps.iter().map(|d| d.next_down()).collect(),
            questions: Questions::new(questions),
            cleared: vec![false; 3 * n + 2 * storeys + questions],
        }
    }

    /// Asks every question of the sub-step of length `h` from `start` to
    /// `end`, with the bounds on the errors of the cubics of q and q̇ of
    /// quantity k the products value[k] · size and rate[k] · size
    /// ([`super::super::bound::Bounds::errors`]).
    pub fn ask(
        &mut self,
        (start, end): (&Stack, &Stack),
        (value, rate, size): (&[f64], &[f64], f64),
        h: f64,
        (config, env): (&Config, &Envelope),
    ) {
        let n = self.dofs;
        // Every floor's u, u̇, ü + a_g against its running peak, read
        // straight from the stacks (the ground added to ü).
        let peaks = [&env.displacement, &env.velocity, &env.acceleration];
        for (order, peaks) in peaks.into_iter().enumerate() {
            let (g0, g1) = match order {
                2 => (start.ground, end.ground),
                _ => ([0.0; 3], [0.0; 3]),
            };
            let (x0, y0) = (&start.rates[order][..n], &start.rates[order + 1][..n]);
            let (x1, y1) = (&end.rates[order][..n], &end.rates[order + 1][..n]);
            let (errors, peaks) = (&value[order * n..order * n + n], &peaks[..n]);
            let out = &mut self.cleared[order * n..order * n + n];
            for i in 0..n {
                let ends = (
                    (x0[i] + g0[0], y0[i] + g0[1]),
                    (x1[i] + g1[0], y1[i] + g1[1]),
                );
                out[i] = clears(ends, h, (errors[i] * size, 0.0), (-peaks[i], peaks[i]));
            }
        }
        // Every storey's drift against its running peak, then its event,
        // in plain loops over the drifts of both ends.
        let storeys = self.grounds.len();
        for (drifts, stack) in self.drifts.iter_mut().zip([start, end]) {
            for (order, out) in drifts.iter_mut().enumerate() {
                storey_drifts(&stack.rates[order], &self.grounds, out);
            }
        }
        let ([s0, s1, s2], [e0, e1, e2]) = (&self.drifts[0], &self.drifts[1]);
        let base = 3 * n;
        let (peaks, out) = (
            &env.drift[..storeys],
            &mut self.cleared[base..base + storeys],
        );
        let errors = &value[base..base + storeys];
        for k in 0..storeys {
            let ends = ((s0[k], s1[k]), (e0[k], e1[k]));
            out[k] = clears(ends, h, (errors[k] * size, 0.0), (-peaks[k], peaks[k]));
        }
        let out = &mut self.cleared[base + storeys..base + 2 * storeys];
        let rates = &rate[base..base + storeys];
        let (branch, plastic) = (&config.branch[..storeys], &config.plastic[..storeys]);
        let limits = &self.yield_limits[..storeys];
        for k in 0..storeys {
            // Elastic: the drift within its yield drift of the plastic
            // offset; yielding: the drift's rate keeps its sign.
            let (ends, error, offset, limits) = match branch[k] {
                Branch::Elastic => (
                    ((s0[k], s1[k]), (e0[k], e1[k])),
                    errors[k],
                    plastic[k],
                    limits[k],
                ),
                Branch::Plus => (
                    ((s1[k], s2[k]), (e1[k], e2[k])),
                    rates[k],
                    0.0,
                    (0f64.next_up(), f64::INFINITY),
                ),
                Branch::Minus => (
                    ((s1[k], s2[k]), (e1[k], e2[k])),
                    rates[k],
                    0.0,
                    (f64::NEG_INFINITY, 0f64.next_down()),
                ),
            };
            out[k] = clears(ends, h, (error * size, offset), limits);
        }
        // Every facing pair's u_A − u_B under its running peak; every
        // contact element's u_A − u_B under its gap.
        let questions = &mut self.questions;
        let base = base + storeys;
        for (k, d) in self.facing.iter().enumerate() {
            let ends = (d.at(start, 0), d.at(end, 0));
            let limits = (f64::NEG_INFINITY, env.relative[k]);
            let error = value[base + k] * size;
            questions.set(k, ends, (error, 0.0), limits);
        }
        let (j, base) = (self.facing.len(), base + self.facing.len());
        for (k, (d, &gap)) in self.gaps.iter().zip(&self.gap_limits).enumerate() {
            let ends = (d.at(start, 0), d.at(end, 0));
            let limits = (f64::NEG_INFINITY, gap);
            questions.set(j + k, ends, (value[base + k] * size, 0.0), limits);
        }
        questions.verdicts(h, &mut self.cleared[3 * n + 2 * storeys..]);
    }

    /// Whether floor i's u (`order` 0), u̇ (1) or ü + a_g (2) stays within
    /// its running peak.
    pub fn floor(&self, order: usize, i: usize) -> bool {
        self.cleared[order * self.dofs + i]
    }

    /// Whether storey k's drift stays within its running peak.
    pub fn drift_below(&self, k: usize) -> bool {
        self.cleared[3 * self.dofs + k]
    }

    /// Whether storey k neither yields (elastic) nor unloads (yielding).
    pub fn storey_quiet(&self, k: usize) -> bool {
        self.cleared[3 * self.dofs + self.grounds.len() + k]
    }

    /// Whether facing pair k's u_A − u_B stays under its running peak.
    pub fn relative_below(&self, k: usize) -> bool {
        self.cleared[3 * self.dofs + 2 * self.grounds.len() + k]
    }

    /// Whether contact element k stays open.
    pub fn open(&self, k: usize) -> bool {
        self.cleared[3 * self.dofs + 2 * self.grounds.len() + self.facing.len() + k]
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::bound::Stack;
    use super::super::super::config::{Branch, Config};
    use super::super::super::hermite::hull;
    use super::super::super::layout::Layout;
    use super::super::super::peaks::Envelope;
    use super::super::ranges::{Ends, Probe};
    use super::super::watched;
    use super::WatchPass;
    use crate::model::buildings;
    use proptest::prelude::*;

    /// Rows of up to 17 floors (three-in-series, two joints) and 11
    /// (block-and-frame, one joint of three floor pairs).
    const ROWS: [&str; 2] = ["three-in-series", "block-and-frame"];
    const FLOORS: usize = 17;

    /// A question of the quiet test on a range (lo, hi).
    type Question = Box<dyn Fn((f64, f64)) -> bool>;

    /// A stack of `FLOORS` floors' rates and a ground (a, ȧ, ä).
    fn stack() -> impl Strategy<Value = Stack> {
        let rates = || prop::collection::vec(-1.0f64..1.0, FLOORS);
        (
            [rates(), rates(), rates(), rates(), rates()],
            prop::array::uniform3(-1.0f64..1.0),
        )
            .prop_map(|(rates, ground)| Stack {
                rates,
                ground,
                snap: true,
            })
    }

    /// Each storey's branch (0 elastic, 1 plus, 2 minus), plastic drift,
    /// yield drift and running peak.
    fn storeys() -> impl Strategy<Value = Vec<(u8, f64, f64, f64)>> {
        prop::collection::vec((0u8..3, -0.3f64..0.3, 0.0f64..2.0, 0.0f64..2.0), FLOORS)
    }

    /// What the hull of `ends`' cubic of q (`order` 0) or q̇ (1), widened
    /// by its error, says of `within`.
    fn on_hull(ends: &Ends, order: usize, within: impl Fn((f64, f64)) -> bool) -> bool {
        let (a, b) = (ends.start, ends.end);
        let e = [ends.errors.0, ends.errors.1][order];
        let (lo, hi) = hull(a[order], a[order + 1], b[order], b[order + 1], ends.h);
        within((lo - e, hi + e))
    }

    proptest! {
        /// On random ends, errors, peaks, branches, yield drifts and gaps,
        /// every verdict of the pass is the widened hull's on the values
        /// Probe::at reads (the per-quantity path's first test), for each
        /// question the quiet test asks, and what it clears the
        /// per-quantity path ([`Ends::clears`], [`Ends::below`]) clears.
        #[test]
        fn every_verdict_is_the_per_quantity_hulls(
            (start, end) in (stack(), stack()),
            errors in prop::collection::vec((0.0f64..0.2, 0.0f64..0.2), 6 * FLOORS),
            floor_peaks in prop::collection::vec(0.0f64..2.5, 3 * FLOORS),
            storeys in storeys(),
            gaps in prop::collection::vec(0.0f64..2.0, FLOORS),
            relative in prop::collection::vec(-0.5f64..2.0, FLOORS),
            h in 0.01f64..1.0,
        ) {
            for name in ROWS {
                let mut layout = Layout::of(&buildings::load(name).expect("shipped"));
                let (n, ns) = (layout.dofs, layout.storeys.len());
                let (nf, np) = (layout.facing.len(), layout.pairs.len());
                let cut = |s: &Stack| Stack {
                    rates: s.rates.clone().map(|mut r| {
                        r.truncate(n);
                        r
                    }),
                    ground: s.ground,
                    snap: true,
                };
                let (start, end) = (cut(&start), cut(&end));
                let mut config = Config::at_rest(ns, np);
                let mut env = Envelope::new(n, ns, nf);
                for (k, &(branch, plastic, dy, peak)) in storeys.iter().take(ns).enumerate() {
                    let branches = [Branch::Elastic, Branch::Plus, Branch::Minus];
                    config.branch[k] = branches[branch as usize];
                    config.plastic[k] = plastic;
                    layout.storeys[k].yield_drift = dy;
                    env.drift[k] = peak;
                }
                for (g, &d) in layout.gaps.iter_mut().zip(&gaps) {
                    *g = d;
                }
                env.relative.copy_from_slice(&relative[..nf]);
                let peaks = [&mut env.displacement, &mut env.velocity, &mut env.acceleration];
                for (order, peaks) in peaks.into_iter().enumerate() {
                    peaks.copy_from_slice(&floor_peaks[order * FLOORS..order * FLOORS + n]);
                }
                let mut pass = WatchPass::new(&layout);
                let (value, rate): (Vec<f64>, Vec<f64>) = errors.iter().copied().unzip();
                pass.ask((&start, &end), (&value, &rate, 1.0), h, (&config, &env));
                let probes = watched(&layout);
                let ends = |k: usize| {
                    let p: &Probe = &probes[k];
                    Ends { start: p.at(&start), end: p.at(&end), errors: errors[k], h }
                };
                let below =
                    |peak: f64| move |(lo, hi): (f64, f64)| lo.abs().max(hi.abs()) <= peak;
                for order in 0..3 {
                    for i in 0..n {
                        let peaks = [&env.displacement, &env.velocity, &env.acceleration];
                        let (k, peak) = (order * n + i, peaks[order][i]);
                        let q = ends(k);
                        prop_assert_eq!(pass.floor(order, i), on_hull(&q, 0, below(peak)));
                        prop_assert!(!pass.floor(order, i) || q.below(peak));
                    }
                }
                for (k, s) in layout.storeys.iter().enumerate() {
                    let q = ends(3 * n + k);
                    let peak = env.drift[k];
                    prop_assert_eq!(pass.drift_below(k), on_hull(&q, 0, below(peak)));
                    prop_assert!(!pass.drift_below(k) || q.clears(0, below(peak)));
                    let (p, dy) = (config.plastic[k], s.yield_drift);
                    let (order, quiet): (usize, Question) = match config.branch[k] {
                        Branch::Elastic => (
                            0,
                            Box::new(move |(lo, hi)| (lo - p).abs().max((hi - p).abs()) < dy),
                        ),
                        Branch::Plus => (1, Box::new(|(lo, _)| lo > 0.0)),
                        Branch::Minus => (1, Box::new(|(_, hi)| hi < 0.0)),
                    };
                    prop_assert_eq!(pass.storey_quiet(k), on_hull(&q, order, &quiet));
                    prop_assert!(!pass.storey_quiet(k) || q.clears(order, quiet));
                }
                for k in 0..nf {
                    let q = ends(3 * n + ns + k);
                    let peak = env.relative[k];
                    let under = |(_, hi): (f64, f64)| hi <= peak;
                    prop_assert_eq!(pass.relative_below(k), on_hull(&q, 0, under));
                }
                for (k, &d) in layout.gaps.iter().enumerate() {
                    let q = ends(3 * n + ns + nf + k);
                    let open = |(_, hi): (f64, f64)| hi < d;
                    prop_assert_eq!(pass.open(k), on_hull(&q, 0, open));
                }
            }
        }
    }

    /// The limits themselves: a quantity at rest exactly at its peak stays
    /// within it, one float above does not; exactly at its gap it touches
    /// (an onset), one float below it stays open; exactly at its yield
    /// drift from the plastic offset it yields; a NaN clears nothing.
    #[test]
    fn strict_and_loose_limits_and_nan() {
        let mut layout = Layout::of(&buildings::load("block-and-frame").expect("shipped"));
        let (n, ns, nf) = (layout.dofs, layout.storeys.len(), layout.facing.len());
        let np = layout.pairs.len();
        let mut config = Config::at_rest(ns, np);
        let mut env = Envelope::new(n, ns, nf);
        // Floor 0 of the block, the block's base storey, the first pair.
        let pair = layout.pairs[0];
        let a = pair.left_dof;
        assert_eq!(
            (layout.storeys[0].upper, layout.storeys[0].lower),
            (a, None)
        );
        let x = 0.3;
        let mut rest = Stack {
            rates: std::array::from_fn(|_| vec![0.0; n]),
            ground: [0.0; 3],
            snap: true,
        };
        rest.rates[0][a] = x;
        layout.gaps[0] = x;
        config.plastic[0] = 0.1;
        layout.storeys[0].yield_drift = x - 0.1;
        env.displacement[a] = x;
        env.drift[0] = x.next_down();
        let ask = |layout: &Layout, config: &Config, env: &Envelope, s: &Stack| {
            let mut pass = WatchPass::new(layout);
            let zeros = vec![0.0; 6 * FLOORS];
            pass.ask((s, s), (&zeros, &zeros, 0.0), 0.5, (config, env));
            pass
        };
        let pass = ask(&layout, &config, &env, &rest);
        assert!(pass.floor(0, a), "at its peak");
        assert!(!pass.drift_below(0), "a float above its peak");
        assert!(!pass.open(0), "at its gap");
        assert!(!pass.storey_quiet(0), "at its yield drift from p");
        layout.gaps[0] = x.next_up();
        layout.storeys[0].yield_drift = (x - 0.1).next_up();
        let pass = ask(&layout, &config, &env, &rest);
        assert!(pass.open(0) && pass.storey_quiet(0));
        rest.rates[1][a] = f64::NAN;
        let pass = ask(&layout, &config, &env, &rest);
        assert!(!pass.floor(0, a) && !pass.open(0) && !pass.storey_quiet(0));
        assert!(!pass.drift_below(0));
    }
}
