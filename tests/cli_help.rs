//! The help texts describe the tool as it is: every ground motion, every
//! contact law and both methods, and clap's own consistency checks pass
//! (unique flags per command).

mod common;

use clap::CommandFactory;
use common::{stdout, succeeds};
use pounding::cli::Cli;
use pounding::model::ContactModel;

/// `pounding --help` names every excitation, contact law and method.
#[test]
fn top_help_names_excitations_laws_and_methods() {
    let text = stdout(&succeeds(&["--help"]));
    let first = text.lines().next().unwrap();
    let laws = ContactModel::ALL.map(|m| m.name());
    let others = [
        "sine",
        "pulses",
        "AT2",
        "columns",
        "Newmark-β",
        "exact event-driven",
    ];
    for word in laws.iter().chain(&others) {
        assert!(first.contains(word), "`{word}` missing from: {first}");
    }
    assert!(!first.contains("sinusoidal ground acceleration"), "{first}");
}

/// The first sentence of `pounding --help` names what the tool studies
/// beyond the pair: rows of buildings, suites of records and the risk of
/// pounding; the short `-h` says so too.
#[test]
fn top_help_first_sentence_names_rows_suites_and_risk() {
    for flag in ["--help", "-h"] {
        let text = stdout(&succeeds(&[flag]));
        let first = text.lines().next().unwrap();
        let sentence = first.split(". ").next().unwrap();
        for word in ["SDOF", "rows of", "buildings", "suites", "risk"] {
            assert!(
                sentence.contains(word),
                "{flag}: `{word}` missing from: {sentence}"
            );
        }
    }
}

/// Each simulating command's options name every law, excitation and method.
#[test]
fn command_help_names_every_choice() {
    for command in ["run", "spectrum", "map", "gap", "similarity", "figure"] {
        let text = stdout(&succeeds(&[command, "--help"]));
        for word in [
            "hunt-crossley",
            "jankowski",
            "pulse-c2",
            ".AT2",
            "plain columns",
            "newmark",
            "exact",
        ] {
            assert!(text.contains(word), "{command} --help lacks `{word}`");
        }
    }
}

/// Clap's debug checks (unique ids and flags, valid defaults) hold for
/// every command; a release build skips them at run time.
#[test]
fn the_command_line_is_consistent() {
    Cli::command().debug_assert();
}

/// Each option appears once in a command's help (`figure` listed
/// `--method` twice, its own and the shared one).
#[test]
fn no_option_is_listed_twice() {
    for command in [
        "run",
        "spectrum",
        "map",
        "gap",
        "similarity",
        "figure",
        "bench",
        "stress",
    ] {
        let text = stdout(&succeeds(&[command, "--help"]));
        let mut seen = std::collections::BTreeSet::new();
        for line in text.lines() {
            let Some(flag) = line.trim_start().strip_prefix("--") else {
                continue;
            };
            let flag = flag.split([' ', '=']).next().unwrap();
            assert!(seen.insert(flag.to_string()), "{command}: --{flag} twice");
        }
    }
}
