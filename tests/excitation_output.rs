//! Every summary names its excitation (SPEC §9), and the type B pulse's
//! initial velocity is said in `run`'s table, JSON and CSV.

mod common;

use common::{json, stdout, succeeds};

const SAYS: &str = "both structures start with ẋ(0) = −1";

#[test]
fn run_names_the_excitation_and_pulse_b_its_initial_velocity() {
    let base = ["run", "--excitation", "pulse-b", "--cycles", "2"];
    let table = stdout(&succeeds(&base));
    assert!(table.contains("pulse-b excitation"), "{table}");
    assert!(table.contains(SAYS), "{table}");
    let v = json(&[&base[..], &["--format", "json"]].concat());
    assert_eq!(v["excitation"], "pulse-b");
    assert!(v["excitation_note"].as_str().unwrap().contains(SAYS));
    let csv = stdout(&succeeds(&[&base[..], &["--format", "csv"]].concat()));
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row = lines.next().unwrap();
    let column = |key: &str| header.iter().position(|h| *h == key).unwrap();
    assert_eq!(row.split(',').nth(column("excitation")), Some("pulse-b"));
    // The note is the one column after the parameters.
    assert!(
        row.contains(",the ground starts with velocity V_p: both"),
        "{row}"
    );
    assert_eq!(column("excitation_note"), column("min_impact_velocity") + 1);
    // The sine says its name and nothing more.
    let v = json(&["run", "--cycles", "1", "--format", "json"]);
    assert_eq!(v["excitation"], "sine");
    assert!(v.get("excitation_note").is_none());
}

#[test]
fn spectrum_names_the_excitation() {
    let spectrum = [
        "spectrum",
        "--excitation",
        "pulse-a",
        "--omega1",
        "0.5:1.0:0.5",
        "--cycles",
        "1",
    ];
    let table = stdout(&succeeds(&spectrum));
    assert!(table.contains("pulse-a excitation"), "{table}");
    let v = json(&[&spectrum[..], &["--format", "json"]].concat());
    assert_eq!(v["excitation"], "pulse-a");
}

#[test]
fn map_json_names_the_excitation() {
    let v = json(&[
        "map",
        "--excitation",
        "pulse-b",
        "--x",
        "omega1=0.5:1.0:0.5",
        "--y",
        "gap=0.1:0.2:0.1",
        "--cycles",
        "1",
        "--format",
        "json",
    ]);
    assert_eq!(v["excitation"], "pulse-b");
    assert!(v["excitation_note"].as_str().unwrap().contains(SAYS));
}
