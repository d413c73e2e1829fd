//! The standard normal distribution: density φ, distribution Φ, its
//! logarithm and slopes far into both tails, and the quantile Φ⁻¹. The
//! fragility fit and the separation at a probability use them (SPEC §12).
//!
//! ```text
//! φ(z) = exp(−z²/2)/√(2π),   Φ(z) = ½ erfc(−z/√2),   λ(z) = φ(z)/Φ(z)
//! ```
//!
//! λ is the inverse Mills ratio, the slope of ln Φ. `erfc` is the `libm`
//! crate's (FreeBSD's msun, under one unit in the last place); Rust's std
//! has no stable error function. Where Φ(z) is tiny (z < −5, and below
//! z ≈ −38 it underflows) ln Φ and λ come from Laplace's continued fraction
//! for Mills's ratio instead, so a likelihood stays finite and exact at any z.

use std::f64::consts::FRAC_1_SQRT_2;

/// ln √(2π).
const LN_SQRT_2PI: f64 = 0.918_938_533_204_672_8;

/// Below −[`TAIL`], ln Φ and λ come from the continued fraction; above it,
/// from `erfc`, where z + λ loses at most z²/(z + λ)·ε ≈ 30ε to cancellation.
const TAIL: f64 = 5.0;

/// Terms of the continued fraction: 40 reach a relative error of 1e-16 at
/// x = 5 and fewer are needed further out (checked against mpmath).
const FRACTION_TERMS: u32 = 40;

/// The density φ(z) = exp(−z²/2)/√(2π).
pub fn pdf(z: f64) -> f64 {
    (-0.5 * z * z - LN_SQRT_2PI).exp()
}

/// The distribution Φ(z) = ½ erfc(−z/√2), to a relative error of a few
/// units in the last place everywhere it does not underflow (z > −38).
pub fn cdf(z: f64) -> f64 {
    0.5 * libm::erfc(-z * FRAC_1_SQRT_2)
}

/// T(x) = 1/(x + 2/(x + 3/(x + …))) for x ≥ [`TAIL`], evaluated from its
/// end. Laplace's continued fraction for Mills's ratio R(x) = (1 − Φ(x))/φ(x)
/// is R(x) = 1/(x + 1/(x + 2/(x + …))) = 1/(x + T(x)), so that
///
/// ```text
/// λ(−x) = 1/R(x) = x + T(x),   −x + λ(−x) = T(x),
/// ```
///
/// the second without the cancellation of its left side.
fn fraction_tail(x: f64) -> f64 {
    (1..=FRACTION_TERMS)
        .rev()
        .fold(0.0, |tail, k| f64::from(k) / (x + tail))
}

/// ln Φ(z), finite and accurate to a few units in the last place for every
/// finite z (ln Φ(−40) = −804.608…, ln Φ(10) = −7.62e-24):
///
/// ```text
/// z < −5:   ln Φ(z) = −z²/2 − ln √(2π) − ln(x + T(x)),  x = −z   (Φ = φ R)
/// z ≤ 0:    ln Φ(z) = ln(½ erfc(−z/√2))
/// z > 0:    ln Φ(z) = ln(1 − ½ erfc(z/√2))  (by ln_1p)
/// ```
///
/// ln(1 − Φ(z)) = ln Φ(−z).
pub fn ln_cdf(z: f64) -> f64 {
    if z < -TAIL {
        let x = -z;
        -0.5 * z * z - LN_SQRT_2PI - (x + fraction_tail(x)).ln()
    } else if z <= 0.0 {
        cdf(z).ln()
    } else {
        (-cdf(-z)).ln_1p()
    }
}

/// The first two slopes of ln Φ at z, as (λ, κ):
///
/// ```text
/// λ(z) = d ln Φ/dz = φ(z)/Φ(z),   κ(z) = −d² ln Φ/dz² = λ(z)(z + λ(z)),
/// ```
///
/// with 0 < κ < 1 (ln Φ is strictly concave). Far in the left tail λ ≈ −z
/// and κ → 1, each taken from the continued fraction; far right both → 0.
pub fn ln_cdf_slopes(z: f64) -> (f64, f64) {
    if z < -TAIL {
        let x = -z;
        let tail = fraction_tail(x);
        let lambda = x + tail;
        (lambda, lambda * tail)
    } else {
        let lambda = pdf(z) / cdf(z);
        (lambda, lambda * (z + lambda))
    }
}

