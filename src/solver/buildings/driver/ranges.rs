//! The rigorous ranges of one watched quantity over a sub-step out of
//! contact (SPEC §13, [`super::super::bound`]), asked for the cheap way
//! first.
//!
//! A quiet sub-step's test asks of each quantity whether its range, or the
//! range of its rate, stays within a limit (a yield drift, a gap, a running
//! peak, one sign). Each range is the cubic Hermite interpolant's widened
//! by its error bound e; the interpolant's exact range needs its turning
//! points (a quadratic's roots), while the hull of its Bernstein control
//! points ([`hull`]) holds it at the cost of four sums. Every question
//! asked here is whether an interval lies within a limit, which an
//! enclosure answering yes answers for the range too: the hull is asked
//! first and the exact range only when the hull cannot clear, so the
//! verdict is the exact range's, bit for bit, and most quantities (far
//! below their peaks, far from yield) never need the roots.

use super::super::bound::{Stack, Watch};
use super::super::hermite::{hull, range};
use super::super::quintic;

/// A watched quantity ([`super::watched`]): a floor's u, u̇ or ü + a_g,
/// or the difference of two floors' u or u̇ (a drift, a relative
/// displacement, a link's stroke or rate), read straight from a
/// [`Stack`]'s rates with the operations of [`Stack::of`] in its order,
/// so that its values are Stack::of's bit for bit.
#[derive(Debug, Clone, Copy)]
pub(super) struct Probe {
    order: usize,
    first: (usize, f64),
    second: Option<(usize, f64)>,
}

impl Probe {
    /// x_first^(order) − x_second^(order) (order 0: u, 1: u̇, 2: ü + a_g).
    pub fn new(order: usize, first: usize, second: Option<usize>) -> Probe {
        Probe {
            order,
            first: (first, 1.0),
            second: second.map(|j| (j, -1.0)),
        }
    }

    /// The same quantity as a [`Watch`], for the bounds of [`super::super::bound`].
    pub fn watch(&self) -> Watch {
        Watch {
            terms: std::iter::once(self.first).chain(self.second).collect(),
            order: self.order,
        }
    }

    /// q, q̇, q̈ at the instant of `stack`.
    #[inline]
    pub fn at(&self, stack: &Stack) -> [f64; 3] {
        std::array::from_fn(|k| {
            let x = &stack.rates[self.order + k];
            let add = |q: f64, (i, c): (usize, f64)| {
                let q = q + c * x[i];
                if self.order == 2 {
                    q + c * stack.ground[k]
                } else {
                    q
                }
            };
            let q = add(0.0, self.first);
            match self.second {
                None => q,
                Some(second) => add(q, second),
            }
        })
    }
}

/// q, q̇, q̈ at both ends of a sub-step of length `h`, with the error bounds
/// of the cubics of q and q̇ ([`super::super::bound::Bounds::errors`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Ends {
    pub start: [f64; 3],
    pub end: [f64; 3],
    pub errors: (f64, f64),
    pub h: f64,
}

impl Ends {
    /// Whether `within` holds for the rigorous range of q (or of q̇ with
    /// `order` 1): on the widened hull, else on the widened exact range.
    /// `within` must hold for every interval inside one it holds for.
    pub fn clears(&self, order: usize, within: impl Fn((f64, f64)) -> bool) -> bool {
        within(self.widened(order, hull)) || within(self.widened(order, range))
    }

    /// The rigorous range of q (order 0) or q̇ (order 1): the exact range
    /// of its cubic, widened by the cubic's error bound.
    pub fn range(&self, order: usize) -> (f64, f64) {
        self.widened(order, range)
    }

    /// Whether q̇ keeps one sign over the sub-step (rigorous range).
    pub fn monotone(&self) -> bool {
        self.clears(1, |(lo, hi)| lo > 0.0 || hi < 0.0)
    }

    /// Whether |q| stays within `peak` over the sub-step, or q is monotone
    /// there (then its extremes are the ends, which are recorded).
    pub fn below(&self, peak: f64) -> bool {
        self.clears(0, |(lo, hi)| lo.abs().max(hi.abs()) <= peak) || self.monotone()
    }

    /// Whether q stays in `limits` over the sub-step on its quintic
    /// Hermite through q, q̇ and q̈ at both ends, widened by `error`
    /// ([`super::super::quintic`]).
    pub fn quintic_within(&self, error: f64, limits: (f64, f64)) -> bool {
        quintic::within(self.start, self.end, self.h, error, limits)
    }

    fn widened(
        &self,
        order: usize,
        cubic: fn(f64, f64, f64, f64, f64) -> (f64, f64),
    ) -> (f64, f64) {
        let (a, b) = (self.start, self.end);
        let e = if order == 0 {
            self.errors.0
        } else {
            self.errors.1
        };
        let (lo, hi) = cubic(a[order], a[order + 1], b[order], b[order + 1], self.h);
        (lo - e, hi + e)
    }
}

#[cfg(test)]
mod tests {
    use super::Ends;
    use proptest::prelude::*;

    proptest! {
        /// Asking the hull first changes no verdict: each question the
        /// quiet test asks (below a peak, within a yield drift of an offset,
        /// under a gap, one sign of the rate) is answered as on the exact
        /// widened range alone.
        #[test]
        fn the_hull_first_gives_the_exact_verdicts(
            start in prop::array::uniform3(-1.0f64..1.0),
            end in prop::array::uniform3(-1.0f64..1.0),
            errors in (0.0f64..0.1, 0.0f64..0.1),
            h in 0.05f64..1.0,
            limit in 0.0f64..1.5,
            offset in -0.3f64..0.3,
        ) {
            let q = Ends { start, end, errors, h };
            let (lo, hi) = q.range(0);
            let (rlo, rhi) = q.range(1);
            let magnitude = |(lo, hi): (f64, f64)| lo.abs().max(hi.abs()) <= limit;
            let within = |(lo, hi): (f64, f64)| (lo - offset).abs().max((hi - offset).abs()) < limit;
            prop_assert_eq!(q.clears(0, magnitude), magnitude((lo, hi)));
            prop_assert_eq!(q.clears(0, within), within((lo, hi)));
            prop_assert_eq!(q.clears(0, |(_, hi)| hi < limit), hi < limit);
            prop_assert_eq!(q.monotone(), rlo > 0.0 || rhi < 0.0);
            prop_assert_eq!(q.below(limit), magnitude((lo, hi)) || rlo > 0.0 || rhi < 0.0);
        }
    }
}
