//! `pounding run --buildings` (SPEC §13): the JSON shape, `--set`, a row
//! whose floors do not pair, and bad input: exit 2 with one line naming the
//! file, the building or joint, the key, the value and what is allowed.

mod common;

use common::{fails, json};

const ROW: &str = "model = \"improved-kelvin\"\n\
    [[building]]\nname = \"low\"\nstoreys = 2\nmass = 1e5\nstiffness = [2e8, 1e8]\nheight = 3\nyield_drift = 0.01\n\
    [[building]]\nname = \"high\"\nstoreys = 3\nmass = 1e5\nstiffness = 1e8\nheight = 3\n\
    [[joint]]\ngap = 0.01\nstiffness = 1e10\n";

fn write(dir: &tempfile::TempDir, name: &str, text: &str) -> String {
    let p = dir.path().join(name);
    std::fs::write(&p, text).unwrap();
    p.to_string_lossy().into_owned()
}

#[test]
fn json_lists_buildings_floors_and_pairs() {
    let v = json(&[
        "run",
        "--buildings",
        "block-and-frame",
        "--excitation",
        "record:presets/synthetic.at2",
        "--format",
        "json",
    ]);
    let b = v["buildings"].as_array().unwrap();
    assert_eq!(b.len(), 2);
    assert_eq!(b[0]["name"], "block");
    assert_eq!(b[0]["floors"].as_array().unwrap().len(), 3);
    assert_eq!(b[1]["floors"].as_array().unwrap().len(), 8);
    for key in [
        "peak_displacement",
        "peak_velocity",
        "peak_absolute_acceleration",
        "peak_drift",
        "drift_ratio",
        "ductility",
        "residual_drift",
    ] {
        assert!(b[1]["floors"][7][key].is_number(), "{key}");
    }
    assert!(b[1]["periods"][0].as_f64().unwrap() > 0.5);
    let pairs = v["pairs"].as_array().unwrap();
    assert_eq!(pairs.len(), 3);
    assert_eq!(pairs[2]["left_floor"], 3);
    assert_eq!(pairs[2]["right_floor"], 3);
    let total: u64 = pairs.iter().map(|p| p["impacts"].as_u64().unwrap()).sum();
    assert_eq!(v["impacts"].as_u64().unwrap(), total);
    assert!(total > 0);
    assert_eq!(v["method"], "exact");
    assert!(v["energy"]["residual"].as_f64().unwrap() < 1e-9);
    assert!(v["energy"]["contact"].as_f64().unwrap() > 0.0);
    assert!(v["elapsed_ms"].as_f64().unwrap() >= 0.0);
}

#[test]
fn the_exact_method_runs_every_hertz_type_law() {
    for model in ["hertz", "hertzdamp", "jankowski", "hunt-crossley"] {
        let v = json(&[
            "run",
            "--buildings",
            "block-and-frame",
            "--model",
            model,
            "--excitation",
            "record:presets/synthetic.at2",
            "--format",
            "json",
        ]);
        assert_eq!(v["method"], "exact", "{model}");
        assert_eq!(v["model"], model);
        assert!(v["impacts"].as_u64().unwrap() > 0, "{model}");
        assert!(v["energy"]["residual"].as_f64().unwrap() < 1e-9, "{model}");
    }
}

#[test]
fn a_row_whose_floors_do_not_pair_runs_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(&dir, "apart.toml", &ROW.replace("height = 3\n\n[[building]]\nname = \"high\"\nstoreys = 3\nmass = 1e5\nstiffness = 1e8\nheight = 3", "height = 3\n\n[[building]]\nname = \"high\"\nstoreys = 3\nmass = 1e5\nstiffness = 1e8\nheight = 3.5").replace("stiffness = 1e8\nheight = 3\n", "stiffness = 1e8\nheight = 3.5\n"));
    let v = json(&["run", "--buildings", &path, "--format", "json"]);
    assert_eq!(v["pairs"].as_array().unwrap().len(), 0);
    assert!(v["note"].as_str().unwrap().contains("no floors pair up"));
}

