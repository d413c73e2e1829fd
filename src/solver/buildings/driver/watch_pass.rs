//! The first pass of the quiet test (SPEC §13) over the watched quantities
//! of [`super::watched`] at once: every floor's u, u̇ and ü + a_g, every
//! storey's drift (against its yield drift or, yielding, its rate against
//! unloading, and against its running peak), every facing pair's relative
//! displacement and every contact element's gap, each asked its question
//! on the widened hull of its Hermite cubic, straight from the two ends'
//! stacks, in blocks of [`LANES`] quantities.
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
//! fl(fl(min c − e) − p), so the four comparisons are the hull's own. A
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

use super::super::bound::Stack;
use super::super::config::{Branch, Config};
use super::super::lanes::LANES;
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

/// The questions of one sub-step in structure-of-arrays form, one entry
/// per question, padded to whole blocks of [`LANES`].
#[derive(Debug, Default)]
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
    fn clear(&mut self) {
        for v in [
            &mut self.q0,
            &mut self.d0,
            &mut self.q1,
            &mut self.d1,
            &mut self.error,
            &mut self.offset,
            &mut self.lower,
            &mut self.upper,
        ] {
            v.clear();
        }
    }

    /// One question: q's (or q̇'s) values and rates at both ends, its
    /// error bound, offset and limits.
    #[inline]
    fn push(
        &mut self,
        ((q0, d0), (q1, d1)): ((f64, f64), (f64, f64)),
        error: f64,
        offset: f64,
        (lower, upper): (f64, f64),
    ) {
        self.q0.push(q0);
        self.d0.push(d0);
        self.q1.push(q1);
        self.d1.push(d1);
        self.error.push(error);
        self.offset.push(offset);
        self.lower.push(lower);
        self.upper.push(upper);
    }

    /// Pads to whole blocks with questions that nothing clears.
    fn pad(&mut self) {
        while !self.q0.len().is_multiple_of(LANES) {
            self.push(((0.0, 0.0), (0.0, 0.0)), 0.0, 0.0, (f64::INFINITY, 0.0));
        }
    }

    /// Each question's verdict on the widened hull over a sub-step of
    /// length `h`, into `out` (one entry per question).
    fn answer(&self, h: f64, out: &mut Vec<bool>) {
        out.clear();
        let rows = self
            .q0
            .chunks_exact(LANES)
            .zip(self.d0.chunks_exact(LANES))
            .zip(self.q1.chunks_exact(LANES))
            .zip(self.d1.chunks_exact(LANES))
            .zip(self.error.chunks_exact(LANES))
            .zip(self.offset.chunks_exact(LANES))
            .zip(self.lower.chunks_exact(LANES))
            .zip(self.upper.chunks_exact(LANES));
        for (((((((q0, d0), q1), d1), e), p), lo), hi) in rows {
            let mut verdict = [false; LANES];
            for l in 0..LANES {
                // The hull's control points, as [`super::super::hermite::hull`] makes them.
                let (b1, b2) = (q0[l] + d0[l] * h / 3.0, q1[l] - d1[l] * h / 3.0);
                let ok = |c: f64| (lo[l] <= (c - e[l]) - p[l]) & ((c + e[l]) - p[l] <= hi[l]);
                verdict[l] = ok(q0[l]) & ok(b1) & ok(b2) & ok(q1[l]);
            }
            out.extend_from_slice(&verdict);
        }
    }
}

/// The first pass: the watched quantities' differences, laid out once per
/// run, and each sub-step's questions and verdicts.
#[derive(Debug, Default)]
pub(super) struct WatchPass {
    /// Floors n.
    dofs: usize,
    storeys: Vec<Difference>,
    facing: Vec<Difference>,
    gaps: Vec<Difference>,
    questions: Questions,
    cleared: Vec<bool>,
}

impl WatchPass {
    pub fn new(layout: &Layout) -> WatchPass {
        let pair = |p: &crate::model::buildings::FloorPair| Difference {
            a: p.left_dof,
            b: p.right_dof,
            w: 1.0,
        };
        WatchPass {
            dofs: layout.dofs,
            storeys: layout
                .storeys
                .iter()
                .map(|s| Difference {
                    a: s.upper,
                    b: s.lower.unwrap_or(s.upper),
                    w: if s.lower.is_some() { 1.0 } else { 0.0 },
                })
                .collect(),
            facing: layout.facing.iter().map(pair).collect(),
            gaps: layout.pairs.iter().map(pair).collect(),
            questions: Questions::default(),
            cleared: Vec::new(),
        }
    }

