//! Peaks that rise inside a quiet sample, located on the interval's own
//! series (SPEC §6, §9) instead of handing the whole interval to the
//! segments' series.
//!
//! A sample whose bounds keep every event away (no yield, no unloading, no
//! contact) but cannot keep |x|, |ẋ| or x1 − x2 below its running peak is
//! still advanced by the map; only the peak that may rise is located. On
//! the sample interval g = g_k + s t, and the motion of one structure is the
//! Taylor series of ẍ = Q/m − (c/m) ẋ − (K/m) x − g about τ_k,
//!
//! ```text
//! x(t) = Σ_{j≤n} x_j t^j,   x_{j+2} = −(c/m)/(j+2) x_{j+1} − [(K/m) x_j + g_j]/((j+1)(j+2)),
//! ```
//!
//! the very series a free segment over the same interval would take (same
//! recurrence, same degree), so a peak located here is the one the
//! segments' series locate, to the bit: its maxima lie at the end or at the
//! zeros of the rate, found by [`super::peaks`] to round-off. The degree is
//! the one the segments use for an interval of that length: its first term
//! left out is below 3e-18 of the motion ([`super::dynamics`]).

use super::dynamics::oscillator;
use super::peaks::{raise_abs_max, raise_max};
use super::series::Series;

/// The series of x and ẋ of one structure over a sample interval, from
/// (x, ẋ) under g = g_k + s t with K/m, c/m and Q/m of its branch.
#[derive(Debug, Clone, Copy)]
pub struct IntervalSeries {
    pub x: Series,
    pub v: Series,
}

impl IntervalSeries {
    /// To degree `n`: (K/m, c/m) = (`stiffness`, `damping`).
    #[inline]
    pub fn new(
        stiffness: f64,
        damping: f64,
        load: f64,
        [x, v]: [f64; 2],
        [g, slope]: [f64; 2],
        n: usize,
    ) -> Self {
        let mut ground = Series {
            degree: 1,
            ..Series::default()
        };
        ground.c[0] = g;
        ground.c[1] = slope;
        let x = oscillator(damping, stiffness, load, x, v, &ground, n);
        IntervalSeries {
            v: x.derivative(),
            x,
        }
    }

    /// Raises `peak` to max |x| over (0, h]; `swing` ≥ the swing of x there.
    #[inline]
    pub fn raise_displacement(&self, h: f64, swing: f64, peak: &mut f64) {
        raise_abs_max(&self.x, Some(&self.v), h, swing, peak);
    }

    /// Raises `peak` to max |ẋ| over (0, h]; `swing` ≥ the swing of ẋ there.
    #[inline]
    pub fn raise_velocity(&self, h: f64, swing: f64, peak: &mut f64) {
        raise_abs_max(&self.v, None, h, swing, peak);
    }

    /// The series of ẍ + g = Q/m − (c/m) ẋ − (K/m) x (SPEC §6): that
    /// combination of the two series, with (K/m, c/m, Q/m) =
    /// (`stiffness`, `damping`, `load`).
    #[inline]
    pub fn absolute_acceleration(&self, [stiffness, damping, load]: [f64; 3]) -> Series {
        let mut a = Series {
            degree: self.x.degree,
            ..Series::default()
        };
        for (j, c) in a.c[..=a.degree].iter_mut().enumerate() {
            let v = if j <= self.v.degree { self.v.c[j] } else { 0.0 };
            *c = -damping * v - stiffness * self.x.c[j];
        }
        a.c[0] += load;
        a
    }

    /// Raises `peak` to max |ẍ + g| over (0, h] on
    /// [`IntervalSeries::absolute_acceleration`]; `swing` ≥ its swing there.
    #[inline]
    pub fn raise_absolute_acceleration(
        &self,
        branch: [f64; 3],
        h: f64,
        swing: f64,
        peak: &mut f64,
    ) {
        let a = self.absolute_acceleration(branch);
        raise_abs_max(&a, None, h, swing, peak);
    }
}

/// Raises `peak` to max (x1 − x2) over (0, h], on the difference of the two
/// structures' series; `swing` ≥ the swing of x1 − x2 there.
#[inline]
pub fn raise_relative(pair: [&IntervalSeries; 2], h: f64, swing: f64, peak: &mut f64) {
    let relative = pair[0].x.minus(&pair[1].x);
    raise_max(&relative, None, 1.0, h, swing, peak);
}
