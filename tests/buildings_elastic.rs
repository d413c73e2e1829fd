//! Elastic rows without contact (SPEC §13): Rayleigh damping is classical,
//! so every floor's motion is the modal superposition of SDOF responses,
//! each in closed form on every linear piece of the record. The exact
//! method's end state equals it to 1e-12 of the building's peaks.
//! And the mirror image: the row reversed under the negated record gives the
//! same peaks per building.

use nalgebra::DMatrix;
use pounding::model::buildings::matrices::{building_stiffness, rayleigh};
use pounding::model::buildings::{self, Building, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, run_row};

/// (u, u̇) at the end of `duration` for one elastic building at rest under
/// ground samples `acc` (m/s², step dt, 0 after the last), by modes.
fn modal(b: &Building, dt: f64, acc: &[f64], duration: f64) -> (Vec<f64>, Vec<f64>) {
    let n = b.storeys();
    let k = building_stiffness(b);
    let sq: Vec<f64> = b.mass.iter().map(|m| m.sqrt()).collect();
    let ks = DMatrix::from_fn(n, n, |i, j| k[(i, j)] / (sq[i] * sq[j]));
    let eig = ks.symmetric_eigen();
    let (a0, a1) = rayleigh(b);
    let mut u = vec![0.0; n];
    let mut v = vec![0.0; n];
    for r in 0..n {
        let w = eig.eigenvalues[r].sqrt();
        let xi = a0 / (2.0 * w) + a1 * w / 2.0;
        let phi: Vec<f64> = (0..n).map(|i| eig.eigenvectors[(i, r)] / sq[i]).collect();
        let gamma: f64 = (0..n).map(|i| phi[i] * b.mass[i]).sum();
        // q̈ + 2ξωq̇ + ω²q = −Γ a(t), a linear on each piece.
        let wd = w * (1.0 - xi * xi).sqrt();
        let (mut q, mut qd) = (0.0, 0.0);
        let mut t = 0.0;
        let mut k = 0;
        while t < duration - 1e-12 {
            let (p0, p1, len) = if k + 1 < acc.len() {
                let len = dt.min(duration - t);
                (-gamma * acc[k], -gamma * (acc[k + 1] - acc[k]) / dt, len)
            } else {
                (0.0, 0.0, duration - t)
            };
            let bb = p1 / (w * w);
            let aa = (p0 - 2.0 * xi * w * bb) / (w * w);
            let c = q - aa;
            let d = (qd - bb + xi * w * c) / wd;
            let e = (-xi * w * len).exp();
            let (s, co) = (wd * len).sin_cos();
            q = aa + bb * len + e * (c * co + d * s);
            qd = bb + e * ((-xi * w) * (c * co + d * s) + wd * (-c * s + d * co));
            t += len;
            k += 1;
        }
        for i in 0..n {
            u[i] += phi[i] * q;
            v[i] += phi[i] * qd;
        }
    }
    (u, v)
}

#[test]
fn elastic_rows_without_contact_are_modal_superposition() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let row = buildings::load_with(
        "three-in-series",
        &[
            "joint1.gap=\"inf\"".into(),
            "joint2.gap=\"inf\"".into(),
            "block.yield_drift=\"inf\"".into(),
            "mid.yield_drift=\"inf\"".into(),
            "tall.yield_drift=\"inf\"".into(),
        ],
    )
    .unwrap();
    for duration in [3.333, 7.5, 12.0] {
        let r = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
        let mut at = 0;
        for (b, floors) in row.buildings.iter().zip(&r.floors) {
            let (u, v) = modal(b, record.dt, &ground_samples(&ground), duration);
            // Relative to the building's peaks over the run.
            let su = floors.iter().fold(0.0f64, |m, f| m.max(f.displacement));
            let sv = floors.iter().fold(0.0f64, |m, f| m.max(f.velocity));
            for i in 0..b.storeys() {
                let du = (r.final_displacement[at + i] - u[i]).abs() / su;
                let dv = (r.final_velocity[at + i] - v[i]).abs() / sv;
                assert!(
                    du < 1e-12 && dv < 1e-12,
                    "{} floor {}: {du:e} {dv:e}",
                    b.name,
                    i + 1
                );
            }
            at += b.storeys();
        }
    }
}

fn ground_samples(g: &Ground) -> Vec<f64> {
    match g {
        Ground::Samples { acceleration, .. } => acceleration.clone(),
        _ => unreachable!(),
    }
}

#[test]
fn the_mirror_image_gives_the_same_peaks() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.5);
    let row = buildings::load("three-in-series").unwrap();
    let options = RowOptions::lasting(ground.end() + 2.0);
    let a = run_row(&row, &ground, &options).unwrap();
    let b = run_row(&row.mirrored(), &ground.negated(), &options).unwrap();
    assert!(a.impacts() > 10, "{}", a.impacts());
    assert_eq!(a.impacts(), b.impacts());
    for (fa, fb) in a.floors.iter().zip(b.floors.iter().rev()) {
        for (x, y) in fa.iter().zip(fb) {
            for (p, q) in [
                (x.displacement, y.displacement),
                (x.velocity, y.velocity),
                (x.drift, y.drift),
                (x.absolute_acceleration, y.absolute_acceleration),
            ] {
                assert!((p - q).abs() <= 1e-12 * p.abs().max(1e-3), "{p} {q}");
            }
        }
    }
}
