//! A segment of the exact method's run: its series and the event that ends
//! it. The driver ([`super::driver`]) builds and cuts segments; the energy
//! balance ([`super::energy`]) integrates over them. Both read it from here.

use super::series::Series;

/// Which event ends a segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Event {
    Onset,
    Separation,
    /// Structure i reaches z = sign · Π_uy.
    Yield(usize, f64),
    /// Structure i, yielded, turns back.
    Unload(usize),
}

/// One segment's series and its earliest event.
#[derive(Default)]
pub struct Segment {
    pub x: [Series; 2],
    pub v: [Series; 2],
    /// f_p, in contact ([`Segment::force`]).
    pub(super) force: Series,
    /// σ(x1 − x2 − Π_d) as [`Segment::write_gap_function`] last wrote it:
    /// out of contact the penetration δ (σ = 1), the onset's event function;
    /// in contact the opening −δ (σ = −1), negative while the structures
    /// overlap and positive once they separate: separation's event function,
    /// whose minimum is the maximum penetration.
    pub(super) gap_function: Series,
    pub(super) contact: bool,
    /// Σ_{k≥1} |c_k| h^k of x1, x2, ẋ1, ẋ2 over the segment's full length h:
    /// how far each can move from its start value, a bound that clears most
    /// event functions and peaks without a search.
    pub swing: [f64; 4],
    /// Where the segment ends: its full length, or the earliest event.
    pub(super) end: (f64, Option<Event>),
}
