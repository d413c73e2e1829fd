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
    #[inline]
    pub fn at(self, tau: f64) -> f64 {
        match self {
            Excitation::Sine => tau.sin(),
            Excitation::None => 0.0,
        }
    }
}
