//! The first question the quiet test asks of every floor (SPEC §13):
//! whether u_i, u̇_i and ü_i + a_g stay below their running peaks over the
//! sub-step, answered straight from the two ends' stacks.
//!
//! These 3n quantities are each one floor's rate, read at both ends with
//! the next rate: q0, q̇0 from the start's stack, q1, q̇1 from the end's
//! (the ground's a_g, ȧ_g added for ü + a_g). The hull of the control
//! points of their Hermite cubic ([`hull`]), widened by the cubic's error
//! bound e, holds q's range; when max(|lo − e|, |hi + e|) is within the
//! peak, so is |q| over the whole sub-step. That is the first test of
//! [`super::ranges::Ends::below`], on the same numbers in the same order,
//! so its verdict is the same; only a quantity it cannot clear goes on to
//! the exact range and the monotone test there.

use super::super::bound::Stack;
use super::super::hermite::hull;

/// Whether floor i's u (`order` 0), u̇ (1) or ü + a_g (2), quantity
/// order · n + i of [`super::watched`], stays within `peak` on the widened
/// hull of its cubic over the sub-step of length `h` from `start` to `end`,
/// with `error` the bound on the cubic's error
/// ([`super::super::bound::Bounds::errors`]).
#[inline]
pub(super) fn floor_below(
    (start, end): (&Stack, &Stack),
    (order, i): (usize, usize),
    error: f64,
    peak: f64,
    h: f64,
) -> bool {
    let value = |stack: &Stack, rate: usize| {
        let x = stack.rates[order + rate][i];
        if order == 2 {
            x + stack.ground[rate]
        } else {
            x
        }
    };
    let (lo, hi) = hull(
        value(start, 0),
        value(start, 1),
        value(end, 0),
        value(end, 1),
        h,
    );
    (lo - error).abs().max((hi + error).abs()) <= peak
}

#[cfg(test)]
mod tests {
    use super::super::super::bound::Stack;
    use super::super::super::hermite::hull;
    use super::super::ranges::{Ends, Probe};
    use super::floor_below;
    use proptest::prelude::*;

    /// A stack of n floors' rates and a ground (a, ȧ, ä).
    fn stack(n: usize) -> impl Strategy<Value = Stack> {
        let rates = prop::collection::vec(-1.0f64..1.0, n);
        (
            [
                rates.clone(),
                rates.clone(),
                rates.clone(),
                rates.clone(),
                rates,
            ],
            prop::array::uniform3(-1.0f64..1.0),
        )
            .prop_map(|(rates, ground)| Stack { rates, ground })
    }

    proptest! {
        /// For every floor quantity of random ends, the verdict is the
        /// widened hull's on q, q̇ as [`Probe::at`] reads them (the ground
        /// in ü + a_g), and a cleared quantity passes [`Ends::below`].
        #[test]
        fn clears_as_the_probes_hull_and_only_what_below_clears(
            (start, end) in (1usize..6).prop_flat_map(|n| (stack(n), stack(n))),
            h in 0.01f64..1.0,
            error in 0.0f64..0.2,
            peak in 0.0f64..2.0,
        ) {
            let n = start.rates[0].len();
            for order in 0..3 {
                for i in 0..n {
                    let probe = Probe::new(order, i, None);
                    let (a, b) = (probe.at(&start), probe.at(&end));
                    let (lo, hi) = hull(a[0], a[1], b[0], b[1], h);
                    let want = (lo - error).abs().max((hi + error).abs()) <= peak;
                    let got = floor_below((&start, &end), (order, i), error, peak, h);
                    prop_assert_eq!(got, want);
                    let ends = Ends { start: a, end: b, errors: (error, error), h };
                    prop_assert!(!got || ends.below(peak));
                }
            }
        }
    }
}
