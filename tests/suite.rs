//! Suites of records (SPEC §12): a list file with scales, comments and paths
//! relative to it; a directory in name order; `synthetic:N@SEED`; and every
//! malformed suite refused with one line naming the file and the line.

use std::fs;
use std::path::Path;

use pounding::model::suite::{SuiteError, SuiteSpec};

const AT2: &str = "PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic\n\
ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    4, DT=   .0200 SEC\n\
0.0 0.1 -0.2 0.05\n";

const ZERO: &str = "PEER NGA STRONG MOTION DATABASE RECORD\nsilent\n\
ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    3, DT=   .0200 SEC\n\
0.0 0.0 0.0\n";

fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

fn error(spec: &str) -> SuiteError {
    match SuiteSpec::parse(spec) {
        Ok(s) => s.load().unwrap_err(),
        Err(e) => e,
    }
}

#[test]
fn a_list_file_with_scales_comments_and_relative_paths() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("records")).unwrap();
    write(&dir.path().join("records"), "a.AT2", AT2);
    write(dir.path(), "b.csv", "0,0.1\n0.02,0.2\n0.04,0\n");
    write(dir.path(), "c.txt", "0 1\n0.01 -2\n");
    let list = write(
        dir.path(),
        "list.txt",
        "# three records\n\nrecords/a.AT2 2.5\n  b.csv\t0.5   \n# units after @\nc.txt@m/s2\n",
    );
    let spec = SuiteSpec::parse(&list).unwrap();
    assert!(matches!(spec, SuiteSpec::List(_)));
    let members = spec.load().unwrap();
    let names: Vec<&str> = members.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["records/a.AT2", "b.csv", "c.txt@m/s2"]);
    let scales: Vec<f64> = members.iter().map(|m| m.scale).collect();
    assert_eq!(scales, [2.5, 0.5, 1.0]);
    assert_eq!(members[2].record.acceleration, [1.0, -2.0]);
    assert!(members.iter().all(|m| !m.is_silent()));
}

#[test]
fn a_directory_in_name_order_skipping_hidden_files_and_the_list() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "b.at2", AT2);
    write(dir.path(), "a.txt", AT2);
    write(dir.path(), ".hidden", "not a record");
    write(dir.path(), "suite.txt", "not read\n");
    fs::create_dir(dir.path().join("sub")).unwrap();
    let members = SuiteSpec::parse(dir.path().to_str().unwrap())
        .unwrap()
        .load()
        .unwrap();
    let names: Vec<&str> = members.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["a.txt", "b.at2"]);
    assert_eq!(
        members[0].record.acceleration,
        members[1].record.acceleration
    );
}

#[test]
fn a_silent_record_is_detected() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "zero.at2", ZERO);
    let members = SuiteSpec::parse(dir.path().to_str().unwrap())
        .unwrap()
        .load()
        .unwrap();
    assert!(members[0].is_silent());
    assert!(members[0].record.is_silent());
}

#[test]
fn malformed_suites_name_the_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "a.at2", AT2);
    let bad_scale = write(dir.path(), "s1.txt", "# c\na.at2 2\na.at2 -1\n");
    let e = error(&bad_scale);
    assert_eq!(e.line, 3, "{e}");
    assert!(
        e.to_string()
            .starts_with(&format!("suite `{bad_scale}` line 3: scale `-1`")),
        "{e}"
    );
    let e = error(&write(dir.path(), "s2.txt", "a.at2 x\n"));
    assert!(
        e.to_string()
            .contains("line 1: scale `x`: must be a number in (0, 1000]"),
        "{e}"
    );
    let e = error(&write(dir.path(), "s3.txt", "\n\nmissing.at2\n"));
    assert!(e.to_string().contains("line 3: record `"), "{e}");
    assert!(
        e.to_string().contains("missing.at2`: cannot be read"),
        "{e}"
    );
    let e = error(&write(dir.path(), "s4.txt", "a.at2 1 extra\n"));
    assert!(
        e.to_string().contains("line 1: expected `PATH [SCALE]`"),
        "{e}"
    );
    let e = error(&write(dir.path(), "s5.txt", "# only a comment\n"));
    assert!(e.to_string().contains("names no record"), "{e}");
    // A record in a listed file is malformed: both lines are named.
    write(dir.path(), "broken.at2", &AT2.replace("-0.2", "-0.2x"));
    let e = error(&write(dir.path(), "s6.txt", "a.at2\nbroken.at2\n"));
    assert!(e.to_string().contains("line 2: record `"), "{e}");
    assert!(
        e.to_string()
            .contains("broken.at2` line 5: `-0.2x` is not a number"),
        "{e}"
    );
    // A record given as the suite itself.
    let e = error(&dir.path().join("a.at2").to_string_lossy());
    assert!(e.to_string().contains("is a record, not a suite"), "{e}");
    // An empty directory, a missing path, a directory with a bad file.
    let empty = dir.path().join("empty");
    fs::create_dir(&empty).unwrap();
    let e = error(empty.to_str().unwrap());
    assert!(e.to_string().contains("holds no record file"), "{e}");
    let e = error(&dir.path().join("nowhere").to_string_lossy());
    assert!(
        e.to_string()
            .contains("No such file or directory; must be a directory"),
        "{e}"
    );
    // Notes beside the records are skipped; notes alone are no suite; a
    // malformed record is an error naming it and its line.
    let mixed = dir.path().join("mixed");
    fs::create_dir(&mixed).unwrap();
    write(&mixed, "notes.md", "# notes\nsome text, no samples\n");
    let e = error(mixed.to_str().unwrap());
    assert!(e.to_string().contains("holds no record file"), "{e}");
    write(&mixed, "quake.csv", "0,0.1\n0.01,0.2\n");
    let members = SuiteSpec::parse(mixed.to_str().unwrap())
        .unwrap()
        .load()
        .unwrap();
    assert_eq!(members.len(), 1);
    assert_eq!(members[0].name, "quake.csv");
    write(&mixed, "broken.csv", "0,0.1\n0.01,0.2\n0.02,oops\n");
    let e = error(mixed.to_str().unwrap());
    assert!(e.to_string().contains("broken.csv` line 3"), "{e}");
    assert!(!e.to_string().contains('\n'), "{e}");
}

#[test]
fn synthetic_suites_and_their_bounds() {
    assert_eq!(
        SuiteSpec::parse("synthetic:4").unwrap(),
        SuiteSpec::Synthetic { count: 4, seed: 1 }
    );
    assert_eq!(
        SuiteSpec::parse("synthetic:4@7").unwrap().to_string(),
        "synthetic:4@7"
    );
    let e = error("synthetic:5000");
    assert_eq!(
        e.to_string(),
        "suite `synthetic:5000`: the count `5000` must be a whole number in [1, 1000]"
    );
    let e = error("synthetic:3@seven");
    assert!(e.to_string().contains("the seed `seven`"), "{e}");
}
