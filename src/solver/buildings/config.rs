//! The configuration of a row between events (SPEC §13): which branch of
//! SPEC §3's bilinear law each storey is on, and which floor pairs are in
//! contact, with what law. A configuration out of contact is a value: its
//! branches are the key of the cache of linear maps.

use crate::model::ContactLaw;

/// The branch of a storey's bilinear law: elastic (z = Δ − p, p the plastic
/// offset) or yielding at z = +Δ_y or −Δ_y.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Branch {
    Elastic,
    Plus,
    Minus,
}

/// One closed contact: its law (with v₀ fixed at onset) and the onset data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closed {
    pub law: ContactLaw,
    pub approach_velocity: f64,
}

/// Branches, plastic offsets and contacts.
#[derive(Debug, Clone, PartialEq)]
pub struct Config {
    pub branch: Vec<Branch>,
    /// p of each storey: z = Δ − p while elastic.
    pub plastic: Vec<f64>,
    pub contact: Vec<Option<Closed>>,
}

impl Config {
    pub fn at_rest(storeys: usize, pairs: usize) -> Config {
        Config {
            branch: vec![Branch::Elastic; storeys],
            plastic: vec![0.0; storeys],
            contact: vec![None; pairs],
        }
    }

    pub fn any_contact(&self) -> bool {
        self.contact.iter().any(Option::is_some)
    }

    /// The branches as bytes, the cache key out of contact, written into
    /// `key` (its allocation reused from sub-step to sub-step).
    pub fn key_into(&self, key: &mut Vec<u8>) {
        key.clear();
        key.extend(self.branch.iter().map(|b| *b as u8));
    }

    /// z of storey `i` at drift Δ (SPEC §3).
    #[inline]
    pub fn z(&self, i: usize, drift: f64, yield_drift: f64) -> f64 {
        match self.branch[i] {
            Branch::Elastic => drift - self.plastic[i],
            Branch::Plus => yield_drift,
            Branch::Minus => -yield_drift,
        }
    }
}
