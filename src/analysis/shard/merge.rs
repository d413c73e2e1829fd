//! A set of parts checked as a whole, and their results put back in order.
//!
//! A merge refuses, naming the files and the shard numbers:
//! - parts of different requests (fingerprint, command or shard count differ);
//! - the same shard twice (two files, or one file given twice);
//! - a missing shard.

use serde::de::DeserializeOwned;

use super::part::{Part, PartError};

/// `part` as named in a refusal: its file and its shard.
fn named(p: &Part) -> String {
    format!("{} (shard {}/{})", p.name, p.header.shard, p.header.shards)
}

/// Checks that `parts` are every shard of one request, once each; returns
/// them in shard order.
pub fn check(mut parts: Vec<Part>) -> Result<Vec<Part>, String> {
    let Some(first) = parts.first().cloned() else {
        return Err("merge: no parts given".into());
    };
    let same = |p: &Part| {
        p.header.fingerprint == first.header.fingerprint
            && p.header.command == first.header.command
            && p.header.shards == first.header.shards
            && p.header.total_units == first.header.total_units
    };
    if let Some(other) = parts.iter().find(|p| !same(p)) {
        return Err(format!(
            "merge: {} and {} are parts of different requests ({} {} and {} {}); \
             merge the parts of one request only",
            named(&first),
            named(other),
            first.header.command,
            short(&first.header.fingerprint),
            other.header.command,
            short(&other.header.fingerprint),
        ));
    }
    parts.sort_by_key(|p| p.header.shard);
    if let Some(w) = parts
        .windows(2)
        .find(|w| w[0].header.shard == w[1].header.shard)
    {
        return Err(format!(
            "merge: shard {}/{} is given twice: {} and {}",
            w[0].header.shard, w[0].header.shards, w[0].name, w[1].name
        ));
    }
    let n = first.header.shards;
    let missing: Vec<String> = (1..=n)
        .filter(|k| !parts.iter().any(|p| p.header.shard == *k))
        .map(|k| k.to_string())
        .collect();
    if !missing.is_empty() {
        let have: Vec<String> = parts.iter().map(named).collect();
        return Err(format!(
            "merge: missing shard{} {} of {n} (given: {})",
            if missing.len() > 1 { "s" } else { "" },
            missing.join(", "),
            have.join(", ")
        ));
    }
    Ok(parts)
}

/// The first 12 digits of a fingerprint, for messages.
fn short(fingerprint: &str) -> String {
    format!(
        "fingerprint {}…",
        fingerprint.chars().take(12).collect::<String>()
    )
}

/// Every unit's result from checked `parts` (see [`check`]), in unit order,
/// and the sum of the parts' computing times in ms.
pub fn assemble<R: DeserializeOwned>(parts: &[Part]) -> Result<(Vec<R>, f64), PartError> {
    let total = parts.first().map_or(0, |p| p.header.total_units);
    let mut slots: Vec<Option<R>> = (0..total).map(|_| None).collect();
    let mut elapsed_ms = 0.0;
    for part in parts {
        let (units, results): (Vec<usize>, Vec<R>) = part.results()?;
        let bad = |why: &str| PartError::Bad(part.name.clone(), why.to_string());
        if units.len() != results.len() || units.len() != part.header.units {
            return Err(bad("its unit list and its results differ in length"));
        }
        for (u, r) in units.into_iter().zip(results) {
            match slots.get_mut(u) {
                Some(slot @ None) => *slot = Some(r),
                Some(Some(_)) => return Err(bad("it holds a unit another part holds too")),
                None => return Err(bad("it holds a unit beyond the sweep")),
            }
        }
        elapsed_ms += part.header.elapsed_ms;
    }
    let results: Option<Vec<R>> = slots.into_iter().collect();
    let results = results.ok_or_else(|| {
        PartError::Bad(
            parts.first().map_or(String::new(), |p| p.name.clone()),
            "the parts together do not hold every unit of the sweep".into(),
        )
    })?;
    Ok((results, elapsed_ms))
}
