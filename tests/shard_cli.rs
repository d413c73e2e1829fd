//! Sharded sweeps end to end: for every command that takes `--shard`, the
//! merge of all N shards (N = 1, 2, 3, 7) is the unsharded output byte for
//! byte but for its timing; `merge` refuses parts of different requests,
//! a shard given twice, a missing shard and a truncated part, naming the
//! files and shard numbers; bad `--shard` values are one line and exit 2.

mod common;

use std::path::Path;
use std::process::{Command, Stdio};

use common::{BIN, fails, stderr, stdout, succeeds};

/// `text` with its timing fields blanked: the number of `"elapsed_ms":…`
/// and the digits before ` ms` (a table's time).
fn untimed(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(i) = rest.find("\"elapsed_ms\":") {
        let (head, tail) = rest.split_at(i + "\"elapsed_ms\":".len());
        out.push_str(head);
        out.push('T');
        rest = tail.trim_start_matches(|c: char| c.is_ascii_digit() || ".e+-".contains(c));
    }
    out.push_str(rest);
    let mut blanked = String::new();
    for line in out.lines() {
        let cut = line
            .strip_suffix(" ms")
            .map(|l| l.trim_end_matches(|c: char| c.is_ascii_digit()));
        blanked.push_str(
            cut.map_or(line.to_string(), |l| format!("{l}T ms"))
                .as_str(),
        );
        blanked.push('\n');
    }
    blanked
}

/// Runs `args` as `n` shards into `dir`, then merges them; the merge's stdout.
fn sharded(args: &[&str], n: usize, dir: &Path) -> String {
    let template = dir.join("p-{k}-of-{n}.part");
    let mut parts = Vec::new();
    // Last to first: the order the tasks run in does not matter.
    for k in (1..=n).rev() {
        let shard = format!("{k}/{n}");
        let mut a: Vec<&str> = args.to_vec();
        a.extend(["--shard", &shard, "--part", template.to_str().unwrap()]);
        let o = succeeds(&a);
        assert!(
            o.stdout.is_empty(),
            "a shard prints nothing: {}",
            stdout(&o)
        );
        parts.push(dir.join(format!("p-{k}-of-{n}.part")));
    }
    let mut m = vec!["merge".to_string()];
    m.extend(parts.iter().map(|p| p.to_str().unwrap().to_string()));
    stdout(&succeeds(&m))
}

/// The merge of every N equals the unsharded output of `args` in `formats`.
fn merges_equal(args: &[&str], formats: &[&str]) {
    for format in formats {
        let mut a = args.to_vec();
        a.extend(["--format", format]);
        let whole = untimed(&stdout(&succeeds(&a)));
        for n in [1, 2, 3, 7] {
            let dir = tempfile::tempdir().unwrap();
            let merged = untimed(&sharded(&a, n, dir.path()));
            assert!(
                merged == whole,
                "{a:?} as {n} shards:\n{merged:.2000}\n---\n{whole:.2000}"
            );
        }
    }
}

const MAP: [&str; 5] = ["map", "--x", "omega1=0.2:2.4:0.2", "--y", "mu=1:3:1"];

#[test]
fn map_merges_to_the_unsharded_map() {
    merges_equal(&MAP, &["json", "csv", "table"]);
    // Cells sharing their baselines (a gap axis): the baseline counts too.
    merges_equal(
        &["map", "--x", "omega1=0.4:2:0.4", "--y", "gap=0.1:1.6:0.5"],
        &["json"],
    );
}

#[test]
fn spectrum_merges_to_the_unsharded_spectrum() {
    merges_equal(
        &[
            "spectrum",
            "--omega1",
            "0.2:2:0.15",
            "--family",
            "gap=0.2,1.5,inf",
        ],
        &["json", "table"],
    );
}

#[test]
fn gap_sweep_merges_to_the_unsharded_sweep() {
    merges_equal(&["gap", "--x", "omega1=0.2:2:0.2"], &["json", "csv"]);
}

const TWO: [&str; 2] = ["--preset", "two-buildings"];

