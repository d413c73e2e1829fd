//! Records chosen from a collection for a target spectrum (SPEC §12): the
//! N that need the least ln-misfit after their least-squares factor
//! ([`super::record_scaling`]), within a factor limit and at most K of one
//! earthquake, then scaled to the code's rule as `records scale` does.
//!
//! 1. Every candidate's spectrum on the design's grid, its factor f_j and
//!    its ln-misfit. A record whose Sa is 0 somewhere cannot be fitted.
//! 2. Those with f_j outside [1/M, M] (M = `max_scale`) are left out.
//! 3. The rest, by ascending misfit (then name), are taken in turn, each
//!    unless K of its event are already taken; a record that names no
//!    event is an event of its own.
//! 4. The first N taken are scaled to the rule (common factor c ≥ 1). A
//!    record whose c·f_j then exceeds M is left out, and 3–4 run again: the
//!    common factor never carries a record past the limit.
//!
//! Fewer than N available is an error that says how many were, and why the
//! others were left out.

use std::collections::HashMap;

use serde::Serialize;

use super::record_scaling::{Design, Matching, least_squares, scale, spectra};
use crate::model::suite::SuiteMember;

/// A record that may be chosen, and the earthquake it comes from.
#[derive(Debug, Clone)]
pub struct Candidate {
    pub member: SuiteMember,
    /// The event read from its header; `None`: its own event.
    pub event: Option<String>,
}

/// How many to choose, and within which limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    pub count: usize,
    /// M: every factor within [1/M, M].
    pub max_scale: f64,
    /// K: at most this many of one event; `None`: no cap.
    pub per_event: Option<usize>,
}

/// How many candidates were left out, and why.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Exclusions {
    /// Sa is 0 somewhere on the grid.
    pub silent: usize,
    /// The least-squares factor is outside [1/M, M].
    pub factor: usize,
    /// Past the first K of their event.
    pub per_event: usize,
    /// Within the limit alone, beyond it once the suite met the rule.
    pub after_common_factor: usize,
}

/// A choice: the members (their scale the factor to run at), in the
/// collection's order, and the scaling of them.
#[derive(Debug, Clone)]
pub struct Selection {
    pub chosen: Vec<SuiteMember>,
    /// Each chosen member's event, in the same order.
    pub events: Vec<Option<String>>,
    pub matching: Matching,
    pub candidates: usize,
    pub excluded: Exclusions,
}

/// Too few records within the limits.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.words())]
pub struct TooFew {
    pub asked: usize,
    pub available: usize,
    pub candidates: usize,
    pub limits: Limits,
    pub excluded: Exclusions,
}

impl TooFew {
    fn words(&self) -> String {
        let m = self.limits.max_scale;
        let mut why = Vec::new();
        let e = &self.excluded;
        if e.factor > 0 {
            why.push(format!(
                "{} need a factor outside [{}, {m}]",
                e.factor,
                1.0 / m
            ));
        }
        if e.after_common_factor > 0 {
            why.push(format!(
                "{} would pass {m} once the suite is scaled to the rule",
                e.after_common_factor
            ));
        }
        if e.per_event > 0 {
            why.push(format!(
                "{} are beyond {} per event",
                e.per_event,
                self.limits.per_event.unwrap_or(0)
            ));
        }
        if e.silent > 0 {
            why.push(format!("{} have Sa = 0 in the range", e.silent));
        }
        format!(
            "--count {}: only {} of the {} records are available within the limits{}",
            self.asked,
            self.available,
            self.candidates,
            if why.is_empty() {
                String::new()
            } else {
                format!(" ({})", why.join("; "))
            }
        )
    }
}

/// Chooses `limits.count` of `candidates` for `design` (module doc).
pub fn select(
    design: &Design,
    candidates: &[Candidate],
    limits: Limits,
) -> Result<Selection, TooFew> {
    let periods = design.grid();
    let members: Vec<SuiteMember> = candidates.iter().map(|c| c.member.clone()).collect();
    let sa = spectra(&members, &periods);
    let target: Vec<f64> = periods
        .iter()
        .map(|&t| design.target.sa(t).unwrap_or(f64::NAN))
        .collect();
    let m = limits.max_scale;
    let mut excluded = Exclusions::default();
    // (misfit, name, index, factor) of those within the limit.
    let mut ranked = Vec::new();
    for (j, s) in sa.iter().enumerate() {
        match least_squares(&target, s) {
            None => excluded.silent += 1,
            Some((f, _)) if !(f >= 1.0 / m && f <= m) => excluded.factor += 1,
            Some((_, misfit)) => ranked.push((misfit, members[j].name.clone(), j)),
        }
    }
    ranked.sort_by(|a, b| a.0.total_cmp(&b.0).then_with(|| a.1.cmp(&b.1)));
    let mut dropped = vec![false; candidates.len()];
    loop {
        let (taken, capped) = take(&ranked, candidates, &dropped, limits.per_event);
        let too_few = |excluded: Exclusions| TooFew {
            asked: limits.count,
            available: taken.len(),
            candidates: candidates.len(),
            limits,
            excluded,
        };
        if taken.len() < limits.count {
            return Err(too_few(Exclusions {
                per_event: capped,
                ..excluded
            }));
        }
        let mut chosen: Vec<usize> = taken[..limits.count].to_vec();
        chosen.sort_unstable();
        let picked: Vec<SuiteMember> = chosen.iter().map(|&j| members[j].clone()).collect();
        // Not silent: every record with Sa = 0 was left out above.
        let matching = scale(design, &picked).expect("chosen records have a spectrum");
        let beyond: Vec<usize> = chosen
            .iter()
            .zip(&matching.records)
            .filter(|(_, r)| r.factor > m)
            .map(|(&j, _)| j)
            .collect();
        if beyond.is_empty() {
            let chosen_members = chosen
                .iter()
                .zip(&matching.records)
                .map(|(&j, r)| SuiteMember {
                    scale: r.factor,
                    ..members[j].clone()
                })
                .collect();
            return Ok(Selection {
                chosen: chosen_members,
                events: chosen
                    .iter()
                    .map(|&j| candidates[j].event.clone())
                    .collect(),
                matching,
                candidates: candidates.len(),
                excluded: Exclusions {
                    per_event: capped,
                    ..excluded
                },
            });
        }
        for j in beyond {
            dropped[j] = true;
            excluded.after_common_factor += 1;
        }
    }
}

/// The ranked candidates taken in turn under the per-event cap, skipping
/// those dropped; and how many the cap turned away.
fn take(
    ranked: &[(f64, String, usize)],
    candidates: &[Candidate],
    dropped: &[bool],
    per_event: Option<usize>,
) -> (Vec<usize>, usize) {
    let mut per: HashMap<String, usize> = HashMap::new();
    let mut taken = Vec::new();
    let mut capped = 0;
    for &(_, ref name, j) in ranked {
        if dropped[j] {
            continue;
        }
        let event = candidates[j]
            .event
            .clone()
            .unwrap_or_else(|| format!("\u{0}{name}"));
        let n = per.entry(event).or_insert(0);
        if per_event.is_some_and(|k| *n >= k) {
            capped += 1;
            continue;
        }
        *n += 1;
        taken.push(j);
    }
    (taken, capped)
}
