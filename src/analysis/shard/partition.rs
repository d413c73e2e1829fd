//! The units of a sweep dealt to N shards by estimated work.
//!
//! Cells of a sweep do not cost the same: a stiffer structure (a higher
//! Π_ω) takes more steps or events per excitation cycle, and a run with
//! contact adds its impacts to a run without. Dealing the same number of
//! cells to every shard would leave the shards holding the high-frequency
//! corner of a map running long after the others, and the job array takes
//! as long as its slowest task. So each unit carries an estimated work and
//! the units are dealt greedily, largest first, each to the shard with the
//! least work so far (longest processing time first): every shard ends
//! within one unit's work of the mean, and a sweep of many small units is
//! balanced to a fraction of a percent.
//!
//! The deal depends on the work estimates alone, with every tie broken by
//! index, so every task of an array computes the same partition and runs
//! its own share of it.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// A shard's load in the heap: least work first, then lowest shard.
#[derive(PartialEq)]
struct Load {
    work: f64,
    shard: usize,
}

impl Eq for Load {}

impl Ord for Load {
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .work
            .total_cmp(&self.work)
            .then(other.shard.cmp(&self.shard))
    }
}

impl PartialOrd for Load {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// The shard (0-based, below `n`) of each unit, given each unit's
/// estimated `work` (finite and ≥ 0; anything else counts as 0).
pub fn partition(work: &[f64], n: usize) -> Vec<usize> {
    let n = n.max(1);
    let clean = |w: f64| if w.is_finite() && w > 0.0 { w } else { 0.0 };
    let mut order: Vec<usize> = (0..work.len()).collect();
    order.sort_by(|&a, &b| clean(work[b]).total_cmp(&clean(work[a])).then(a.cmp(&b)));
    let mut heap: BinaryHeap<Load> = (0..n).map(|shard| Load { work: 0.0, shard }).collect();
    let mut shard_of = vec![0; work.len()];
    for i in order {
        let mut least = heap.pop().expect("n >= 1 shards");
        shard_of[i] = least.shard;
        least.work += clean(work[i]);
        heap.push(least);
    }
    shard_of
}

/// The units of shard `k` (0-based) in increasing order.
pub fn units_of(shard_of: &[usize], k: usize) -> Vec<usize> {
    (0..shard_of.len()).filter(|&i| shard_of[i] == k).collect()
}

/// Each shard's total estimated work.
pub fn loads(work: &[f64], shard_of: &[usize], n: usize) -> Vec<f64> {
    let mut loads = vec![0.0; n.max(1)];
    for (w, &s) in work.iter().zip(shard_of) {
        loads[s] += w;
    }
    loads
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_unit_once_and_deterministic() {
        let work: Vec<f64> = (0..100).map(|i| 1.0 + (i % 7) as f64).collect();
        let a = partition(&work, 3);
        assert_eq!(a, partition(&work, 3));
        assert!(a.iter().all(|&s| s < 3));
        let l = loads(&work, &a, 3);
        let mean = l.iter().sum::<f64>() / 3.0;
        assert!(l.iter().all(|&x| x <= mean + 7.0), "{l:?}");
        // More shards than units: the extra shards are empty.
        assert_eq!(partition(&[1.0, 2.0], 4).len(), 2);
        assert_eq!(units_of(&partition(&[1.0, 2.0], 4), 3), Vec::<usize>::new());
    }
}
