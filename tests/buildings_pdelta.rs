//! P-Δ and collapse (SPEC §15), each checked against what can be known
//! without the solver:
//!
//! - the periods under gravity are the roots of det(K₀ − K_G − ω²M) = 0,
//!   here the characteristic polynomial of two storeys;
//! - one elastic storey under a constant ground acceleration from rest
//!   oscillates, damped, about the static offset −m a/(k − P/h), with
//!   ω² = (k − P/h)/m;
//! - a storey whose post-yield stiffness αk − P/h is negative ratchets over
//!   under a pulse: the exact method's collapse instant is the independent
//!   reference's (Dormand–Prince with bisection on the event), and Newmark's
//!   converges to it;
//! - with a vanishing gravity mass the run is the run without P-Δ;
//! - the energy balance closes with the P-Δ work in the storeys' springs.

use pounding::model::buildings::matrices::periods;
use pounding::model::buildings::{self, Ground, Row};
use pounding::reference::row::reference_row;
use pounding::solver::buildings::{RowOptions, run_newmark, run_row};

const G: f64 = 9.80665;

fn row(text: &str) -> Row {
    buildings::parse("t.toml", text).unwrap_or_else(|e| panic!("{e}"))
}

fn refusal(text: &str) -> String {
    buildings::parse("t.toml", text).unwrap_err().to_string()
}

/// One building of one storey: m = 2e5 kg, k = 8e7 N/m, h = 4 m.
fn one_storey(extra: &str) -> String {
    format!(
        "[[building]]\nname = \"tower\"\nstoreys = 1\nmass = 2.0e5\nstiffness = 8.0e7\nheight = 4.0\n\
         damping = 0.03\n{extra}\n"
    )
}

#[test]
fn periods_under_gravity_are_the_roots_of_the_characteristic_polynomial() {
    let text = "[[building]]\nname = \"a\"\nstoreys = 2\nmass = [3.0e5, 2.0e5]\n\
                stiffness = [2.0e8, 1.5e8]\nheight = [4.0, 3.0]\np_delta = true\n\
                gravity_mass = [9.0e5, 7.0e5]\n";
    let r = row(text);
    let b = &r.buildings[0];
    // Storey stiffness under gravity: k_i − P_i/h_i, P_2 = g m_g2, P_1 = g (m_g1 + m_g2).
    let k1 = 2.0e8 - G * (9.0e5 + 7.0e5) / 4.0;
    let k2 = 1.5e8 - G * 7.0e5 / 3.0;
    let (m1, m2) = (3.0e5, 2.0e5);
    // det [[k1 + k2 − m1 λ, −k2], [−k2, k2 − m2 λ]] = 0:
    // m1 m2 λ² − (m1 k2 + m2 (k1 + k2)) λ + k1 k2 = 0.
    let (a, bb, c) = (m1 * m2, -(m1 * k2 + m2 * (k1 + k2)), k1 * k2);
    let disc = (bb * bb - 4.0 * a * c).sqrt();
    let lambdas = [2.0 * c / (-bb + disc), (-bb + disc) / (2.0 * a)];
    let expected: Vec<f64> = {
        let mut t: Vec<f64> = lambdas
            .iter()
            .map(|l| 2.0 * std::f64::consts::PI / l.sqrt())
            .collect();
        t.sort_by(|x, y| y.total_cmp(x));
        t
    };
    let got = periods(b);
    for (g, e) in got.iter().zip(&expected) {
        assert!((g - e).abs() <= 1e-12 * e, "period {g} against {e}");
    }
    // θ_i = P_i/(k_i h_i).
    let theta = [G * 1.6e6 / (2.0e8 * 4.0), G * 7.0e5 / (1.5e8 * 3.0)];
    for (i, t) in theta.iter().enumerate() {
        assert!(
            (b.stability_coefficient(i) - t).abs() <= 1e-15,
            "θ_{}",
            i + 1
        );
    }
    // Gravity lengthens the periods.
    let bare = row(&text
        .replace("p_delta = true\n", "")
        .replace("gravity_mass = [9.0e5, 7.0e5]\n", ""));
    assert!(periods(&bare.buildings[0])[0] < got[0]);
}

