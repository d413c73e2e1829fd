//! The check of the quiet test (SPEC §13), in tests only: every sub-step
//! the bounds of [`super::super::bound`] clear for the map is walked again
//! by the Taylor series of the same motion, at 64 points per series step,
//! and must hold no event (no floor pair closing, no elastic storey
//! reaching its yield drift, no yielding storey's drift rate changing
//! sign, no drift reaching collapse) and no new peak of any watched
//! quantity beyond its ends, which the map step records. The pair's
//! `sample_run::tests` check its chord margins the same way.

use std::cell::Cell;

use crate::model::buildings::ground::Piece;

use super::super::bound::Watch;
use super::super::config::Branch;
use super::super::peaks::Envelope;
use super::super::poly;
use super::super::taylor::Series;
use super::rising::quantity;
use super::{Run, ground_at};

/// Points per series step.
const POINTS: usize = 64;
/// Relative slack for the rounding of the series against the map.
const SLACK: f64 = 1e-9;

thread_local! {
    /// Quiet sub-steps checked on this thread.
    pub(super) static CHECKED: Cell<usize> = const { Cell::new(0) };
    /// Sub-steps whose located peaks were checked on this thread.
    pub(super) static LOCATED: Cell<usize> = const { Cell::new(0) };
}

impl Run<'_> {
    /// Walks the quiet sub-step from the current state to t + h (ending at
    /// (u1, v1)) by the series; panics at an event or a new peak inside.
    pub(super) fn check_quiet(&mut self, piece: &Piece, h: f64, (u1, v1): (&[f64], &[f64])) {
        let n = self.layout.dofs;
        let env = &self.envelope;
        let (mut u, mut v) = (self.u.clone(), self.v.clone());
        let (mut us, mut vs, mut acc) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let size = |x: &[f64]| x.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
        let (su, sv) = (size(&u), size(&v));
        // Absolute accelerations at both ends.
        let absolute = |x: &[f64], y: &[f64], t: f64| {
            let a = ground_at(piece, t).0;
            let mut acc = vec![0.0; n];
            self.system.acceleration(x, y, a, &mut acc);
            acc.iter().map(|x| x + a).collect::<Vec<_>>()
        };
        let a0 = absolute(&self.u, &self.v, self.t);
        let a1 = absolute(u1, v1, self.t + h);
        let sa = size(&a0).max(size(&a1)).max(size(&env.acceleration));
        // A peak may reach the larger of its running value and its ends.
        let bound =
            |peak: f64, a: f64, b: f64, scale: f64| peak.max(a.abs()).max(b.abs()) + SLACK * scale;
        let mut s0 = 0.0;
        while s0 < h {
            let ground = ground_at(piece, self.t + s0);
            let series = Series::new(
                &self.system,
                &u,
                &v,
                (ground.0, ground.1, piece.sigma),
                (su, sv),
            );
            let end = (h - s0).min(series.radius);
            for p in 0..=POINTS {
                let s = end * p as f64 / POINTS as f64;
                series.state(s, &mut us, &mut vs);
                let a = ground_at(piece, self.t + s0 + s).0;
                self.system.acceleration(&us, &vs, a, &mut acc);
                for i in 0..n {
                    assert!(us[i].abs() <= bound(env.displacement[i], self.u[i], u1[i], su));
                    assert!(vs[i].abs() <= bound(env.velocity[i], self.v[i], v1[i], sv));
                    let abs = acc[i] + a;
                    assert!(
                        abs.abs() <= bound(env.acceleration[i], a0[i], a1[i], sa),
                        "new acceleration peak inside"
                    );
                }
                for (k, st) in self.layout.storeys.iter().enumerate() {
                    let d = self.layout.drift(st, &us);
                    let rate = self.layout.drift(st, &vs);
                    let ends = (self.layout.drift(st, &self.u), self.layout.drift(st, u1));
                    assert!(
                        d.abs() <= bound(env.drift[k], ends.0, ends.1, su),
                        "new drift peak"
                    );
                    assert!(d.abs() < st.collapse_drift, "collapse inside");
                    match self.config.branch[k] {
                        Branch::Elastic => assert!(
                            (d - self.config.plastic[k]).abs() < st.yield_drift,
                            "yield inside a quiet sub-step"
                        ),
                        Branch::Plus => assert!(rate > -SLACK * sv, "unloading inside"),
                        Branch::Minus => assert!(rate < SLACK * sv, "unloading inside"),
                    }
                }
                for (p, &d) in self.layout.pairs.iter().zip(&self.layout.gaps) {
                    assert!(us[p.left_dof] - us[p.right_dof] < d, "onset inside");
                }
                for (k, p) in self.layout.facing.iter().enumerate() {
                    let r = us[p.left_dof] - us[p.right_dof];
                    let ends = (
                        self.u[p.left_dof] - self.u[p.right_dof],
                        u1[p.left_dof] - u1[p.right_dof],
                    );
                    assert!(r <= env.relative[k].max(ends.0).max(ends.1) + SLACK * su);
                }
            }
            series.state(end, &mut us, &mut vs);
            u.copy_from_slice(&us);
            v.copy_from_slice(&vs);
            s0 += end;
        }
        CHECKED.set(CHECKED.get() + 1);
    }

    /// Checks the peaks [`Run::locate_rising`] raised over the quiet
    /// sub-step of length h from the current state, against `before`: each
    /// raised value is the largest of its quantity on a dense walk of the
    /// series from the start (64 points, then the best one refined by
    /// golden sections on its neighbours), with ü from the equation of
    /// motion at each point, not from the series' own polynomial; and it
    /// is, to 1e-13 of its size, the largest value of the quantity's
    /// polynomial on the fixed order's series ([`super::super::taylor::ORDER`]),
    /// where [`Run::locate_rising`] takes the series to the order the
    /// sub-step's length needs.
    pub(super) fn check_located(&self, piece: &Piece, h: f64, before: &Envelope) {
        let n = self.layout.dofs;
        let ground = ground_at(piece, self.t);
        let size = |x: &[f64]| x.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
        let series = Series::new(
            &self.system,
            &self.u,
            &self.v,
            (ground.0, ground.1, piece.sigma),
            (size(&self.u), size(&self.v)),
        );
        assert!(series.radius >= h);
        let (mut us, mut vs, mut acc) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        // Every watched quantity at s, in the order of `watched` (|·| but
        // the signed relative displacements).
        let mut at = |s: f64| {
            series.state(s, &mut us, &mut vs);
            let a = ground_at(piece, self.t + s).0;
            self.system.acceleration(&us, &vs, a, &mut acc);
            let mut q: Vec<f64> = us.iter().chain(&vs).map(|x| x.abs()).collect();
            q.extend(acc.iter().map(|x| (x + a).abs()));
            q.extend(
                self.layout
                    .storeys
                    .iter()
                    .map(|st| self.layout.drift(st, &us).abs()),
            );
            q.extend(
                self.layout
                    .facing
                    .iter()
                    .map(|p| us[p.left_dof] - us[p.right_dof]),
            );
            q
        };
        let grid: Vec<Vec<f64>> = (0..=POINTS)
            .map(|p| at(h * p as f64 / POINTS as f64))
            .collect();
        let peaks = |e: &Envelope| {
            let mut p: Vec<f64> = [&e.displacement, &e.velocity, &e.acceleration, &e.drift]
                .into_iter()
                .flatten()
                .copied()
                .collect();
            p.extend(&e.relative);
            p
        };
        let (old, new) = (peaks(before), peaks(&self.envelope));
        let storeys = self.layout.storeys.len();
        for k in 0..old.len() {
            if new[k] == old[k] {
                continue;
            }
            let best = (0..=POINTS)
                .max_by(|&a, &b| grid[a][k].total_cmp(&grid[b][k]))
                .expect("points");
            let step = h / POINTS as f64;
            let (mut lo, mut hi) = (
                (best as f64 - 1.0).max(0.0) * step,
                ((best + 1) as f64 * step).min(h),
            );
            let g = 0.5 * (5f64.sqrt() - 1.0);
            for _ in 0..80 {
                let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
                if at(x1)[k] < at(x2)[k] {
                    lo = x1;
                } else {
                    hi = x2;
                }
            }
            let dense = grid[best][k].max(at(0.5 * (lo + hi))[k]);
            // The scale of the other checks: at least 1e-6 of its unit.
            let scale = new[k].abs().max(1e-6);
            assert!(
                (new[k] - dense).abs() <= SLACK * scale,
                "located peak {} of quantity {k} against {dense} on the dense walk",
                new[k]
            );
            let fixed = fixed_order_peak(&series, &self.watch[k], k, 3 * n + storeys, h);
            assert!(
                (new[k] - old[k].max(fixed)).abs() <= 1e-13 * scale,
                "located peak {} of quantity {k} against {fixed} on the fixed order",
                new[k]
            );
        }
        LOCATED.set(LOCATED.get() + 1);
    }
}

