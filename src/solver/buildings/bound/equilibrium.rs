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
//! Since any u* will do, it is taken as
//!
//! ```text
//! u* = K⁻¹M⁻¹q − a* K⁻¹1,
//! ```
//!
//! two vectors fixed while the configuration and its load stay: K⁻¹1 made
//! with K⁻¹, and K⁻¹M⁻¹q kept by [`Rest`] until the branches or the load
//! change (an event). A sub-step then costs O(n) for u* and the residual
//! on K's nonzeros, not the n² of K⁻¹ applied afresh; u* differs from
//! that product only by rounding, which the residual measures.
//!
//! After a storey yields, the row swings about its residual drift, which
//! the size from the origin counts as motion: through the free vibration
//! after a strong record every sub-step's allowance then stays as large as
//! the residual drift, and the quiet test fails on yield for each.

use nalgebra::DMatrix;

use crate::numerics::extremes::largest;

/// K⁻¹ and K's nonzeros by rows, of one configuration out of contact.
#[derive(Debug, Clone)]
pub struct Equilibrium {
    /// K⁻¹ by rows (n × n).
    inverse: Vec<f64>,
    /// K⁻¹1: the rest point's response to the ground's a*.
    ground_response: Vec<f64>,
    /// K's nonzeros (j, K_ij) of row i in `entries[start[i]..start[i + 1]]`.
    entries: Vec<(usize, f64)>,
    start: Vec<usize>,
    /// Whether the ground's a_g is at rest (σ = 0).
    line: bool,
}

impl Equilibrium {
    /// From the augmented matrix `a` of [`super::super::propagator`] (dofs
    /// `n`), whose rows n … 2n begin with −K; none where K is singular, or
    /// singular to working precision: where κ∞(K) = ‖K‖∞‖K⁻¹‖∞ ≥ 1/ε
    /// (a yielding storey whose post-yield ratio is 1e-300, say) u* has no
    /// correct digit and may be astronomically far, where products of it
    /// overflow; such a K is taken as the singular one it rounds to.
    pub fn of(a: &DMatrix<f64>, n: usize) -> Option<Equilibrium> {
        let k = DMatrix::from_fn(n, n, |i, j| -a[(n + i, j)]);
        let inverse = k.clone().try_inverse()?;
        let norm = |m: &DMatrix<f64>| {
            m.row_iter()
                .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
                .fold(0.0, f64::max)
        };
        let kappa = norm(&k) * norm(&inverse);
        // A NaN or ∞ in K⁻¹ fails it too.
        if kappa.is_nan() || kappa * f64::EPSILON >= 1.0 {
            return None;
        }
        let mut entries = Vec::new();
        let mut start = vec![0];
        for i in 0..n {
            entries.extend((0..n).filter(|&j| k[(i, j)] != 0.0).map(|j| (j, k[(i, j)])));
            start.push(entries.len());
        }
        let inverse: Vec<f64> = (0..n * n).map(|e| inverse[(e / n, e % n)]).collect();
        Some(Equilibrium {
            ground_response: inverse
                .chunks_exact(n)
                .map(|row| row.iter().sum())
                .collect(),
            inverse,
            entries,
            start,
            line: a[(2 * n + 1, 2 * n)] == 0.0,
        })
    }

    /// The rest point u* of the configuration of `branches` under `load`
    /// and the ground's a* = `still` (module doc), into `point`, and the
    /// residual M⁻¹q − a* 1 − K u* as computed, into `residual`: w* + (w −
    /// w*) is w itself whatever rounding u* carries.
    pub fn point(
        &self,
        (branches, rest): (&[u8], &mut Rest),
        load: &[f64],
        still: f64,
        (point, residual): (&mut [f64], &mut [f64]),
    ) {
        let n = point.len();
        point.copy_from_slice(&rest.point(self, branches, load, still)[..n]);
        for (i, r) in residual.iter_mut().enumerate() {
            *r = load[i] - still;
            for &(j, k) in &self.entries[self.start[i]..self.start[i + 1]] {
                *r -= k * point[j];
            }
        }
    }

    /// ‖D(w − w*)‖∞ (module doc) at (u, u̇) under ground (a, ȧ) with load
    /// M⁻¹q, for the scaling `scale` (the diagonal of D), in the
    /// configuration of `branches`, whose K⁻¹M⁻¹q `rest` keeps.
    pub fn size(
        &self,
        (u, v): (&[f64], &[f64]),
        (a, rate): (f64, f64),
        load: &[f64],
        scale: &[f64],
        (branches, rest): (&[u8], &mut Rest),
    ) -> f64 {
        let n = u.len();
        let still = if self.line { a } else { 0.0 };
        let gamma = (n + 3) as f64 * f64::EPSILON;
        let point = &rest.point(self, branches, load, still)[..n];
        let (u, v, load) = (&u[..n], &v[..n], &load[..n]);
        let (on_u, on_v) = (&scale[..n], &scale[n..2 * n]);
        let on_load = &scale[2 * n + 2..3 * n + 2];
        let mut m = largest(
            ((a - still) * scale[2 * n]).abs(),
            (rate * scale[2 * n + 1]).abs(),
        );
        for i in 0..n {
            let (mut residual, mut terms) = (load[i] - still, load[i].abs() + still.abs());
            for &(j, k) in &self.entries[self.start[i]..self.start[i + 1]] {
                let x = k * point[j];
                residual -= x;
                terms += x.abs();
            }
            m = largest(m, ((u[i] - point[i]) * on_u[i]).abs());
            m = largest(m, (v[i] * on_v[i]).abs());
            m = largest(m, (residual.abs() + gamma * terms) * on_load[i]);
        }
        m
    }
}

