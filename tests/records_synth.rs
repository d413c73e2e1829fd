//! `pounding records synth` (SPEC §12): the files it writes read back bit
//! for bit as the in-memory suite `synthetic:N@SEED`, the same seed gives the
//! same bytes, record j does not depend on N, and bad flags exit 2 naming
//! the flag, the value and the range.

mod common;

use std::fs;
use std::path::Path;

use common::{fails, succeeds};
use pounding::model::record::Record;
use pounding::model::suite::{SuiteMember, SuiteSpec};

fn synth(dir: &Path, count: &str, seed: &str) {
    succeeds(&[
        "records",
        "synth",
        "--count",
        count,
        "--seed",
        seed,
        "--out",
        dir.to_str().unwrap(),
    ]);
}

fn load(spec: &str) -> Vec<SuiteMember> {
    SuiteSpec::parse(spec).unwrap().load().unwrap()
}

/// Every number of a record, as bits.
fn bits(r: &Record) -> Vec<u64> {
    [r.dt, r.peak, r.dominant_omega()]
        .iter()
        .chain(&r.acceleration)
        .chain(&r.velocity)
        .chain(&r.displacement)
        .map(|v| v.to_bits())
        .collect()
}

#[test]
fn files_read_back_bit_for_bit_as_the_suite_in_memory() {
    let dir = tempfile::tempdir().unwrap();
    synth(dir.path(), "3", "5");
    let memory = load("synthetic:3@5");
    let from_dir = load(dir.path().to_str().unwrap());
    let from_list = load(dir.path().join("suite.txt").to_str().unwrap());
    assert_eq!(memory.len(), 3);
    for ((m, d), l) in memory.iter().zip(&from_dir).zip(&from_list) {
        assert_eq!(bits(&m.record), bits(&d.record), "{} vs {}", m.name, d.name);
        assert_eq!(bits(&m.record), bits(&l.record));
        assert_eq!((m.scale, d.scale, l.scale), (1.0, 1.0, 1.0));
    }
    assert_eq!(from_dir[0].name, "synthetic-001.at2");
    assert_eq!(memory[2].name, "synthetic-003");
    assert_eq!(memory[0].record.acceleration.len(), 2001);
}

#[test]
fn the_same_seed_gives_the_same_bytes_and_record_j_ignores_n() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    synth(a.path(), "2", "9");
    synth(b.path(), "4", "9");
    for name in ["synthetic-001.at2", "synthetic-002.at2"] {
        let (x, y) = (
            fs::read(a.path().join(name)).unwrap(),
            fs::read(b.path().join(name)).unwrap(),
        );
        assert_eq!(x, y, "{name}");
    }
    assert_ne!(
        fs::read(a.path().join("synthetic-001.at2")).unwrap(),
        fs::read(a.path().join("synthetic-002.at2")).unwrap()
    );
    // synthetic:2@9 is a prefix of synthetic:4@9.
    let (two, four) = (load("synthetic:2@9"), load("synthetic:4@9"));
    assert_eq!(bits(&two[1].record), bits(&four[1].record));
    // Written again over itself: the same bytes.
    let before = fs::read(a.path().join("synthetic-002.at2")).unwrap();
    synth(a.path(), "2", "9");
    assert_eq!(
        fs::read(a.path().join("synthetic-002.at2")).unwrap(),
        before
    );
}

#[test]
fn clough_penzien_and_other_parameters_are_stated_in_the_header() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    succeeds(&[
        "records",
        "synth",
        "--count",
        "1",
        "--out",
        out,
        "--filter",
        "clough-penzien",
        "--duration",
        "5",
        "--dt",
        "0.005",
        "--pga",
        "0.5",
    ]);
    let text = fs::read_to_string(dir.path().join("synthetic-001.at2")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[1].contains("Clough-Penzien"), "{}", lines[1]);
    assert!(lines[1].contains("PGA 0.5 g"), "{}", lines[1]);
    assert_eq!(lines[3], "NPTS= 1001, DT= 0.005 SEC");
    let members = load(dir.path().to_str().unwrap());
    assert!((members[0].record.peak / 9.80665 - 0.5).abs() < 1e-12);
    // Not the default parameters: the list does not claim synthetic:1@1.
    let list = fs::read_to_string(dir.path().join("suite.txt")).unwrap();
    assert!(!list.contains("synthetic:1@"), "{list}");
}

#[test]
fn bad_flags_exit_2_naming_the_flag_value_and_range() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    let base = ["records", "synth", "--count", "2", "--out", out];
    let cases: [(&[&str], &[&str]); 7] = [
        (&["--zeta-g", "-1"], &["--zeta-g -1", "(0, 5]"]),
        (&["--omega-g", "0"], &["--omega-g 0", "rad/s"]),
        (&["--pga", "11"], &["--pga 11", "(0, 10] g"]),
        (&["--dt", "0.5"], &["--dt 0.5", "(0, 0.1] s"]),
        (&["--duration", "0"], &["--duration 0", "(0, 600] s"]),
        (
            &["--filter", "clough-penzien", "--zeta-f", "9"],
            &["--zeta-f 9", "(0, 5]"],
        ),
        (&["--dt", "abc"], &["--dt", "abc"]),
    ];
    for (extra, fragments) in cases {
        fails(&[&base[..], extra].concat(), 2, fragments);
    }
    fails(
        &["records", "synth", "--count", "0", "--out", out],
        2,
        &["--count 0", "[1, 1000]"],
    );
    let missing = dir.path().join("missing");
    let missing = missing.to_str().unwrap();
    fails(
        &["records", "synth", "--count", "1", "--out", missing],
        2,
        &["--out", missing, "must exist"],
    );
    // Nothing was written by the refusals.
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn a_target_that_is_not_a_regular_file_is_refused_before_any_write() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("synthetic-002.at2")).unwrap();
    fails(
        &[
            "records",
            "synth",
            "--count",
            "2",
            "--out",
            dir.path().to_str().unwrap(),
        ],
        1,
        &["synthetic-002.at2", "not a regular file"],
    );
    assert!(!dir.path().join("synthetic-001.at2").exists());
    assert!(!dir.path().join("suite.txt").exists());
}
