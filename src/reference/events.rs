//! The instants where the right-hand side changes (SPEC §3–4), as zeros of
//! event functions g(y) that cross from g ≤ 0 to g > 0:
//!
//! | event | active while | g |
//! |---|---|---|
//! | contact onset | open | δ = x1 − x2 − Π_d |
//! | separation | in contact | −δ |
//! | yield of spring i towards σ | spring i elastic | σ z_i − Π_uy,i |
//! | unloading of spring i | spring i yielded with sign σ | −σ ẋ_i |

use super::dopri5::Vector;
use super::system::{Branch, Mode, Structures};

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Event {
    Onset,
    Separation,
    Yield { spring: usize, sign: f64 },
    Unload { spring: usize },
}

/// At most one contact event and two per spring.
pub const MAX_EVENTS: usize = 5;

/// The events that can end the current mode.
pub fn active(system: &Structures, mode: &Mode) -> ([Event; MAX_EVENTS], usize) {
    let mut list = [Event::Onset; MAX_EVENTS];
    let mut n = 0;
    let mut push = |e| {
        list[n] = e;
        n += 1;
    };
    match mode.contact {
        None if system.gap.is_finite() => push(Event::Onset),
        None => {}
        Some(_) => push(Event::Separation),
    }
    for (spring, branch) in mode.springs.iter().enumerate() {
        match branch {
            Branch::Elastic { .. } if system.yield_displacement[spring].is_finite() => {
                push(Event::Yield { spring, sign: 1.0 });
                push(Event::Yield { spring, sign: -1.0 });
            }
            Branch::Elastic { .. } => {}
            Branch::Yielded { .. } => push(Event::Unload { spring }),
        }
    }
    (list, n)
}

/// g(y) of an event in the mode it ends.
#[inline]
pub fn value(system: &Structures, mode: &Mode, event: Event, y: &Vector) -> f64 {
    match event {
        Event::Onset => system.penetration(y),
        Event::Separation => -system.penetration(y),
        Event::Yield { spring, sign } => {
            let z = system.elastic_part(spring, mode.springs[spring], y[2 * spring]);
            sign * z - system.yield_displacement[spring]
        }
        Event::Unload { spring } => match mode.springs[spring] {
            Branch::Yielded { sign } => -sign * y[2 * spring + 1],
            Branch::Elastic { .. } => -1.0,
        },
    }
}

/// Relative width in θ at which a bracket counts as closed.
const THETA_TOLERANCE: f64 = 1e-15;

/// The smallest θ found in (lo, hi] with g(θ) > 0, given g(lo) ≤ 0 < g(hi):
/// Illinois regula falsi, returning the far side of the final bracket.
pub fn locate(
    g: impl Fn(f64) -> f64,
    mut lo: f64,
    mut g_lo: f64,
    mut hi: f64,
    mut g_hi: f64,
) -> f64 {
    let mut side = 0i8;
    for _ in 0..200 {
        if hi - lo <= THETA_TOLERANCE * hi.max(1e-300) {
            break;
        }
        let mut s = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
        if !(s > lo && s < hi) {
            s = 0.5 * (lo + hi);
        }
        let gs = g(s);
        if gs > 0.0 {
            (hi, g_hi) = (s, gs);
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        } else {
            (lo, g_lo) = (s, gs);
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        }
    }
    hi
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locates_root_of_cubic_to_round_off() {
        let g = |t: f64| t * t * t - 0.125;
        let t = locate(g, 0.0, g(0.0), 1.0, g(1.0));
        assert!((t - 0.5).abs() < 1e-14, "{t}");
        assert!(g(t) > 0.0);
    }
}