/// Coefficients of Wichura's algorithm AS 241 (PPND16), Applied Statistics
/// 37 (1988) 477–484, lowest degree first: the central region |p − ½| ≤ 0.425
/// in r = 0.180625 − q², then r = √(−ln min(p, 1 − p)) − 1.6 up to r ≤ 5,
/// and r − 5 beyond.
#[allow(clippy::excessive_precision, reason = "the published digits, verbatim")]
const CENTRAL: ([f64; 8], [f64; 8]) = (
    [
        3.387_132_872_796_366_608,
        1.331_416_678_917_843_774_5e2,
        1.971_590_950_306_551_442_7e3,
        1.373_169_376_550_946_112_5e4,
        4.592_195_393_154_987_145_7e4,
        6.726_577_092_700_870_085_3e4,
        3.343_057_558_358_812_810_5e4,
        2.509_080_928_730_122_672_7e3,
    ],
    [
        1.0,
        4.231_333_070_160_091_125_2e1,
        6.871_870_074_920_579_083e2,
        5.394_196_021_424_751_107_7e3,
        2.121_379_430_158_659_586_7e4,
        3.930_789_580_009_271_061e4,
        2.872_908_573_572_194_267_4e4,
        5.226_495_278_852_854_561e3,
    ],
);
#[allow(clippy::excessive_precision, reason = "the published digits, verbatim")]
const INTERMEDIATE: ([f64; 8], [f64; 8]) = (
    [
        1.423_437_110_749_683_577_34,
        4.630_337_846_156_545_295_9,
        5.769_497_221_460_691_405_5,
        3.647_848_324_763_204_605_04,
        1.270_458_252_452_368_382_58,
        2.417_807_251_774_506_117_7e-1,
        2.272_384_498_926_918_458_33e-2,
        7.745_450_142_783_414_076_4e-4,
    ],
    [
        1.0,
        2.053_191_626_637_758_821_87,
        1.676_384_830_183_803_849_4,
        6.897_673_349_851_000_045_5e-1,
        1.481_039_764_274_800_745_9e-1,
        1.519_866_656_361_645_719_66e-2,
        5.475_938_084_995_344_946e-4,
        1.050_750_071_644_416_843_24e-9,
    ],
);
#[allow(clippy::excessive_precision, reason = "the published digits, verbatim")]
const FAR: ([f64; 8], [f64; 8]) = (
    [
        6.657_904_643_501_103_777_2,
        5.463_784_911_164_114_369_9,
        1.784_826_539_917_291_335_8,
        2.965_605_718_285_048_912_3e-1,
        2.653_218_952_657_612_309_3e-2,
        1.242_660_947_388_078_438_6e-3,
        2.711_555_568_743_487_578_15e-5,
        2.010_334_399_292_288_132_65e-7,
    ],
    [
        1.0,
        5.998_322_065_558_879_376_9e-1,
        1.369_298_809_227_358_053_1e-1,
        1.487_536_129_085_061_485_25e-2,
        7.868_691_311_456_132_591e-4,
        1.846_318_317_510_054_681_8e-5,
        1.421_511_758_316_445_888_7e-7,
        2.044_263_103_389_939_785_64e-15,
    ],
);

/// A ratio of two degree-7 polynomials at r, by Horner's rule.
fn rational((num, den): &([f64; 8], [f64; 8]), r: f64) -> f64 {
    let horner = |c: &[f64; 8]| c.iter().rev().fold(0.0, |acc, &k| acc * r + k);
    horner(num) / horner(den)
}

