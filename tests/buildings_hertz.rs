//! The exact method under the Hertz-type laws (SPEC §13 with §10), whose
//! contact phases it carries by an embedded Runge–Kutta pair: against the
//! independent reference, by the energy balance, and by the restitution an
//! isolated impact achieves, which for these laws depends on e alone (the
//! pair's values, pinned in `tests/contact_laws.rs`).

use pounding::accuracy::row_bench::{acceleration_error, peak_error};
use pounding::model::ContactModel;
use pounding::model::buildings::{self, Ground, parse};
use pounding::model::record::read;
use pounding::reference::row::reference_row;
use pounding::solver::buildings::{RowOptions, run_row};

const LAWS: [ContactModel; 4] = [
    ContactModel::Hertz,
    ContactModel::HertzDamp,
    ContactModel::Jankowski,
    ContactModel::HuntCrossley,
];

/// Block-and-frame under the synthetic record, each law: every floor's
/// peaks |u|, |u̇|, |Δ| within 1e-9 of the reference (relative to the
/// building's largest of each kind, and the absolute acceleration to its
/// own;
/// the method's steps are held to 1e-12 of the motion's scale, and the
/// reference to 1e-13, so what remains is their accumulated local errors,
/// measured at 5e-12 to 2e-11), and equal impact counts at every floor pair.
#[test]
fn every_hertz_type_law_matches_the_reference() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.0);
    let duration = ground.end() + 2.0;
    for model in LAWS {
        let mut row = buildings::load("block-and-frame").unwrap();
        row.model = model;
        let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
        let reference = reference_row(&row, &ground, duration, 1e-13);
        let counts: Vec<usize> = exact.pairs.iter().map(|p| p.impacts.len()).collect();
        assert_eq!(counts, reference.impacts, "{model}: impacts per pair");
        assert!(exact.impacts() > 0, "{model}");
        let worst = peak_error(&exact, &reference);
        println!("{model}: {worst:e}");
        assert!(worst < 1e-9, "{model}: worst relative difference {worst:e}");
        // Each floor's peak absolute acceleration, relative to its own:
        // on the Runge–Kutta steps through contact it is taken from the
        // equation of motion, not from the interpolant's second derivative,
        // which on the shortest steps is rounding (measured: 7e-11 at worst,
        // Jankowski; the interpolant gave up to 48 % on far floors).
        for (b, floors) in exact.floors.iter().enumerate() {
            for (i, f) in floors.iter().enumerate() {
                let want = reference.absolute_acceleration[b][i];
                let e = (f.absolute_acceleration - want).abs() / want;
                assert!(e < 1e-9, "{model}: building {b} floor {}: {e:e}", i + 1);
            }
        }
        // The bench's column: relative to each building's largest, so no
        // more than the largest per-floor difference above.
        let bench = acceleration_error(&exact, &reference);
        assert!(
            bench < 1e-9 && bench > 0.0,
            "{model}: bench's acceleration error {bench:e}"
        );
        for p in &exact.pairs {
            for i in &p.impacts {
                assert!(i.end > i.start && i.max_force > 0.0, "{model}: {i:?}");
            }
        }
    }
}

/// E_kin + E_damp + E_spring + E_contact = E_in to 1e-9 of max |E_in|
/// (SPEC §6), the work taken on the Runge–Kutta steps' polynomials.
#[test]
fn the_balance_closes_under_every_hertz_type_law() {
    let record = read("presets/synthetic.at2").unwrap();
    let ground = Ground::from_record(&record, 1.5);
    for model in LAWS {
        let mut row = buildings::load("block-and-frame").unwrap();
        row.model = model;
        let options = RowOptions {
            energy: true,
            ..RowOptions::lasting(ground.end() + 2.0)
        };
        let r = run_row(&row, &ground, &options).unwrap();
        let e = r.energy.unwrap();
        assert!(r.impacts() > 0, "{model}");
        assert!(e.residual() < 1e-9, "{model}: residual {:e}", e.residual());
        if model == ContactModel::Hertz {
            // Elastic: what the contact stores it returns.
            assert!(e.contact.abs() < 1e-9 * e.max_input, "{e:?}");
        } else {
            assert!(e.contact > 0.0, "{model}: {e:?}");
        }
    }
}

/// Two one-storey buildings, the contact far stiffer than the storeys (it
/// lasts about 0.15 ms, a radian of the stiffer storey is 50 ms): the first
/// impact achieves the restitution of two free masses, which for a
/// Hertz-type law is a function of e alone (λv₀ is fixed; m̄ and v₀ only
/// scale time), pinned from the pair's exact method and reference. The
/// storeys' forces over the contact leave ~1e-5.
#[test]
fn an_isolated_impact_achieves_the_free_masses_restitution() {
    let cases = [
        (ContactModel::Hertz, 1.0),
        (ContactModel::HertzDamp, 0.795_972_596),
        (ContactModel::HuntCrossley, 0.767_999_790),
        (ContactModel::Jankowski, 0.697_749_096),
    ];
    for (model, achieved) in cases {
        let text = format!(
            "model = \"{}\"\nrestitution = 0.7\n\
             [[building]]\nname = \"soft\"\nstoreys = 1\nmass = 1e5\nstiffness = 1e6\nheight = 3\ndamping = 0\n\
             [[building]]\nname = \"stiff\"\nstoreys = 1\nmass = 1e5\nstiffness = 4e7\nheight = 3\ndamping = 0\n\
             [[joint]]\ngap = 0.005\nstiffness = 1e16\n",
            model.name()
        );
        let row = parse("impact.toml", &text).unwrap();
        let ground = Ground::sine(2.0, 2.0 * std::f64::consts::PI, 1.0);
        let r = run_row(&row, &ground, &RowOptions::lasting(1.5)).unwrap();
        let first = r.pairs[0].impacts[0];
        assert!(first.approach_velocity > 0.01, "{first:?}");
        let got = first.separation_velocity / first.approach_velocity;
        println!("{model}: {got} ({:e})", got - achieved);
        assert!((got - achieved).abs() < 1e-4, "{model}: achieved {got}");
    }
}
