//! The quiet test's state size measured from a rest point of the motion
//! (SPEC §13), so that a row swinging about a point away from the origin
//! (a residual drift after yielding, a ground acceleration) has the size
//! of its swing.
//!
//! The error bounds of [`super::Bounds`] rest on
//! |q⁽ᵏ⁾(t)| = |cᵀ𝒜ᵏe^{𝒜t}w(0)|. For any w* with 𝒜w* = 0, e^{𝒜t}w* = w*
//! and 𝒜ᵏw* = 0 (k ≥ 1), so q⁽ᵏ⁾(t) = cᵀ𝒜ᵏe^{𝒜t}(w(0) − w*) too, and
//! the bound may take ‖D(w(0) − w*)‖∞ for ‖D w(0)‖∞. With K = M⁻¹K, and
//! the ground at rest only on a line (σ = 0, where (a_g, ȧ_g) = (a*, 0) is
//! still),
//!
//! ```text
//! w* = (u*, 0, a*, 0, q*),   q* = K u* + a* 1,   a* = a_g if σ = 0, else 0,
//! ```
//!
//! is at rest for every u*, and
//! w − w* = (u − u*, u̇, a_g − a*, ȧ_g, M⁻¹q − K u* − a* 1). The u* taken is
//! K⁻¹(M⁻¹q − a* 1) in floating point (the static displacement under the
//! load and the ground's acceleration), so the last part is that solve's
//! residual, whose computed value is widened by the rounding of its own
//! sums, γ(|M⁻¹q_i| + |a*| + Σ_j|K_ij u*_j|) with γ = (n + 3)ε: w* is then
//! exactly at rest whatever rounding u* carries, and the size's own
//! relative rounding is far inside the bound's allowance. The smaller of
//! the two sizes is taken; where K is singular, the size from the origin.
//!
//! After a storey yields, the row swings about its residual drift, which
//! the size from the origin counts as motion: through the free vibration
//! after a strong record every sub-step's allowance then stays as large as
//! the residual drift, and the quiet test fails on yield for each.

use nalgebra::DMatrix;

/// K⁻¹ and K's nonzeros by rows, of one configuration out of contact.
#[derive(Debug, Clone)]
pub struct Equilibrium {
    /// K⁻¹ by rows (n × n).
    inverse: Vec<f64>,
    /// K's nonzeros (j, K_ij) of row i in `entries[start[i]..start[i + 1]]`.
    entries: Vec<(usize, f64)>,
    start: Vec<usize>,
    /// Whether the ground's a_g is at rest (σ = 0).
    line: bool,
}

impl Equilibrium {
    /// From the augmented matrix `a` of [`super::super::propagator`] (dofs
    /// `n`), whose rows n … 2n begin with −K; none where K is singular.
    pub fn of(a: &DMatrix<f64>, n: usize) -> Option<Equilibrium> {
        let k = DMatrix::from_fn(n, n, |i, j| -a[(n + i, j)]);
        let inverse = k.clone().try_inverse()?;
        if !inverse.iter().all(|x| x.is_finite()) {
            return None;
        }
        let mut entries = Vec::new();
        let mut start = vec![0];
        for i in 0..n {
            entries.extend((0..n).filter(|&j| k[(i, j)] != 0.0).map(|j| (j, k[(i, j)])));
            start.push(entries.len());
        }
        Some(Equilibrium {
            inverse: (0..n * n).map(|e| inverse[(e / n, e % n)]).collect(),
            entries,
            start,
            line: a[(2 * n + 1, 2 * n)] == 0.0,
        })
    }

