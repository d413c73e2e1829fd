//! Ground acceleration g(τ) of SPEC §2, per unit amplitude a_p.

/// The excitation a run is driven by.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Excitation {
    /// g(τ) = sin τ, the paper's sinusoidal pulse train.
    #[default]
    Sine,
    /// g(τ) = 0: free motion from the initial state (isolated impacts, tests).
    None,
}

impl Excitation {
    /// g(τ).
    #[inline]
    pub fn at(self, tau: f64) -> f64 {
        self.phasor(tau)[0]
    }

    /// (g(τ), dg/dτ): for the sine, (sin τ, cos τ). Carried along a run so the
    /// next value can be had by a rotation instead of a new `sin` (see
    /// [`Rotation`]).
    #[inline]
    pub fn phasor(self, tau: f64) -> [f64; 2] {
        match self {
            Excitation::Sine => {
                let (s, c) = tau.sin_cos();
                [s, c]
            }
            Excitation::None => [0.0, 0.0],
        }
    }
}

/// 1/k for k < 64 (1/0 unused), so that 1/k! comes by multiplication.
const RECIPROCALS: [f64; 64] = {
    let mut r = [0.0; 64];
    let mut k = 1;
    while k < 64 {
        r[k] = 1.0 / k as f64;
        k += 1;
    }
    r
};

impl Excitation {
    /// Taylor coefficients of g about τ: g(τ + t) = Σ_k out[k] t^k, for
    /// k < out.len(). For the sine, g^{(k)}(τ) cycles through sin τ, cos τ,
    /// −sin τ, −cos τ, so out[k] = g^{(k)}(τ)/k!. The event-driven method
    /// expands the ground motion this way on each segment.
    pub fn taylor(self, tau: f64, out: &mut [f64]) {
        match self {
            Excitation::Sine => {
                let (s, c) = tau.sin_cos();
                let cycle = [s, c, -s, -c];
                let mut inv_factorial = 1.0;
                for (k, o) in out.iter_mut().enumerate() {
                    if k > 0 {
                        inv_factorial *= RECIPROCALS[k.min(RECIPROCALS.len() - 1)];
                    }
                    *o = cycle[k % 4] * inv_factorial;
                }
            }
            Excitation::None => out.iter_mut().for_each(|o| *o = 0.0),
        }
    }

    /// The first τ after `tau` at which g changes formula (a kink or jump),
    /// where a segment of the event-driven method must end: never, for the
    /// sine. Pulses (pieces of sinusoids) and records (piecewise linear) end
    /// their pieces here.
    pub fn next_break(self, _tau: f64) -> f64 {
        f64::INFINITY
    }
}

/// Advances the phasor (sin τ, cos τ) by a fixed step h:
/// sin(τ+h) = sin τ cos h + cos τ sin h, cos(τ+h) = cos τ cos h − sin τ sin h.
/// Each use adds about one rounding error, so a run re-synchronises the
/// phasor from τ now and then ([`Excitation::phasor`]). It maps the zero
/// phasor of [`Excitation::None`] to itself.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    pub step: f64,
    sin: f64,
    cos: f64,
}

impl Rotation {
    pub fn new(step: f64) -> Self {
        let (sin, cos) = step.sin_cos();
        Rotation { step, sin, cos }
    }

    #[inline]
    pub fn advance(&self, [s, c]: [f64; 2]) -> [f64; 2] {
        [s * self.cos + c * self.sin, c * self.cos - s * self.sin]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_tracks_sine() {
        let r = Rotation::new(0.001);
        let mut p = Excitation::Sine.phasor(0.0);
        for _ in 0..1000 {
            p = r.advance(p);
        }
        assert!((p[0] - 1f64.sin()).abs() < 1e-14 && (p[1] - 1f64.cos()).abs() < 1e-14);
    }

    #[test]
    fn taylor_series_of_the_sine_sums_to_it() {
        let mut c = [0.0; 24];
        Excitation::Sine.taylor(0.3, &mut c);
        let t: f64 = 1.2;
        let sum: f64 = c
            .iter()
            .enumerate()
            .map(|(k, a)| a * t.powi(k as i32))
            .sum();
        assert!((sum - 1.5f64.sin()).abs() < 1e-15);
    }
}
