//! Row presets with random, possibly hostile values of every key of
//! `[[building]]` (P-Δ's among them) and `[[joint]]` (and the row's own
//! keys): every case ends
//! in a finite result or a one-line refusal (exit 2), never a panic, a
//! hang, a failed run or a non-finite number. The cases run through the
//! command's own path (`run --buildings`: the preset's checks, the work
//! bound, the run, the report's audit and its JSON), called as a library
//! rather than as a process, under a short sine so that each takes
//! milliseconds.

use proptest::prelude::*;

use pounding::cli::CliError;
use pounding::cli::buildings::{BuildingsArgs, run};
use pounding::cli::output::{Emit, Format};
use pounding::cli::params::ParamArgs;

/// A value no key takes, or one at or past the edge of every range.
fn hostile() -> BoxedStrategy<String> {
    prop_oneof![
        Just("0".to_string()),
        Just("-1".to_string()),
        Just("1e-300".to_string()),
        Just("1e300".to_string()),
        Just("5e-324".to_string()),
        Just("inf".to_string()),
        Just("-inf".to_string()),
        Just("nan".to_string()),
        Just("\"inf\"".to_string()),
        Just("\"abc\"".to_string()),
        Just("[]".to_string()),
        Just("true".to_string()),
        Just("{ a = 1 }".to_string()),
        (-300i32..300).prop_map(|e| format!("1e{e}")),
        (-300i32..300).prop_map(|e| format!("-3.7e{e}")),
    ]
    .boxed()
}

/// A number in `10^[lo, hi]`, mostly; now and then a hostile value.
fn number(lo: f64, hi: f64) -> BoxedStrategy<String> {
    prop_oneof![
        40 => (lo..=hi).prop_map(|e| format!("{:e}", 10f64.powf(e))),
        1 => hostile(),
    ]
    .boxed()
}

/// A number in `[lo, hi]`, mostly; now and then a hostile value.
fn plain(lo: f64, hi: f64) -> BoxedStrategy<String> {
    prop_oneof![
        40 => (lo..=hi).prop_map(|x| format!("{x:?}")),
        1 => hostile(),
    ]
    .boxed()
}

/// A per-storey key: one number for every storey, or a list (of the right
/// length mostly, of a wrong one now and then).
fn per_storey(value: BoxedStrategy<String>, storeys: usize) -> BoxedStrategy<String> {
    prop_oneof![
        12 => value.clone(),
        8 => prop::collection::vec(value.clone(), storeys).prop_map(|v| format!("[{}]", v.join(", "))),
        1 => prop::collection::vec(value, 0..6).prop_map(|v| format!("[{}]", v.join(", "))),
    ]
    .boxed()
}

/// `key = value`, or the key left out (its default, or "missing key").
fn entry(key: &'static str, value: BoxedStrategy<String>) -> BoxedStrategy<String> {
    prop_oneof![
        40 => value.prop_map(move |v| format!("{key} = {v}\n")),
        1 => Just(String::new()),
    ]
    .boxed()
}

fn building(index: usize) -> BoxedStrategy<String> {
    let storeys = prop_oneof![
        60 => (1usize..=4).prop_map(|n| (n, n.to_string())),
        1 => Just((2, "0".to_string())),
        1 => Just((2, "201".to_string())),
        1 => Just((2, "2.5".to_string())),
        1 => Just((2, "\"3\"".to_string())),
        1 => Just((2, "-1".to_string())),
    ];
    let name = prop_oneof![
        40 => Just(format!("\"b{index}\"")),
        1 => Just("\"b0\"".to_string()),
        1 => Just("\"\"".to_string()),
        1 => Just("7".to_string()),
    ];
    (storeys, name)
        .prop_flat_map(|((n, storeys), name)| {
            (
                entry("mass", per_storey(number(3.0, 6.0), n)),
                entry("stiffness", per_storey(number(6.0, 10.0), n)),
                entry("height", per_storey(plain(2.0, 5.0), n)),
                entry(
                    "yield_drift",
                    per_storey(
                        prop_oneof![4 => number(-3.0, -1.0), 1 => Just("\"inf\"".to_string())]
                            .boxed(),
                        n,
                    ),
                ),
                entry("alpha", plain(0.0, 0.3)),
                entry("damping", plain(0.0, 0.2)),
                // P-Δ (SPEC §15), in two buildings of five: θ from small to
                // past 1, gravity masses up to ten times a floor's.
                prop_oneof![
                    3 => Just(String::new()),
                    2 => (
                        entry(
                            "p_delta",
                            prop_oneof![
                                8 => Just("true".to_string()),
                                1 => Just("false".to_string()),
                                1 => hostile(),
                            ]
                            .boxed(),
                        ),
                        entry("gravity_mass", per_storey(number(3.0, 7.0), n)),
                        entry("collapse_drift_ratio", plain(0.01, 0.3)),
                    )
                        .prop_map(|(p, g, c)| format!("{p}{g}{c}")),
                ],
            )
                .prop_map(move |(m, k, h, y, a, d, pd)| {
                    format!(
                        "[[building]]\nname = {name}\nstoreys = {storeys}\n{m}{k}{h}{y}{a}{d}{pd}"
                    )
                })
        })
        .boxed()
}

