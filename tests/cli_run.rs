//! `pounding run` end to end: the JSON object, the history CSV, and every bad
//! input of the parameter table (exit code 2, one clear line, no panic).

mod common;

use common::{fails, history_json, json, parse_json, stderr, stdout, succeeds};

#[test]
fn json_has_every_key() {
    let text = stdout(&succeeds(&["run", "--preset", "set1", "--format", "json"]));
    assert_eq!(
        text.trim().lines().count(),
        1,
        "exactly one JSON object on one line"
    );
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    // It says which program wrote it, from which preset, in which units,
    // before anything else, as every other command's report does.
    assert!(text.starts_with(r#"{"version":"#), "{}", &text[..60]);
    let at = |key: &str| text.find(&format!("\"{key}\":")).unwrap();
    assert!(
        at("version") < at("preset") && at("preset") < at("units") && at("units") < at("params")
    );
    assert_eq!(v["version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(v["preset"], "set1");
    assert_eq!(v["units"], "dimensionless (Π-groups of SPEC §1)");
    for key in pounding::model::params::keys() {
        assert!(v["params"].get(key).is_some(), "params.{key} missing");
    }
    assert_eq!(v["model"], "improved-kelvin");
    assert_eq!(v["dt"], 0.001);
    assert!((v["tau_end"].as_f64().unwrap() - 16.0 * std::f64::consts::PI).abs() < 1e-9);
    assert!(v["steps"].as_u64().unwrap() >= 50_266);
    assert_eq!(v["impacts"], 9);
    assert_eq!(v["impact_list"].as_array().unwrap().len(), 9);
    for key in [
        "start",
        "end",
        "approach_velocity",
        "separation_velocity",
        "restitution",
        "peak_force",
        "max_penetration",
    ] {
        assert!(v["impact_list"][0][key].is_number(), "impact_list[0].{key}");
    }
    assert!((v["left"]["peak_displacement"].as_f64().unwrap() - 3.22245).abs() < 2e-5);
    assert_eq!(v["left"]["yielded"], true);
    assert_eq!(v["right"]["yielded"], false);
    assert!(v["max_force"].as_f64().unwrap() > 30.0);
    assert!(v["min_force"].as_f64().unwrap() >= 0.0);
    assert!(v["energy_residual"].as_f64().unwrap() < 1e-6);
    assert!(v["elapsed_ms"].as_f64().unwrap() > 0.0);
}

#[test]
fn infinite_gap_is_written_as_inf_in_json() {
    let v = json(&["run", "--no-pounding", "--format", "json", "--cycles", "1"]);
    assert_eq!(v["params"]["gap"], "inf");
    assert_eq!(v["impacts"], 0);
}

#[test]
fn history_csv_has_one_row_per_step() {
    let dir = std::env::temp_dir().join(format!("pounding-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("h.csv");
    let v = history_json(&path);
    let csv = std::fs::read_to_string(&path).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "tau,x1,v1,a1,x2,v2,a2,fs1,fs2,fp,ag,vg,ug"
    );
    // One row per accepted step plus the initial state.
    assert_eq!(lines.count() as u64, v["steps"].as_u64().unwrap() + 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn csv_and_table_formats() {
    let text = stdout(&succeeds(&["run", "--preset", "set2", "--format", "csv"]));
    assert_eq!(text.lines().count(), 2);
    // Self-describing: the preset and every parameter, then the results.
    let mut rows = text.lines().map(|l| l.split(',').collect::<Vec<_>>());
    let (header, row) = (rows.next().unwrap(), rows.next().unwrap());
    assert_eq!(header.len(), row.len());
    let cell = |key: &str| row[header.iter().position(|h| *h == key).unwrap()];
    assert_eq!(cell("preset"), "set2");
    for key in pounding::model::params::keys() {
        assert!(header.contains(&key), "column {key} missing");
    }
    assert_eq!((cell("omega1"), cell("method")), ("1.5", "newmark"));
    assert_eq!(cell("impacts"), "26");
    let text = stdout(&succeeds(&["run", "--preset", "set2", "--model", "kelvin"]));
    assert!(
        text.contains("kelvin contact") && text.contains("(tension)"),
        "{text}"
    );
}

/// Each bad input: exit code 2 and a one-line message with the given fragments.
#[test]
fn bad_input_is_a_clear_error() {
    let cases: &[(&[&str], &[&str])] = &[
        (&["run", "--set", "bogus=1"], &["unknown parameter `bogus`"]),
        (
            &["run", "--set", "gap=abc"],
            &["`gap` = abc", "not a number"],
        ),
        (&["run", "--set", "gap=NaN"], &["`gap` = NaN"]),
        (
            &["run", "--set", "mass_ratio=0"],
            &["`mass_ratio` = 0", "[0.001, 1000]"],
        ),
        (&["run", "--set", "mass_ratio=-2"], &["`mass_ratio` = -2"]),
        (
            &["run", "--set", "restitution=0"],
            &["`restitution` = 0", "[0.001, 1]"],
        ),
        (
            &["run", "--set", "restitution=1.5"],
            &["`restitution` = 1.5", "[0.001, 1]"],
        ),
        (&["run", "--dt", "0"], &["`dt` = 0", "[1e-6, 0.3142]"]),
        (&["run", "--dt", "-0.001"], &["`dt` = -0.001"]),
        (
            &["run", "--set", "gap=-0.1"],
            &["`gap` = -0.1", "[0, 1e6], or inf"],
        ),
        (&["run", "--set", "yield1=-1"], &["`yield1` = -1"]),
        (&["run", "--set", "yield2=0"], &["`yield2` = 0"]),
        (
            &["run", "--set", "damping=-0.05"],
            &["`damping` = -0.05", "[0, 1]"],
        ),
        (
            &["run", "--set", "contact_omega=-50"],
            &["`contact_omega` = -50"],
        ),
        (&["run", "--set", "alpha=1.5"], &["`alpha` = 1.5", "[0, 1]"]),
        (
            &["run", "--set", "alpha=-0.1"],
            &["`alpha` = -0.1", "[0, 1]"],
        ),
        (&["run", "--cycles", "0"], &["`cycles` = 0", "[1, 100000]"]),
        (&["run", "--cycles", "2.5"], &["`cycles` = 2.5"]),
        (
            &["run", "--set", "model=hertz-mindlin"],
            &["`model` = hertz-mindlin", "kelvin"],
        ),
        (&["run", "--set", "gap"], &["KEY=VALUE"]),
        (
            &["run", "--preset", "set3"],
            &["no preset named `set3`", "set1", "set2"],
        ),
    ];
    for (args, fragments) in cases {
        fails(args, 2, fragments);
    }
}

#[test]
fn malformed_preset_names_file_line_and_column() {
    let dir = std::env::temp_dir().join(format!("pounding-preset-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("broken.toml");
    std::fs::write(&path, "mass_ratio = 0.5\nomega1 = [oops\n").unwrap();
    let preset = ["run", "--preset", path.to_str().unwrap()];
    fails(&preset, 2, &[&format!("{}:2:", path.display())]);
    std::fs::write(&path, "restitution = 2\n").unwrap();
    fails(&preset, 2, &["broken.toml", "`restitution` = 2"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn coarse_dt_is_a_warning_not_an_error() {
    let o = succeeds(&["run", "--dt", "0.01", "--format", "json"]);
    let err = stderr(&o);
    assert!(
        err.contains("warning") && err.contains("steps per contact period"),
        "{err}"
    );
    let v = parse_json(&o.stdout);
    assert!(v["left"]["peak_displacement"].as_f64().unwrap().is_finite());
}

#[test]
fn physical_preset_runs_its_own_pi_groups() {
    // two-buildings holds only a [physical] table: its Π-groups, not set 1's, are run.
    let v = json(&[
        "run",
        "--preset",
        "two-buildings",
        "--format",
        "json",
        "--cycles",
        "1",
    ]);
    let omega1 = v["params"]["omega1"].as_f64().unwrap();
    // Π_ω1 = ω1/ω_p = (2π/0.95)/(2π/1.0) = 1/0.95.
    assert!((omega1 - 1.0 / 0.95).abs() < 1e-12, "{omega1}");
    // Π_d = d ω_p²/a_p = 0.025 (2π)² / (0.5 g).
    let gap = v["params"]["gap"].as_f64().unwrap();
    let expected = 0.025 * (2.0 * std::f64::consts::PI).powi(2) / (0.5 * 9.80665);
    assert!((gap - expected).abs() < 1e-12, "{gap} vs {expected}");
}

/// The guide's key list (docs/src/physics/pair.md) is the parameter table:
/// one row per key, with its symbol, meaning and range exactly as the table
/// states them.
#[test]
fn the_guide_lists_every_key_of_the_table() {
    let guide = include_str!("../docs/src/physics/pair.md");
    let rows: Vec<String> = pounding::model::params::FIELDS
        .iter()
        .map(|f| {
            format!(
                "| `{}` | {} | {} | {} |",
                f.key,
                f.symbol,
                f.meaning,
                f.range().replace('|', "\\|")
            )
        })
        .collect();
    let missing: Vec<&String> = rows
        .iter()
        .filter(|r| !guide.contains(r.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "docs/src/physics/pair.md lacks these rows:\n{}",
        rows.join("\n")
    );
}

/// The demands of SPEC §6 per structure in JSON (ductility ∞ written "inf",
/// JSON staying valid), in CSV's columns and in the table.
#[test]
fn json_csv_and_table_carry_the_demands() {
    // Set 1 with an elastic right structure.
    let case = ["run", "--preset", "set1", "--set", "yield2=inf"];
    let with = |format: &'static str| [&case[..], &["--format", format]].concat();
    let v = json(&with("json"));
    let left = &v["left"];
    for key in [
        "peak_absolute_acceleration",
        "ductility",
        "residual_displacement",
        "hysteretic_energy",
    ] {
        assert!(left[key].is_number(), "left.{key}: {}", left[key]);
    }
    let (u, mu) = (
        left["peak_displacement"].as_f64().unwrap(),
        left["ductility"].as_f64().unwrap(),
    );
    assert!((mu - u / 0.9).abs() < 1e-12 * mu, "{mu} vs {u}/0.9");
    assert!(left["peak_absolute_acceleration"].as_f64().unwrap() > 30.0);
    assert!(left["hysteretic_energy"].as_f64().unwrap() > 1.0);
    assert!(left["residual_displacement"].as_f64().unwrap() < 0.0);
    let right = &v["right"];
    assert_eq!(right["ductility"], "inf");
    assert_eq!(right["residual_displacement"], 0.0);
    assert!(right["hysteretic_energy"].as_f64().unwrap().abs() < 1e-9);
    let springs = v["energy"]["spring_by_structure"].as_array().unwrap();
    let sum: f64 = springs.iter().map(|s| s.as_f64().unwrap()).sum();
    let spring = v["energy"]["spring"].as_f64().unwrap();
    assert!((sum - spring).abs() < 1e-12 * spring.abs());

    let text = stdout(&succeeds(&with("csv")));
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let cell = |name: &str| row[header.iter().position(|h| *h == name).unwrap()];
    assert_eq!(cell("right_ductility"), "inf");
    assert_eq!(cell("right_residual_displacement"), "0");
    assert_eq!(
        cell("left_ductility").parse::<f64>().unwrap(),
        left["ductility"].as_f64().unwrap()
    );
    for side in ["left", "right"] {
        assert!(
            cell(&format!("{side}_peak_absolute_acceleration"))
                .parse::<f64>()
                .is_ok()
        );
        assert!(
            cell(&format!("{side}_hysteretic_energy"))
                .parse::<f64>()
                .is_ok()
        );
    }

    let table = stdout(&succeeds(&[
        "run",
        "--preset",
        "set1",
        "--set",
        "yield2=inf",
    ]));
    assert!(table.contains("   A ") && table.contains("E_h"), "{table}");
    let right_line = table.lines().find(|l| l.starts_with("right (2)")).unwrap();
    assert!(right_line.contains(" inf "), "{right_line}");
}