#[test]
fn one_storey_under_a_constant_ground_acceleration_oscillates_about_the_softened_offset() {
    let (m, k, h, xi): (f64, f64, f64, f64) = (2.0e5, 8.0e7, 4.0, 0.03);
    let gm = 1.5e6;
    let r = row(&one_storey(&format!(
        "p_delta = true\ngravity_mass = {gm:e}"
    )));
    let ke = k - G * gm / h;
    let w = (ke / m).sqrt();
    let wd = w * (1.0 - xi * xi).sqrt();
    // ü_g = a on [0, 3 s]: 3001 equal samples, linear between them.
    let a = 2.0;
    let dt = 1e-3;
    let ground = Ground::Samples {
        dt,
        acceleration: vec![a; 3001],
    };
    // u(t) = u_s (1 − e^{−ξωt}(cos ω_d t + ξω/ω_d sin ω_d t)), u_s = −m a/(k − P/h).
    let us = -m * a / ke;
    let closed = |t: f64| {
        let e = (-xi * w * t).exp();
        let (s, c) = (wd * t).sin_cos();
        (
            us * (1.0 - e * (c + xi * w / wd * s)),
            us * e * (w * w / wd) * s,
        )
    };
    for duration in [0.37, 1.23, 2.9] {
        let run = run_row(&r, &ground, &RowOptions::lasting(duration)).unwrap();
        let (u, v) = closed(duration);
        let scale = us.abs();
        assert!(
            (run.final_displacement[0] - u).abs() <= 1e-12 * scale,
            "u({duration}) = {} against {u}",
            run.final_displacement[0]
        );
        assert!(
            (run.final_velocity[0] - v).abs() <= 1e-12 * scale * w,
            "u̇({duration}) = {} against {v}",
            run.final_velocity[0]
        );
    }
    // The first overshoot: |u|max = |u_s|(1 + e^{−ξπ/√(1−ξ²)}) at t = π/ω_d.
    let run = run_row(&r, &ground, &RowOptions::lasting(2.9)).unwrap();
    let peak = us.abs() * (1.0 + (-xi * std::f64::consts::PI / (1.0 - xi * xi).sqrt()).exp());
    let got = run.floors[0][0].displacement;
    assert!((got - peak).abs() <= 1e-12 * peak, "{got} against {peak}");
    assert_eq!(run.collapse, None);
}

/// One storey that loses more to P-Δ than it keeps after yielding
/// (αk = 4e6 < P/h = 1e7 N/m), under one cycle of a sine strong enough to
/// yield it: it ratchets over.
fn ratcheting() -> (Row, Ground) {
    let gm = 1e7 * 4.0 / G;
    let r = row(&one_storey(&format!(
        "yield_drift = 0.01\nalpha = 0.05\np_delta = true\ngravity_mass = {gm:e}\ncollapse_drift_ratio = 0.08"
    )));
    (r, Ground::sine(6.0, 2.0 * std::f64::consts::PI / 0.8, 0.8))
}

#[test]
fn a_storey_with_negative_post_yield_stiffness_collapses_where_the_reference_says() {
    let (r, ground) = ratcheting();
    let b = &r.buildings[0];
    assert!(b.alpha * b.stiffness[0] < b.geometric_stiffness(0));
    let duration = 10.0;
    let run = run_row(&r, &ground, &RowOptions::lasting(duration)).unwrap();
    let collapse = run.collapse.expect("the storey ratchets over");
    assert_eq!((collapse.building, collapse.storey), (0, 1));
    // The peak drift is the collapse drift, reached at that instant.
    let cd = 0.08 * 4.0;
    assert!((run.floors[0][0].drift - cd).abs() <= 1e-12 * cd);
    let reference = reference_row(&r, &ground, duration, 1e-13);
    let (rb, rs, rt) = reference.collapse.expect("the reference collapses too");
    assert_eq!((rb, rs), (0, 1));
    assert!(
        (collapse.time - rt).abs() <= 1e-9,
        "exact {} against the reference {rt}",
        collapse.time
    );
    for (got, want) in [
        (run.floors[0][0].displacement, reference.displacement[0][0]),
        (run.floors[0][0].velocity, reference.velocity[0][0]),
        (
            run.floors[0][0].absolute_acceleration,
            reference.absolute_acceleration[0][0],
        ),
    ] {
        assert!((got - want).abs() <= 1e-9 * want, "{got} against {want}");
    }
    // Newmark locates the same collapse, converging at second order.
    let errors: Vec<f64> = [4e-4, 2e-4, 1e-4]
        .iter()
        .map(|&dt| {
            let nm = run_newmark(&r, &ground, duration, dt).unwrap();
            let c = nm.collapse.expect("Newmark collapses too");
            assert_eq!((c.building, c.storey), (0, 1));
            (c.time - collapse.time).abs()
        })
        .collect();
    eprintln!(
        "collapse at t = {} s (exact), {rt} s (reference), Newmark's errors at Δt = 4e-4, 2e-4, 1e-4 s: {errors:?}",
        collapse.time
    );
    for pair in errors.windows(2) {
        let order = (pair[0] / pair[1]).log2();
        assert!(order > 1.6, "order {order} from errors {errors:?}");
    }
    assert!(errors[2] < 1e-5, "{errors:?}");
}