/// K⁻¹M⁻¹q of the configuration in force (module doc), kept from sub-step
/// to sub-step while its branches and its load stay the same, and the
/// rest point u* of the current sub-step.
#[derive(Debug, Clone, Default)]
pub struct Rest {
    branches: Vec<u8>,
    load: Vec<f64>,
    static_load: Vec<f64>,
    point: Vec<f64>,
}

impl Rest {
    /// u* = K⁻¹M⁻¹q − a* K⁻¹1 of `equilibrium` (the configuration of
    /// `branches`) under `load` and the ground's a* = `still`; K⁻¹M⁻¹q is
    /// made afresh only when the branches or the load have changed.
    fn point(
        &mut self,
        equilibrium: &Equilibrium,
        branches: &[u8],
        load: &[f64],
        still: f64,
    ) -> &[f64] {
        let n = load.len();
        if self.branches != branches || self.load != load {
            self.branches.clear();
            self.branches.extend_from_slice(branches);
            self.load.clear();
            self.load.extend_from_slice(load);
            self.static_load.clear();
            self.static_load.extend(
                equilibrium
                    .inverse
                    .chunks_exact(n)
                    .map(|row| row.iter().zip(load).map(|(k, q)| k * q).sum::<f64>()),
            );
        }
        self.point.clear();
        self.point.extend(
            self.static_load
                .iter()
                .zip(&equilibrium.ground_response)
                .map(|(p, r)| p - still * r),
        );
        &self.point
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Bounds, Watch};
    use super::Rest;
    use crate::model::buildings::load;
    use crate::solver::buildings::config::{Branch, Config};
    use crate::solver::buildings::layout::Layout;
    use crate::solver::buildings::propagator::augmented;
    use crate::solver::buildings::quintic;
    use crate::solver::buildings::system::System;
    use nalgebra::{DMatrix, DVector};

    /// Block-and-frame's layout, floors, fastest rate and storeys.
    fn block_and_frame() -> (Layout, usize, f64, usize) {
        let layout = Layout::of(&load("block-and-frame").expect("a shipped row"));
        let (n, s, storeys) = (layout.dofs, layout.rate, layout.storeys.len());
        (layout, n, s, storeys)
    }

