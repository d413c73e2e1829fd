use super::power_coefficient;
use crate::model::buildings;
use crate::model::buildings::contact::element_law;
use crate::numerics::dopri5;
use crate::solver::buildings::config::{Closed, Config};
use crate::solver::buildings::layout::Layout;
use crate::solver::buildings::poly;
use crate::solver::buildings::system::System;
use crate::solver::buildings::taylor::Series;

/// The coefficients of x^α, orders 0 to `top`, by the recurrence.
fn powers(x: &[f64], alpha: f64, top: usize) -> Vec<f64> {
    let mut w = Vec::new();
    for k in 0..=top {
        let c = power_coefficient(&x[..=k], &w, alpha);
        w.push(c);
    }
    w
}

/// (a + b s)^α = a^α Σ_k C(α, k) (b/a)^k s^k, the binomial series:
/// the recurrence meets it to 1e-14 relative over orders 0 to 30, for
/// a slope either way and α = 0.35, 0.2, 0.5 and 1.5.
#[test]
fn a_line_to_a_real_power_is_the_binomial_series() {
    for &alpha in &[0.35, 0.2, 0.5, 1.5] {
        for &(a, b) in &[(0.3, 2.0), (0.04, -0.01), (2.5, 7.0)] {
            let mut x = vec![0.0; 31];
            x[0] = a;
            x[1] = b;
            let w = powers(&x, alpha, 30);
            // C(α, k)(b/a)^k a^α, built term by term.
            let mut expected = f64::powf(a, alpha);
            for (k, &wk) in w.iter().enumerate() {
                if k > 0 {
                    expected *= (alpha - (k - 1) as f64) / k as f64 * (b / a);
                }
                let rel = (wk - expected).abs() / expected.abs();
                assert!(rel <= 1e-14, "α {alpha}, ({a}, {b}), order {k}: {rel:e}");
            }
        }
    }
}

/// (e^{λs})^α = e^{αλs}: the recurrence on x_k = λ^k/k!, summed to
/// order 30 at s = 1/(2|λ|) and 1/|λ|, gives e^{αλs} to 1e-14 relative.
///
/// Its coefficients one by one cannot be held relative to their own size:
/// x_k enters w_k as α w_0 x_k/x_0, so x_k's own rounding ε|x_k| moves
/// w_k = (αλ)^k/k! by ε α^(1−k) of itself, and the recurrence carries the
/// errors of lower orders on with weights that grow like 2^k (measured:
/// 2.8e-7 of α|x_30| at α = 0.35, λ = 3). The sum at s weighs them by s^k,
/// and inside the series' radius they stay at rounding.
#[test]
fn an_exponential_to_a_real_power_is_an_exponential() {
    for &alpha in &[0.35, 0.7] {
        for &lambda in &[3.0, -40.0, 0.5] {
            let mut x = vec![1.0];
            for k in 1..=30 {
                let prev = x[k - 1];
                x.push(prev * lambda / k as f64);
            }
            let w = powers(&x, alpha, 30);
            for s in [0.5 / lambda.abs(), 1.0 / lambda.abs()] {
                let sum = w.iter().rev().fold(0.0, |acc, &c| acc * s + c);
                let exact = (alpha * lambda * s).exp();
                let rel = (sum - exact).abs() / exact;
                assert!(rel <= 1e-14, "α {alpha}, λ {lambda}, s {s}: {rel:e}");
            }
        }
    }
}

/// block-and-frame-retrofit with its damper at α = 0.35: its layout and,
/// with `roof` the block's roof pair closed under the improved Kelvin law
/// (its product h δ δ̇ in the series too), its system.
fn retrofit(roof: bool) -> (Layout, System) {
    let row = buildings::load_with("block-and-frame-retrofit", &["link1.exponent=0.35".into()])
        .expect("shipped");
    let layout = Layout::of(&row);
    let mut config = Config::at_rest(layout.storeys.len(), layout.pairs.len());
    if roof {
        let k = layout.hard - 1;
        config.contact[k] = Some(Closed {
            law: element_law(&row, &layout.elements[k], 0.05),
            approach_velocity: 0.05,
        });
    }
    let system = System::of(&layout, &config);
    assert_eq!(system.products.len(), usize::from(roof));
    (layout, system)
}

/// ẏ = (u̇, ü) of the row with its dampers, written out here from the
/// equation of motion (SPEC §13, §14) under the ground a_g + ȧ_g s.
fn rate(layout: &Layout, system: &System, ground: (f64, f64), s: f64, y: &[f64]) -> Vec<f64> {
    let n = y.len() / 2;
    let (u, v) = y.split_at(n);
    let mut out = v.to_vec();
    let mut acc = vec![0.0; n];
    system.acceleration(u, v, ground.0 + ground.1 * s, &mut acc);
    for d in &layout.dampers {
        let rate = v[d.left] - v[d.right];
        let force = d.damping * rate.abs().powf(d.exponent) * rate.signum();
        acc[d.left] -= force / layout.mass[d.left];
        acc[d.right] += force / layout.mass[d.right];
    }
    out.extend(acc);
    out
}