/// The largest value on [0, h] of watched quantity `k` (|·|, but the signed
/// relative displacements from index `signed` on) as a polynomial of
/// `series`: what [`Run::locate_rising`] takes on its own series.
fn fixed_order_peak(series: &Series, watch: &Watch, k: usize, signed: usize, h: f64) -> f64 {
    let mut c = Vec::new();
    quantity(series, watch, &mut c);
    if k < signed {
        poly::max_abs(&c, h)
    } else {
        poly::max(&c, h)
    }
}

#[cfg(test)]
mod tests {
    use super::{CHECKED, LOCATED};
    use crate::model::ContactModel;
    use crate::model::buildings::{self, Ground};
    use crate::model::simulated::Simulation;
    use crate::solver::buildings::{RowOptions, run_row};

    /// Block-and-frame under three simulated records at scales where it
    /// stays elastic, yields and pounds, under both laws of the Kelvin
    /// family: every sub-step the map takes passes the series check, those
    /// that only the quintic of [`super::super::super::quintic`] cleared of
    /// an onset, a yield or a rising peak among them.
    #[test]
    fn every_cleared_sub_step_holds_no_event_and_no_new_peak() {
        let base = buildings::load("block-and-frame").expect("shipped");
        let before = CHECKED.get();
        let located = LOCATED.get();
        let mut held = 0;
        for (seed, scale) in [(1u64, 0.5), (2, 2.0), (3, 3.0)] {
            let record = Simulation {
                dt: 0.005,
                duration: 3.0,
                ..Default::default()
            }
            .record("check", seed, 1);
            let ground = Ground::from_record(&record, scale);
            for model in [ContactModel::Kelvin, ContactModel::ImprovedKelvin] {
                let row = buildings::Row {
                    model,
                    ..base.clone()
                };
                let run = run_row(&row, &ground, &RowOptions::lasting(ground.end() + 1.0));
                let profile = run.expect("runs").profile;
                assert!(profile.map_steps > 0);
                held += profile.held;
            }
        }
        let checked = CHECKED.get() - before;
        assert!(checked > 1000, "{checked} sub-steps checked");
        let located = LOCATED.get() - located;
        assert!(
            located > 10,
            "{located} sub-steps with located peaks checked"
        );
        // Among the sub-steps checked, those the quintic cleared.
        assert!(held > 50, "{held} sub-steps cleared by the quintic checked");
    }
}
