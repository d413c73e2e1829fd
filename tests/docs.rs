//! The user guide and the README are tested as they are read:
//! - every ```` ```console ```` block of README.md and `docs/src/` is a
//!   trycmd case: each `$ pounding …` line runs, and what it prints must
//!   match the lines under it (`...` a whole line that varies, `[..]` the
//!   varying part of one, such as a timing);
//! - at least 80 % of the command examples run that way; the rest stand in
//!   ```` ```sh ```` blocks, each with its reason in the text beside it;
//! - every relative link resolves to a file of the repository;
//! - the README's set-up is the command CI runs.
//!
//! To refresh the outputs after a deliberate change of a command:
//! `TRYCMD=overwrite cargo test --release --test docs`, then put back the
//! elisions of timings it wrote out.

use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every Markdown file under `docs/`, in name order.
fn markdown_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let mut files = vec![root().join("README.md")];
    walk(&root().join("docs"), &mut files);
    files
}

/// The fenced blocks of a Markdown file: (info string, lines), in order.
fn fenced_blocks(text: &str) -> Vec<(String, Vec<String>)> {
    let mut blocks = Vec::new();
    let mut open: Option<(String, Vec<String>)> = None;
    for line in text.lines() {
        match open.as_mut() {
            None => {
                if let Some(info) = line.strip_prefix("```") {
                    open = Some((info.trim().to_string(), Vec::new()));
                }
            }
            Some((_, lines)) => {
                if line.starts_with("```") {
                    blocks.push(open.take().unwrap());
                } else {
                    lines.push(line.to_string());
                }
            }
        }
    }
    blocks
}

/// Every `$ pounding …` block runs in a fresh folder whose `presets/` is the
/// repository's (so `record:presets/synthetic.at2` reads the shipped
/// record), and files the examples write land there, not in the checkout.
#[test]
fn every_console_example_prints_what_it_shows() {
    let work = tempfile::tempdir().unwrap();
    std::os::unix::fs::symlink(root().join("presets"), work.path().join("presets")).unwrap();
    // The cases run where a reader runs them; the other tests of this file
    // use absolute paths only.
    std::env::set_current_dir(work.path()).unwrap();
    let cases = trycmd::TestCases::new();
    cases
        .register_bin("pounding", Path::new(env!("CARGO_BIN_EXE_pounding")))
        .register_bin("mkdir", Path::new("/bin/mkdir"))
        .env("NO_COLOR", "1");
    for file in markdown_files() {
        cases.case(file);
    }
    cases.run();
}

/// A command example is a `pounding …` line in a console block (run) or in
/// a `sh` block (shown, not run: Slurm, a long sweep, pip). At least 80 %
/// run.
#[test]
fn most_command_examples_run() {
    let (mut run, mut shown) = (0usize, Vec::new());
    for file in markdown_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        for (info, lines) in fenced_blocks(&text) {
            let lang = info.split(',').next().unwrap_or("");
            for line in &lines {
                match lang {
                    "console" | "trycmd" if line.starts_with("$ pounding") => run += 1,
                    "sh" if line.trim_start().starts_with("pounding ") => {
                        shown.push(format!("{}: {line}", file.display()))
                    }
                    _ => {}
                }
            }
        }
    }
    let total = run + shown.len();
    assert!(run >= 40, "only {run} examples run");
    assert!(
        run * 5 >= total * 4,
        "{run} of {total} command examples run; shown only:\n{}",
        shown.join("\n")
    );
}

/// Every fence names its language: trycmd takes a bare ```` ``` ```` block
/// for a case, and a repository browser colours by it.
#[test]
fn every_fence_names_its_language() {
    for file in markdown_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        for (info, lines) in fenced_blocks(&text) {
            assert!(
                !info.is_empty(),
                "{}: a fence without a language, opening {:?}",
                file.display(),
                lines.first()
            );
        }
    }
}

