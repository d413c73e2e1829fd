//! No two files of `src/` import each other, directly or through a longer
//! loop: every import runs one way, from the file that uses a thing to the
//! file that owns it.
//!
//! The rules, so that an edge means "this file needs that file":
//!
//! - a file is the module its path names: `src/a/b.rs` and `src/a/b/mod.rs`
//!   are `a::b`, `src/lib.rs` is the crate root (`src/main.rs`, the binary,
//!   is left out);
//! - a file's imports are the paths it names outside comments: `use` trees
//!   (braces expanded) and paths written inline, from `crate::`, `super::`
//!   (any number) or `self::`. Its `#[cfg(test)] mod tests` is left out: a
//!   test may reach anywhere;
//! - a path goes to the longest module it names (`crate::a::b::C` to `a::b`
//!   when that is a file, else to `a`);
//! - a parent module (a `mod.rs` or `lib.rs`) that re-exports an item of a
//!   child (`pub use child::Item`) is a signpost, not the owner: a path
//!   through the parent to that item goes on to the child. A parent's own
//!   uses of its descendants (declaring, re-exporting) are not edges.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

type Module = Vec<String>;

/// Every file of `src/` (but the binary) as its module and its text.
fn files(dir: &Path, module: &[String], out: &mut BTreeMap<Module, (bool, String)>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        let mut m = module.to_vec();
        if path.is_dir() {
            m.push(name);
            files(&path, &m, out);
        } else if let Some(stem) = name.strip_suffix(".rs") {
            let parent = matches!(stem, "mod" | "lib");
            if stem == "main" && module.is_empty() {
                continue;
            }
            if !parent {
                m.push(stem.to_string());
            }
            out.insert(m, (parent, fs::read_to_string(&path).unwrap()));
        }
    }
}

/// `text` without comments and without its test module.
fn code(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths of a `use` tree, braces expanded: `a::{b, c::{D, E}}`.
fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find('{') else {
        return vec![tree];
    };
    let (prefix, inner) = (&tree[..open], &tree[open + 1..tree.len() - 1]);
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.is_empty())
        .flat_map(|p| expand(p).into_iter().map(move |q| format!("{prefix}{q}")))
        .collect()
}

/// A `use` tree without its renames: `{a::X as Y, b}` → `{a::X, b}`.
fn without_renames(tree: &str) -> String {
    let mut out = String::new();
    let mut words = tree.split_whitespace();
    while let Some(w) = words.next() {
        if w == "as" {
            // Keep what closes after the new name: `Y},` → `},`.
            let next = words.next().unwrap_or("");
            out.extend(
                next.chars()
                    .skip_while(|c| c.is_alphanumeric() || *c == '_'),
            );
        } else {
            out.push_str(w);
        }
    }
    out
}

/// Every path a file's code names: its `use` trees and inline paths.
fn paths(code: &str) -> Vec<(bool, String)> {
    let mut out = Vec::new();
    let mut rest = code;
    // `use` and `pub use` trees (true: a re-export).
    while let Some(i) = rest.find("use ") {
        let before = &rest[..i];
        let at_start = before.is_empty()
            || before.ends_with(|c: char| {
                c.is_whitespace() || c == ';' || c == '}' || c == '{' || c == ')'
            });
        let after = &rest[i + 4..];
        let Some(end) = after.find(';') else { break };
        if at_start && !before.trim_end().ends_with("fn") {
            let public = before.trim_end().ends_with("pub") || before.trim_end().ends_with(')');
            for p in expand(&without_renames(&after[..end])) {
                out.push((public, p));
            }
        }
        rest = &after[end.min(after.len())..];
    }
    // Inline paths.
    let chars: Vec<char> = code.chars().collect();
    let text: String = chars.iter().collect();
    for start in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(i) = text[from..].find(start) {
            let at = from + i;
            let prev = text[..at].chars().last().unwrap_or(' ');
            if !(prev.is_alphanumeric() || prev == '_' || prev == ':') {
                let path: String = text[at..]
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                    .collect();
                out.push((false, path.trim_end_matches(':').to_string()));
            }
            from = at + start.len();
        }
    }
    out
}

/// The absolute segments of `path` as seen from `module` (`super` is the
/// module above: for a parent file, above its folder).
fn absolute(path: &str, module: &[String]) -> Option<Module> {
    let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
    let mut base: Module;
    let mut i = 0;
    match segs.first()? {
        &"crate" => {
            base = Vec::new();
            i = 1;
        }
        &"self" | &"super" => {
            base = module.to_vec();
            if segs[0] == "self" {
                i = 1;
            }
            while segs.get(i) == Some(&"super") {
                base.pop();
                i += 1;
            }
        }
        _ => return None,
    }
    base.extend(segs[i..].iter().map(|s| s.to_string()));
    Some(base)
}