fn joint() -> BoxedStrategy<String> {
    (
        entry(
            "gap",
            prop_oneof![4 => plain(0.0, 0.1), 1 => Just("\"inf\"".to_string())].boxed(),
        ),
        entry("stiffness", number(6.0, 12.0)),
    )
        .prop_map(|(g, k)| format!("[[joint]]\n{g}{k}"))
        .boxed()
}

/// A whole preset: the row's keys, one to three buildings and (mostly) one
/// joint per neighbouring pair.
fn preset() -> impl Strategy<Value = String> {
    let model = prop_oneof![
        6 => Just("\"kelvin\""),
        6 => Just("\"improved-kelvin\""),
        6 => Just("\"hertz\""),
        6 => Just("\"hertzdamp\""),
        6 => Just("\"jankowski\""),
        6 => Just("\"hunt-crossley\""),
        1 => Just("\"springy\""),
    ];
    (
        1usize..=3,
        prop_oneof![40 => Just(0i32), 1 => Just(1), 1 => Just(-1)],
    )
        .prop_flat_map(move |(n, extra)| {
            let joints = (n as i32 - 1 + extra).max(0) as usize;
            (
                model.clone(),
                entry("restitution", plain(0.1, 1.0)),
                entry("min_impact_velocity", number(-4.0, -2.0)),
                (0..n).map(building).collect::<Vec<_>>(),
                prop::collection::vec(joint(), joints),
            )
                .prop_map(|(model, e, v, buildings, joints)| {
                    format!(
                        "model = {model}\n{e}{v}{}{}",
                        buildings.join(""),
                        joints.join("")
                    )
                })
        })
}

/// What a case ended in.
enum Outcome {
    Ran(serde_json::Value),
    Refused(String),
}

/// `run --buildings FILE --period 0.5 --cycles 1 --tail 0.3 --format json`.
fn run_preset(text: &str) -> Result<Outcome, String> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("row.toml");
    std::fs::write(&path, text).unwrap();
    let args = BuildingsArgs {
        buildings: Some(path.to_string_lossy().into_owned()),
        period: Some(0.5),
        tail: Some(0.3),
        ..BuildingsArgs::default()
    };
    let params = ParamArgs {
        cycles: Some("1".into()),
        ..ParamArgs::default()
    };
    let mut json = None;
    let outcome = run(&args, &params, 1, false, |r: &dyn Emit| {
        json = Some(r.render(Format::Json)?);
        Ok(())
    });
    match outcome {
        Ok(()) => {
            let text = json.ok_or("no report")?;
            Ok(Outcome::Ran(
                serde_json::from_str(&text).map_err(|e| e.to_string())?,
            ))
        }
        Err(CliError::Usage(m)) => Ok(Outcome::Refused(m)),
        Err(e) => Err(format!("exit {}: {e}", e.exit_code())),
    }
}

/// Every number of a report, with its path; the strings `inf`, `-inf` and
/// `nan` are the non-finite values a report marks as possible. A null is a
/// NaN serde_json could not write, but for `collapsed`, which a row with
/// P-Δ reports as null when no building collapsed (SPEC §15).
fn non_finite(v: &serde_json::Value, path: &str, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Null if path == ".collapsed" => {}
        serde_json::Value::Null => out.push(format!("{path} = null")),
        serde_json::Value::String(s) if s == "nan" || s == "-inf" => {
            out.push(format!("{path} = {s}"))
        }
        serde_json::Value::Array(items) => {
            for (i, x) in items.iter().enumerate() {
                non_finite(x, &format!("{path}[{i}]"), out);
            }
        }
        serde_json::Value::Object(map) => {
            for (k, x) in map {
                non_finite(x, &format!("{path}.{k}"), out);
            }
        }
        _ => {}
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    #[test]
    fn every_preset_runs_finite_or_is_refused_in_one_line(text in preset()) {
        match run_preset(&text) {
            Ok(Outcome::Ran(report)) => {
                let mut bad = Vec::new();
                non_finite(&report, "", &mut bad);
                prop_assert!(bad.is_empty(), "{bad:?}\n{text}");
                prop_assert!(report["buildings"].as_array().is_some_and(|b| !b.is_empty()));
            }
            Ok(Outcome::Refused(message)) => {
                prop_assert!(!message.contains('\n'), "{message}");
                prop_assert!(message.chars().count() < 400, "{message}");
            }
            Err(failed) => prop_assert!(false, "{failed}\n{text}"),
        }
    }
}

/// The strategy reaches both ends: some presets run, some are refused.
#[test]
fn the_cases_include_runs_and_refusals() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let (mut ran, mut refused) = (0, 0);
    for _ in 0..40 {
        let text = preset().new_tree(&mut runner).unwrap().current();
        match run_preset(&text) {
            Ok(Outcome::Ran(_)) => ran += 1,
            Ok(Outcome::Refused(_)) => refused += 1,
            Err(e) => panic!("{e}\n{text}"),
        }
    }
    eprintln!("ran {ran}, refused {refused}");
    assert!(ran >= 5 && refused >= 5, "ran {ran}, refused {refused}");
}
