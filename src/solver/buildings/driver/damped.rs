//! A row's step with its fluid viscous dampers carried inside the Taylor
//! series (SPEC §14, [`super::super::power_series`]), where that pays
//! against the collocated step of [`super::super::damper_collocation`].
//!
//! Away from a reversal a damper's force c_l|Δv|^α sgn Δv is analytic in
//! time as far as Δv's nearest (complex) zero, at a distance ρ of the
//! order of |Δv/Δv̇|, and the series of the motion with the force in it
//! reaches some 0.3 to 0.8 ρ at K = 40 orders, where the collocated step,
//! its error O(h⁸) held to 1e-12, reaches some 0.03 ρ at ten times the
//! cost. The series cannot reach a reversal (its radius falls with ρ: the
//! steps towards it shrink geometrically), which the collocated step
//! crosses by placing the kink on its dense output; and it is explicit, so
//! that over a step of many relaxation times of a stiff damper it would
//! magnify rounding as e^(h/τ): see [`Run::damped_series`].

use super::super::taylor::Series;
use super::Run;

/// Steps of the damped series at most this many relaxation times of the
/// stiffest damper long ([`super::super::damper::Damper::relaxation`]).
///
/// Over h = 6τ the damper's fast mode e^(−s/τ) has its largest Taylor
/// term, 6⁵/5! = 6⁶/6! ≈ 65, at orders 5 and 6, and its term of order
/// [`super::super::taylor::MAX_ORDER`] is 6⁴⁰/40! ≈ 1.6e-17: the rounding
/// carried into that mode stays under e⁶ ≈ 400 ulps, some 4e-14, below
/// the 1e-12 to which steps are held. Six rather than three, on
/// block-and-frame-retrofit with its damper at α = 0.35 under
/// synthetic:2000: 3,630 collocated steps against 4,296, the run 1.17
/// times faster, and the damper row 2.64e-10 from the independent
/// reference at c = 4e6 against 2.51e-10 (its limit 5e-9).
pub const RELAXATIONS: f64 = 6.0;

/// Relative size of a damper's force's last two terms at a damped step's
/// end: the link's peak force, taken on that series, is compared at 1e-12.
const FORCE_TOLERANCE: f64 = 1e-14;

impl Run<'_> {
    /// The series of the motion from the current state with the dampers'
    /// forces in it, over at most `rem`, when it replaces the collocated
    /// step (else None, and the step goes by the collocation as before);
    /// its radius cut to where it holds:
    ///
    /// - no pair is closed under a Hertz-type law (its force is not
    ///   analytic at onset; the improved Kelvin law's products are carried
    ///   by the series as they are without dampers), no damper's Δv is 0
    ///   (a reversal: the force's branch point), and the coefficients are
    ///   finite (they overflow where Δv is within rounding of 0);
    /// - the step is at most [`RELAXATIONS`] relaxation times τ of every
    ///   damper: an explicit series over h carries the rounding of its
    ///   low orders into the damper's fast mode, magnified up to e^(h/τ)
    ///   (e⁶ ≈ 400 ulps at six);
    /// - the step is within each damper's force's own radius, its last two
    ///   coefficients F_k h^k within [`FORCE_TOLERANCE`] of F_0: the motion's
    ///   test sees F only through F/m against the motion's scales, so a
    ///   weak damper's series could run past Δv's zero, where the series
    ///   of F, from which the link's peak force is taken, diverges;
    /// - the step reaches the sub-step's end, or is at least the
    ///   collocation's next step (`next_contact_step`): near a reversal,
    ///   where the series' steps shrink with the distance to it, and where
    ///   the damper is stiff over the collocation's step, the collocation
    ///   takes over. The balance sits at equal lengths: on
    ///   block-and-frame-retrofit at α = 0.35 under synthetic:2000, series
    ///   steps allowed down to half or 0.7 of the collocation's made the
    ///   run 1.2 and 1.06 times longer, held to 1.5 or 2.5 times it, 1.04
    ///   and 1.15 times.
    pub(super) fn damped_series(
        &mut self,
        rem: f64,
        ground: (f64, f64, f64),
        scale: (f64, f64),
    ) -> Option<Series> {
        let dampers = &self.layout.dampers;
        let mut hertzian = self.config.contact.iter().flatten();
        if hertzian.any(|c| !c.law.is_analytic()) || dampers.iter().any(|d| d.rate(&self.v) == 0.0)
        {
            return None;
        }
        // The relaxation bound is known from the start's Δv alone: where it
        // already falls short of both the sub-step's end and the
        // collocation's next step, the series would be declined, and is
        // not filled.
        let stiffest = dampers
            .iter()
            .map(|d| RELAXATIONS * d.relaxation(d.rate(&self.v)))
            .fold(f64::INFINITY, f64::min);
        if stiffest < rem && stiffest < self.next_contact_step {
            return None;
        }
        // Filled to the order that carries it over the shorter of the
        // sub-step and that bound, the longest step it can take (on
        // block-and-frame-retrofit at α = 0.35 under synthetic:2000 the
        // accepted series' orders sum to 67,152 so, 81,415 filled over
        // the sub-step, in as many steps to within 0.4 %).
        let mut series = std::mem::take(&mut self.spare_series);
        let start = (&self.u[..], &self.v[..]);
        let want = rem.min(stiffest);
        series.fill_damped(&self.system, start, ground, scale, (want, dampers));
        let finite = series.held().iter().all(|x| x.is_finite());
        let mut reach = series.radius.min(stiffest);
        for force in series.forces.chunks_exact(series.degree + 1) {
            let k = series.degree;
            for (j, f) in [(k - 1, force[k - 1]), (k, force[k])] {
                if f != 0.0 {
                    let r = (FORCE_TOLERANCE * force[0].abs() / f.abs()).powf(1.0 / j as f64);
                    reach = reach.min(r);
                }
            }
        }
        series.radius = reach;
        let end = rem.min(reach);
        if finite && (end >= rem || end >= self.next_contact_step) {
            self.profile.collocation.series += 1;
            Some(series)
        } else {
            self.spare_series = series;
            None
        }
    }
}
