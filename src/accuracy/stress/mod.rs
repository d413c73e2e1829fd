//! The numerical stress test of `pounding stress`: corner and random
//! parameter sets ([`cases`]), each run once with the project's default solver
//! options unless the case says otherwise, and checked ([`checks`]) for:
//! finite outputs, a closed energy balance, Newton convergence at every step
//! (retries allowed and reported), no tension from the improved Kelvin element
//! for e ≥ 0.4, and, where the case asks, bounded amplitude (stability) or
//! bounded memory.

pub mod cases;
pub mod checks;

pub use cases::{Case, Expect, corner_cases, random_cases};
pub use checks::{Outcome, check};
