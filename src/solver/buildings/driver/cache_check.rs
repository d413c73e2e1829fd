//! The maps kept across runs ([`super::MapCache`]) change what a run costs,
//! never what it computes: a configuration takes the series for its first
//! [`super::FRESH`] − 1 quiet tests of each run whether or not an earlier
//! run left its map in the cache, so a run with a warm cache takes the
//! same steps, bit for bit, as one with a fresh cache.

#[cfg(test)]
mod tests {
    use crate::model::buildings::{self, Ground};
    use crate::model::simulated::Simulation;
    use crate::solver::buildings::profile::Cause;
    use crate::solver::buildings::{MapCache, RowOptions, RowRun, run_row, run_row_cached};

    fn ground(seed: u64, scale: f64) -> Ground {
        let record = Simulation {
            dt: 0.005,
            duration: 4.0,
            ..Default::default()
        }
        .record("cache", seed, 1);
        Ground::from_record(&record, scale)
    }

    fn same(a: &RowRun, b: &RowRun) {
        assert_eq!(a.final_displacement, b.final_displacement);
        assert_eq!(a.final_velocity, b.final_velocity);
        assert_eq!(a.floors, b.floors);
        assert_eq!(a.pairs, b.pairs);
        assert_eq!(a.series_steps, b.series_steps);
        assert_eq!(a.profile.map_steps, b.profile.map_steps);
    }

    /// Block-and-frame yielding under two records, one after the other in
    /// one cache and each with a fresh one: equal runs, fewer maps made.
    #[test]
    fn a_warm_cache_takes_the_steps_of_a_fresh_one() {
        let row = buildings::load("block-and-frame").expect("shipped");
        let mut cache = MapCache::default();
        let mut made = (0, 0);
        for (seed, scale) in [(5u64, 3.0), (6, 3.0), (5, 3.0)] {
            let g = ground(seed, scale);
            let options = RowOptions::lasting(g.end() + 1.0);
            let warm = run_row_cached(&row, &g, &options, &mut cache).expect("runs");
            let fresh = run_row(&row, &g, &options).expect("runs");
            same(&warm, &fresh);
            assert!(fresh.profile.careful.of(Cause::Fresh) > 0);
            assert!(
                fresh.configurations > 3,
                "{} configurations",
                fresh.configurations
            );
            made.0 += warm.maps_made;
            made.1 += fresh.maps_made;
        }
        assert!(
            made.0 < made.1,
            "maps made warm {} and fresh {}",
            made.0,
            made.1
        );
    }
}