#[test]
fn suite_merges_to_the_unsharded_suite() {
    merges_equal(
        &[
            &["suite"],
            &TWO[..],
            &["--suite", "synthetic:4@2", "--level", "0.3g"],
        ]
        .concat(),
        &["json", "csv"],
    );
}

#[test]
fn gap_suite_merges_to_the_unsharded_separation() {
    merges_equal(
        &[
            &["gap"],
            &TWO[..],
            &["--suite", "synthetic:4@2", "--level", "0.3g"],
        ]
        .concat(),
        &["json", "table"],
    );
}

#[test]
fn ida_merges_to_the_unsharded_ida() {
    merges_equal(
        &[
            &["ida"],
            &TWO[..],
            &["--suite", "synthetic:3@2", "--levels", "0.1:0.3:0.1"],
        ]
        .concat(),
        &["json", "table"],
    );
    // A suite scaled to a design spectrum, then as a whole to each level.
    merges_equal(
        &[
            &["ida"],
            &TWO[..],
            &[
                "--suite",
                "synthetic:3@2",
                "--target",
                "asce7:SDS=1.0,SD1=0.6,TL=8",
                "--levels",
                "0.2,0.4",
            ],
        ]
        .concat(),
        &["json"],
    );
}

#[test]
fn suite_map_merges_to_the_unsharded_suite_map() {
    merges_equal(
        &[
            &["map"],
            &TWO[..],
            &[
                "--suite",
                "synthetic:2@2",
                "--x",
                "period1=0.5:0.7:0.1",
                "--y",
                "gap=0.01:0.03:0.02",
            ],
        ]
        .concat(),
        &["json", "csv"],
    );
}

/// A row's retrofit map: each unit is one cell's records, reduced to the
/// cell; the merge of any number of shards is the whole map, bit for bit.
#[test]
fn retrofit_map_merges_to_the_unsharded_map() {
    merges_equal(
        &[
            "map",
            "--buildings",
            "block-and-frame-retrofit",
            "--suite",
            "synthetic:2@2",
            "--level",
            "0.3",
            "--x",
            "link1.damping=2e6:6e6:4e6",
            "--y",
            "joint1.bumper.thickness=0.002:0.004:0.002",
        ],
        &["json", "csv", "table"],
    );
}

/// A row's studies: each unit is one record's two row runs at one level,
/// and the merge rebuilds every building's and joint's demands from them.
#[test]
fn row_studies_merge_to_their_unsharded_outputs() {
    let row = ["--buildings", "block-and-frame", "--suite", "synthetic:4@2"];
    merges_equal(
        &[&["suite"], &row[..], &["--level", "0.3g"]].concat(),
        &["json", "csv", "table"],
    );
    merges_equal(
        &[
            &["ida"],
            &row[..],
            &["--levels", "0.1:0.3:0.1", "--drift", "0.005,frame:0.01"],
        ]
        .concat(),
        &["json", "table"],
    );
    // An IDA to collapse (SPEC §15): collapsed runs carry their collapse in
    // the parts, and their infinite demands merge as they were.
    merges_equal(
        &[
            "ida",
            "--buildings",
            "block-and-frame-pdelta",
            "--suite",
            "synthetic:3@2",
            "--levels",
            "0.6,1.2",
            "--collapse",
        ],
        &["json", "table"],
    );
    merges_equal(
        &[
            "gap",
            "--buildings",
            "three-in-series",
            "--suite",
            "synthetic:3@2",
            "--level",
            "0.2g",
        ],
        &["json", "csv"],
    );
}

/// A row's part is not a pair's: the same suite on the pair and on a row
/// are different requests, and a part of one does not merge with the other's.
#[test]
fn row_and_pair_parts_do_not_mix() {
    let dir = tempfile::tempdir().unwrap();
    let template = dir.path().join("{command}-{k}.part");
    let suite = ["suite", "--suite", "synthetic:2@2", "--level", "0.3g"];
    let pair = [&suite[..], &TWO[..]].concat();
    let row = [&suite[..], &["--buildings", "two-buildings"]].concat();
    for (args, k) in [(&pair, "1/2"), (&row, "2/2")] {
        let mut a = args.clone();
        a.extend(["--shard", k, "--part", template.to_str().unwrap()]);
        succeeds(&a);
    }
    let parts = ["suite-1.part", "suite-2.part"].map(|p| dir.path().join(p));
    fails(
        &[
            "merge",
            parts[0].to_str().unwrap(),
            parts[1].to_str().unwrap(),
        ],
        2,
        &["suite-1.part", "suite-2.part", "different requests"],
    );
}