#[test]
fn a_vanishing_gravity_mass_gives_the_run_without_p_delta() {
    // A preset takes gravity masses of 1 kg and more; the limit is the
    // solver's, so the row is built here with 1e-20 kg a floor.
    let a = buildings::load("block-and-frame").unwrap();
    let mut b = a.clone();
    b.buildings[1].p_delta = Some(pounding::model::buildings::PDelta {
        gravity_mass: vec![1e-20; 8],
        collapse_drift_ratio: 0.1,
    });
    let ground = Ground::sine(3.0, 2.0 * std::f64::consts::PI / 0.6, 3.0);
    let ra = run_row(&a, &ground, &RowOptions::lasting(6.0)).unwrap();
    let rb = run_row(&b, &ground, &RowOptions::lasting(6.0)).unwrap();
    assert!(ra.impacts() > 0);
    assert_eq!(ra.impacts(), rb.impacts());
    for (fa, fb) in ra.floors.iter().flatten().zip(rb.floors.iter().flatten()) {
        for (x, y) in [
            (fa.displacement, fb.displacement),
            (fa.velocity, fb.velocity),
            (fa.absolute_acceleration, fb.absolute_acceleration),
            (fa.drift, fb.drift),
        ] {
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(1e-300),
                "{x} against {y}"
            );
        }
    }
}

#[test]
fn the_energy_balance_closes_with_p_delta_and_yielding() {
    let (r, ground) = ratcheting();
    let run = run_row(
        &r,
        &ground,
        &RowOptions {
            energy: true,
            ..RowOptions::lasting(10.0)
        },
    )
    .unwrap();
    assert!(run.collapse.is_some());
    let e = run.energy.unwrap();
    assert!(e.residual() < 1e-9, "residual {:e}", e.residual());
}

#[test]
fn bad_p_delta_keys_are_refused_naming_building_key_value_and_range() {
    let e = refusal(&one_storey("p_delta = true\ngravity_mass = 1e8"));
    assert!(
        e.starts_with("t.toml: building `tower`: storey 1: θ = P/(k h) = 3.0646")
            && e.contains("must be < 1"),
        "{e}"
    );
    assert_eq!(
        refusal(&one_storey("p_delta = true\ngravity_mass = -3")),
        "t.toml: building `tower`: `gravity_mass` = -3: must be in [1, 1e10] (kg)"
    );
    assert_eq!(
        refusal(&one_storey("p_delta = true\ngravity_mass = [1e5, 2e5]")),
        "t.toml: building `tower`: `gravity_mass` has 2 values: must be a number or a list of 1 (one per storey)"
    );
    // A θ far past 1 reads in the short form.
    let e = refusal(&one_storey("p_delta = true\ngravity_mass = 1e10"));
    assert!(e.contains("θ = P/(k h) = "), "{e}");
    assert!(e.len() < 300, "{e}");
    assert_eq!(
        refusal(&one_storey("p_delta = true\ncollapse_drift_ratio = 1.0")),
        "t.toml: building `tower`: `collapse_drift_ratio` = 1: must be in (0, 1)"
    );
    assert_eq!(
        refusal(&one_storey("gravity_mass = 1e5")),
        "t.toml: building `tower`: `gravity_mass` applies with P-Δ only: set `p_delta = true`, or remove `gravity_mass`"
    );
    assert_eq!(
        refusal(&one_storey("p_delta = \"yes\"")),
        "t.toml: building `tower`: `p_delta` = \"yes\": must be true or false"
    );
}

/// The shipped P-Δ row struck hard enough to collapse (SPEC §15): the
/// exact method's collapse is the reference's, building, storey and
/// instant, with 38 impacts each, and every peak up to it agrees to 1e-9.
#[test]
fn the_shipped_p_delta_row_collapses_where_the_reference_says() {
    let r = buildings::load("block-and-frame-pdelta").unwrap();
    let record = pounding::model::simulated::Simulation::synthetic("synthetic:2000", 2000).unwrap();
    let ground = Ground::from_record(&record, 6.0);
    let duration = ground.end() + pounding::model::buildings::matrices::default_tail(&r);
    let run = run_row(&r, &ground, &RowOptions::lasting(duration)).unwrap();
    let c = run.collapse.expect("it collapses at scale 6");
    let reference = reference_row(&r, &ground, duration, 1e-13);
    let (b, s, t) = reference.collapse.expect("the reference collapses too");
    assert_eq!((c.building, c.storey), (b, s));
    assert_eq!(
        (c.building, c.storey),
        (1, 4),
        "the frame's storey above the struck floor"
    );
    assert!((c.time - t).abs() <= 1e-9, "{} against {t}", c.time);
    let impacts: Vec<usize> = run.pairs.iter().map(|p| p.impacts.len()).collect();
    assert_eq!(impacts, reference.impacts);
    for (k, floors) in run.floors.iter().enumerate() {
        for (i, f) in floors.iter().enumerate() {
            for (got, want) in [
                (f.displacement, reference.displacement[k][i]),
                (f.velocity, reference.velocity[k][i]),
                (f.drift, reference.drift[k][i]),
            ] {
                assert!(
                    (got - want).abs() <= 1e-9 * want.max(1e-3),
                    "{got} against {want}"
                );
            }
        }
    }
}
