//! `pounding map --buildings ROW --suite …` end to end (SPEC §12, §14): a
//! cell is `pounding suite --buildings ROW --set X=x --set Y=y`, bit for
//! bit, in every quantity it reports; its link forces are those of
//! `pounding run` on each record; bad axes are refused with one line.

mod common;

use common::{fails, json, stdout, succeeds};
use serde_json::Value;

const ROW: [&str; 8] = [
    "--buildings",
    "block-and-frame-retrofit",
    "--suite",
    "synthetic:5@3",
    "--level",
    "0.3",
    "--format",
    "json",
];

fn map(x: &str, y: &str) -> Value {
    let mut args = vec!["map", "--x", x, "--y", y];
    args.extend(ROW);
    json(&args)
}

/// numpy's median of `v` (linear between the order statistics), as SPEC
/// §12 defines it.
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let h = (v.len() - 1) as f64 * 0.5;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(v.len() - 1);
    if v[lo] == v[hi] || h == lo as f64 {
        return v[lo];
    }
    v[lo] + (h - lo as f64) * (v[hi] - v[lo])
}

#[test]
fn a_cell_is_the_suite_with_its_two_sets() {
    let m = map(
        "link1.damping=2e6:6e6:4e6",
        "joint1.bumper.thickness=0.002:0.004:0.001",
    );
    let cells = m["cells"].as_array().unwrap();
    assert_eq!(cells.len(), 6);
    assert_eq!(m["buildings"], serde_json::json!(["block", "frame"]));
    assert_eq!(m["links"], serde_json::json!(["link1"]));
    // Row 1 (thickness 3 mm), column 1 (c = 6e6).
    let cell = &cells[3];
    assert_eq!(
        (cell["x"].as_f64(), cell["y"].as_f64()),
        (Some(6e6), Some(0.003))
    );
    let mut args = vec![
        "suite",
        "--set",
        "link1.damping=6e6",
        "--set",
        "joint1.bumper.thickness=0.003",
    ];
    args.extend(ROW);
    let s = json(&args);
    let records = s["records"].as_array().unwrap();
    let pounded = records
        .iter()
        .filter(|r| r["joints"][0]["impacts"].as_u64().unwrap() > 0)
        .count();
    assert_eq!(
        cell["pounding_probability"][0].as_f64().unwrap(),
        pounded as f64 / 5.0
    );
    let stat = |name: &str| -> f64 {
        s["statistics"]["demands"]
            .as_array()
            .unwrap()
            .iter()
            .find(|d| d["demand"] == name)
            .unwrap_or_else(|| panic!("{name}"))["median"]
            .as_f64()
            .unwrap()
    };
    for (b, name) in ["block", "frame"].iter().enumerate() {
        // Bit for bit: the same runs and the same statistics.
        assert_eq!(
            cell["median_drift_ratio"][b].as_f64().unwrap(),
            stat(&format!("{name}.max_drift_ratio")),
            "{name}"
        );
        assert_eq!(
            cell["median_acceleration_g"][b].as_f64().unwrap(),
            stat(&format!("{name}.max_absolute_acceleration_g")),
            "{name}"
        );
    }
    // The link's force: each record run alone, at the suite's scale.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    succeeds(&[
        "records", "synth", "--count", "5", "--seed", "3", "--out", out,
    ]);
    let forces: Vec<f64> = records
        .iter()
        .map(|r| {
            let name = r["record"].as_str().unwrap();
            let scale = r["scale"].as_f64().unwrap().to_string();
            let path = format!("record:{out}/{name}.at2");
            let run = json(&[
                "run",
                "--buildings",
                "block-and-frame-retrofit",
                "--set",
                "link1.damping=6e6",
                "--set",
                "joint1.bumper.thickness=0.003",
                "--excitation",
                &path,
                "--scale",
                &scale,
                "--format",
                "json",
            ]);
            assert_eq!(
                run["impacts"].as_u64(),
                r["impacts"].as_u64(),
                "{name}: the same run"
            );
            run["links"][0]["max_force_kn"].as_f64().unwrap()
        })
        .collect();
    assert_eq!(
        cell["median_link_force_kn"][0].as_f64().unwrap(),
        median(forces)
    );
}

