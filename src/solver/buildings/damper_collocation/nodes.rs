//! The nodes of Radau IIA with S = 4, 5 or 6 stages (SPEC §14): the roots
//! of
//!
//! ```text
//! P_S(θ) = d^(S−1)/dθ^(S−1) [θ^(S−1) (θ − 1)^S],
//! ```
//!
//! the last c_S = 1 (Hairer & Wanner, IV.5). The S-point quadrature on
//! them is exact to degree 2S − 2, so a force collocated there misses its
//! motion's end by O(h^(2S)). Each value is the double nearest the root
//! (checked by `the_nodes_are_the_roots_of_the_radau_polynomial`, which
//! finds them by Newton's method on P_S with compensated Horner sums).

/// S = 4: 0.0886, 0.4095, 0.7877, 1.
const FOUR: [f64; 4] = [
    0.088_587_959_512_703_94,
    0.409_466_864_440_734_7,
    0.787_659_461_760_847,
    1.0,
];

/// S = 5: 0.0571, 0.2768, 0.5836, 0.8602, 1.
const FIVE: [f64; 5] = [
    0.057_104_196_114_517_68,
    0.276_843_013_638_123_8,
    0.583_590_432_368_916_8,
    0.860_240_135_656_219_5,
    1.0,
];

/// S = 6: 0.0398, 0.1980, 0.4380, 0.6955, 0.9015, 1.
const SIX: [f64; 6] = [
    0.039_809_857_051_468_74,
    0.198_013_417_873_608_18,
    0.437_974_810_247_386_16,
    0.695_464_273_353_636_1,
    0.901_464_914_201_173_6,
    1.0,
];

/// The S nodes c_1 < … < c_S = 1 of Radau IIA; S outside 4 … 6 does not
/// compile.
pub(super) const fn radau<const S: usize>() -> [f64; S] {
    let table: &[f64] = match S {
        4 => &FOUR,
        5 => &FIVE,
        6 => &SIX,
        _ => panic!("Radau IIA nodes are tabled for 4, 5 and 6 stages"),
    };
    let mut nodes = [0.0; S];
    let mut i = 0;
    while i < S {
        nodes[i] = table[i];
        i += 1;
    }
    nodes
}

#[cfg(test)]
mod tests {
    use super::radau;

    /// P_S's coefficients in powers of θ: θ^(S−1)(θ − 1)^S =
    /// Σ_k C(S, k)(−1)^(S−k) θ^(S−1+k), differentiated S − 1 times.
    fn coefficients(s: usize) -> Vec<f64> {
        let factorial = |n: usize| (1..=n).map(|k| k as f64).product::<f64>();
        let binomial = |n: usize, k: usize| factorial(n) / (factorial(k) * factorial(n - k));
        (0..=s)
            .map(|k| {
                let sign = if (s - k).is_multiple_of(2) { 1.0 } else { -1.0 };
                sign * binomial(s, k) * factorial(s - 1 + k) / factorial(k)
            })
            .collect()
    }

    /// a + b as the rounded sum and its exact error (Knuth's TwoSum).
    fn two_sum(a: f64, b: f64) -> (f64, f64) {
        let s = a + b;
        let z = s - a;
        (s, (a - (s - z)) + (b - z))
    }

    /// p(θ) and p'(θ) by Horner's rule with each rounding error carried
    /// (Graillat, Langlois & Louvet's compensated Horner): as accurate as
    /// Horner's rule in twice the precision. The coefficients are
    /// integers, exact in f64.
    fn compensated(p: &[f64], theta: f64) -> (f64, f64) {
        let (mut value, mut carried) = (0.0, 0.0);
        let (mut slope, mut slope_carried) = (0.0, 0.0);
        for &c in p.iter().rev() {
            // p' ← p' θ + p, then p ← p θ + c, each product's error by FMA.
            let product = slope * theta;
            let product_error = slope.mul_add(theta, -product);
            let (sum, sum_error) = two_sum(product, value);
            slope_carried = slope_carried * theta + carried + product_error + sum_error;
            slope = sum;
            let product = value * theta;
            let product_error = value.mul_add(theta, -product);
            let (sum, sum_error) = two_sum(product, c);
            carried = carried * theta + product_error + sum_error;
            value = sum;
        }
        (value + carried, slope + slope_carried)
    }

    /// The tabled nodes are the roots of P_S: Newton's method on P_S,
    /// deflated by the roots already found (Maehly's), from the
    /// equispaced θ = (i + 1/2)/S, its values summed in twice the
    /// precision, finds S roots, each within 1e-16 of a tabled node (the
    /// doubles there are 1.1e-16 apart at most), the largest 1, for S = 4,
    /// 5 and 6.
    #[test]
    fn the_nodes_are_the_roots_of_the_radau_polynomial() {
        fn check<const S: usize>() {
            let p = coefficients(S);
            let mut found: Vec<f64> = Vec::new();
            for i in 0..S {
                let mut theta = (i as f64 + 0.5) / S as f64;
                for _ in 0..100 {
                    let (value, slope) = compensated(&p, theta);
                    let repelled: f64 = found.iter().map(|r| 1.0 / (theta - r)).sum();
                    let step = value / (slope - value * repelled);
                    theta -= step;
                    if step.abs() <= 1e-17 {
                        break;
                    }
                }
                found.push(theta);
            }
            found.sort_by(f64::total_cmp);
            let tabled = radau::<S>();
            for (i, (&root, &node)) in found.iter().zip(&tabled).enumerate() {
                assert!(
                    (root - node).abs() <= 1e-16,
                    "S = {S}, node {i}: tabled {node}, root {root}"
                );
            }
            assert_eq!(tabled[S - 1], 1.0);
        }
        check::<4>();
        check::<5>();
        check::<6>();
    }
}
