//! Peaks that may rise inside an otherwise quiet sub-step (SPEC §13),
//! located on the sub-step's own closed form instead of a series walk.
//!
//! Out of contact the motion over the sub-step is x(s) = e^{As} x₀ plus the
//! particular part of the piece's linear ground (ä_g = σ a_g): an entire
//! function of s, whose Taylor series at s = 0 is the series of
//! [`super::super::taylor`] from the sub-step's start. That series is
//! taken to the lowest order K that carries it over the sub-step
//! ([`fill_over`](super::super::taylor::Series::fill_over): its last two
//! terms within the tolerance at h,
//!
//! ```text
//! ‖u_k, u̇_k‖ h^k ≤ TOLERANCE · scale,   k = K − 1, K,
//! ```
//!
//! the truncation the fixed order leaves at its radius): a sub-step is at
//! most one radian of the fastest mode, where the coefficients fall like
//! (ωh)^k/k!, so K is 17 or 18 (block-and-frame's IDA, ωh = 0.84) against
//! the fixed order's 24, and each quantity's polynomial, its turning
//! points and the end state cost that much less. One series then gives
//! every watched quantity q(s) on [0, h] as a polynomial exact to its
//! tolerance ([`quantity`]), and a peak of |q| inside is the
//! largest turning point of that polynomial ([`poly::max_abs`],
//! [`poly::max`] for the signed relative displacement): the same value the
//! series path records, without its event search or the other quantities.
//! Its end state is that series' at h too, as the series path takes it,
//! so that the run stays close to one that walks such sub-steps by the
//! series (the map's end differs from it by rounding only, but rounding
//! that events then magnify). A sub-step whose series does not reach its
//! end goes by the series path. The series' vectors are the series steps'
//! spare ones, reused.

use crate::model::buildings::ground::Piece;

use super::super::bound::Watch;
use super::super::peaks::{Envelope, raise};
use super::super::poly;
use super::super::taylor::Series;
use super::{Run, ground_at};

impl Run<'_> {
    /// Raises the peaks of the watched quantities `rising` (indices into
    /// [`super::watched`]) over the sub-step of length `h` from the current
    /// state, and puts the series' state at h into `end`; false, raising
    /// nothing, when the series from the start does not reach h.
    pub(super) fn locate_rising(
        &mut self,
        piece: &Piece,
        h: f64,
        rising: &[usize],
        end: (&mut [f64], &mut [f64]),
    ) -> bool {
        let (a, rate) = ground_at(piece, self.t);
        let size = |x: &[f64]| x.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
        let scale = (size(&self.u), size(&self.v));
        let mut series = std::mem::take(&mut self.spare_series);
        let ground = (a, rate, piece.sigma);
        series.fill_over(&self.system, (&self.u, &self.v), ground, scale, h);
        if series.radius < h {
            self.spare_series = series;
            return false;
        }
        series.state(h, end.0, end.1);
        let (n, storeys) = (self.layout.dofs, self.layout.storeys.len());
        let mut c = std::mem::take(&mut self.buf);
        for &k in rising {
            quantity(&series, &self.watch[k], &mut c);
            match peak_of(&mut self.envelope, k, (n, storeys)) {
                (r, true) => *r = r.max(poly::max(&c, h)),
                (peak, false) => raise(peak, poly::max_abs(&c, h)),
            }
        }
        self.buf = c;
        self.spare_series = series;
        true
    }
}

/// The running peak of watched quantity `k` ([`super::watched`], in a row
/// of `n` floors and `storeys` storeys) in `env`, and whether it is the
/// largest signed value (a facing pair's relative displacement) rather
/// than the largest magnitude.
pub(super) fn peak_of(
    env: &mut Envelope,
    k: usize,
    (n, storeys): (usize, usize),
) -> (&mut f64, bool) {
    match k {
        k if k < n => (&mut env.displacement[k], false),
        k if k < 2 * n => (&mut env.velocity[k - n], false),
        k if k < 3 * n => (&mut env.acceleration[k - 2 * n], false),
        k if k < 3 * n + storeys => (&mut env.drift[k - 3 * n], false),
        k => (&mut env.relative[k - 3 * n - storeys], true),
    }
}

/// The coefficients of watched quantity `watch` on `series`: the
/// absolute acceleration of its floor (order 2), or its terms on the
/// velocities (order 1) or on the displacements (order 0).
pub(super) fn quantity(series: &Series, watch: &Watch, out: &mut Vec<f64>) {
    match watch.order {
        2 => series.absolute_acceleration(watch.terms[0].0, out),
        1 => series.combine(&[], &watch.terms, out),
        _ => series.combine(&watch.terms, &[], out),
    }
}