#[test]
fn more_damping_lowers_the_frame_and_raises_the_link_force() {
    // The physics the map is for: a stiffer dashpot across the joint
    // carries more force and holds the flexible frame back (SPEC §14).
    let m = map("link1.damping=1e6:9e6:8e6", "joint1.gap=0.005:0.005:1");
    let cells = m["cells"].as_array().unwrap();
    let (weak, strong) = (&cells[0], &cells[1]);
    let get = |c: &Value, k: &str, i: usize| c[k][i].as_f64().unwrap();
    assert!(get(strong, "median_link_force_kn", 0) > 1.5 * get(weak, "median_link_force_kn", 0));
    assert!(get(strong, "median_drift_ratio", 1) < get(weak, "median_drift_ratio", 1));
}

#[test]
fn csv_has_one_line_per_cell_and_quantity() {
    let o = succeeds(&[
        "map",
        "--buildings",
        "block-and-frame-retrofit",
        "--suite",
        "synthetic:2@3",
        "--level",
        "0.3",
        "--x",
        "link1.damping=2e6:4e6:2e6",
        "--y",
        "frame.damping=0.05:0.05:1",
        "--format",
        "csv",
    ]);
    let text = stdout(&o);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "version,units,x,y,quantity,of,value,records,measure"
    );
    // 2 cells × (1 joint + 2 × 2 buildings + 1 link).
    assert_eq!(lines.len(), 1 + 2 * 6);
    assert!(
        lines[1].contains(",pounding_probability,joint1,"),
        "{}",
        lines[1]
    );
    assert!(
        lines[6].contains(",median_link_force_kn,link1,"),
        "{}",
        lines[6]
    );
}

#[test]
fn bad_axes_are_refused_with_one_line() {
    let base = [
        "map",
        "--buildings",
        "block-and-frame-retrofit",
        "--suite",
        "synthetic:2",
        "--level",
        "0.3",
    ];
    let cases: [(&str, &str, &[&str]); 6] = [
        // An unknown key.
        (
            "joint1.gapp=0.01:0.02:0.01",
            "link1.damping=1e6:2e6:1e6",
            &["--x", "gapp"],
        ),
        // A key that is not a number.
        (
            "frame.name=1:2:1",
            "link1.damping=1e6:2e6:1e6",
            &["--x", "name"],
        ),
        // Out of the key's range: a bumper thicker than the gap.
        (
            "link1.damping=1e6:2e6:1e6",
            "joint1.bumper.thickness=0.004:0.006:0.001",
            &["--y", "thickness"],
        ),
        // A link with k = c = 0.
        (
            "link1.damping=0:2e6:1e6",
            "joint1.gap=0.005:0.006:0.001",
            &["--x", "damping"],
        ),
        // Both axes on one key.
        (
            "joint1.gap=0.005:0.006:0.001",
            "joint1.gap=0.005:0.006:0.001",
            &["both set `joint1.gap`"],
        ),
        // Not a grid.
        (
            "link1.damping=1e6",
            "joint1.gap=0.005:0.006:0.001",
            &["--x", "KEY=START:STOP:STEP"],
        ),
    ];
    for (x, y, says) in cases {
        let mut args = base.to_vec();
        args.extend(["--x", x, "--y", y]);
        fails(&args, 2, says);
    }
    // A cell whose two values clash: the bumper is thicker than the gap.
    let mut args = base.to_vec();
    args.extend([
        "--x",
        "joint1.gap=0.004:0.006:0.002",
        "--y",
        "joint1.bumper.thickness=0.0045:0.0045:1",
    ]);
    fails(
        &args,
        2,
        &[
            "cell joint1.gap=0.004, joint1.bumper.thickness=0.0045",
            "(0, 0.004]",
        ],
    );
    // --buildings needs a suite.
    fails(
        &[
            "map",
            "--buildings",
            "block-and-frame-retrofit",
            "--x",
            "joint1.gap=0.01:0.02:0.01",
            "--y",
            "link1.damping=1e6:2e6:1e6",
        ],
        2,
        &["--buildings", "--suite"],
    );
}
