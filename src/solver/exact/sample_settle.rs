//! A sample that the tight loop's chord bounds did not clear because an
//! extremum came near its running peak (SPEC §6, §9), taken again with that
//! extremum located.
//!
//! The chord margin of [`super::sample_run`] spends the whole second-order
//! bound near an extremum, so every sample whose extremum comes within about
//! (ωh)²/8 of its running peak fails [`Pair::step`], and most of those do
//! raise the peak. Over such a sample a quantity q is monotone where its
//! rate r keeps one sign; and it has exactly one turning point where r
//! changes sign and r is itself monotone (r' keeping one sign). Each is
//! shown by the chord bound on the end values (a rate keeps its sign where
//! both end values are beyond the chord margin of its second derivative):
//!
//! ```text
//! q         r = q'         r'          |r''| ≤          |r'''| ≤
//! x         ẋ              ẍ           J                J₄
//! ẋ         ẍ              x⁽³⁾        J₄               J₅ = (c/m) J₄ + (K/m) J
//! ẍ + g     x⁽³⁾ + s       x⁽⁴⁾        J₅               (c/m) J₅ + (K/m) J₄
//! x1 − x2   ẋ1 − ẋ2        ẍ1 − ẍ2     J(1) + J(2)      J₄(1) + J₄(2)
//! ```
//!
//! (J, J₄ of the module head of [`super::sample_run`]; x⁽ⁿ⁺²⁾ = −(c/m)
//! x⁽ⁿ⁺¹⁾ − (K/m) x⁽ⁿ⁾ for n ≥ 2 since g'' = 0 inside, so each bound follows
//! from the two before it.) The turning point is the root of r on the
//! interval's series ([`IntervalSeries`], the series a free segment over the
//! sample would take), and q there is the interior extremum: q's range over
//! the interval is that of its two ends and that value. The range must lie
//! inside the event band (the yield surface for x, the loading side for ẋ
//! where yielded, below the gap for x1 − x2), and raises the running peak.
//! A value at a root of its rate is insensitive to the root's error (an
//! error ε in t moves it by |r'| ε²/2), so it is the true extremum to
//! round-off.
//!
//! Where neither holds (the rate's own turning point inside, or an event
//! band within the margin), the sample is left to the full tests of
//! [`super::sample::clear`].

// Comparisons are written `!(a > b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::roots::monotone_root;
use super::sample_peaks::IntervalSeries;
use super::sample_run::{Margins, Pair, Peaks, Step, inside};
use super::series::Series;

/// Whether a rate with end values `r` keeps one sign over the interval,
/// with `margin` ≥ the chord margin of its second derivative (and room for
/// the end values' round-off).
#[inline]
fn keeps_sign(r: [f64; 2], margin: f64) -> bool {
    let room = margin + 4.0 * f64::EPSILON * (r[0].abs() + r[1].abs());
    r[0].min(r[1]) > room || r[0].max(r[1]) < -room
}

/// The range [lo, hi] of q over the interval from its end values `q`, its
/// rate's `r` and its rate's rate's `r1`, with the chord margins of the
/// second derivatives of r (`margin_r`) and of r' (`margin_r1`); `turning`
/// gives q at the rate's one root where it has one. `None` where neither
/// the rate nor its rate is shown to keep its sign.
fn range(
    q: [f64; 2],
    (r, margin_r): ([f64; 2], f64),
    (r1, margin_r1): ([f64; 2], f64),
    turning: impl FnOnce() -> Option<f64>,
) -> Option<[f64; 2]> {
    let ends = [q[0].min(q[1]), q[0].max(q[1])];
    if keeps_sign(r, margin_r) {
        return Some(ends);
    }
    if !keeps_sign(r1, margin_r1) {
        return None;
    }
    // r is monotone: a zero inside only where its ends have opposite signs.
    if r[0] * r[1] >= 0.0 {
        return Some(ends);
    }
    let at_turn = turning()?;
    Some([ends[0].min(at_turn), ends[1].max(at_turn)])
}

/// q at the one root of its rate `dq` on [0, h].
fn at_turning_point(q: &Series, dq: &Series, h: f64) -> Option<f64> {
    monotone_root(dq, h).map(|t| q.value(t))
}

/// Both ends inside (lo, hi) with room for round-off.
#[inline]
fn within([lo, hi]: [f64; 2], range: [f64; 2]) -> bool {
    inside(lo, range[0], hi) && inside(lo, range[1], hi)
}

