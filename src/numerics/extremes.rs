//! The smaller and the larger of two floats by one comparison each (one
//! `minsd` or `maxsd`), for the tight loops of the quiet test, where
//! `f64::min` and `f64::max` cost more for their care of a NaN.
//!
//! On numbers both give the same value (up to the sign of a zero, which no
//! comparison sees). A NaN is not propagated: `least(x, y)` and
//! `largest(x, y)` give y when either is a NaN, so a caller that must see a
//! NaN asks for it apart.

/// x if x < y, else y.
#[inline(always)]
pub fn least(x: f64, y: f64) -> f64 {
    if x < y { x } else { y }
}

/// x if x > y, else y.
#[inline(always)]
pub fn largest(x: f64, y: f64) -> f64 {
    if x > y { x } else { y }
}

#[cfg(test)]
mod tests {
    use super::{largest, least};

    /// On numbers, the values of `f64::min` and `f64::max`; a NaN gives
    /// the second operand.
    #[test]
    fn agree_with_min_and_max_on_numbers() {
        let xs = [
            -2.5,
            -0.0,
            0.0,
            1e-300,
            3.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for &x in &xs {
            for &y in &xs {
                assert_eq!(least(x, y), x.min(y));
                assert_eq!(largest(x, y), x.max(y));
            }
        }
        assert_eq!(least(f64::NAN, 1.0), 1.0);
        assert!(largest(1.0, f64::NAN).is_nan());
    }
}
