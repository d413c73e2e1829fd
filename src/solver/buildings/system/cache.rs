//! The systems of a row's configurations out of contact, kept by their
//! branches (SPEC §13): at an event the run needs the new configuration's
//! system, and out of contact M⁻¹K, M⁻¹C, their nonzeros and their
//! columns depend on the branches alone; the plastic offsets p enter only
//! M⁻¹q ([`System`]'s opening), which is made afresh each time. A system
//! made from the kept one is therefore the one [`System::of`] makes, bit
//! for bit, at the cost of M⁻¹q alone: its matrices and their sparse
//! forms are the kept one's, shared by reference count, not copied.
//! Configurations with a closed pair, whose law depends on the approach
//! velocity at onset, are made afresh.

use std::collections::HashMap;

use super::super::config::Config;
use super::super::layout::Layout;
use super::System;

/// The systems met out of contact, by their branches ([`Config::key_into`]).
#[derive(Debug, Default)]
pub struct Systems {
    by_branches: HashMap<Vec<u8>, System>,
    /// The key of the configuration asked for, its allocation reused.
    key: Vec<u8>,
}

impl Systems {
    /// The system of `config` in `layout`: made from the kept one of its
    /// branches when it has no closed pair (and kept, the first time).
    pub fn of(&mut self, layout: &Layout, config: &Config) -> System {
        if config.any_contact() {
            return System::of(layout, config);
        }
        config.key_into(&mut self.key);
        if let Some(kept) = self.by_branches.get(&self.key) {
            return kept.with_load_of(layout, config);
        }
        let system = System::of(layout, config);
        self.by_branches.insert(self.key.clone(), system.clone());
        system
    }
}

#[cfg(test)]
mod tests {
    use super::{System, Systems};
    use crate::model::buildings;
    use crate::model::buildings::contact::element_law;
    use crate::solver::buildings::config::{Branch, Closed, Config};
    use crate::solver::buildings::layout::Layout;

    /// Every field of two systems, to the bit.
    fn same(a: &System, b: &System) -> bool {
        let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        bits(a.stiffness.as_slice()) == bits(b.stiffness.as_slice())
            && bits(a.damping.as_slice()) == bits(b.damping.as_slice())
            && bits(&a.load) == bits(&b.load)
            && a.products == b.products
            && a.entries == b.entries
            && a.row_start == b.row_start
            && format!("{:?}", a.columns) == format!("{:?}", b.columns)
    }

    /// Block-and-frame with P-Δ (its geometric stiffness in K) under a
    /// sequence of configurations that come back to the same branches with
    /// other plastic offsets, and one with its roofs in contact: each
    /// system from the cache is [`System::of`]'s bit for bit, and the
    /// offsets reach the load (two offsets give two loads).
    #[test]
    fn a_kept_system_is_the_fresh_one_bit_for_bit() {
        let row = buildings::load("block-and-frame-pdelta").expect("shipped");
        let layout = Layout::of(&row);
        let storeys = layout.storeys.len();
        let mut systems = Systems::default();
        let mut config = Config::at_rest(storeys, layout.pairs.len());
        let mut loads = Vec::new();
        for round in 0..3 {
            for k in 0..storeys {
                config.plastic[k] = 1e-3 * (round as f64 + 1.0) * (k as f64 - 4.5);
            }
            config.branch[2] = Branch::Plus;
            config.branch[5] = [Branch::Minus, Branch::Elastic, Branch::Minus][round];
            let kept = systems.of(&layout, &config);
            assert!(same(&kept, &System::of(&layout, &config)), "round {round}");
            loads.push(kept.load.clone());
        }
        assert_ne!(loads[0], loads[2], "the offsets reach the load");
        let roof = layout.pairs.len() - 1;
        config.contact[roof] = Some(Closed {
            law: element_law(&row, &layout.elements[roof], 0.1),
            approach_velocity: 0.1,
        });
        let closed = systems.of(&layout, &config);
        assert!(same(&closed, &System::of(&layout, &config)));
        assert!(closed.load != loads[2], "the contact's k̄d reaches the load");
    }
}
