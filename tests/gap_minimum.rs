//! The gap that prevents pounding (SPEC §11): the exact minimum gap against
//! its definition and the independent reference integrator, SPEC's set-1
//! numbers, and the code rules.

use pounding::analysis::gap::{CodeRules, MinimumGap, correlation, minimum_gap, minimum_gaps};
use pounding::model::{Method, Params, SET1, SET2};
use pounding::reference::{ReferenceOptions, reference};
use pounding::solver::{FullHistory, exact, run, solve};

fn exact_at_gap(p: &Params, gap: f64) -> Params {
    Params {
        gap,
        method: Method::Exact,
        ..p.clone()
    }
}

#[test]
fn set1_matches_spec_example() {
    let g = minimum_gap(&SET1);
    // SPEC §11 gives four decimals.
    assert!((g.exact - 2.5736).abs() < 5e-5, "exact {}", g.exact);
    assert!(
        (g.rules.srss - 2.4419).abs() < 5e-5,
        "SRSS {}",
        g.rules.srss
    );
    assert!(
        (g.rules.absolute_sum - 2.7055).abs() < 5e-5,
        "ABS {}",
        g.rules.absolute_sum
    );
    assert!(g.completed);
    // SRSS is too small here, ABS conservative.
    let [abs, srss, _] = g.ratios().map(Option::unwrap);
    assert!(abs > 1.0 && srss < 1.0);
}

#[test]
fn minimum_gap_reproduces_its_definition() {
    for p in [SET1, SET2] {
        let g = minimum_gap(&p);
        assert!(g.exact > 0.0);
        // Just above: no contact ever; just below: at least one impact.
        let above = run(&exact_at_gap(&p, g.exact + 1e-6));
        assert!(
            above.impacts.is_empty(),
            "{} impacts above",
            above.impacts.len()
        );
        for below in [1e-3, 1e-6] {
            let r = run(&exact_at_gap(&p, g.exact - below));
            assert!(!r.impacts.is_empty(), "no impact at Π_d,min − {below}");
        }
        // The independent reference (Dormand–Prince, its own event location) agrees.
        let tight = ReferenceOptions::with_tolerance(1e-10);
        let reference_above = reference(&exact_at_gap(&p, g.exact + 1e-6), &tight);
        assert!(reference_above.impacts.is_empty());
        let reference_below = reference(&exact_at_gap(&p, g.exact - 1e-4), &tight);
        assert!(!reference_below.impacts.is_empty());
    }
}

#[test]
fn tracked_maximum_bounds_the_sampled_history() {
    // The maximum located on the series is at least every sample of
    // x1 − x2 and within the sampling error (Δτ = 1e-3: ½ max|ẍ| Δτ² ≲ 1e-5).
    let p = exact_at_gap(&SET1, f64::INFINITY);
    let mut history = FullHistory::with_capacity(60_000);
    let r = exact::simulate(&p, &exact::ExactOptions::default(), &mut history);
    let tracked = r.max_relative_displacement.unwrap();
    let sampled = history
        .samples
        .iter()
        .map(|s| s.x[0] - s.x[1])
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(tracked >= sampled - 1e-12, "{tracked} < {sampled}");
    assert!(tracked - sampled < 1e-5, "{tracked} vs {sampled}");
    // Newmark does not track it.
    let newmark = solve(
        &Params {
            method: Method::Newmark,
            ..p.clone()
        },
        &mut (),
    );
    assert_eq!(newmark.max_relative_displacement, None);
}

#[test]
fn absolute_sum_is_never_below_exact() {
    // x1 − x2 ≤ |x1| + |x2| at every instant, on a coarse Π_ω1 sweep at μ = 2.25.
    let points: Vec<Params> = (1..=30)
        .map(|i| {
            let w = 0.1 * i as f64;
            Params {
                omega1: w,
                omega2: 2.25 * w,
                ..SET1
            }
        })
        .collect();
    for g in minimum_gaps(&points) {
        assert!(
            g.rules.absolute_sum >= g.exact,
            "Π_ω1 = {}: ABS {} < exact {}",
            g.omega1,
            g.rules.absolute_sum,
            g.exact
        );
        assert!(g.rules.double_difference <= g.rules.srss + 1e-15);
    }
}

#[test]
fn double_difference_correlation_by_hand() {
    // ξ = 0.05, r = 0.5: 8·0.0025·1.5·0.5^1.5 / (0.75² + 4·0.0025·0.5·1.5²)
    //  = 0.0106066 / 0.57375 = 0.0184865.
    let rho = correlation(1.0, 2.0, 0.05);
    assert!((rho - 0.018_486_451_8).abs() < 1e-9, "{rho}");
    // Set 1, r = 1.05/2.36.
    assert!((correlation(1.05, 2.36, 0.05) - 0.013_141_917_4).abs() < 1e-9);
    // DDC with ρ: √(u1² + u2² − 2ρ u1 u2).
    let r = CodeRules::of(3.0, 4.0, 1.0, 2.0, 0.05);
    assert!((r.double_difference - (25.0 - 24.0 * rho).sqrt()).abs() < 1e-14);
}

#[test]
fn newmark_free_run_gives_no_minimum_gap() {
    let p = Params {
        gap: f64::INFINITY,
        ..SET1
    };
    assert_eq!(MinimumGap::from_free_run(&p, &run(&p)), None);
}