    /// Asks every question of the sub-step of length `h` from `start` to
    /// `end`, with `errors`(k) the bounds on the errors of the cubics of q
    /// and q̇ of quantity k ([`super::super::bound::Bounds::errors`]).
    pub fn ask(
        &mut self,
        (start, end): (&Stack, &Stack),
        errors: impl Fn(usize) -> (f64, f64),
        h: f64,
        (layout, config, env): (&Layout, &Config, &Envelope),
    ) {
        let n = self.dofs;
        let storeys = self.storeys.len();
        let value_error = |k: usize| errors(k).0;
        let qs = &mut self.questions;
        qs.clear();
        // Every floor's u, u̇, ü + a_g against its running peak.
        let peaks = [&env.displacement, &env.velocity, &env.acceleration];
        for (order, peaks) in peaks.into_iter().enumerate() {
            let read = |stack: &Stack, i: usize| {
                let (x, y) = (stack.rates[order][i], stack.rates[order + 1][i]);
                if order == 2 {
                    (x + stack.ground[0], y + stack.ground[1])
                } else {
                    (x, y)
                }
            };
            for (i, &peak) in peaks.iter().enumerate() {
                let ends = (read(start, i), read(end, i));
                qs.push(ends, value_error(order * n + i), 0.0, (-peak, peak));
            }
        }
        // Every storey's drift against its running peak, then its event.
        let base = 3 * n;
        for (k, d) in self.storeys.iter().enumerate() {
            let ends = (d.at(start, 0), d.at(end, 0));
            let peak = env.drift[k];
            qs.push(ends, value_error(base + k), 0.0, (-peak, peak));
        }
        for (k, (d, s)) in self.storeys.iter().zip(&layout.storeys).enumerate() {
            let (error, rate_error) = errors(base + k);
            match config.branch[k] {
                Branch::Elastic => {
                    let dy = s.yield_drift;
                    let ends = (d.at(start, 0), d.at(end, 0));
                    let limits = ((-dy).next_up(), dy.next_down());
                    qs.push(ends, error, config.plastic[k], limits);
                }
                branch => {
                    let ends = (d.at(start, 1), d.at(end, 1));
                    let limits = if branch == Branch::Plus {
                        (0f64.next_up(), f64::INFINITY)
                    } else {
                        (f64::NEG_INFINITY, 0f64.next_down())
                    };
                    qs.push(ends, rate_error, 0.0, limits);
                }
            }
        }
        // Every facing pair's u_A − u_B under its running peak.
        let base = base + storeys;
        for (k, d) in self.facing.iter().enumerate() {
            let ends = (d.at(start, 0), d.at(end, 0));
            let limits = (f64::NEG_INFINITY, env.relative[k]);
            qs.push(ends, value_error(base + k), 0.0, limits);
        }
        // Every contact element's u_A − u_B under its gap.
        let base = base + self.facing.len();
        for (k, (d, &gap)) in self.gaps.iter().zip(&layout.gaps).enumerate() {
            let ends = (d.at(start, 0), d.at(end, 0));
            let limits = (f64::NEG_INFINITY, gap.next_down());
            qs.push(ends, value_error(base + k), 0.0, limits);
        }
        qs.pad();
        qs.answer(h, &mut self.cleared);
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
        self.cleared[3 * self.dofs + self.storeys.len() + k]
    }

    /// Whether facing pair k's u_A − u_B stays under its running peak.
    pub fn relative_below(&self, k: usize) -> bool {
        self.cleared[3 * self.dofs + 2 * self.storeys.len() + k]
    }

    /// Whether contact element k stays open.
    pub fn open(&self, k: usize) -> bool {
        self.cleared[3 * self.dofs + 2 * self.storeys.len() + self.facing.len() + k]
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
            .prop_map(|(rates, ground)| Stack { rates, ground })
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
                pass.ask((&start, &end), |k| errors[k], h, (&layout, &config, &env));
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
        };
        rest.rates[0][a] = x;
        layout.gaps[0] = x;
        config.plastic[0] = 0.1;
        layout.storeys[0].yield_drift = x - 0.1;
        env.displacement[a] = x;
        env.drift[0] = x.next_down();
        let ask = |layout: &Layout, config: &Config, env: &Envelope, s: &Stack| {
            let mut pass = WatchPass::new(layout);
            pass.ask((s, s), |_| (0.0, 0.0), 0.5, (layout, config, env));
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