/// The file that owns what `path` names, following parents' re-exports.
fn owner(
    path: &[String],
    all: &BTreeMap<Module, (bool, String)>,
    reexports: &BTreeMap<Module, BTreeMap<String, Module>>,
    depth: usize,
) -> Option<Module> {
    let mut k = path.len();
    while !all.contains_key(&path[..k]) {
        k = k.checked_sub(1)?;
    }
    let module = path[..k].to_vec();
    if depth < 8
        && let Some(name) = path.get(k)
        && let Some(target) = reexports.get(&module).and_then(|r| r.get(name))
    {
        let mut next = target.clone();
        next.extend(path[k + 1..].iter().cloned());
        return owner(&next, all, reexports, depth + 1);
    }
    Some(module)
}

fn graph() -> BTreeMap<Module, BTreeSet<Module>> {
    let mut all = BTreeMap::new();
    files(
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src")),
        &[],
        &mut all,
    );
    let mut reexports: BTreeMap<Module, BTreeMap<String, Module>> = BTreeMap::new();
    for (m, (parent, text)) in &all {
        if !parent {
            continue;
        }
        for (public, p) in paths(&code(text)) {
            // `pub use child::Item` (relative to the parent) or a full path.
            let full = if p.starts_with("crate::")
                || p.starts_with("super::")
                || p.starts_with("self::")
            {
                absolute(&p, m)
            } else if public {
                let mut f = m.clone();
                f.extend(p.split("::").map(String::from));
                Some(f)
            } else {
                None
            };
            if let (true, Some(full)) = (public, full)
                && full.len() > m.len()
                && full.starts_with(m)
                && let Some(name) = full.last()
                && name != "*"
            {
                reexports
                    .entry(m.clone())
                    .or_default()
                    .insert(name.clone(), full);
            }
        }
    }
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for (m, (parent, text)) in &all {
        let e = edges.entry(m.clone()).or_default();
        for (_, p) in paths(&code(text)) {
            let Some(abs) = absolute(&p, m) else {
                continue;
            };
            let Some(to) = owner(&abs, &all, &reexports, 0) else {
                continue;
            };
            let own_part = *parent && to.starts_with(m);
            if to != *m && !own_part {
                e.insert(to);
            }
        }
    }
    edges
}

/// The loops of `edges`: its strongly connected parts of two files or more.
fn loops(edges: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<Vec<String>> {
    let reach = |from: &Module| {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.clone()];
        while let Some(n) = stack.pop() {
            for t in edges.get(&n).into_iter().flatten() {
                if seen.insert(t.clone()) {
                    stack.push(t.clone());
                }
            }
        }
        seen
    };
    let reachable: BTreeMap<&Module, BTreeSet<Module>> =
        edges.keys().map(|m| (m, reach(m))).collect();
    let mut done = BTreeSet::new();
    let mut out = Vec::new();
    for m in edges.keys() {
        if done.contains(m) {
            continue;
        }
        let part: Vec<&Module> = edges
            .keys()
            .filter(|n| *n == m || (reachable[m].contains(*n) && reachable[*n].contains(m)))
            .collect();
        if part.len() > 1 {
            out.push(part.iter().map(|n| n.join("::")).collect());
        }
        done.extend(part.into_iter().cloned());
    }
    out
}

#[test]
fn no_two_files_import_each_other() {
    let loops = loops(&graph());
    assert!(loops.is_empty(), "files in a loop of imports: {loops:#?}");
}

/// The parser sees the shapes the code uses, and the loop finder finds a loop.
#[test]
fn the_check_sees_imports_and_loops() {
    assert_eq!(
        expand(&without_renames("super::{a::B as F, c::{D, E}}")),
        ["super::a::B", "super::c::D", "super::c::E"]
    );
    let m = |s: &str| s.split("::").map(String::from).collect::<Module>();
    assert_eq!(
        absolute("super::super::x::Y", &m("solver::exact::driver")),
        Some(m("solver::x::Y"))
    );
    let found = paths("use super::batch::NewBaseline;\nfn f() { super::spectrum::combine(); }");
    assert!(found.iter().any(|(_, p)| p == "super::batch::NewBaseline"));
    assert!(found.iter().any(|(_, p)| p == "super::spectrum::combine"));
    let mut edges = BTreeMap::new();
    edges.insert(m("a"), BTreeSet::from([m("b")]));
    edges.insert(m("b"), BTreeSet::from([m("c")]));
    edges.insert(m("c"), BTreeSet::from([m("a")]));
    edges.insert(m("d"), BTreeSet::from([m("a")]));
    assert_eq!(loops(&edges), vec![vec!["a", "b", "c"]]);
    // The graph holds the edges a file's imports make.
    let g = graph();
    assert!(g[&m("analysis::batch")].contains(&m("analysis::baseline")));
    assert!(g[&m("model::preset")].contains(&m("model::params")));
}
