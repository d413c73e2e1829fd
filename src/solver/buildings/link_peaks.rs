//! The links' peaks inside one step of the exact method (SPEC §14), on the
//! polynomials of its [`Series`]: |Δu| and |Δv| on theirs, |F| on its own
//! for a linear link.

use crate::model::buildings::LinkElement;
use crate::solver::exact::contact_rk::equispaced_quintic;

use super::link::LinkResult;
use super::poly;
use super::taylor::Series;

/// Raises each link's peaks over [0, end] of a step written as `series`:
/// |Δu| and |Δv| on their polynomials; |F| on its polynomial for a linear
/// link, and on the quintic through six equally spaced values of F for a
/// damper (α < 1), as the Hertz-type contact forces are taken.
pub fn peaks_on(
    links: &[LinkElement],
    series: &Series,
    end: f64,
    out: &mut [LinkResult],
    (du, dv): (&mut Vec<f64>, &mut Vec<f64>),
) {
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
        let force: Vec<f64> = if l.is_linear() {
            du.iter()
                .zip(dv.iter())
                .map(|(x, y)| l.link.stiffness * x + l.link.damping * y)
                .collect()
        } else {
            let values = std::array::from_fn(|j| {
                let s = end * j as f64 / 5.0;
                l.force(poly::eval(du, s), poly::eval(dv, s))
            });
            equispaced_quintic(&values, end).c[..=5].to_vec()
        };
        if poly::magnitude_bound(&force, end) > r.max_force {
            r.max_force = r.max_force.max(poly::max_abs(&force, end));
        }
    }
}
