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
}
