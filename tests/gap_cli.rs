//! `pounding gap` end to end: set 1's minimum gap and code rules (SPEC §11),
//! the sweep over one parameter, and bad input.

mod common;

use common::{fails, json, stdout, succeeds};

#[test]
fn set1_gap_and_rules() {
    let v = json(&["gap", "--preset", "set1", "--format", "json"]);
    let pt = &v["points"][0];
    let close = |key: &str, want: f64| {
        let got = pt[key].as_f64().unwrap();
        assert!((got - want).abs() < 5e-5, "{key}: {got} vs {want}");
    };
    close("exact", 2.5736);
    assert!((pt["rules"]["srss"].as_f64().unwrap() - 2.4419).abs() < 5e-5);
    assert!((pt["rules"]["absolute_sum"].as_f64().unwrap() - 2.7055).abs() < 5e-5);
    assert!(pt["ratio_srss"].as_f64().unwrap() < 1.0);
    assert!(pt["ratio_absolute_sum"].as_f64().unwrap() > 1.0);
    assert_eq!(pt["pounds_at_set_gap"], true);
    assert_eq!(v["method"], "exact");
    assert_eq!(v["params"]["gap"], 0.2);
    let table = stdout(&succeeds(&["gap"]));
    assert!(
        table.contains("2.5736") && table.contains("too small"),
        "{table}"
    );
}

#[test]
fn sweep_along_omega1() {
    let v = json(&["gap", "--x", "omega1=0.5:2.5:0.5", "--format", "json"]);
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 5);
    assert_eq!(v["x"]["key"], "omega1");
    for pt in points {
        let x = pt["x"].as_f64().unwrap();
        assert_eq!(pt["omega1"].as_f64(), Some(x));
        assert!(pt["rules"]["absolute_sum"].as_f64() >= pt["exact"].as_f64());
    }
    let text = stdout(&succeeds(&[
        "gap",
        "--x",
        "omega1=0.5:2.5:0.5",
        "--format",
        "csv",
    ]));
    assert_eq!(text.lines().count(), 6);
    assert!(text.lines().next().unwrap().contains("min_gap"));
}

#[test]
fn bad_axis_is_one_line_and_exit_2() {
    for (x, says) in [
        ("bogus=1:2:1", "unknown axis"),
        ("omega1=1:2", "expected KEY=START:STOP:STEP"),
        ("omega1=0.5:1e6:1", "omega1"),
    ] {
        fails(&["gap", "--x", x], 2, &[says]);
    }
}
