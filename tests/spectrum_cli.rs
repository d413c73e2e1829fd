//! `pounding spectrum` from the outside: JSON shape, CSV header, bad input.

mod common;

use common::{fails, json, stdout, succeeds};

#[test]
fn json_has_the_issue_shape() {
    let v = json(&[
        "spectrum",
        "--preset",
        "fig8-gap",
        "--omega1",
        "1.0:1.1:0.1",
        "--format",
        "json",
    ]);
    assert_eq!(v["mu"], 1.5);
    assert_eq!(v["model"], "improved-kelvin");
    let curves = v["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 3);
    assert_eq!(curves[0]["family"], serde_json::json!({"gap": 0.2}));
    assert_eq!(curves[2]["family"], serde_json::json!({"gap": "inf"}));
    let p = &curves[0]["points"][1];
    assert_eq!(p["omega1"], 1.1);
    assert!((p["omega2"].as_f64().unwrap() - 1.65).abs() < 1e-12);
    for k in ["left", "right", "free_left", "free_right"] {
        assert!(p[k]["peak_displacement"].as_f64().unwrap() > 0.0);
        assert!(p[k]["peak_velocity"].as_f64().unwrap() > 0.0);
    }
    assert!(p["impacts"].as_u64().unwrap() > 0);
    assert_eq!(p["region"], "amplification");
    assert!(v["elapsed_ms"].as_f64().unwrap() >= 0.0);
    // Self-describing: parameters, method, units and grid.
    assert_eq!(v["method"], "exact");
    assert_eq!(
        v["params"]["mass_ratio"],
        v["params"]["mass_ratio"].as_f64().unwrap()
    );
    assert!(v["units"].as_str().unwrap().starts_with("dimensionless"));
    assert_eq!(v["grid"]["points"], 2);
    assert_eq!(v["grid"]["step"], 0.1);
    // Without a family.
    let v = json(&[
        "spectrum",
        "--omega1",
        "0.1:0.1:0.1",
        "--mu",
        "2.25",
        "--format",
        "json",
    ]);
    assert_eq!(v["curves"][0]["family"], serde_json::json!({}));
    assert_eq!(v["curves"][0]["points"][0]["region"], "none");
}

#[test]
fn csv_has_one_row_per_point() {
    let out = stdout(&succeeds(&[
        "spectrum",
        "--family",
        "mass_ratio=0.1,0.9",
        "--omega1",
        "0.1:0.3:0.1",
        "--format",
        "csv",
    ]));
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 1 + 2 * 3);
    // Every row carries what the JSON says first (version, preset, units),
    // its family member, the grid and the whole parameter set.
    assert!(
        lines[0]
            .starts_with("version,preset,units,family,omega1_grid,mu,mass_ratio,omega1,omega2,")
    );
    assert!(lines[0].ends_with(",impacts,region,min_gap_no_pounding"));
    let columns = lines[0].split(',').count();
    assert!(lines.iter().all(|l| l.split(',').count() == columns));
    let head = format!(
        "{},set1,dimensionless (Π-groups of SPEC §1),mass_ratio=0.9,0.1:0.3:0.1,",
        env!("CARGO_PKG_VERSION")
    );
    assert!(lines[4].starts_with(&head), "{}", lines[4]);
    let header: Vec<&str> = lines[0].split(',').collect();
    let row: Vec<&str> = lines[4].split(',').collect();
    let cell = |key: &str| row[header.iter().position(|h| *h == key).unwrap()];
    assert_eq!(cell("mass_ratio"), "0.9");
    assert_eq!(cell("method"), "exact");
    assert_eq!(cell("model"), "improved-kelvin");
    assert_eq!(cell("omega1"), "0.1");
}

/// Set 1's point Π_ω1 = 1.05 carries the gap `pounding gap` finds there
/// (2.5736, SPEC §11), in JSON and CSV; Newmark does not track it.
#[test]
fn min_gap_no_pounding_matches_the_gap_command() {
    let gap = json(&["gap", "--preset", "set1", "--format", "json"]);
    let want = gap["points"][0]["exact"].as_f64().unwrap();
    assert!((want - 2.5736).abs() < 5e-5, "{want}");
    let grid = ["spectrum", "--preset", "set1", "--omega1", "1.05:1.05:0.05"];
    let v = json(&[&grid[..], &["--format", "json"]].concat());
    let got = v["curves"][0]["points"][0]["min_gap_no_pounding"]
        .as_f64()
        .unwrap();
    assert!((got - want).abs() < 1e-9, "{got} vs {want}");
    let out = stdout(&succeeds(&[&grid[..], &["--format", "csv"]].concat()));
    let last: f64 = out
        .lines()
        .nth(1)
        .unwrap()
        .rsplit(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((last - want).abs() < 1e-9, "{last} vs {want}");
    let newmark = [&grid[..], &["--method", "newmark", "--format", "json"]].concat();
    let v = json(&newmark);
    assert!(v["curves"][0]["points"][0]["min_gap_no_pounding"].is_null());
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    for (args, needle) in [
        (vec!["--omega1", "3:1:0.1"], "`omega1` grid = 3:1:0.1"),
        (vec!["--mu", "0"], "--mu 0"),
        (
            vec!["--family", "restitution=0.5,7"],
            "`restitution` = 7: must be a number in [0.001, 1]",
        ),
        (vec!["--family", "omega2=1,2"], "swept"),
        (vec!["--set", "gap=-1"], "`gap` = -1"),
    ] {
        let mut all = vec!["spectrum"];
        all.extend(args);
        fails(&all, 2, &[needle]);
    }
}

/// The spectrum, map and gap CSVs say in every row what their JSON says
/// first: the version, the preset and the units.
#[test]
fn csv_rows_carry_version_preset_and_units_as_the_json_does() {
    for args in [
        &["spectrum", "--omega1", "0.5:1:0.5"][..],
        &["map", "--x", "omega1=0.5:1:0.5", "--y", "mu=1:2:1"][..],
        &["gap", "--x", "omega1=0.5:1:0.5"][..],
    ] {
        let v = json(&[args, &["--preset", "set2", "--format", "json"]].concat());
        let csv = stdout(&succeeds(
            &[args, &["--preset", "set2", "--format", "csv"]].concat(),
        ));
        let lines: Vec<&str> = csv.lines().collect();
        assert!(lines.len() > 1, "{args:?}");
        let header: Vec<&str> = lines[0].split(',').collect();
        assert_eq!(header[..3], ["version", "preset", "units"], "{args:?}");
        for line in &lines[1..] {
            let row: Vec<&str> = line.split(',').collect();
            assert_eq!(row.len(), header.len(), "{args:?}");
            for (i, key) in ["version", "preset", "units"].iter().enumerate() {
                assert_eq!(row[i], v[key].as_str().unwrap(), "{args:?} {key}");
            }
        }
    }
}