/// Writes the shards of `MAP` (with `extra`) into `dir`; their paths.
fn map_parts(dir: &Path, n: usize, extra: &[&str]) -> Vec<String> {
    (1..=n)
        .map(|k| {
            let path = dir.join(format!("p{k}.part")).to_str().unwrap().to_string();
            let shard = format!("{k}/{n}");
            let mut a: Vec<&str> = MAP.to_vec();
            a.extend(extra);
            a.extend(["--shard", &shard, "--part", &path]);
            succeeds(&a);
            path
        })
        .collect()
}

#[test]
fn merge_refuses_other_requests_duplicates_missing_and_truncated_parts() {
    let dir = tempfile::tempdir().unwrap();
    let a = map_parts(&dir.path().join("a").tap_mkdir(), 3, &[]);
    let b = map_parts(&dir.path().join("b").tap_mkdir(), 3, &["--set", "gap=0.3"]);
    // Different requests.
    fails(
        &["merge", &a[0], &a[1], &b[2]],
        2,
        &[
            "different requests",
            "p1.part (shard 1/3)",
            "p3.part (shard 3/3)",
        ],
    );
    // The same shard twice, from two runs or one file given twice.
    let again = map_parts(&dir.path().join("c").tap_mkdir(), 3, &[]);
    fails(
        &["merge", &a[0], &a[1], &a[2], &again[1]],
        2,
        &["shard 2/3 is given twice", "a/p2.part", "c/p2.part"],
    );
    fails(&["merge", &a[0], &a[0], &a[1], &a[2]], 2, &["given twice"]);
    // A missing shard.
    fails(
        &["merge", &a[0], &a[2]],
        2,
        &["missing shard 2 of 3", "p1.part (shard 1/3)"],
    );
    // A part cut short, as by a task killed while writing outside this program.
    let bytes = std::fs::read(&a[1]).unwrap();
    std::fs::write(&a[1], &bytes[..bytes.len() - 10]).unwrap();
    fails(
        &["merge", &a[0], &a[1], &a[2]],
        2,
        &["p2.part", "incomplete"],
    );
    std::fs::write(&a[1], &bytes[..40]).unwrap();
    fails(
        &["merge", &a[0], &a[1], &a[2]],
        2,
        &["p2.part", "incomplete"],
    );
    // Not a part at all.
    std::fs::write(&a[1], "hello\n").unwrap();
    fails(
        &["merge", &a[0], &a[1], &a[2]],
        2,
        &["p2.part", "not a part"],
    );
}

trait MkDir {
    fn tap_mkdir(self) -> Self;
}

impl MkDir for std::path::PathBuf {
    fn tap_mkdir(self) -> Self {
        std::fs::create_dir_all(&self).unwrap();
        self
    }
}

/// Runs `args` with the Slurm array variables `vars` only.
fn with_slurm(args: &[&str], vars: &[(&str, &str)]) -> std::process::Output {
    let mut c = Command::new(BIN);
    c.args(args).stdin(Stdio::null());
    for (k, _) in std::env::vars() {
        if k.starts_with("SLURM_") {
            c.env_remove(k);
        }
    }
    for (k, v) in vars {
        c.env(k, v);
    }
    c.output().unwrap()
}