#[test]
fn bad_input_exits_2_with_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            ROW.replace("[2e8, 1e8]", "[2e8, 1e8, 1e8]"),
            vec!["building `low`", "`stiffness` has 3 values", "list of 2"],
        ),
        (
            ROW.replace("mass = 1e5\nstiffness = 1e8", "mass = -1\nstiffness = 1e8"),
            vec!["building `high`", "`mass` = -1", "in [1, 1e9] (kg)"],
        ),
        (
            ROW.replace(
                "mass = 1e5\nstiffness = 1e8",
                "mass = 1e5\nstiffness = \"inf\"",
            ),
            vec![
                "building `high`",
                "`stiffness` = inf",
                "in [100, 1e13] (N/m)",
            ],
        ),
        (
            ROW.replace("yield_drift = 0.01", "yield_drift = 0"),
            vec!["building `low`", "`yield_drift` = 0", "≥ 1e-5 (m)"],
        ),
        (
            format!("{ROW}[[joint]]\ngap = 0.01\nstiffness = 1e10\n"),
            vec!["2 [[joint]] tables for 2 buildings", "must be 1"],
        ),
        (
            ROW.replace("storeys = 3", "storeys = 201"),
            vec!["building `high`", "`storeys` = 201", "1 to 200"],
        ),
        (
            ROW.replace("storeys = 3", "storeys = 0"),
            vec!["`storeys` = 0", "1 to 200"],
        ),
        (
            ROW.replace("height = 3\nyield_drift", "heigth = 3\nyield_drift"),
            vec!["building `low`", "unknown key `heigth`"],
        ),
        (
            ROW.replace("gap = 0.01", "gap = 0.01\nwidth = 2"),
            vec!["joint1", "unknown key `width`"],
        ),
        // Two buildings of one name would make `--set NAME.KEY`, `--drift
        // NAME:…` and the pairs of the output ambiguous.
        (
            ROW.replace("name = \"high\"", "name = \"low\""),
            vec!["building 2: `name` = \"low\": building 1 has this name already"],
        ),
        // Physical ranges: a storey of 1e-300 m, a period of a microsecond,
        // a restitution of 1e-10 (each ran without end, or gave drift
        // ratios of 1e297).
        (
            ROW.replace("height = 3\nyield_drift", "height = 1e-300\nyield_drift"),
            vec!["building `low`", "`height` = 1e-300", "in [0.1, 100] (m)"],
        ),
        (
            ROW.replace("stiffness = [2e8, 1e8]", "stiffness = [1e13, 1e13]")
                .replace(
                    "name = \"low\"\nstoreys = 2\nmass = 1e5",
                    "name = \"low\"\nstoreys = 2\nmass = 1",
                ),
            vec![
                "building `low`",
                "`mass` and `stiffness` give a shortest period",
                "[0.001, 100] s",
            ],
        ),
        (
            format!("restitution = 1e-10\n{ROW}"),
            vec!["`restitution` = 1e-10", "in [0.001, 1]"],
        ),
    ];
    for (i, (text, fragments)) in cases.iter().enumerate() {
        let path = write(&dir, &format!("bad{i}.toml"), text);
        let mut all = fragments.clone();
        all.push(&path);
        fails(&["run", "--buildings", &path], 2, &all);
    }
    // Eleven buildings.
    let mut many = String::from("model = \"kelvin\"\n");
    for i in 0..11 {
        many += &format!("[[building]]\nname = \"b{i}\"\nstoreys = 1\nmass = 1\nstiffness = 1\n");
    }
    for _ in 0..10 {
        many += "[[joint]]\ngap = 0.01\nstiffness = 1\n";
    }
    let path = write(&dir, "many.toml", &many);
    fails(
        &["run", "--buildings", &path],
        2,
        &["11 [[building]] tables", "1 to 10"],
    );
    // --set names the building and joint it edits.
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame",
            "--set",
            "frame.mass=[1, 2]",
        ],
        2,
        &["building `frame`", "`mass` has 2 values", "list of 8"],
    );
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame",
            "--set",
            "joint1.stiffness=-5",
        ],
        2,
        &["joint1", "`stiffness` = -5"],
    );
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame",
            "--set",
            "tower.mass=1",
        ],
        2,
        &["no building named `tower`"],
    );
    // A contact stiffness of 1e300 N/m ran and printed 300-digit floor
    // accelerations and a NaN energy balance with exit 0; it is beyond what
    // the solvers resolve, and refused with the largest allowed here.
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame",
            "--set",
            "joint1.stiffness=1e300",
        ],
        2,
        &[
            "presets/buildings/block-and-frame.toml: joint1: `stiffness` = 1e300: must be at most 1.875e15 here",
            "floors block 1 – frame 1",
            "1e5 rad/s",
        ],
    );
    // Two buildings named alike through --set.
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame",
            "--set",
            "frame.name=\"block\"",
        ],
        2,
        &["building 2: `name` = \"block\": building 1 has this name already"],
    );
    // A long Newmark step is refused at once, with the limit and what
    // sets it (it stopped at 6.29 s as a failed run, exit 1, "more than 10⁸
    // events"): 20 steps per the 18.4 ms period of the contact
    // element at the block's roof, √(k̄/m̄) with m̄ = 4e5·3e5/7e5 kg.
    let m_bar = 4e5 * 3e5 / 7e5;
    let contact_period = std::f64::consts::TAU / (2e10f64 / m_bar).sqrt();
    assert!((contact_period / 20.0 - 9.198e-4).abs() < 1e-7);
    for dt in ["10", "0.002"] {
        fails(
            &[
                "run",
                "--buildings",
                "block-and-frame",
                "--method",
                "newmark",
                "--dt",
                dt,
            ],
            2,
            &[
                &format!("--dt `{dt}`: must be <= 0.0009198 s on this row"),
                "20 steps per shortest period, 0.0184 s of the contact of block 3 – frame 3",
            ],
        );
    }
    // Under a record, its sample interval bounds the step too: a Hertz
    // law has no contact period, so the 5 ms of the record sets it.
    fails(
        &[
            "run",
            "--buildings",
            "two-buildings",
            "--model",
            "hertz",
            "--method",
            "newmark",
            "--excitation",
            "synthetic:400",
            "--dt",
            "0.006",
        ],
        2,
        &["--dt `0.006`: must be <= 0.005 s on this row (the record's sample interval"],
    );
    // A history's columns are the pair's: asked of a row, it is refused,
    // not silently dropped, and nothing is written.
    let history = dir.path().join("h.csv");
    let shown = history.display().to_string();
    fails(
        &["run", "--buildings", "two-buildings", "--history", &shown],
        2,
        &[&format!("--history {shown}: not with run --buildings")],
    );
    assert!(!history.exists(), "no history file is written for a row");
    // Just inside the limit, the run runs.
    let v = json(&[
        "run",
        "--buildings",
        "block-and-frame",
        "--method",
        "newmark",
        "--dt",
        "0.0009",
        "--format",
        "json",
    ]);
    assert_eq!(v["method"], "newmark");
    assert!(v["impacts"].as_u64().unwrap() > 0, "{v}");
    // Work beyond the commands' bound (a tail of 1e7 s, a Newmark step of
    // 1 ns) is refused at once, never a wait without end.
    let block = ["--buildings", "block-and-frame"];
    for (what, extra) in [
        ("run --buildings", vec!["run", "--tail", "1e7"]),
        (
            "run --buildings",
            vec!["run", "--method", "newmark", "--dt", "1e-9"],
        ),
        ("gap --buildings", vec!["gap", "--tail", "1e7"]),
        ("bench --buildings", vec!["bench", "--tail", "1e6"]),
    ] {
        let mut args = extra.clone();
        args.extend(block);
        fails(&args, 2, &[what, "--allow-long"]);
    }
}

