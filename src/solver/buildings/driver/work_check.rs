//! The checks of the balance's closed forms on map steps ([`super::work`]),
//! in tests only:
//!
//! - every map step of a run under [`checking`] is walked again by the
//!   Taylor series of the same motion from the same state, each piece
//!   integrated by the Gauss–Legendre rule as a series step is, and each
//!   term (and each link's dissipation) must agree with the closed forms
//!   to 1e-12 of the energy the row holds at the step's start (or of the
//!   step's largest term, if larger): the springs' terms are differences
//!   of stored energy, whose rounding is relative to it;
//! - a run with [`super::RowOptions::series_only`] takes every sub-step by
//!   the series, the way the balance was taken before the closed forms, to
//!   compare whole runs' balances against.

use std::cell::Cell;

use crate::model::buildings::ground::Piece;

use super::super::energy::{NODES, RowEnergy, gauss_legendre};
use super::super::taylor::Series;
use super::{Run, ground_triple};

/// What the map steps checked on this thread met: how many, the worst
/// difference against the series (relative to the step's largest term),
/// and how many had a yielding storey, a plastic offset, P-Δ, a link.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Checked {
    pub steps: usize,
    pub worst: f64,
    pub yielding: usize,
    pub offset: usize,
    pub p_delta: usize,
    pub link: usize,
}

thread_local! {
    static CHECKING: Cell<bool> = const { Cell::new(false) };
    static CHECKED: Cell<Checked> = Cell::new(Checked::default());
}

/// Whether map steps are checked against the series on this thread.
pub(super) fn checking() -> bool {
    CHECKING.with(Cell::get)
}

impl Run<'_> {
    /// The energy the row holds: ½Σ m u̇², and ½|VΔ| of each storey and
    /// ½k_l Δu² of each link (J).
    fn held(&self) -> f64 {
        let layout = &self.layout;
        let kinetic: f64 = (0..layout.dofs)
            .map(|i| 0.5 * layout.mass[i] * self.v[i] * self.v[i])
            .sum();
        let storeys: f64 = layout
            .storeys
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let d = layout.drift(s, &self.u);
                0.5 * (self.shear(k, s, d) * d).abs()
            })
            .sum();
        let links: f64 = layout
            .links
            .iter()
            .map(|l| {
                0.5 * l.link.stiffness
                    * (self.u[l.pair.left_dof] - self.u[l.pair.right_dof]).powi(2)
            })
            .sum();
        kinetic + storeys + links
    }

    /// Integrates the map step from the current state over h on `piece` by
    /// the series and compares with the closed forms' `step` and each
    /// link's `dissipated` energy.
    pub(super) fn check_work(&self, piece: &Piece, h: f64, step: &RowEnergy, dissipated: &[f64]) {
        let (nodes, weights) = gauss_legendre(NODES);
        let (mut u, mut v) = (self.u.clone(), self.v.clone());
        let mut sums = RowEnergy::default();
        let mut links = vec![0.0; self.layout.links.len()];
        let size = |x: &[f64]| x.iter().fold(1e-6f64, |m, x| m.max(x.abs()));
        let mut s0 = 0.0;
        while s0 < h {
            let ground = ground_triple(piece, self.t + s0);
            let mut series = Series::default();
            let scale = (size(&u), size(&v));
            series.fill_over(&self.system, (&u, &v), ground, scale, h - s0);
            let end = (h - s0).min(series.radius);
            self.quadrature(&series, end, (&nodes, &weights), &mut sums, &mut links);
            series.state(end, &mut u, &mut v);
            s0 = if end >= h - s0 { h } else { s0 + end };
        }
        let pairs = [
            (step.input, sums.input),
            (step.damping, sums.damping),
            (step.spring, sums.spring),
            (step.contact, sums.contact),
            (step.bumper, sums.bumper),
            (step.link, sums.link),
        ];
        let all = pairs
            .into_iter()
            .chain(dissipated.iter().copied().zip(links.iter().copied()));
        // The energy the row holds at the start: the springs' terms are
        // differences of it, whose rounding is relative to it.
        let held = self.held();
        let scale = all
            .clone()
            .fold(held, |m, (a, b)| m.max(a.abs()).max(b.abs()));
        let worst = all.fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
        CHECKED.with(|c| {
            let mut seen = c.get();
            seen.steps += 1;
            seen.worst = seen.worst.max(worst);
            let yielding = self
                .config
                .branch
                .iter()
                .any(|b| *b != super::Branch::Elastic);
            seen.yielding += usize::from(yielding);
            seen.offset += usize::from(self.config.plastic.iter().any(|p| *p != 0.0));
            let p_delta = self.layout.storeys.iter().any(|s| s.geometric > 0.0);
            seen.p_delta += usize::from(p_delta);
            seen.link += usize::from(!self.layout.links.is_empty());
            c.set(seen);
        });
    }
}

#[cfg(test)]
mod tests {
    use super::{CHECKED, CHECKING, Checked};
    use crate::model::buildings::matrices::default_tail;
    use crate::model::buildings::{self, Ground, Row};
    use crate::model::simulated::Simulation;
    use crate::solver::buildings::{RowOptions, RowRun, run_row};