/// The series with the damper's force in it, from a state where the
/// damper slides at Δv = ±0.08 m/s, reaches at least half the distance
/// ρ = |Δv/Δv̇| to Δv's zero along its tangent, or half the radius of the
/// same state's series without the damper where that is shorter (in
/// contact; measured 0.64 and 0.80 ρ apart, 0.78 and 0.96 of the radius
/// without the damper in contact), and its
/// state at its radius is that of 4,000 fixed Dormand–Prince steps of the
/// same equation to 1e-12 of the motion's scales, out of contact and with
/// the block's roof in improved Kelvin contact; the force's series it
/// keeps is the law c_l |Δv|^α sgn Δv at its own Δv to 1e-12 over the
/// first half of the step (measured under 2e-16).
#[test]
fn a_damped_series_step_meets_a_fine_dormand_prince_run() {
    for roof in [false, true] {
        let (layout, system) = retrofit(roof);
        let n = layout.dofs;
        let d = layout.dampers[0];
        for sign in [1.0, -1.0] {
            let mut u: Vec<f64> = (0..n).map(|i| 2e-3 * ((i as f64) * 0.7).sin()).collect();
            let mut v: Vec<f64> = (0..n).map(|i| 0.05 * ((i as f64) * 1.3).cos()).collect();
            if roof {
                let p = layout.pairs[layout.hard - 1];
                u[p.left_dof] = u[p.right_dof] + layout.gaps[layout.hard - 1] + 2e-5;
                v[p.left_dof] = v[p.right_dof] + 0.05;
            }
            v[d.left] = v[d.right] + sign * 0.08;
            let size = |x: &[f64]| x.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
            let scale = (size(&u), size(&v));
            let ground = (1.2, -9.0);
            let mut series = Series::default();
            let start = (&u[..], &v[..]);
            let dampers = &layout.dampers[..];
            series.fill_damped(
                &system,
                start,
                (ground.0, ground.1, 0.0),
                scale,
                (1.0, dampers),
            );
            let h = series.radius;
            let y0: Vec<f64> = u.iter().chain(&v).copied().collect();
            let f = |s: f64, y: &Vec<f64>| rate(&layout, &system, ground, s, y);
            let dv = |y: &[f64]| y[n + d.left] - y[n + d.right];
            let tangent = f(0.0, &y0);
            let rho = (dv(&y0) / dv(&tangent)).abs();
            // The same state's series without the damper's force.
            let mut bare = Series::default();
            bare.fill_over(&system, start, (ground.0, ground.1, 0.0), scale, 1.0);
            assert!(
                h > 0.5 * rho.min(bare.radius),
                "radius {h:e} against ρ {rho:e} and {:e} without the damper",
                bare.radius
            );
            let steps = 4000;
            let dt = h / steps as f64;
            let mut y = y0.clone();
            for j in 0..steps {
                let s = j as f64 * dt;
                let f0 = f(s, &y);
                y = dopri5::step(&f, s, &y, &f0, dt).y1;
            }
            let (mut eu, mut ev) = (vec![0.0; n], vec![0.0; n]);
            series.state(h, &mut eu, &mut ev);
            let worst = (0..n)
                .map(|i| {
                    ((eu[i] - y[i]) / scale.0)
                        .abs()
                        .max(((ev[i] - y[n + i]) / scale.1).abs())
                })
                .fold(0.0, f64::max);
            println!(
                "roof {roof}, Δv {:+}: radius {h:e} ({:.2} ρ, order {}), worst {worst:e}",
                sign * 0.08,
                h / rho,
                series.degree
            );
            assert!(worst < 1e-12, "roof {roof}, sign {sign}: {worst:e}");
            // The force's series the fill keeps is the law at the series'
            // own Δv, inside the step.
            let force = series.damper_force(0).expect("the damper's force");
            assert_eq!(force.len(), series.degree + 1);
            assert!(series.damper_force(1).is_none());
            for s in [0.0, 0.25 * h, 0.5 * h] {
                series.state(s, &mut eu, &mut ev);
                let rate = ev[d.left] - ev[d.right];
                let law = d.damping * rate.abs().powf(d.exponent) * rate.signum();
                let off = (poly::eval(force, s) - law).abs() / law.abs();
                println!("  F at {:.2} h: {off:e} of the law", s / h);
                assert!(off < 1e-12, "roof {roof}, sign {sign}, s {s:e}: {off:e}");
            }
        }
    }
}