#[test]
fn bad_shards_are_one_line_and_exit_2() {
    for (shard, why) in [
        ("0/3", "K must be 1 to 3"),
        ("4/3", "K must be 1 to 3"),
        ("1/0", "N must be at least 1"),
        ("x", "expected K/N"),
    ] {
        let mut a = MAP.to_vec();
        a.extend(["--shard", shard]);
        fails(&a, 2, &["--shard", why]);
    }
    let mut a = MAP.to_vec();
    a.extend(["--shard", "slurm"]);
    let o = with_slurm(&a, &[]);
    assert_eq!(o.status.code(), Some(2));
    common::assert_one_line(&o, &["--shard slurm", "not a task of a job array"]);
    let mut a = MAP.to_vec();
    a.extend(["--part", "x.part"]);
    fails(&a, 2, &["--part", "--shard"]);
    fails(&["gap", "--shard", "1/2"], 2, &["--shard", "--x"]);
}

#[test]
fn slurm_tasks_from_zero_or_one_and_skip_done() {
    let dir = tempfile::tempdir().unwrap();
    let template = dir.path().join("s-{k}.part");
    let mut a = MAP.to_vec();
    a.extend([
        "--format",
        "json",
        "--shard",
        "slurm",
        "--part",
        template.to_str().unwrap(),
    ]);
    // An array 0-1 and an array 1-2 give the same two shards.
    for (id, min) in [("0", "0"), ("2", "1")] {
        let o = with_slurm(
            &a,
            &[
                ("SLURM_ARRAY_TASK_ID", id),
                ("SLURM_ARRAY_TASK_COUNT", "2"),
                ("SLURM_ARRAY_TASK_MIN", min),
            ],
        );
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let p1 = dir.path().join("s-1.part");
    let p2 = dir.path().join("s-2.part");
    let merged = stdout(&succeeds(&[
        "merge",
        p1.to_str().unwrap(),
        p2.to_str().unwrap(),
    ]));
    let mut w = MAP.to_vec();
    w.extend(["--format", "json"]);
    assert_eq!(untimed(&merged), untimed(&stdout(&succeeds(&w))));
    // A complete part is not computed again with --skip-done.
    let before = std::fs::read(&p1).unwrap();
    let mut again = MAP.to_vec();
    again.extend(["--format", "json", "--shard", "1/2", "--part"]);
    again.push(template.to_str().unwrap());
    again.push("--skip-done");
    let o = succeeds(&again);
    assert!(stderr(&o).contains("skipped"), "{}", stderr(&o));
    assert_eq!(std::fs::read(&p1).unwrap(), before);
    // A truncated one is.
    std::fs::write(&p1, &before[..before.len() / 2]).unwrap();
    let o = succeeds(&again);
    assert!(!stderr(&o).contains("skipped"));
    assert!(pounding::analysis::shard::Part::read(&p1).is_ok());
    // `merge --out` writes the file.
    let out = dir.path().join("merged.json");
    succeeds(&[
        "merge",
        "--out",
        out.to_str().unwrap(),
        p1.to_str().unwrap(),
        p2.to_str().unwrap(),
    ]);
    assert_eq!(
        untimed(&std::fs::read_to_string(&out).unwrap()),
        untimed(&merged)
    );
}

#[test]
fn merge_refuses_parts_whose_inputs_changed_since() {
    let dir = tempfile::tempdir().unwrap();
    let preset = dir.path().join("mine.toml");
    let text = std::fs::read_to_string("presets/set1.toml").unwrap();
    std::fs::write(&preset, &text).unwrap();
    let template = dir.path().join("p-{k}.part");
    for k in ["1/2", "2/2"] {
        let mut a = MAP.to_vec();
        a.extend(["--preset", preset.to_str().unwrap(), "--shard", k]);
        a.extend(["--part", template.to_str().unwrap()]);
        succeeds(&a);
    }
    let parts = [dir.path().join("p-1.part"), dir.path().join("p-2.part")];
    let parts: Vec<&str> = parts.iter().map(|p| p.to_str().unwrap()).collect();
    succeeds(&[&["merge"], &parts[..]].concat());
    // The preset edited after the shards ran.
    std::fs::write(&preset, text.replace("gap = 0.2", "gap = 0.25")).unwrap();
    fails(
        &[&["merge"], &parts[..]].concat(),
        2,
        &["p-1.part", "no longer makes here"],
    );
}