    /// Block-and-frame elastic (scale 1) and yielding (2, 3), its retrofit
    /// with a linear link and bumpers (1, 3), its P-Δ variant yielding (3)
    /// and collapsing (6).
    const CASES: [(&str, f64); 7] = [
        ("block-and-frame", 1.0),
        ("block-and-frame", 2.0),
        ("block-and-frame", 3.0),
        ("block-and-frame-retrofit", 1.0),
        ("block-and-frame-retrofit", 3.0),
        ("block-and-frame-pdelta", 3.0),
        ("block-and-frame-pdelta", 6.0),
    ];

    /// `row` under synthetic:2000 at `scale`, for the record's length and
    /// the row's tail (as `run --buildings`), with its balance or without.
    fn run_with(row: &Row, scale: f64, (energy, series_only): (bool, bool)) -> RowRun {
        let record = Simulation::synthetic("synthetic:2000", 2000).expect("a record");
        let ground = Ground::from_record(&record, scale);
        let options = RowOptions {
            energy,
            series_only,
            ..RowOptions::lasting(ground.end() + default_tail(row))
        };
        run_row(row, &ground, &options).expect("runs")
    }

    fn run(row: &Row, scale: f64) -> RowRun {
        run_with(row, scale, (true, false))
    }

    /// On [`CASES`]' every map step the closed forms give the series'
    /// quadrature on the same interval to 1e-12 of the energy the row holds
    /// (about 9,000 steps; the worst was 3.5e-13), with yielding storeys (a
    /// storey yields mostly in contact: some 50 map steps), plastic
    /// offsets, P-Δ and a link among them.
    #[test]
    fn map_steps_give_the_series_quadrature() {
        CHECKING.with(|c| c.set(true));
        CHECKED.with(|c| c.set(Checked::default()));
        for (name, scale) in CASES {
            let row = buildings::load(name).expect("shipped");
            let r = run(&row, scale);
            assert!(r.map_steps > 100, "{name}: {} map steps", r.map_steps);
        }
        CHECKING.with(|c| c.set(false));
        let seen = CHECKED.with(|c| c.get());
        assert!(seen.worst < 1e-12, "{seen:?}");
        assert!(
            seen.yielding > 20 && seen.offset > 1000 && seen.p_delta > 1000 && seen.link > 1000,
            "{seen:?}"
        );
    }

    /// The balance with closed forms on the map steps against the balance
    /// with every sub-step by the series (as it was taken before): each
    /// term, and each link's dissipated energy, within 1e-10 of max |E_in|
    /// on [`CASES`], both closing to 1e-12; the run with closed forms takes
    /// the same steps, bit for bit, as the run without its balance.
    #[test]
    fn the_closed_forms_give_the_series_balance() {
        for (name, scale) in CASES {
            let row = buildings::load(name).expect("shipped");
            let new = run(&row, scale);
            let bare = run_with(&row, scale, (false, false));
            assert_eq!(new.final_displacement, bare.final_displacement);
            assert_eq!(new.final_velocity, bare.final_velocity);
            // By their printing, exact for floats, where an open impact's
            // end at a collapse is NaN.
            let show = |r: &RowRun| format!("{:?} {:?} {:?}", r.floors, r.pairs, r.collapse);
            assert_eq!(show(&new), show(&bare));
            assert_eq!(
                (new.map_steps, new.series_steps),
                (bare.map_steps, bare.series_steps)
            );
            let old = run_with(&row, scale, (true, true));
            assert_eq!(old.map_steps, 0, "{name}");
            assert!(new.map_steps > 100, "{name} {scale}: {}", new.map_steps);
            let (e, f) = (new.energy.expect("asked"), old.energy.expect("asked"));
            let top = e.max_input.max(f.max_input);
            let terms = [
                ("input", e.input, f.input),
                ("kinetic", e.kinetic, f.kinetic),
                ("damping", e.damping, f.damping),
                ("spring", e.spring, f.spring),
                ("contact", e.contact, f.contact),
                ("bumper", e.bumper, f.bumper),
                ("link", e.link, f.link),
            ];
            let links = new.links.iter().zip(&old.links);
            let links = links.map(|(a, b)| ("link energy", a.energy, b.energy));
            let mut worst = (0.0f64, "");
            for (term, a, b) in terms.into_iter().chain(links) {
                if (a - b).abs() > worst.0 * top {
                    worst = ((a - b).abs() / top, term);
                }
                assert!(
                    (a - b).abs() < 1e-10 * top,
                    "{name} at {scale}: {term} {a} against {b} (max |E_in| {top})"
                );
            }
            assert!(e.residual() < 1e-12 && f.residual() < 1e-12, "{e:?} {f:?}");
            // Shown with --nocapture.
            let (r, g) = (e.residual(), f.residual());
            eprintln!(
                "{name} at {scale}: worst {:.1e} ({}), residuals {r:.1e} and {g:.1e}",
                worst.0, worst.1
            );
        }
    }
}
