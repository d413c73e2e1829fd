//! `pounding suite|ida|gap --buildings` end to end (SPEC §12, §13): a suite
//! record is bit for bit `run --buildings --excitation record:PATH --scale
//! s`; the IDA's fragility and the separation per joint come with the
//! report's own records; bad input exits 2 with one line naming the flag,
//! the value and what is allowed.

mod common;

use common::{fails, json, pounding, succeeds};

/// A directory of three simulated records, as `records synth` writes them.
fn records() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    succeeds(&["records", "synth", "--count", "3", "--out", out]);
    dir
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The largest of `key` over a building's floors in `run --buildings` JSON.
fn largest(building: &serde_json::Value, key: &str) -> f64 {
    building["floors"]
        .as_array()
        .unwrap()
        .iter()
        .map(|fl| f(&fl[key]).abs())
        .fold(0.0, f64::max)
}

#[test]
fn a_suite_record_is_run_buildings_with_its_scale_bit_for_bit() {
    let dir = records();
    let suite = dir.path().to_str().unwrap();
    let v = json(&[
        "suite",
        "--buildings",
        "block-and-frame",
        "--suite",
        suite,
        "--level",
        "0.25",
        "--format",
        "json",
    ]);
    assert_eq!(v["preset"], "block-and-frame");
    assert_eq!(v["method"], "exact");
    let rows = v["records"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    for r in rows {
        let path = dir.path().join(r["record"].as_str().unwrap());
        // The scale as JSON writes it reads back as the same float.
        let scale = r["scale"].to_string();
        let run = json(&[
            "run",
            "--buildings",
            "block-and-frame",
            "--excitation",
            &format!("record:{}", path.display()),
            "--scale",
            &scale,
            "--format",
            "json",
        ]);
        assert_eq!(f(&r["duration_s"]).to_bits(), f(&run["duration"]).to_bits());
        assert_eq!(r["impacts"], run["impacts"]);
        for (b, mine) in run["buildings"]
            .as_array()
            .unwrap()
            .iter()
            .zip(r["buildings"].as_array().unwrap())
        {
            assert_eq!(b["name"], mine["name"]);
            for (theirs, ours) in [
                ("drift_ratio", "max_drift_ratio"),
                ("peak_absolute_acceleration", "max_absolute_acceleration_g"),
                ("residual_drift", "max_residual_drift_m"),
            ] {
                assert_eq!(
                    largest(b, theirs).to_bits(),
                    f(&mine[ours]).to_bits(),
                    "{} {ours}",
                    mine["name"]
                );
            }
        }
        let force = run["pairs"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| f(&p["max_force"]))
            .fold(0.0, f64::max);
        assert_eq!(
            force.to_bits(),
            f(&r["joints"][0]["max_force_kn"]).to_bits()
        );
        assert!(f(&r["joints"][0]["min_gap"]) > 0.005, "it pounds at 5 mm");
    }
    let names: Vec<&str> = v["statistics"]["demands"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["demand"].as_str().unwrap())
        .collect();
    for key in [
        "block.max_drift_ratio",
        "frame.max_absolute_acceleration_g",
        "no_pounding.frame.max_residual_drift_m",
        "joint1.max_force_kn",
        "joint1.min_gap_m",
    ] {
        assert!(names.contains(&key), "{key} in {names:?}");
    }
}

#[test]
fn ida_fits_each_limit_state_on_the_counts_of_its_records() {
    let v = json(&[
        "ida",
        "--buildings",
        "block-and-frame",
        "--suite",
        "synthetic:4",
        "--levels",
        "0.1:0.4:0.1",
        "--drift",
        "0.005,frame:0.01",
        "--acceleration",
        "block:2g",
        "--force",
        "20000",
        "--building",
        "frame",
        "--format",
        "json",
    ]);
    let labels: Vec<&str> = v["fragility"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["limit_state"].as_str().unwrap())
        .collect();
    assert_eq!(
        labels,
        [
            "pounding (frame)",
            "drift>0.005 (frame)",
            "drift>0.01 (frame)",
            "acceleration>2g (block)",
            "force>20000kN (frame)"
        ]
    );
    // The counts are the report's own records'.
    let levels = v["levels"].as_array().unwrap();
    for (l, level) in levels.iter().enumerate() {
        let exceeded = level["records"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|r| f(&r["buildings"][1]["max_drift_ratio"]) > 0.005)
            .count();
        assert_eq!(v["fragility"][1]["counts"][l]["exceeded"], exceeded);
        assert_eq!(v["fragility"][1]["counts"][l]["runs"], 4);
    }
    assert!(v["fragility"][0].get("no_pounding_counts").is_none());
    assert_eq!(v["limit_states"][2]["kind"], "drift");
    assert_eq!(v["limit_states"][2]["building"], "frame");
    assert_eq!(v["limit_states"][2]["ratio"], 0.01);
    // A level is the suite at that level, record for record.
    let suite = json(&[
        "suite",
        "--buildings",
        "block-and-frame",
        "--suite",
        "synthetic:4",
        "--level",
        "0.3",
        "--format",
        "json",
    ]);
    assert_eq!(levels[2]["records"], suite["records"]);
}

#[test]
fn gap_per_joint_at_a_probability_is_the_order_statistic() {
    let v = json(&[
        "gap",
        "--buildings",
        "three-in-series",
        "--suite",
        "synthetic:5",
        "--level",
        "0.2",
        "--probability",
        "0.5,0.9",
        "--format",
        "json",
    ]);
    let joints = v["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 2);
    for (j, joint) in joints.iter().enumerate() {
        let mut gaps: Vec<f64> = v["records"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| f(&r["joints"][j]["min_gap"]))
            .collect();
        gaps.sort_by(f64::total_cmp);
        // ⌈0.5·5⌉ = 3rd, ⌈0.9·5⌉ = 5th.
        let at = &joint["study"]["at_probability"];
        assert_eq!(f(&at[0]["empirical"]).to_bits(), gaps[2].to_bits());
        assert_eq!(f(&at[1]["empirical"]).to_bits(), gaps[4].to_bits());
        let rules: Vec<&str> = joint["study"]["rules"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["rule"].as_str().unwrap())
            .collect();
        assert_eq!(rules, ["ABS", "SRSS", "DDC"]);
    }
    let csv = succeeds(&[
        "gap",
        "--buildings",
        "three-in-series",
        "--suite",
        "synthetic:5",
        "--level",
        "0.2",
        "--format",
        "csv",
    ]);
    // A header, then a line per record and joint.
    assert_eq!(String::from_utf8_lossy(&csv.stdout).lines().count(), 1 + 10);
}

#[test]
fn tables_print_and_csv_has_a_line_per_building_and_joint() {
    let args = [
        "suite",
        "--buildings",
        "block-and-frame",
        "--suite",
        "synthetic:2",
        "--im",
        "sa",
        "--level",
        "0.5",
    ];
    let table = String::from_utf8_lossy(&succeeds(&args).stdout).into_owned();
    assert!(
        table.contains("each record scaled to sa:0.2874 = 0.5 g"),
        "{table}"
    );
    assert!(table.contains("joint1.min_gap_m"), "{table}");
    let csv = succeeds(&[&args[..], &["--format", "csv"]].concat());
    // Two records, each two buildings and one joint.
    assert_eq!(String::from_utf8_lossy(&csv.stdout).lines().count(), 1 + 6);
    let ida = succeeds(&[
        "ida",
        "--buildings",
        "two-buildings",
        "--suite",
        "synthetic:2",
        "--levels",
        "0.1,0.2",
        "--drift",
        "0.01",
    ]);
    assert!(String::from_utf8_lossy(&ida.stdout).contains("drift>0.01 (any)"));
}

#[test]
fn bad_input_is_one_line_naming_the_flag_and_what_is_allowed() {
    fn ida<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let mut a = vec![
            "ida",
            "--buildings",
            "block-and-frame",
            "--suite",
            "synthetic:2",
            "--levels",
            "0.1,0.2",
        ];
        a.extend(extra);
        a
    }
    fails(
        &ida(&["--drift", "0.01,0"]),
        2,
        &["--drift `0`", "drift ratio in (0, 1)"],
    );
    fails(&ida(&["--drift", "1.5"]), 2, &["--drift `1.5`"]);
    fails(
        &ida(&["--building", "tower"]),
        2,
        &["--building `tower`", "(block, frame) or any"],
    );
    fails(
        &ida(&["--force", "tower:500"]),
        2,
        &["--force `tower:500`", "block, frame"],
    );
    fails(&ida(&["--ductility", "2"]), 2, &["--ductility", "--drift"]);
    fails(
        &ida(&["--acceleration=-1g"]),
        2,
        &["--acceleration `-1g`", "> 0"],
    );
    fails(
        &[
            "ida",
            "--preset",
            "two-buildings",
            "--suite",
            "synthetic:2",
            "--levels",
            "0.1",
            "--drift",
            "0.01",
        ],
        2,
        &["--drift", "--buildings"],
    );
    fn suite<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let mut a = vec![
            "suite",
            "--buildings",
            "block-and-frame",
            "--suite",
            "synthetic:2",
        ];
        a.extend(extra);
        a
    }
    fails(
        &suite(&["--method", "newmark"]),
        2,
        &["--method newmark", "exact"],
    );
    fails(
        &suite(&["--preset", "set1"]),
        2,
        &["--preset", "--buildings"],
    );
    fails(&suite(&["--im", "sa:20"]), 2, &["--im", "(0, 10]"]);
    fails(&suite(&["--level", "0"]), 2, &["--level 0"]);
    fails(
        &["suite", "--buildings", "nowhere", "--suite", "synthetic:2"],
        2,
        &["nowhere", "block-and-frame"],
    );
    fails(
        &[
            "gap",
            "--buildings",
            "block-and-frame",
            "--probability",
            "0.5",
        ],
        2,
        &["--probability", "--suite"],
    );
    fails(
        &[
            "gap",
            "--buildings",
            "block-and-frame",
            "--suite",
            "synthetic:2",
            "--probability",
            "1",
        ],
        2,
        &["--probability `1`", "between 0 and 1"],
    );
    fails(
        &[
            "gap",
            "--buildings",
            "block-and-frame",
            "--suite",
            "synthetic:2",
            "--scale",
            "2",
        ],
        2,
        &["--scale", "drop --scale"],
    );
}

