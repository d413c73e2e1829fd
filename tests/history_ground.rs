//! The history CSV carries the ground motion in Π form (SPEC §9): ag, vg, ug
//! after the structures' channels, checked against the pulses' closed forms.

use std::f64::consts::PI;
use std::process::Command;

/// Runs `pounding run --excitation NAME --history -`; the rows as numbers
/// and the column index of each name.
fn history(excitation: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let o = Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args([
            "run",
            "--excitation",
            excitation,
            "--cycles",
            "2",
            "--history",
            "-",
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines();
    let names = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (names, rows)
}

fn column(names: &[String], name: &str) -> usize {
    names.iter().position(|n| n == name).unwrap()
}

/// Type A: u̇_g = 1 − cos τ, u_g = τ − sin τ on [0, 2π]; at the pulse's end
/// (a step ends there exactly) the ground has moved 2π and is at rest, and
/// after it drifts at velocity 0.
#[test]
fn pulse_a_ground_ends_at_its_closed_form() {
    let (names, rows) = history("pulse-a");
    assert_eq!(names.join(","), "tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp,ag,vg,ug");
    let [tau, ag, vg, ug] = ["tau", "ag", "vg", "ug"].map(|n| column(&names, n));
    let end = rows
        .iter()
        .find(|r| r[tau] == 2.0 * PI)
        .expect("a row at the pulse's end τ = 2π");
    assert!((end[ug] - 2.0 * PI).abs() < 1e-12, "{}", end[ug]);
    assert!(end[vg].abs() < 1e-12, "{}", end[vg]);
    // Inside the pulse, every row against the closed form.
    for r in rows.iter().filter(|r| r[tau] <= 2.0 * PI) {
        let t = r[tau];
        assert!((r[ag] - t.sin()).abs() < 1e-12);
        assert!((r[vg] - (1.0 - t.cos())).abs() < 1e-12);
        assert!((r[ug] - (t - t.sin())).abs() < 1e-12);
    }
    // After it: no acceleration, the ground at rest at 2π.
    let last = rows.last().unwrap();
    assert!(last[tau] > 3.0 * PI);
    assert_eq!(last[ag], 0.0);
    assert!((last[ug] - 2.0 * PI).abs() < 1e-12 && last[vg].abs() < 1e-12);
}

/// Type B: the ground starts with velocity V_p (vg = 1 at τ = 0, the step
/// that gives both structures ẋ(0) = −1), u̇_g = cos τ, u_g = sin τ.
#[test]
fn pulse_b_ground_starts_with_its_velocity_step() {
    let (names, rows) = history("pulse-b");
    let [tau, ag, vg, ug, v1, v2] =
        ["tau", "ag", "vg", "ug", "v1", "v2"].map(|n| column(&names, n));
    let first = &rows[0];
    assert_eq!(first[tau], 0.0);
    assert_eq!((first[vg], first[ug], first[ag]), (1.0, 0.0, 0.0));
    assert_eq!((first[v1], first[v2]), (-1.0, -1.0));
    for r in rows.iter().filter(|r| r[tau] <= 2.0 * PI) {
        let t = r[tau];
        assert!((r[ag] + t.sin()).abs() < 1e-12);
        assert!((r[vg] - t.cos()).abs() < 1e-12 && (r[ug] - t.sin()).abs() < 1e-12);
    }
}
