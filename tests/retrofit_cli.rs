//! The retrofit keys of a row preset (SPEC §14) on the command line: bad
//! values are one line and exit 2, naming the file, the joint or link, the
//! key, the value and what is allowed; `--set` reaches a bumper's and a
//! link's keys; `run --buildings` reports each bumper and link, and a row
//! without a retrofit says nothing of them.

mod common;

use common::{fails, json};

const ROW: &str = "model = \"improved-kelvin\"\n\
    [[building]]\nname = \"low\"\nstoreys = 2\nmass = 1e5\nstiffness = [2e8, 1e8]\nheight = 3\n\
    [[building]]\nname = \"high\"\nstoreys = 3\nmass = 1e5\nstiffness = 1e8\nheight = 3\n\
    [[joint]]\ngap = 0.01\nstiffness = 1e10\n\
    bumper = { thickness = 0.005, stiffness = 1e8, restitution = 0.8 }\n\
    [[link]]\njoint = 1\nfloor = 2\nstiffness = 1e6\ndamping = 1e5\nexponent = 1.0\n";

#[test]
fn bad_retrofit_values_exit_2_with_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            ROW.replace("thickness = 0.005", "thickness = 0.02"),
            vec!["joint1: bumper `thickness` = 0.02", "(0, 0.01]"],
        ),
        (
            ROW.replace("thickness = 0.005", "thickness = 0"),
            vec!["joint1: bumper `thickness` = 0", "(0, 0.01]"],
        ),
        (
            ROW.replace(
                "stiffness = 1e8, restitution",
                "stiffness = -1, restitution",
            ),
            vec!["joint1: bumper `stiffness` = -1", "finite number > 0"],
        ),
        (
            ROW.replace(
                "stiffness = 1e8, restitution",
                "stiffness = \"inf\", restitution",
            ),
            vec!["joint1: bumper `stiffness` = inf", "finite number > 0"],
        ),
        (
            ROW.replace("restitution = 0.8", "restitution = 1.5"),
            vec!["joint1: bumper `restitution` = 1.5", "[0.001, 1]"],
        ),
        (
            ROW.replace("restitution = 0.8", "restitution = 0"),
            vec!["joint1: bumper `restitution` = 0", "[0.001, 1]"],
        ),
        (
            ROW.replace("restitution = 0.8", "restitution = 0.8, floors = [3]"),
            vec![
                "joint1: bumper `floors` holds 3",
                "building `low` has no floor 3",
            ],
        ),
        (
            ROW.replace("restitution = 0.8", "restitution = 0.8, colour = 1"),
            vec![
                "joint1: bumper unknown key `colour`",
                "thickness, stiffness",
            ],
        ),
        (
            ROW.replace("joint = 1\n", "joint = 2\n"),
            vec!["link1: `joint` = 2", "from 1 to 1"],
        ),
        (
            ROW.replace("floor = 2\n", "floor = 3\n"),
            vec!["link1: `floor` = 3", "from 1 to 2", "building `low`"],
        ),
        (
            ROW.replace(
                "height = 3\n[[building]]",
                "height = [3, 3.5]\n[[building]]",
            ),
            vec![
                "link1: `floor` = 2",
                "has no floor of `high` at its elevation",
            ],
        ),
        (
            ROW.replace("stiffness = 1e6\n", "stiffness = -1\n"),
            vec!["link1: `stiffness` = -1", "finite number ≥ 0 (N/m)"],
        ),
        (
            ROW.replace("damping = 1e5\n", "damping = -2\n"),
            vec!["link1: `damping` = -2", "finite number ≥ 0"],
        ),
        (
            ROW.replace(
                "stiffness = 1e6\ndamping = 1e5\n",
                "stiffness = 0\ndamping = 0\n",
            ),
            vec![
                "link1: `stiffness` = 0 and `damping` = 0",
                "one of them > 0",
            ],
        ),
        (
            ROW.replace("exponent = 1.0", "exponent = 1.5"),
            vec!["link1: `exponent` = 1.5", "(0, 1]"],
        ),
        (
            ROW.replace("exponent = 1.0", "exponent = 0"),
            vec!["link1: `exponent` = 0", "(0, 1]"],
        ),
        (
            ROW.replace("exponent = 1.0", "exponent = 1.0\nstroke = 1"),
            vec!["link1: unknown key `stroke`", "joint, floor"],
        ),
    ];
    for (i, (text, fragments)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("r{i}.toml"));
        std::fs::write(&path, text).unwrap();
        let file = path.to_string_lossy().into_owned();
        let mut want = vec![file.as_str()];
        want.extend(fragments);
        fails(&["run", "--buildings", &file], 2, &want);
    }
    // `--set` meets the same checks.
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame-retrofit",
            "--set",
            "link1.exponent=2",
        ],
        2,
        &[
            "presets/buildings/block-and-frame-retrofit.toml: link1: `exponent` = 2",
            "(0, 1]",
        ],
    );
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame-retrofit",
            "--set",
            "joint1.bumper.thickness=0.01",
        ],
        2,
        &["joint1: bumper `thickness` = 0.01", "(0, 0.005]"],
    );
    fails(
        &[
            "run",
            "--buildings",
            "block-and-frame-retrofit",
            "--set",
            "link7.damping=1",
        ],
        2,
        &["--set `link7.damping=1`", "no link `link7`"],
    );
}

#[test]
fn run_reports_each_bumper_and_link() {
    let v = json(&[
        "run",
        "--buildings",
        "block-and-frame-retrofit",
        "--set",
        "link1.damping=2e6",
        "--format",
        "json",
    ]);
    let bumpers = v["bumpers"].as_array().expect("bumpers");
    assert_eq!(bumpers.len(), 3, "{v}");
    assert!(
        bumpers.iter().any(|b| b["contacts"].as_u64().unwrap() > 0),
        "{v}"
    );
    let links = v["links"].as_array().expect("links");
    assert_eq!(links.len(), 1);
    assert_eq!(links[0]["floors"], "block 3 – frame 3");
    assert!(links[0]["max_force_kn"].as_f64().unwrap() > 0.0);
    assert!(links[0]["energy_kj"].as_f64().unwrap() > 0.0);
    assert!(v["energy"]["residual"].as_f64().unwrap() < 1e-9, "{v}");
    // Without a retrofit the report has no such keys.
    let bare = json(&["run", "--buildings", "block-and-frame", "--format", "json"]);
    assert!(bare.get("bumpers").is_none() && bare.get("links").is_none());
    assert!(bare["energy"].get("link").is_none(), "{bare}");
}
