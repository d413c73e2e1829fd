//! Bad input never hangs, panics or prints more than one line: the real
//! binary on every input-validation finding of the hardening review, then
//! on generated hostile inputs (every key of the parameter table × hostile
//! values, malformed presets, grids and families). Each run must end within
//! [`LIMIT`] (the child is killed otherwise), exit 0 or 2, never 101, and on
//! exit 2 print exactly one line naming the key or the file.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use pounding::model::params::{FIELDS, Kind};

mod common;

/// Longest any one run may take.
const LIMIT: Duration = Duration::from_secs(10);

#[derive(Debug)]
struct Outcome {
    code: Option<i32>,
    stderr: String,
    timed_out: bool,
}

static COUNTER: AtomicUsize = AtomicUsize::new(0);

fn scratch() -> PathBuf {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("pounding-robust-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the binary with `args`, stdout discarded, killed after [`LIMIT`].
fn pounding(args: &[String]) -> Outcome {
    let dir = scratch();
    let err_path = dir.join("stderr");
    let err_file = std::fs::File::create(&err_path).unwrap();
    let mut child = Command::new(common::BIN)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(err_file)
        .spawn()
        .expect("binary starts");
    let start = Instant::now();
    let (code, timed_out) = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break (status.code(), false);
        }
        if start.elapsed() > LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            break (None, true);
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let stderr = String::from_utf8_lossy(&std::fs::read(&err_path).unwrap()).into_owned();
    let _ = std::fs::remove_dir_all(&dir);
    Outcome {
        code,
        stderr,
        timed_out,
    }
}

fn strings(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| s.to_string()).collect()
}

/// One case: arguments, the exit codes allowed, and what the error line must contain.
struct Case {
    args: Vec<String>,
    codes: &'static [i32],
    names: Vec<String>,
}

/// Checks one outcome; returns why it broke the promise, if it did.
fn verdict(case: &Case, o: &Outcome) -> Result<(), String> {
    if o.timed_out {
        return Err("did not finish within the limit".into());
    }
    let code = o.code.ok_or("killed by a signal")?;
    if code == 101 || o.stderr.contains("panicked") {
        return Err(format!("panicked: {}", o.stderr));
    }
    if !case.codes.contains(&code) {
        return Err(format!(
            "exit {code}, expected {:?}: {}",
            case.codes, o.stderr
        ));
    }
    if code == 2 {
        let lines: Vec<&str> = o.stderr.lines().collect();
        if lines.len() != 1 {
            return Err(format!(
                "{} lines on stderr: {:.300}",
                lines.len(),
                o.stderr
            ));
        }
        if lines[0].len() > 600 {
            return Err(format!("a {}-byte line", lines[0].len()));
        }
        if !case.names.iter().any(|n| lines[0].contains(n.as_str())) {
            return Err(format!("names none of {:?}: {}", case.names, lines[0]));
        }
    }
    Ok(())
}

/// Runs the cases on two threads; returns (tried, handled, count by exit code, failures).
fn run_all(cases: &[Case]) -> (usize, usize, [usize; 3], Vec<String>) {
    let next = AtomicUsize::new(0);
    let results: Vec<(usize, Option<i32>, Result<(), String>)> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..2)
            .map(|_| {
                s.spawn(|| {
                    let mut out = Vec::new();
                    loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        let Some(case) = cases.get(i) else { break };
                        let o = pounding(&case.args);
                        out.push((i, o.code, verdict(case, &o)));
                    }
                    out
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().unwrap())
            .collect()
    });
    let mut by_code = [0; 3];
    let mut failures = Vec::new();
    for (i, code, v) in &results {
        match code {
            Some(0) => by_code[0] += 1,
            Some(2) => by_code[1] += 1,
            _ => by_code[2] += 1,
        }
        if let Err(why) = v {
            let args: Vec<String> = cases[*i]
                .args
                .iter()
                .map(|a| a.chars().take(60).collect())
                .collect();
            failures.push(format!("{args:?}: {why}"));
        }
    }
    (
        results.len(),
        results.len() - failures.len(),
        by_code,
        failures,
    )
}