/// The lines of a Markdown file outside its fenced blocks.
fn prose_lines(text: &str) -> Vec<&str> {
    let mut in_fence = false;
    text.lines()
        .filter(|line| {
            if line.starts_with("```") {
                in_fence = !in_fence;
                return false;
            }
            !in_fence
        })
        .collect()
}

/// The targets of a file's Markdown links and images, outside code, with
/// their `#fragment` if any (web addresses left out).
fn relative_links(text: &str) -> Vec<String> {
    let mut links = Vec::new();
    for line in prose_lines(text) {
        // Drop code spans: `a](b)` inside backticks is not a link.
        let mut prose = String::new();
        for (i, part) in line.split('`').enumerate() {
            if i % 2 == 0 {
                prose.push_str(part);
            }
        }
        let mut rest = prose.as_str();
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let end = after.find(')').unwrap_or(after.len());
            let target = after[..end].split_whitespace().next().unwrap_or("");
            if !target.is_empty() && !target.contains("://") && !target.starts_with("mailto:") {
                links.push(target.to_string());
            }
            rest = &after[end..];
        }
    }
    links
}

/// A heading's anchor as GitHub and mdBook write it: lower case, letters,
/// digits, `-` and `_` kept, each space a `-`, the rest dropped.
fn anchor(heading: &str) -> String {
    heading
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            c if c.is_whitespace() => Some('-'),
            _ => None,
        })
        .collect()
}

/// The anchors of a Markdown file's headings, outside code.
fn anchors(text: &str) -> Vec<String> {
    prose_lines(text)
        .into_iter()
        .filter(|line| line.starts_with('#'))
        .map(|line| anchor(line.trim_start_matches('#').trim()))
        .collect()
}

/// Every relative link names a file that exists, and a `#fragment` names a
/// heading of that file (or of the file itself, for `#…` alone).
#[test]
fn every_relative_link_resolves() {
    let mut broken = Vec::new();
    let mut count = 0;
    for file in markdown_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        for link in relative_links(&text) {
            count += 1;
            let (path, fragment) = match link.split_once('#') {
                Some((p, f)) => (p, Some(f)),
                None => (link.as_str(), None),
            };
            let target = if path.is_empty() {
                file.clone()
            } else {
                file.parent().unwrap().join(path)
            };
            if !target.exists() {
                broken.push(format!("{}: {link}", file.display()));
            } else if let Some(fragment) = fragment {
                let heads = anchors(&std::fs::read_to_string(&target).unwrap());
                if !heads.iter().any(|h| h == fragment) {
                    broken.push(format!("{}: {link} (no such heading)", file.display()));
                }
            }
        }
    }
    assert!(
        count >= 30,
        "only {count} links found: is the parser blind?"
    );
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

/// Every chapter file under docs/src is listed in SUMMARY.md, and every
/// listed chapter exists (mdbook's `create-missing = false` fails the build
/// too, where mdbook is installed).
#[test]
fn the_summary_lists_every_chapter() {
    let src = root().join("docs/src");
    let summary = std::fs::read_to_string(src.join("SUMMARY.md")).unwrap();
    let listed: Vec<String> = relative_links(&summary)
        .into_iter()
        .filter(|l| !l.is_empty())
        .collect();
    for chapter in &listed {
        assert!(src.join(chapter).exists(), "SUMMARY lists {chapter}");
    }
    for file in markdown_files() {
        let Ok(rel) = file.strip_prefix(&src) else {
            continue;
        };
        let rel = rel.to_string_lossy().to_string();
        assert!(
            rel == "SUMMARY.md" || listed.contains(&rel),
            "docs/src/{rel} is not in SUMMARY.md"
        );
    }
}

/// The README's set-up is `cargo run --release` and `cargo test --release`,
/// and CI runs that same test command.
#[test]
fn the_readme_set_up_is_what_ci_runs() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    assert!(readme.contains("cargo run --release\ncargo test --release\n"));
    assert!(ci.lines().any(|l| l.trim() == "cargo test --release"));
    assert!(
        readme.lines().count() <= 200,
        "README.md has {} lines",
        readme.lines().count()
    );
}
