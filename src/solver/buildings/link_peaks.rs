//! The links' peaks inside one step of the exact method (SPEC §14), on the
//! polynomials of its [`Series`]: |Δu| and |Δv| on theirs, |F| on its own
//! for a linear link, and for a damper on a step of the series with its
//! force in it (its Taylor series, [`super::power_series`]) or a
//! collocated step (its force polynomial).

use crate::model::buildings::LinkElement;
use crate::solver::exact::contact_rk::equispaced_quintic;

use super::link::LinkResult;
use super::poly;
use super::taylor::Series;

/// Raises each link's peaks over [0, end] of a step written as `series`:
/// |Δu| and |Δv| on their polynomials; |F| on its polynomial for a linear
/// link, and for a damper (α < 1) on F's Taylor series where the step is
/// the series with the damper's force in it ([`Series::damper_force`]: F
/// is analytic over the step, and that series is the one the motion
/// carried; a step 0.3 to 0.4 of the way to Δv's nearest zero is too long
/// for the quintic, which missed the peak force by 1.5e-9 at c = 1e5) and
/// on a collocated step's force polynomial (the force its motion
/// answers, where the law at an all but locked damper's interpolated Δv
/// would amplify Δv's error), else on the quintic through six equally
/// spaced values of F, as the Hertz-type contact forces are taken on the
/// Runge–Kutta steps.
pub fn peaks_on(
    links: &[LinkElement],
    series: &Series,
    end: f64,
    out: &mut [LinkResult],
    (du, dv): (&mut Vec<f64>, &mut Vec<f64>),
) {
    // The dampers are the links that are not linear, in link order
    // ([`super::damper::Damper::all`]): this one's index among them.
    let mut damper = 0;
    for (l, r) in links.iter().zip(out) {
        let (a, b) = (l.pair.left_dof, l.pair.right_dof);
        series.combine(&[(a, 1.0), (b, -1.0)], &[], du);
        series.combine(&[], &[(a, 1.0), (b, -1.0)], dv);
        if poly::magnitude_bound(du, end) > r.stroke {
            r.stroke = r.stroke.max(poly::max_abs(du, end));
        }
        if poly::magnitude_bound(dv, end) > r.max_rate {
            r.max_rate = r.max_rate.max(poly::max_abs(dv, end));
        }
        let (linear, quintic);
        let force: &[f64] = if l.is_linear() {
            linear = du
                .iter()
                .zip(dv.iter())
                .map(|(x, y)| l.link.stiffness * x + l.link.damping * y)
                .collect::<Vec<f64>>();
            &linear
        } else {
            damper += 1;
            match series.damper_force(damper - 1) {
                Some(force) => force,
                None => {
                    let values = std::array::from_fn(|j| {
                        let s = end * j as f64 / 5.0;
                        l.force(poly::eval(du, s), poly::eval(dv, s))
                    });
                    quintic = equispaced_quintic(&values, end);
                    &quintic.c[..=5]
                }
            }
        };
        if poly::magnitude_bound(force, end) > r.max_force {
            r.max_force = r.max_force.max(poly::max_abs(force, end));
        }
    }
}
