//! Generic numerical building blocks that know nothing of structures or
//! contact: the Dormand–Prince 5(4) pair with dense output ([`dopri5`]).
//! The reference integrates every phase with it; the exact method uses it
//! only inside contact phases of the Hertz-type laws, whose force is not
//! analytic at onset (δ^{3/2}), so a Taylor series in τ does not apply there.

pub mod dopri5;
