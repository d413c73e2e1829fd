//! No absurd number is reported as a result: a report holding a non-finite
//! number where a finite one is meant fails in its one writer, in every
//! format, naming the quantity (exit 1, a failed run), while the numbers a
//! report marks as possibly infinite (an elastic storey's ductility, an
//! open joint's gap) pass.

use pounding::analysis::buildings_report::RowReport;
use pounding::cli::CliError;
use pounding::cli::output::{Format, render};
use pounding::model::buildings::{Ground, load};
use pounding::solver::buildings::{RowOptions, run_row};

/// The block-and-frame row under a short sine, exact method, with its
/// energy balance.
fn report() -> RowReport {
    let row = load("block-and-frame").unwrap();
    let ground = Ground::sine(3.0, std::f64::consts::TAU, 1.0);
    let options = RowOptions {
        energy: true,
        ..RowOptions::lasting(1.5)
    };
    let run = run_row(&row, &ground, &options).unwrap();
    RowReport::new(&row, &run, (&ground, "sine"), "exact", 1.0)
}

#[test]
fn a_finite_report_renders_in_every_format() {
    let r = report();
    // The block's storeys yield at 8 mm: a finite ductility; the report
    // as a whole passes in every format.
    for format in [Format::Table, Format::Json, Format::Csv] {
        assert!(render(&r, format).is_ok(), "{format:?}");
    }
}

#[test]
fn a_non_finite_quantity_fails_every_format_and_is_named() {
    let mut r = report();
    // What the joint of 1e300 N/m gave: a NaN energy balance.
    r.energy.as_mut().expect("exact method").residual = f64::NAN;
    for format in [Format::Table, Format::Json, Format::Csv] {
        let e = render(&r, format).unwrap_err();
        assert_eq!(e.exit_code(), 1);
        let CliError::Failed(message) = e else {
            panic!("{format:?}: not a failed run");
        };
        assert_eq!(
            message,
            "the result holds a non-finite number, energy.residual = nan: the run went wrong, so nothing is reported"
        );
    }
    // An overflowed peak deep in the report is named by its path.
    let mut r = report();
    r.buildings[1].floors[2].peak_absolute_acceleration = f64::INFINITY;
    let e = render(&r, Format::Csv).unwrap_err().to_string();
    assert!(
        e.contains("buildings[1].floors[2].peak_absolute_acceleration = inf"),
        "{e}"
    );
}

#[test]
fn quantities_marked_as_possibly_infinite_pass() {
    let mut r = report();
    // An elastic storey's ductility is ∞ by definition (SPEC §6).
    r.buildings[0].floors[0].ductility = f64::INFINITY;
    let text = render(&r, Format::Json).unwrap();
    assert!(text.contains("\"ductility\":\"inf\""), "{text}");
}
