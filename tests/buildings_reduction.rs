//! Two one-storey buildings are the SDOF pair of SPEC §2 (SPEC §13,
//! reduction): the row preset `two-buildings` under the `two-buildings`
//! preset's sine gives that preset's peaks, in metres, to 1e-10.

use pounding::model::buildings::{self, Ground};
use pounding::model::{Method, preset::builtin};
use pounding::solver::buildings::{RowOptions, run_row};
use pounding::solver::run;

const G: f64 = 9.80665;

#[test]
fn two_one_storey_buildings_are_the_sdof_pair() {
    let mut p = builtin("two-buildings").unwrap().params;
    p.method = Method::Exact;
    let sdof = run(&p);
    let (ap, omega_p) = (0.5 * G, 2.0 * std::f64::consts::PI);
    let le = ap / (omega_p * omega_p);
    let row = buildings::load("two-buildings").unwrap();
    let ground = Ground::Sine {
        amplitude: ap,
        omega: omega_p,
        end: 8.0,
    };
    let r = run_row(&row, &ground, &RowOptions::lasting(8.0)).unwrap();
    let want = [
        (
            sdof.left.peak_displacement * le,
            sdof.left.peak_velocity * ap / omega_p,
        ),
        (
            sdof.right.peak_displacement * le,
            sdof.right.peak_velocity * ap / omega_p,
        ),
    ];
    for (b, (u, v)) in want.iter().enumerate() {
        let f = &r.floors[b][0];
        assert!(
            (f.displacement - u).abs() < 1e-10,
            "{} {}",
            f.displacement,
            u
        );
        assert!((f.velocity - v).abs() < 1e-10, "{} {}", f.velocity, v);
    }
    assert_eq!(r.impacts(), sdof.impacts.len());
    let acc = [
        sdof.left.peak_absolute_acceleration,
        sdof.right.peak_absolute_acceleration,
    ];
    for (floors, want) in r.floors.iter().zip(acc) {
        let got = floors[0].absolute_acceleration;
        assert!((got - want * ap).abs() < 1e-9 * got, "{got} {}", want * ap);
    }
}
