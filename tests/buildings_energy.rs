//! The energy balance of a row closes with the exact method (SPEC §6, §13):
//! E_kin + E_damp + E_spring + E_contact = E_in to 1e-9 of max |E_in|,
//! with yielding and impacts at several floor pairs.

use pounding::model::buildings::{self, Ground};
use pounding::model::record::read;
use pounding::solver::buildings::{RowOptions, run_row};

#[test]
fn the_balance_closes_with_the_exact_method() {
    let record = read("presets/synthetic.at2").unwrap();
    for (name, scale) in [
        ("block-and-frame", 1.5),
        ("three-in-series", 1.5),
        ("two-buildings", 3.0),
    ] {
        let ground = Ground::from_record(&record, scale);
        let row = buildings::load(name).unwrap();
        let r = run_row(
            &row,
            &ground,
            &RowOptions {
                energy: true,
                ..RowOptions::lasting(ground.end() + 2.0)
            },
        )
        .unwrap();
        let e = r.energy.unwrap();
        assert!(r.impacts() > 0, "{name}");
        assert!(e.contact > 0.0 && e.damping > 0.0, "{name}: {e:?}");
        assert!(
            e.residual() < 1e-9,
            "{name}: residual {:e} {e:?}",
            e.residual()
        );
    }
}