impl Pair {
    /// One interval from (x, ẋ) under g = g_k + s t, as [`Pair::step`],
    /// with each quantity that comes near its running peak settled by the
    /// ranges of the module's head; `degree` is the interval series'. The
    /// step with the raised peaks, or `None` where the sample needs the full
    /// tests.
    pub fn settle<const ACCEL: bool>(
        &self,
        x: [f64; 2],
        v: [f64; 2],
        [g, s]: [f64; 2],
        peaks: &Peaks,
        degree: usize,
    ) -> Option<Step> {
        let (c, k, h) = (self.damping, self.stiffness, self.length);
        let [xe, ve] = self.advance(x, v, [g, s]);
        if !(xe[0] + xe[1] + ve[0] + ve[1]).is_finite() {
            return None;
        }
        let g_end = s.mul_add(h, g);
        let x_span = [0, 1].map(|i| [x[i].min(xe[i]), x[i].max(xe[i])]);
        let v_span = [0, 1].map(|i| [v[i].min(ve[i]), v[i].max(ve[i])]);
        let margins = self.margins(
            [
                [x_span[0][0], x_span[1][0]],
                [x_span[0][1], x_span[1][1]],
                [v_span[0][0], v_span[1][0]],
                [v_span[0][1], v_span[1][1]],
            ],
            g.abs().max(g_end.abs()),
            s.abs(),
        );
        let Margins {
            x: mx,
            v: mv,
            a: ma,
            jerk: mj,
        } = margins;
        // At both ends: ẍ + g, ẍ, x⁽³⁾ (= (ẍ + g)' − s) and x⁽⁴⁾.
        let accel = [0, 1].map(|i| {
            [
                self.load[i] - c[i] * v[i] - k[i] * x[i],
                self.load[i] - c[i] * ve[i] - k[i] * xe[i],
            ]
        });
        let rate = [0, 1].map(|i| [accel[i][0] - g, accel[i][1] - g_end]);
        let jerk = [0, 1].map(|i| [0, 1].map(|e| -c[i] * rate[i][e] - k[i] * [v[i], ve[i]][e] - s));
        let snap = [0, 1].map(|i| [0, 1].map(|e| -c[i] * jerk[i][e] - k[i] * rate[i][e]));
        let mut series: [Option<IntervalSeries>; 2] = [None, None];
        let mut series_of = |i: usize| {
            *series[i].get_or_insert_with(|| {
                IntervalSeries::new(k[i], c[i], self.load[i], [x[i], v[i]], [g, s], degree)
            })
        };
        let mut out = *peaks;
        for i in 0..2 {
            let band_x = [self.watch_x[0][i], self.watch_x[1][i]];
            let band_v = [self.watch_v[0][i], self.watch_v[1][i]];
            let [x_lo, x_hi] = x_span[i];
            if !((x_lo - mx[i] > band_x[0].max(-peaks.x[i]))
                && (x_hi + mx[i] < band_x[1].min(peaks.x[i])))
            {
                let q = range(
                    [x[i], xe[i]],
                    ([v[i], ve[i]], mv[i]),
                    (rate[i], ma[i]),
                    || {
                        let sr = series_of(i);
                        at_turning_point(&sr.x, &sr.v, h)
                    },
                )?;
                if !within(band_x, q) {
                    return None;
                }
                out.x[i] = out.x[i].max(q[0].abs()).max(q[1].abs());
            }
            let [v_lo, v_hi] = v_span[i];
            if !((v_lo - mv[i] > band_v[0].max(-peaks.v[i]))
                && (v_hi + mv[i] < band_v[1].min(peaks.v[i])))
            {
                let q = range([v[i], ve[i]], (rate[i], ma[i]), (jerk[i], mj[i]), || {
                    let sr = series_of(i);
                    at_turning_point(&sr.v, &sr.v.derivative(), h)
                })?;
                if !within(band_v, q) {
                    return None;
                }
                out.v[i] = out.v[i].max(q[0].abs()).max(q[1].abs());
            }
            if ACCEL && accel[i][0].abs().max(accel[i][1].abs()) + ma[i] >= peaks.a[i] {
                // (ẍ + g)' = x⁽³⁾ + s, (ẍ + g)'' = x⁽⁴⁾.
                let rise = [jerk[i][0] + s, jerk[i][1] + s];
                let q = range(
                    accel[i],
                    (rise, mj[i]),
                    (snap[i], c[i] * mj[i] + k[i] * ma[i]),
                    || {
                        let a = series_of(i).absolute_acceleration([k[i], c[i], self.load[i]]);
                        at_turning_point(&a, &a.derivative(), h)
                    },
                )?;
                out.a[i] = out.a[i].max(q[0].abs()).max(q[1].abs());
            }
        }
        // x1 − x2: below the gap and, where tracked, its running maximum.
        let relative = [x[0] - x[1], xe[0] - xe[1]];
        let relative_top = relative[0].max(relative[1]);
        if relative_top + mx[0] + mx[1] >= self.gap.min(peaks.relative) {
            let q = range(
                relative,
                ([v[0] - v[1], ve[0] - ve[1]], mv[0] + mv[1]),
                (
                    [rate[0][0] - rate[1][0], rate[0][1] - rate[1][1]],
                    ma[0] + ma[1],
                ),
                || {
                    let [a, b] = [series_of(0), series_of(1)];
                    at_turning_point(&a.x.minus(&b.x), &a.v.minus(&b.v), h)
                },
            )?;
            if !(self.gap - q[1] > 4.0 * f64::EPSILON * q[0].abs().max(q[1].abs())) {
                return None;
            }
            out.relative = out.relative.max(q[1]);
        }
        out.x = [0, 1].map(|i| out.x[i].max(xe[i].abs()));
        out.v = [0, 1].map(|i| out.v[i].max(ve[i].abs()));
        if ACCEL {
            out.a = [0, 1].map(|i| out.a[i].max(accel[i][1].abs()));
        }
        out.relative = out.relative.max(relative[1]);
        Some(Step {
            clear: true,
            cleared: [true; 3],
            x: xe,
            v: ve,
            peaks: out,
        })
    }
}
