//! Generic numerical building blocks that know nothing of structures or
//! contact: the multiply-add of the hot loops ([`madd`]), their one-instruction
//! extremes ([`extremes`]), the
//! Dormand–Prince 5(4) pair with dense output ([`dopri5`]), and the standard
//! normal distribution of the risk statistics ([`normal`]).
//! The reference integrates every phase with the pair; the exact method uses it
//! only inside contact phases of the Hertz-type laws, whose force is not
//! analytic at onset (δ^{3/2}), so a Taylor series in τ does not apply there.

pub mod dopri5;
pub mod extremes;
pub mod normal;

/// a·b + c: fused, with one rounding, where the build's target has a fused
/// multiply-add instruction; else a product and a sum (a fused one in
/// software costs a library call, slower than both). The results of the
/// two differ in the last bits only.
#[inline(always)]
pub fn madd(a: f64, b: f64, c: f64) -> f64 {
    if cfg!(any(target_feature = "fma", target_arch = "aarch64")) {
        a.mul_add(b, c)
    } else {
        a * b + c
    }
}