/// Every cycloidal pulse of SPEC §9 runs on a row; the type B pulse says
/// that the floors start moving against the ground; an option that makes no
/// sense for the row's motion (cycles of a pulse, the amplitude or period
/// of a record, a pulse the pair does not have) is one line and exit 2.
#[test]
fn rows_take_every_pulse() {
    for pulse in ["pulse-a", "pulse-b", "pulse-c1", "pulse-c2"] {
        let v = json(&[
            "run",
            "--buildings",
            "block-and-frame",
            "--excitation",
            pulse,
            "--amplitude",
            "0.5g",
            "--format",
            "json",
        ]);
        assert_eq!(v["excitation"], pulse);
        assert!(v["impacts"].as_u64().unwrap() > 0, "{pulse}");
        assert!(v["energy"]["residual"].as_f64().unwrap() < 1e-9, "{pulse}");
        let note = v.get("excitation_note").and_then(|n| n.as_str());
        if pulse == "pulse-b" {
            // V_p = a_p/ω_p = 0.5 g/(2π/1 s).
            let vp = 0.5 * 9.80665 / (2.0 * std::f64::consts::PI);
            assert!(note.unwrap().contains(&format!("{vp:.6}")), "{note:?}");
            let top = v["buildings"][1]["floors"][7]["peak_velocity"]
                .as_f64()
                .unwrap();
            assert!(top >= vp * (1.0 - 1e-12), "{top} < {vp}");
        } else {
            assert!(note.is_none(), "{pulse}: {note:?}");
        }
    }
    let row = ["run", "--buildings", "block-and-frame"];
    for (extra, fragments) in [
        (
            vec!["--excitation", "pulse-b", "--cycles", "3"],
            vec!["--cycles `3`", "only a sine", "pulse-b", "--tail"],
        ),
        (
            vec!["--excitation", "pulse-c3"],
            vec!["`pulse-c3`", "pulse-c1, pulse-c2"],
        ),
        (
            vec!["--excitation", "pulse-b", "--period", "0"],
            vec!["--period 0", "> 0"],
        ),
        (
            vec!["--excitation", "pulse-c1", "--amplitude=-1g"],
            vec!["--amplitude `-1g`", "> 0"],
        ),
        (
            vec!["--excitation", "synthetic:200", "--amplitude", "0.3g"],
            vec!["--amplitude `0.3g`", "own units", "--scale"],
        ),
        (
            vec![
                "--excitation",
                "record:presets/synthetic.at2",
                "--period",
                "2",
            ],
            vec!["--period `2`", "sine or a pulse"],
        ),
    ] {
        let mut args = row.to_vec();
        args.extend(extra);
        fails(&args, 2, &fragments);
    }
}