fn assert_all(label: &str, cases: Vec<Case>) {
    let (tried, handled, by_code, failures) = run_all(&cases);
    eprintln!(
        "{label}: tried {tried}, handled {handled}; exit 0: {}, exit 2: {}, other: {}",
        by_code[0], by_code[1], by_code[2]
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn bad(args: &[&str], names: &[&str]) -> Case {
    Case {
        args: strings(args),
        codes: &[2],
        names: strings(names),
    }
}

/// `run --set KEY=VALUE` refused with a line holding `says`.
fn bad_set(assignment: &str, says: &str) -> Case {
    bad(&["run", "--set", assignment], &[says])
}

/// A one-cycle `run` with `--set assignment`.
fn one_cycle_with(assignment: String) -> Vec<String> {
    vec![
        "run".into(),
        "--cycles".into(),
        "1".into(),
        "--set".into(),
        assignment,
    ]
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

#[test]
fn every_finding_is_a_clear_error() {
    let dir = scratch();
    let family_preset = write(
        &dir,
        "family.toml",
        "gap = 0.2\n[spectrum]\nmu = 1.5\nfamily = { dt = [1e-12] }\n",
    );
    let physical = write(
        &dir,
        "both.toml",
        &format!(
            "gap = 5.0\n{}",
            include_str!("../presets/two-buildings.toml")
                .lines()
                .filter(|l| !l.starts_with("name"))
                .collect::<Vec<_>>()
                .join("\n")
        ),
    );
    let bad_spectrum = write(&dir, "spec.toml", "[spectrum]\nmu = -1\n");
    let named_five = write(&dir, "five.toml", "name = 5\n");
    let tiny_dt = format!("dt=0.{}1", "0".repeat(300));
    let huge_key = write(
        &dir,
        "huge.toml",
        &format!("{} = 1\n", "k".repeat(1_000_000)),
    );
    // `run --set`: values that ran for ever, that printed nonsense with exit
    // 0, or that the message wrote wrongly (a line break, 300 zeros); the method key.
    let set_findings = [
        (
            "contact_omega=1e300",
            "`contact_omega` = 1e300: must be a number in [1, 1e6]",
        ),
        (
            "mass_ratio=1e300",
            "`mass_ratio` = 1e300: must be a number in [0.001, 1000]",
        ),
        (
            "restitution=1e-100",
            "`restitution` = 1e-100: must be a number in [0.001, 1]",
        ),
        ("mass_ratio=1e-320", "`mass_ratio` = 1e-320"),
        (
            "omega1=1e100",
            "`omega1` = 1e100: must be a number in [0, 1000]",
        ),
        (
            "dt=1e300",
            "`dt` = 1e300: must be a number in [1e-6, 0.3142]",
        ),
        ("dt=60", "`dt` = 60"),
        ("omega1=1e300", "`omega1` = 1e300"),
        ("contact_omega=1e15", "`contact_omega` = 1e15"),
        ("restitution=1e-20", "`restitution` = 1e-20"),
        ("gap=0.1\nmass_ratio=2", "`gap` = 0.1\\nmass_ratio=2"),
        (&tiny_dt, "`dt` = 1e-301"),
        (
            "method=rk4",
            "`method` = rk4: must be one of: newmark, exact",
        ),
    ];
    let mut cases: Vec<Case> = set_findings
        .iter()
        .map(|(assignment, says)| bad_set(assignment, says))
        .collect();
    cases.extend([
        bad(
            &["run", "--set", "omega2=30", "--dt", "0.1"],
            &["`dt` = 0.1: must be <= 0.01047"],
        ),
        bad(
            &["spectrum", "--omega1", "1e300:1e300:1"],
            &["`omega1` grid = 1e300:1e300:1"],
        ),
        bad(
            &[
                "spectrum", "--mu", "1000", "--omega1", "1:3:1", "--dt", "1e-5",
            ],
            &["`omega2` = 3000"],
        ),
        // Every path that sets a value validates it.
        bad(
            &["spectrum", "--family", "dt=1e-9"],
            &["--family: `dt` = 1e-9"],
        ),
        bad(
            &["spectrum", "--preset", &family_preset],
            &[&format!(
                "{family_preset}:4: [spectrum] family: `dt` = 1e-12"
            )],
        ),
        // Silently ignored input.
        bad(
            &["run", "--preset", &physical],
            &["`gap` and the [physical] table"],
        ),
        bad(
            &["run", "--preset", &bad_spectrum],
            &[&format!("{bad_spectrum}:2: [spectrum] `mu` = -1")],
        ),
        // Messages that named the wrong thing.
        bad(
            &["similarity", "--omega-p", "1e300"],
            &["--omega-p 1e300: must be a number in [0.01, 1000] (rad/s)"],
        ),
        bad(
            &["run", "--preset", &named_five],
            &[&format!("{named_five}:1: `name` = 5: must be a string")],
        ),
        bad(&["run", "--preset", &huge_key], &["(1000000 characters)"]),
        bad(&["run", "--repeat", "-1"], &["'--repeat <N>'"]),
        bad(
            &["similarity", "--ap", "-1", "--omega-p", "6"],
            &["--ap `-1`"],
        ),
        bad(&["similarity", "--omega-p", "-6"], &["--omega-p -6"]),
        bad(&["stress", "--cases", "-3"], &["'--cases <N>'"]),
        bad(&["stress", "--seed", "-3"], &["'--seed <S>'"]),
    ]);
    assert_all("findings", cases);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A FIFO among the user's presets is neither listed nor opened (opening it
/// would block until a writer came).
#[test]
fn a_fifo_in_the_presets_folder_does_not_block() {
    let dir = scratch();
    let fifo = dir.join("pipe.toml");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("mkfifo unavailable: skipped");
        return;
    }
    std::fs::write(dir.join("mine.toml"), "gap = 0.3\n").unwrap();
    assert_eq!(
        pounding::model::preset::user_preset_names(&dir),
        vec!["mine".to_string()]
    );
    let d = dir.display().to_string();
    let fifo = fifo.display().to_string();
    let cases = vec![
        bad(
            &["run", "--presets", &d, "--preset", "pipe"],
            &["no preset named `pipe`"],
        ),
        bad(&["run", "--preset", &fifo], &["no preset named"]),
        Case {
            args: strings(&["run", "--presets", &d, "--preset", "mine", "--cycles", "1"]),
            codes: &[0],
            names: vec![],
        },
    ];
    assert_all("fifo", cases);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Hostile values for any key.
fn hostile_values() -> Vec<String> {
    let mut v = strings(&[
        "NaN",
        "nan",
        "-NaN",
        "inf",
        "-inf",
        "infinity",
        "0",
        "-0",
        "-1",
        "-1e-300",
        "1e-320",
        "1e300",
        "1e309",
        "-1e300",
        "2.5",
        "4294967296",
        "",
        " ",
        "abc",
        "1e",
        "0x10",
        "1,5",
        "1_000",
        "１",
        "∞",
        "🙂",
        "\n",
        "0.5\n",
        "\t1",
        "1 2",
        "--",
        "=",
        "1e-6",
        "0.1",
        "1",
    ]);
    v.push("9".repeat(400));
    v.push("x".repeat(100_000));
    v
}

#[test]
fn generated_bad_inputs_are_handled() {
    let mut cases = Vec::new();
    // Every key of the table × every hostile value, as --set (run, 1 cycle).
    for f in FIELDS {
        for value in hostile_values() {
            cases.push(Case {
                args: one_cycle_with(format!("{}={value}", f.key)),
                codes: &[0, 2],
                names: vec![format!("`{}`", f.key)],
            });
        }
        // The ends of the stated range pass the key's own check (a run may
        // still refuse Δτ against the frequencies); just outside them fails it.
        if let Kind::Number { min, max, .. } = f.kind {
            for (v, codes) in [
                (min, &[0, 2][..]),
                (max, &[0, 2][..]),
                (min - (min.abs() * 1e-3).max(1e-300), &[2][..]),
                (max * 1.001, &[2][..]),
            ] {
                let codes: &'static [i32] = if codes.len() == 2 { &[0, 2] } else { &[2] };
                cases.push(Case {
                    args: one_cycle_with(format!("{}={v:e}", f.key)),
                    codes,
                    names: if codes.len() == 2 {
                        vec![format!("`{}` = {v:e}", f.key), "`dt`".into()]
                    } else {
                        vec![format!("`{}` = ", f.key)]
                    },
                });
            }
        }
    }
    // Keys that do not exist.
    for key in [
        "bogus",
        "",
        " ",
        "Mass_Ratio",
        "mass ratio",
        "μ",
        "\n",
        &"k".repeat(100_000),
    ] {
        cases.push(bad(
            &["run", "--set", &format!("{key}=1")],
            &["unknown parameter", "expected KEY=VALUE"],
        ));
    }
    // Malformed grids.
    for grid in [
        "",
        "1",
        "1:2",
        "1:2:3:4",
        "a:b:c",
        "3:1:0.1",
        "0.1:3:0",
        "0.1:3:-1",
        "-1:3:0.1",
        "0.1:inf:0.1",
        "NaN:1:0.1",
        "0.1:1e300:1",
        "0.1:3:1e-9",
        "1e300:1e300:1",
        "0.1:3000:1",
        "\n:1:1",
    ] {
        cases.push(bad(&["spectrum", "--omega1", grid], &["`omega1` grid"]));
    }
    // Malformed families.
    for family in [
        "",
        "=",
        "gap",
        "gap=",
        "gap=,",
        "gap=0.2,,1",
        "omega1=1,2",
        "omega2=1",
        "mu=0",
        "mu=-1",
        "mu=inf",
        "mu=NaN",
        "bogus=1",
        "dt=1e-9",
        "dt=60",
        "restitution=0,1",
        "contact_omega=1e300",
        "model=hertz-mindlin",
        "method=rk4",
        "cycles=0",
        "gap=\n",
    ] {
        cases.push(bad(
            &["spectrum", "--omega1", "1:1.1:0.1", "--family", family],
            &["--family"],
        ));
    }
    // Malformed presets, written to a temporary folder.
    let dir = scratch();
    let presets: Vec<&str> = vec![
        "=",
        "gap = = 1",
        "gap = [1, 2]",
        "gap = { a = 1 }",
        "gap = \"abc\"",
        "gap = -1",
        "gap = nan",
        "cycles = 2.5",
        "cycles = -1",
        "cycles = 1e10",
        "model = 1",
        "model = \"hertz-mindlin\"",
        "method = \"rk4\"",
        "name = 5",
        "description = []",
        "bogus = 1",
        "[spectrum]\nmu = -1",
        "[spectrum]\nomega1 = 5",
        "[spectrum]\nomega1 = \"1e300:1e300:1\"",
        "[spectrum]\nfamily = { dt = [1e-12] }",
        "[spectrum]\nfamily = { gap = [0.2], mu = [1] }",
        "[spectrum]\nfamily = \"gap\"",
        "[spectrum]\nbogus = 1",
        "[spectrum]\nmu = 1000",
        "spectrum = 5",
        "[physical]\nm1 = 1",
        "gap = 5\n[physical]\nm1 = 1",
        "[physical]\nbogus = 1",
        "\u{0}",
        "gap = 0.2\ngap = 0.3",
        "dt = 0.3\nomega2 = 30",
    ];
    for (i, text) in presets.iter().enumerate() {
        let path = write(&dir, &format!("p{i}.toml"), text);
        cases.push(bad(&["run", "--preset", &path], &[&path]));
    }
    // Binary garbage.
    let garbage: Vec<u8> = (0..4096u32)
        .map(|i| (i.wrapping_mul(2654435761) >> 24) as u8)
        .collect();
    let path = dir.join("garbage.toml");
    std::fs::write(&path, garbage).unwrap();
    let path = path.display().to_string();
    cases.push(bad(&["run", "--preset", &path], &[&path]));
    assert!(cases.len() >= 200, "{} generated inputs", cases.len());
    assert_all("generated", cases);
    std::fs::remove_dir_all(&dir).unwrap();
}