/// The quantile Φ⁻¹(p) for 0 < p < 1 by AS 241, to about 1 part in 10¹⁶
/// (Φ⁻¹(0.975) = 1.959963984540054, Φ⁻¹(1e-300) = −37.0471); −∞ at 0, ∞ at
/// 1, NaN outside [0, 1].
pub fn quantile(p: f64) -> f64 {
    if !(0.0..=1.0).contains(&p) {
        return f64::NAN;
    }
    let q = p - 0.5;
    if q.abs() <= 0.425 {
        return q * rational(&CENTRAL, 0.180625 - q * q);
    }
    let tail = if q < 0.0 { p } else { 1.0 - p };
    if tail == 0.0 {
        return if q < 0.0 {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        };
    }
    let r = (-tail.ln()).sqrt();
    let z = if r <= 5.0 {
        rational(&INTERMEDIATE, r - 1.6)
    } else {
        rational(&FAR, r - 5.0)
    };
    if q < 0.0 { -z } else { z }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(got: f64, want: f64, rel: f64) -> bool {
        (got - want).abs() <= rel * want.abs().max(f64::MIN_POSITIVE)
    }

    /// Φ⁻¹ at textbook probabilities, the references computed by mpmath at 80
    /// digits (root of Φ(z) = p): within 1e-9 as asked, and in fact 1e-14.
    #[test]
    fn quantile_matches_known_values() {
        let cases = [
            (1e-300, -37.047_096_299_361_2),
            (1e-20, -9.262_340_089_798_408),
            (1e-10, -6.361_340_902_404_056),
            (0.001, -3.090_232_306_167_813_5),
            (0.025, -1.959_963_984_540_054),
            (0.1, -1.281_551_565_544_600_5),
            (0.16, -0.994_457_883_209_753_2),
            (0.75, 0.674_489_750_196_081_7),
            (0.84, 0.994_457_883_209_753_2),
            (0.9, 1.281_551_565_544_600_5),
            (0.975, 1.959_963_984_540_054),
            (0.999, 3.090_232_306_167_813_5),
        ];
        for (p, want) in cases {
            let got = quantile(p);
            assert!((got - want).abs() <= 1e-9, "Φ⁻¹({p}) = {got}, want {want}");
            assert!(close(got, want, 1e-14), "Φ⁻¹({p}) = {got}, want {want}");
        }
        assert_eq!(quantile(0.5), 0.0);
        assert_eq!(quantile(0.0), f64::NEG_INFINITY);
        assert_eq!(quantile(1.0), f64::INFINITY);
        assert!(quantile(-0.1).is_nan() && quantile(1.5).is_nan() && quantile(f64::NAN).is_nan());
    }

    /// Φ(Φ⁻¹(p)) = p over 1e-12 … 1 − 1e-12: the two share no code but erfc.
    #[test]
    fn quantile_inverts_cdf() {
        let mut p = 1e-12;
        while p < 1.0 - 1e-12 {
            for p in [p, 1.0 - p] {
                let back = cdf(quantile(p));
                // dΦ = φ dz: an error of ε|z| in z moves Φ by φ(z)·ε|z| ≤ pε·z².
                assert!(close(back, p, 2e-14), "Φ(Φ⁻¹({p})) = {back}");
            }
            p *= 1.7;
        }
    }

    /// ln Φ, λ and κ against mpmath at 60 digits, on both sides of the
    /// switch to the continued fraction and far into both tails.
    #[test]
    fn ln_cdf_and_slopes_match_mpmath() {
        // z, ln Φ(z), λ(z), κ(z)
        let cases = [
            (
                -40.0,
                -804.608_442_013_753_8,
                40.024_968_847_207_26,
                0.999_377_331_621_408_6,
            ),
            (
                -10.0,
                -53.231_285_150_512_47,
                10.098_093_233_962_512,
                0.990_554_622_174_343_7,
            ),
            (
                -5.5,
                -17.779_376_352_625_26,
                5.671_410_313_897_306,
                0.972_138_222_145_553_8,
            ),
            (
                -5.0,
                -15.064_998_393_988_726,
                5.186_503_967_125_842,
                0.967_303_565_382_887_8,
            ),
            (
                -4.5,
                -12.592_419_735_713_08,
                4.704_319_844_827_732,
                0.961_185_900_715_224_5,
            ),
            (
                -1.0,
                -1.841_021_645_009_263_5,
                1.525_135_276_160_981,
                0.800_902_334_429_651_2,
            ),
            (
                0.0,
                -std::f64::consts::LN_2,
                0.797_884_560_802_865_4,
                0.636_619_772_367_581_3,
            ),
            (
                1.5,
                -0.069_143_455_612_233_98,
                0.138_789_750_458_850_76,
                0.227_447_220_520_706_2,
            ),
            (
                5.0,
                -2.866_516_129_637_636e-7,
                1.486_719_940_904_912_4e-6,
                7.433_601_914_860_711e-6,
            ),
            (
                10.0,
                -7.619_853_024_160_526e-24,
                7.694_598_626_706_419e-23,
                7.694_598_626_706_419e-22,
            ),
        ];
        for (z, ln_phi, lambda, kappa) in cases {
            let (l, k) = ln_cdf_slopes(z);
            assert!(close(ln_cdf(z), ln_phi, 1e-14), "ln Φ({z}) = {}", ln_cdf(z));
            assert!(close(l, lambda, 1e-13), "λ({z}) = {l}");
            assert!(close(k, kappa, 1e-12), "κ({z}) = {k}");
        }
        // Finite where Φ underflows, and −z²/2 to leading order.
        let far = ln_cdf(-1e5);
        assert!(far.is_finite() && close(far, -5e9, 1e-8));
        let (lambda, kappa) = ln_cdf_slopes(-1e5);
        assert!(close(lambda, 1e5, 1e-9) && kappa > 0.0 && kappa <= 1.0);
    }

    #[test]
    fn density() {
        let sqrt_2pi = (2.0 * std::f64::consts::PI).sqrt();
        assert!(close(pdf(0.0), 1.0 / sqrt_2pi, 1e-15));
        assert!(close(pdf(2.0), (-2.0f64).exp() / sqrt_2pi, 1e-15));
    }
}