#[test]
fn gap_lists_each_joint_beside_the_code_rules() {
    let v = json(&[
        "gap",
        "--buildings",
        "three-in-series",
        "--excitation",
        "record:presets/synthetic.at2",
        "--format",
        "json",
    ]);
    let joints = v["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 2);
    for j in joints {
        let g = j["min_gap"].as_f64().unwrap();
        let abs = j["abs"].as_f64().unwrap();
        let srss = j["srss"].as_f64().unwrap();
        let ddc = j["ddc"].as_f64().unwrap();
        assert!(g > 0.0 && g <= abs + 1e-12, "{j}");
        assert!(ddc <= srss && srss <= abs, "{j}");
    }
}

#[test]
fn figure_buildings_writes_envelopes_and_impact_forces() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("row.svg");
    let out = out.to_string_lossy().into_owned();
    common::succeeds(&[
        "figure",
        "buildings",
        "--buildings",
        "block-and-frame",
        "--excitation",
        "record:presets/synthetic.at2",
        "--out",
        &out,
    ]);
    let svg = std::fs::read_to_string(&out).unwrap();
    for title in [
        "peak floor displacement",
        "peak storey drift ratio",
        "peak floor acceleration",
        "impact forces",
        "frame apart",
    ] {
        assert!(svg.contains(title), "{title}");
    }
    fails(
        &[
            "figure",
            "buildings",
            "--buildings",
            "block-and-frame",
            "--out",
            "x.gif",
        ],
        2,
        &["--out x.gif", ".svg or .png"],
    );
}

/// `run --buildings … --no-pounding` is the row with every joint open: no
/// impact, and the same peaks as `--set jointN.gap=inf` on each joint; `gap`
/// and `figure`, which make that run themselves, refuse it in one line.
#[test]
fn no_pounding_opens_every_joint() {
    let base = [
        "run",
        "--buildings",
        "three-in-series",
        "--excitation",
        "record:presets/synthetic.at2",
        "--format",
        "json",
    ];
    let pounding = json(&base);
    assert!(pounding["impacts"].as_u64().unwrap() > 0);
    let free = json(&[&base[..], &["--no-pounding"]].concat());
    let open = json(
        &[
            &base[..],
            &["--set", "joint1.gap=inf", "--set", "joint2.gap=inf"],
        ]
        .concat(),
    );
    assert_eq!(free["impacts"].as_u64(), Some(0));
    assert_eq!(free["buildings"], open["buildings"]);
    assert_ne!(free["buildings"], pounding["buildings"]);
    for command in [
        vec!["gap", "--buildings", "block-and-frame", "--no-pounding"],
        vec![
            "figure",
            "buildings",
            "--buildings",
            "block-and-frame",
            "--no-pounding",
            "--out",
            "f.svg",
        ],
    ] {
        fails(
            &command,
            2,
            &["--no-pounding: not with", "drop --no-pounding"],
        );
    }
}
