//! Peaks that may rise inside an otherwise quiet sub-step (SPEC §13),
//! located on the sub-step's own closed form instead of a series walk.
//!
//! Out of contact the motion over the sub-step is x(s) = e^{As} x₀ plus the
//! particular part of the piece's linear ground (ä_g = σ a_g): an entire
//! function of s, whose Taylor series at s = 0 is the series of
//! [`super::super::taylor`] from the sub-step's start. Where that series'
//! radius covers the whole sub-step, one series gives every watched
//! quantity q(s) on [0, h] as a polynomial exact to its tolerance, and a
//! peak of |q| inside is the largest turning point of that polynomial
//! ([`poly::max_abs`], [`poly::max`] for the signed relative
//! displacement): the same value the series path records, without its
//! event search or the other quantities. Its end state is that series' at
//! h too, as the series path takes it, so that the run stays bit-close to
//! one that walks such sub-steps by the series (the map's end differs from
//! it by rounding only, but rounding that events then magnify). A sub-step
//! whose series does not reach its end goes by the series path.

use crate::model::buildings::ground::Piece;

use super::super::peaks::raise;
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
        let series = Series::new(
            &self.system,
            &self.u,
            &self.v,
            (a, rate, piece.sigma),
            scale,
        );
        if series.radius < h {
            return false;
        }
        series.state(h, end.0, end.1);
        let n = self.layout.dofs;
        let storeys = self.layout.storeys.len();
        let mut c = std::mem::take(&mut self.buf);
        let env = &mut self.envelope;
        for &k in rising {
            let w = &self.watch[k];
            match w.order {
                2 => series.absolute_acceleration(k - 2 * n, &mut c),
                1 => series.combine(&[], &w.terms, &mut c),
                _ => series.combine(&w.terms, &[], &mut c),
            }
            match k {
                k if k < n => raise(&mut env.displacement[k], poly::max_abs(&c, h)),
                k if k < 2 * n => raise(&mut env.velocity[k - n], poly::max_abs(&c, h)),
                k if k < 3 * n => raise(&mut env.acceleration[k - 2 * n], poly::max_abs(&c, h)),
                k if k < 3 * n + storeys => raise(&mut env.drift[k - 3 * n], poly::max_abs(&c, h)),
                k => {
                    let r = &mut env.relative[k - 3 * n - storeys];
                    *r = r.max(poly::max(&c, h));
                }
            }
        }
        self.buf = c;
        true
    }
}