    /// Block-and-frame with the frame's first storey yielding (its other
    /// storeys and the block elastic with plastic offsets of 1 to 10 mm):
    /// swinging by 1 mm and 1 cm/s about its static point under the load and
    /// a ground acceleration of 2 m/s² on a line, its size from that point
    /// is below a tenth of its size from the origin; and at 200 points of
    /// a sub-step of one radian each floor's u, u̇ and ü + a_g has its
    /// |q⁗| and |q⁽⁵⁾|, by nalgebra's exponential (no code shared), within
    /// the bounds the size gives (value_error · size · 384/h⁴), and its
    /// |q⁽⁶⁾| within the quintic's (quintic_error · size · 46080/h⁶).
    #[test]
    fn the_size_from_rest_bounds_the_derivatives_over_the_sub_step() {
        let (layout, n, s, storeys) = block_and_frame();
        let mut config = Config::at_rest(storeys, layout.pairs.len());
        config.branch[3] = Branch::Plus;
        config.plastic = (0..storeys).map(|i| 1e-3 * (i + 1) as f64).collect();
        let system = System::of(&layout, &config);
        let a = augmented(&system, 0.0);
        let h = 1.0 / s;
        let watch: Vec<Watch> = (0..3)
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
        let mut key = Vec::new();
        config.key_into(&mut key);
        let plain = bounds.size(
            (&u, &v),
            (ground, rate),
            &system.load,
            (&key, &mut Rest::default()),
        );
        let from_rest = equilibrium.size(
            (&u, &v),
            (ground, rate),
            &system.load,
            &bounds.scale,
            (&key, &mut Rest::default()),
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
        // Each quantity as a row cᵀ of the augmented state: a unit row of u
        // or u̇, or row n + i of 𝒜 with a_g's unit row for ü_i + a_g.
        let rows: Vec<DVector<f64>> = watch
            .iter()
            .map(|watch| {
                let i = watch.terms[0].0;
                match watch.order {
                    2 => DVector::from_fn(3 * n + 2, |j, _| {
                        a[(n + i, j)] + if j == 2 * n { 1.0 } else { 0.0 }
                    }),
                    order => {
                        DVector::from_fn(
                            3 * n + 2,
                            |j, _| {
                                if j == order * n + i { 1.0 } else { 0.0 }
                            },
                        )
                    }
                }
            })
            .collect();
        let a2 = &a * &a;
        let a4 = &a2 * &a2;
        let a5 = &a4 * &a;
        let a6 = &a5 * &a;
        for p in 0..=200 {
            let t = h * p as f64 / 200.0;
            let x = (&a * t).exp() * &w;
            let (d4, d5, d6) = (&a4 * &x, &a5 * &x, &a6 * &x);
            for (k, c) in rows.iter().enumerate() {
                let (value, rate) = bounds.errors(k, plain);
                let factor = 384.0 / h.powi(4);
                assert!(c.dot(&d4).abs() <= value * factor, "q⁗ of {k} at {t}");
                assert!(c.dot(&d5).abs() <= rate * factor, "q⁽⁵⁾ of {k} at {t}");
                let sixth = bounds.quintic_error(k, plain) * quintic::REMAINDER / h.powi(6);
                assert!(c.dot(&d6).abs() <= sixth, "q⁽⁶⁾ of {k} at {t}");
            }
        }
    }

    /// A K singular to working precision has no rest point, as a singular
    /// one has none: two one-storey buildings, one yielding with the
    /// post-yield ratio 1e-300 (κ∞ about 1e304, where u* would be of the
    /// order 1e299 and its products overflow), the other elastic; with a
    /// ratio of 1e-6 (κ∞ about 1e8) the rest point is kept.
    #[test]
    fn a_stiffness_singular_to_working_precision_has_no_rest_point() {
        let augmented = |soft: f64| {
            let (n, k) = (2, [soft, 7.4e4]);
            // (u, u̇, a_g, ȧ_g, M⁻¹q): only −K's block matters here.
            DMatrix::from_fn(3 * n + 2, 3 * n + 2, |i, j| {
                if (n..2 * n).contains(&i) && j == i - n {
                    -k[j]
                } else {
                    0.0
                }
            })
        };
        assert!(super::Equilibrium::of(&augmented(2e-300), 2).is_none());
        assert!(super::Equilibrium::of(&augmented(0.0), 2).is_none());
        assert!(super::Equilibrium::of(&augmented(2e-3), 2).is_some());
    }

    /// The rest point a kept [`Rest`] gives is K⁻¹(M⁻¹q − a*1) by
    /// nalgebra's LU within 1e-12 of its size, across a run of sub-steps
    /// whose ground changes each time and whose configuration changes its
    /// load (new plastic offsets, same branches) and its branches; and the
    /// size it gives is the one a fresh [`Rest`] gives, bit for bit, so no
    /// stale K⁻¹M⁻¹q is ever used.
    #[test]
    fn a_kept_rest_point_follows_the_load_and_the_branches() {
        let (layout, n, s, storeys) = block_and_frame();
        let h = 1.0 / s;
        let watch: Vec<Watch> = (0..n)
            .map(|i| Watch {
                terms: vec![(i, 1.0)],
                order: 0,
            })
            .collect();
        let mut kept = Rest::default();
        let mut key = Vec::new();
        let configs = [
            (None, 1e-3),
            (None, 2e-3),
            (Some(3), 2e-3),
            (Some(3), -1e-3),
            (None, 1e-3),
        ];
        for (step, (yielding, offset)) in configs.into_iter().enumerate() {
            let mut config = Config::at_rest(storeys, layout.pairs.len());
            if let Some(k) = yielding {
                config.branch[k] = Branch::Minus;
            }
            config.plastic = (0..storeys).map(|i| offset * (i + 1) as f64).collect();
            config.key_into(&mut key);
            let system = System::of(&layout, &config);
            let (bounds, _) = Bounds::with_map(&augmented(&system, 0.0), n, h, s, &watch);
            let equilibrium = bounds.equilibrium.as_ref().expect("K is regular");
            let k = DMatrix::from_fn(n, n, |i, j| system.stiffness[(i, j)]);
            for sub in 0..3 {
                let ground = 0.7 * step as f64 - 0.3 * sub as f64;
                let u: Vec<f64> = (0..n).map(|i| 1e-3 * (i + sub) as f64).collect();
                let v: Vec<f64> = (0..n).map(|i| 1e-2 * (i as f64 - 4.0)).collect();
                let sizes = [&mut kept, &mut Rest::default()].map(|rest| {
                    equilibrium.size(
                        (&u, &v),
                        (ground, 1.0),
                        &system.load,
                        &bounds.scale,
                        (&key, rest),
                    )
                });
                assert_eq!(sizes[0].to_bits(), sizes[1].to_bits());
                let b = DVector::from_fn(n, |i, _| system.load[i] - ground);
                let want = k.clone().lu().solve(&b).expect("regular");
                let got = &kept.point;
                let scale = want.amax();
                for i in 0..n {
                    assert!(
                        (got[i] - want[i]).abs() <= 1e-12 * scale,
                        "u*_{i}: {} against {}",
                        got[i],
                        want[i]
                    );
                }
            }
        }
    }
}