    /// ‖D(w − w*)‖∞ (module doc) at (u, u̇) under ground (a, ȧ) with load
    /// M⁻¹q, for the scaling `scale` (the diagonal of D); u* is written
    /// into `rest`.
    pub fn size(
        &self,
        (u, v): (&[f64], &[f64]),
        (a, rate): (f64, f64),
        load: &[f64],
        scale: &[f64],
        rest: &mut Vec<f64>,
    ) -> f64 {
        let n = u.len();
        let still = if self.line { a } else { 0.0 };
        let gamma = (n + 3) as f64 * f64::EPSILON;
        rest.clear();
        rest.extend(self.inverse.chunks_exact(n).map(|row| {
            row.iter()
                .zip(load)
                .map(|(k, q)| k * (q - still))
                .sum::<f64>()
        }));
        let mut m = ((a - still) * scale[2 * n])
            .abs()
            .max((rate * scale[2 * n + 1]).abs());
        for i in 0..n {
            let (mut residual, mut terms) = (load[i] - still, load[i].abs() + still.abs());
            for &(j, k) in &self.entries[self.start[i]..self.start[i + 1]] {
                residual -= k * rest[j];
                terms += (k * rest[j]).abs();
            }
            m = m
                .max(((u[i] - rest[i]) * scale[i]).abs())
                .max((v[i] * scale[n + i]).abs())
                .max((residual.abs() + gamma * terms) * scale[2 * n + 2 + i]);
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Bounds, Watch};
    use crate::model::buildings::load;
    use crate::solver::buildings::config::{Branch, Config};
    use crate::solver::buildings::layout::Layout;
    use crate::solver::buildings::propagator::augmented;
    use crate::solver::buildings::system::System;
    use nalgebra::{DMatrix, DVector};

    /// Block-and-frame with the frame's first storey yielding (its other
    /// storeys and the block elastic with plastic offsets of 1 to 10 mm):
    /// swinging by 1 mm and 1 cm/s about its static point under the load and
    /// a ground acceleration of 2 m/s² on a line, its size from that point
    /// is below a tenth of its size from the origin; and at 200 points of
    /// a sub-step of one radian each floor's |u⁗| and |u⁽⁵⁾|, by
    /// nalgebra's exponential (no code shared), stay within the bounds
    /// the size gives (value_error · size · 384/h⁴).
    #[test]
    fn the_size_from_rest_bounds_the_derivatives_over_the_sub_step() {
        let row = load("block-and-frame").expect("a shipped row");
        let layout = Layout::of(&row);
        let (n, s) = (layout.dofs, layout.rate);
        let storeys = layout.storeys.len();
        let mut config = Config::at_rest(storeys, layout.pairs.len());
        config.branch[3] = Branch::Plus;
        config.plastic = (0..storeys).map(|i| 1e-3 * (i + 1) as f64).collect();
        let system = System::of(&layout, &config);
        let a = augmented(&system, 0.0);
        let h = 1.0 / s;
        let watch: Vec<Watch> = (0..2)
            .flat_map(|order| {
                (0..n).map(move |i| Watch {
                    terms: vec![(i, 1.0)],
                    order,
                })
            })
            .collect();
        let (bounds, _) = Bounds::with_map(&a, n, h, s, &watch);
        let equilibrium = bounds.equilibrium.as_ref().expect("K is regular");
        let (ground, rate) = (2.0, 30.0);
        let k = DMatrix::from_fn(n, n, |i, j| system.stiffness[(i, j)]);
        let b = DVector::from_fn(n, |i, _| system.load[i] - ground);
        let still = k.lu().solve(&b).expect("regular");
        let u: Vec<f64> = (0..n)
            .map(|i| still[i] + 1e-3 * (i as f64 * 0.7).sin())
            .collect();
        let v: Vec<f64> = (0..n).map(|i| 1e-2 * (i as f64 * 1.3).cos()).collect();
        let plain = bounds.size((&u, &v), (ground, rate), &system.load, &mut Vec::new());
        let mut rest = Vec::new();
        let from_rest = equilibrium.size(
            (&u, &v),
            (ground, rate),
            &system.load,
            &bounds.scale,
            &mut rest,
        );
        let scale = &bounds.scale;
        let mut origin = (ground * scale[2 * n])
            .abs()
            .max((rate * scale[2 * n + 1]).abs());
        for i in 0..n {
            origin = origin
                .max((u[i] * scale[i]).abs())
                .max((v[i] * scale[n + i]).abs())
                .max((system.load[i] * scale[2 * n + 2 + i]).abs());
        }
        assert!(from_rest < 0.1 * origin, "{from_rest} against {origin}");
        assert_eq!(plain, from_rest.min(origin));
        let w = DVector::from_iterator(
            3 * n + 2,
            u.iter()
                .chain(&v)
                .copied()
                .chain([ground, rate])
                .chain(system.load.iter().copied()),
        );
        let a2 = &a * &a;
        let a4 = &a2 * &a2;
        let a5 = &a4 * &a;
        for p in 0..=200 {
            let t = h * p as f64 / 200.0;
            let x = (&a * t).exp() * &w;
            let (d4, d5) = (&a4 * &x, &a5 * &x);
            for (k, watch) in watch.iter().enumerate() {
                let row = watch.order * n + watch.terms[0].0;
                let (value, rate) = bounds.errors(k, plain);
                let factor = 384.0 / h.powi(4);
                assert!(d4[row].abs() <= value * factor, "q⁗ of {k} at {t}");
                assert!(d5[row].abs() <= rate * factor, "q⁽⁵⁾ of {k} at {t}");
            }
        }
    }
}
