//! `pounding run` with a `[physical]` preset (SPEC §8, §12): the demands in
//! SI beside Π, at the table's a_p and ω_p under the sine and at a record's
//! own under a record, whose Π-groups then follow that a_p and ω_p.

mod common;

use common::{json, stdout, succeeds};

const G: f64 = 9.80665;

#[test]
fn the_demands_are_in_si_at_the_tables_scales() {
    let v = json(&[
        "run",
        "--preset",
        "two-buildings",
        "--method",
        "exact",
        "--format",
        "json",
    ]);
    // [physical]: a_p = 0.5 g, period_p = 1 s, m2 = 1e6 kg.
    let (ap, omega_p, m2) = (0.5 * G, 2.0 * std::f64::consts::PI, 1.0e6);
    let le = ap / (omega_p * omega_p);
    let si = &v["si"];
    assert!((si["ap"].as_f64().unwrap() - ap).abs() < 1e-12);
    for side in ["left", "right"] {
        let pi = &v[side];
        let d = &si[side];
        let close = |got: f64, want: f64| (got - want).abs() <= 1e-12 * want.abs().max(1e-300);
        assert!(close(
            d["peak_displacement_m"].as_f64().unwrap(),
            pi["peak_displacement"].as_f64().unwrap() * le
        ));
        assert!(close(
            d["peak_velocity_m_s"].as_f64().unwrap(),
            pi["peak_velocity"].as_f64().unwrap() * ap / omega_p
        ));
        assert!(close(
            d["peak_absolute_acceleration_g"].as_f64().unwrap(),
            pi["peak_absolute_acceleration"].as_f64().unwrap() * ap / G
        ));
        assert!(close(
            d["hysteretic_energy_kj"].as_f64().unwrap(),
            pi["hysteretic_energy"].as_f64().unwrap() * m2 * ap * le / 1e3
        ));
    }
    let kn = si["max_force_kn"].as_f64().unwrap();
    assert!((kn - v["max_force"].as_f64().unwrap() * m2 * ap / 1e3).abs() < 1e-9 * kn);
    // The set's Π_d is the table's 25 mm over l_e.
    assert!((v["params"]["gap"].as_f64().unwrap() - 0.025 / le).abs() < 1e-12);
    // Without [physical] there is no SI.
    assert!(
        json(&["run", "--preset", "set1", "--format", "json"])
            .get("si")
            .is_none()
    );
}

#[test]
fn under_a_record_the_pi_groups_follow_its_a_p_and_omega_p() {
    let v = json(&[
        "run",
        "--preset",
        "two-buildings",
        "--excitation",
        "record:presets/synthetic.at2",
        "--method",
        "exact",
        "--format",
        "json",
    ]);
    let (ap, omega_p) = (v["a_p"].as_f64().unwrap(), v["omega_p"].as_f64().unwrap());
    // The record's peak is 0.3 g (its own a_p), ω_p its dominant frequency.
    assert!((ap - 0.3 * G).abs() < 1e-9, "{ap}");
    assert_eq!(v["samples"], 1000);
    assert_eq!(v["record_dt"], 0.01);
    let le = ap / (omega_p * omega_p);
    // Same buildings: Π_d = 25 mm / l_e, Π_ω1 = (2π/0.95)/ω_p, Π_uy1 = 0.11 m / l_e.
    let p = &v["params"];
    assert!((p["gap"].as_f64().unwrap() * le - 0.025).abs() < 1e-15);
    assert!((p["yield1"].as_f64().unwrap() * le - 0.11).abs() < 1e-14);
    assert!(
        (p["omega1"].as_f64().unwrap() * omega_p - 2.0 * std::f64::consts::PI / 0.95).abs() < 1e-12
    );
    assert_eq!(v["si"]["ap"].as_f64().unwrap(), ap);
    // The table says so in SI.
    let text = stdout(&succeeds(&[
        "run",
        "--preset",
        "two-buildings",
        "--excitation",
        "record:presets/synthetic.at2",
    ]));
    assert!(text.contains("in SI, at a_p ="), "{text}");
    assert!(text.contains("E_h kJ"), "{text}");
}

#[test]
fn a_pi_override_is_refused_where_the_record_sets_the_pi_groups() {
    common::fails(
        &[
            "run",
            "--preset",
            "two-buildings",
            "--excitation",
            "record:presets/synthetic.at2",
            "--set",
            "gap=0.5",
        ],
        2,
        &["gap", "[physical]"],
    );
}