#[test]
fn long_work_needs_allow_long_and_is_refused_before_any_run() {
    let start = std::time::Instant::now();
    let o = fails(
        &[
            "ida",
            "--buildings",
            "three-in-series",
            "--suite",
            "synthetic:100",
            "--levels",
            "0.01:10:0.01",
        ],
        2,
        &["ida --buildings", "--allow-long"],
    );
    assert!(o.stdout.is_empty());
    assert!(start.elapsed().as_secs() < 30, "refused at once");
    // Within the bound it runs.
    let o = pounding(&[
        "suite",
        "--buildings",
        "two-buildings",
        "--suite",
        "synthetic:1",
    ]);
    assert!(o.status.success());
}

/// A row's separation study writes each top-level key of its JSON once:
/// the joints are the study's entries, each naming its buildings and gap
/// (a parser that kept the first of two `joints` would lose the study).
#[test]
fn gap_suite_json_names_each_key_once() {
    #[derive(serde::Deserialize)]
    struct Top {
        buildings: Vec<serde_json::Value>,
        joints: Vec<serde_json::Value>,
        records: Vec<serde_json::Value>,
    }
    let out = succeeds(&[
        "gap",
        "--buildings",
        "three-in-series",
        "--suite",
        "synthetic:3",
        "--level",
        "0.2",
        "--format",
        "json",
    ]);
    // serde refuses a struct's field given twice.
    let top: Top = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((top.buildings.len(), top.records.len()), (3, 3));
    assert_eq!(top.joints.len(), 2);
    for j in &top.joints {
        assert!(j["left"].is_string() && j["gap_m"].as_f64().unwrap() > 0.0);
        assert!(j["study"]["at_probability"].is_array(), "{j}");
    }
}
