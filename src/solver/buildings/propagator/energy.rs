//! The energy balance's integrals over a map step (SPEC §6 summed over
//! buildings, §13; links §14), in closed form, made once per cached map.
//!
//! On a map step the configuration is fixed and out of contact, and the
//! augmented state w = (u, u̇, a_g, ȧ_g, M⁻¹q) of [`super`] moves by
//! w(s) = e^{𝒜s} w₀. Three integrands of the balance are quadratic forms of
//! w,
//!
//! ```text
//! E_damp:  u̇ᵀC u̇,              E_in:  −a_g Σ m_i u̇_i,
//! link l:  c_l (u̇_A − u̇_B)²    (its dashpot, α = 1; the whole of E_l),
//! ```
//!
//! each wᵀQw with Q symmetric, so over the step
//!
//! ```text
//! ∫₀ʰ w(s)ᵀQ w(s) ds = w₀ᵀ W w₀,   W = ∫₀ʰ e^{𝒜ᵀs} Q e^{𝒜s} ds,
//! ```
//!
//! exactly. W comes from Van Loan's block exponential (C. F. Van Loan,
//! "Computing integrals involving the matrix exponential", IEEE Trans.
//! Automatic Control 23, 1978, Theorem 1):
//!
//! ```text
//! exp([[−𝒜ᵀ, Q], [0, 𝒜]] h) = [[F₁₁, G₁₂], [0, F₂₂]],   W = F₂₂ᵀ G₁₂,
//! ```
//!
//! taken by [`super::super::expm`] on the scaled 𝒜̃ = D𝒜D⁻¹ of
//! [`super::super::bound::scaled`] (so that its norm is a few units and the
//! squarings few): e^{𝒜s} = D⁻¹e^{𝒜̃s}D gives W = D W̃ D with W̃ the integral
//! of Q̃ = D⁻¹QD⁻¹ under 𝒜̃. W is linear in Q, so Q̃ enters divided by its
//! largest entry (the off-diagonal block would otherwise set the norm, and
//! the squarings, of the whole) and W̃ is multiplied back.
//!
//! The other terms need no integral: in a fixed configuration out of
//! contact a storey's shear is linear in its drift, V = (k − k_G)Δ −
//! (1 − α)k p elastic or V = (αk − k_G)Δ ± (1 − α)kΔ_y yielding (SPEC §3,
//! §15), and a link's spring force is k_l Δu, so their work ∫ V dΔ is
//! the trapezoid (Δ₁ − Δ₀)(V₀ + V₁)/2, exact for a linear V; E_kin is taken
//! from the state; the contact and bumper terms are zero.
//!
//! **Measured from a rest point.** After a storey yields the row swings
//! about its residual drift: u and M⁻¹q are then large and their effects
//! on u̇ cancel, and a quadratic form of w would lose the digits of that
//! cancellation squared. As in [`super::super::bound::Equilibrium`], any
//! w* with 𝒜w* = 0 stays put, w* = (u*, 0, a*, 0, K u* + a* 1) (K here
//! M⁻¹K, a* = a_g on a line, σ = 0, else 0), so w(s) = w* + e^{𝒜s}δ with
//! δ = w₀ − w*, taking u* = K⁻¹(M⁻¹q − a* 1), the static displacement, as
//! the quiet test takes it and from the same kept vectors
//! ([`Equilibrium::point`]; none where K is singular). w* moves no floor,
//! so the damping and dashpot integrals are δᵀWδ; E_in's a_g holds a*
//! beside δ's part, whose work is
//! −a* Σ m_i ∫ u̇_i ds = −a* Σ m_i (u_i(h) − u_i(0)):
//!
//! ```text
//! E_in = δᵀW_in δ − a* Σ m_i (u_i(h) − u_i(0)).
//! ```
//!
//! δ's last part, M⁻¹q − K u* − a* 1, is the solve's residual as computed,
//! so w* + δ = w₀ whatever the rounding of u*.
//!
//! Per step the forms cost one product δ_i δ_j per pair i ≤ j, and one sum
//! of as many terms per form ([`WorkForms::on`]).

use nalgebra::DMatrix;

use super::super::bound::{Equilibrium, Rest, scaled};
use super::super::expm::exponential_blocks;
use super::super::layout::Layout;
use super::super::sparse::Sparse;

/// Where each form is in [`WorkForms`]'s list: E_damp, E_in, then each
/// link's dashpot in link order.
pub const DAMPING: usize = 0;
pub const INPUT: usize = 1;
pub const FIRST_LINK: usize = 2;

/// The matrices W of the balance's quadratic forms over one map step, each
/// packed as its upper triangle row by row, the entries off the diagonal
/// doubled, so that w₀ᵀWw₀ = Σ_{i ≤ j} P_ij w_i w_j.
#[derive(Debug, Clone)]
pub struct WorkForms {
    /// The size of w, 3n + 2.
    size: usize,
    /// The forms one after another, each size (size + 1)/2 long.
    packed: Vec<f64>,
    /// The configuration's rest points (none where K is singular).
    equilibrium: Option<Equilibrium>,
    /// Whether the ground's a_g stays put on the piece (σ = 0).
    line: bool,
    /// The floors' masses (kg).
    mass: Vec<f64>,
}

/// The matrices Q of the integrands above on w = (u, u̇, a_g, ȧ_g, M⁻¹q), in
/// the order of [`DAMPING`], [`INPUT`], [`FIRST_LINK`].
pub fn integrands(layout: &Layout) -> Vec<DMatrix<f64>> {
    let n = layout.dofs;
    let d = 3 * n + 2;
    let v = |i: usize| n + i;
    let mut damping = DMatrix::zeros(d, d);
    for i in 0..n {
        for j in 0..n {
            // C = M (M⁻¹C), symmetric; its two halves averaged.
            let c = 0.5
                * (layout.mass[i] * layout.damping[(i, j)]
                    + layout.mass[j] * layout.damping[(j, i)]);
            damping[(v(i), v(j))] = c;
        }
    }
    let mut input = DMatrix::zeros(d, d);
    for i in 0..n {
        input[(v(i), 2 * n)] = -0.5 * layout.mass[i];
        input[(2 * n, v(i))] = -0.5 * layout.mass[i];
    }
    let mut forms = vec![damping, input];
    for l in &layout.links {
        let (a, b) = (v(l.pair.left_dof), v(l.pair.right_dof));
        let c = l.link.damping;
        let mut q = DMatrix::zeros(d, d);
        q[(a, a)] = c;
        q[(b, b)] = c;
        q[(a, b)] = -c;
        q[(b, a)] = -c;
        forms.push(q);
    }
    forms
}

/// W = ∫₀ʰ e^{𝒜ᵀs} Q e^{𝒜s} ds by Van Loan's block exponential, with the
/// scaling D of `scale` (𝒜̃ = D𝒜D⁻¹ given as `scaled`).
fn integral(scaled: &DMatrix<f64>, scale: &[f64], q: &DMatrix<f64>, h: f64) -> DMatrix<f64> {
    let d = scaled.nrows();
    let mut q_scaled = DMatrix::from_fn(d, d, |i, j| q[(i, j)] / (scale[i] * scale[j]));
    let size = q_scaled.amax();
    if size == 0.0 {
        return DMatrix::zeros(d, d);
    }
    q_scaled /= size;
    let mut block = DMatrix::zeros(2 * d, 2 * d);
    for i in 0..d {
        for j in 0..d {
            block[(i, j)] = -scaled[(j, i)] * h;
            block[(i, d + j)] = q_scaled[(i, j)] * h;
            block[(d + i, d + j)] = scaled[(i, j)] * h;
        }
    }
    let e = exponential_blocks(&Sparse::of(&block), d);
    let w = e.z.transpose() * &e.y;
    // Back to 𝒜 and Q: W = D W̃ D, W̃ times the size taken out of Q̃;
    // symmetric but for rounding, so its two halves are averaged.
    DMatrix::from_fn(d, d, |i, j| {
        0.5 * (w[(i, j)] + w[(j, i)]) * size * scale[i] * scale[j]
    })
}

impl WorkForms {
    /// The forms of the augmented matrix `a` ([`super::augmented`]) of a row
    /// laid out as `layout`, over a step of length h, scaled by the row's
    /// fastest rate `rate`.
    pub fn of(a: &DMatrix<f64>, layout: &Layout, h: f64, rate: f64) -> WorkForms {
        let d = a.nrows();
        let (scale, scaled) = scaled(a, layout.dofs, rate);
        let mut packed = Vec::new();
        for q in integrands(layout) {
            let w = integral(&scaled, &scale, &q, h);
            for i in 0..d {
                packed.push(w[(i, i)]);
                packed.extend((i + 1..d).map(|j| 2.0 * w[(i, j)]));
            }
        }
        let n = layout.dofs;
        WorkForms {
            size: d,
            packed,
            equilibrium: Equilibrium::of(a, n),
            line: a[(2 * n + 1, 2 * n)] == 0.0,
            mass: layout.mass.clone(),
        }
    }

    /// The integrals over the step (J, one per form, into `out`) from its
    /// start (u, u̇) under ground (a_g, ȧ_g) with load M⁻¹q, to
    /// displacements `u1`: δᵀWδ, and E_in's part of the rest point (module
    /// doc), which `rest` keeps for the configuration of its branches.
    /// `w` and `pairs` are buffers for δ and the products δ_i δ_j.
    pub fn on(
        &self,
        (u, v): (&[f64], &[f64]),
        (a, rate): (f64, f64),
        (load, u1): (&[f64], &[f64]),
        rest: (&[u8], &mut Rest),
        (w, pairs): (&mut Vec<f64>, &mut Vec<f64>),
        out: &mut [f64],
    ) {
        let (d, n) = (self.size, self.mass.len());
        let still = if self.line { a } else { 0.0 };
        w.clear();
        w.resize(d, 0.0);
        let (us, tail) = w.split_at_mut(n);
        let residual = &mut tail[n + 2..];
        // u* and the residual M⁻¹q − a* 1 − K u* (none where K is singular:
        // u* = 0).
        match &self.equilibrium {
            Some(e) => e.point(rest, load, still, (us, residual)),
            None => {
                for (r, q) in residual.iter_mut().zip(load) {
                    *r = q - still;
                }
            }
        }
        for (x, u) in us.iter_mut().zip(u) {
            *x = u - *x;
        }
        tail[..n].copy_from_slice(v);
        tail[n] = a - still;
        tail[n + 1] = rate;
        pairs.clear();
        for i in 0..d {
            pairs.extend(w[i..].iter().map(|x| w[i] * x));
        }
        let len = pairs.len();
        for (form, out) in self.packed.chunks_exact(len).zip(out.iter_mut()) {
            *out = dot(form, pairs);
        }
        let moved: f64 = (0..n).map(|i| self.mass[i] * (u1[i] - u[i])).sum();
        out[INPUT] -= still * moved;
    }

    /// How many forms: 2 and one per link.
    pub fn len(&self) -> usize {
        self.packed.len() / (self.size * (self.size + 1) / 2)
    }

    pub fn is_empty(&self) -> bool {
        self.packed.is_empty()
    }
}

/// Σ x_k y_k in eight running sums, which the compiler keeps in one vector.
fn dot(x: &[f64], y: &[f64]) -> f64 {
    const WIDTH: usize = 8;
    let mut sums = [0.0; WIDTH];
    let (xc, yc) = (x.chunks_exact(WIDTH), y.chunks_exact(WIDTH));
    let tail: f64 = xc
        .remainder()
        .iter()
        .zip(yc.remainder())
        .map(|(a, b)| a * b)
        .sum();
    for (a, b) in xc.zip(yc) {
        for k in 0..WIDTH {
            sums[k] += a[k] * b[k];
        }
    }
    sums.iter().sum::<f64>() + tail
}

#[cfg(test)]
mod tests {
    use super::{DAMPING, INPUT, Rest, WorkForms};
    use crate::model::buildings::parse;
    use crate::solver::buildings::config::Config;
    use crate::solver::buildings::layout::Layout;
    use crate::solver::buildings::propagator::augmented;
    use crate::solver::buildings::system::System;

    /// Two one-storey buildings that never touch: two independent SDOF
    /// oscillators (SPEC §13's reduction), with Rayleigh damping c = 2ξmω.
    fn pair() -> Layout {
        let text = "model = \"kelvin\"\nrestitution = 0.5\n\
             [[building]]\nname = \"soft\"\nstoreys = 1\nmass = 2e5\nstiffness = 3e7\nheight = 3\ndamping = 0.05\n\
             [[building]]\nname = \"stiff\"\nstoreys = 1\nmass = 1e5\nstiffness = 8e7\nheight = 3\ndamping = 0.12\n\
             [[joint]]\ngap = \"inf\"\nstiffness = 1e10\n";
        Layout::of(&parse("two.toml", text).expect("a row"))
    }

    /// ∫₀ʰ e^{−βt} (1, cos γt, sin γt) dt.
    fn exponential_integrals(beta: f64, gamma: f64, h: f64) -> [f64; 3] {
        let (e, (s, c)) = ((-beta * h).exp(), (gamma * h).sin_cos());
        let r = beta * beta + gamma * gamma;
        [
            (1.0 - e) / beta,
            (e * (-beta * c + gamma * s) + beta) / r,
            (e * (-beta * s - gamma * c) + gamma) / r,
        ]
    }

    /// Per floor: (m, c, ω, ζ, ω_d).
    fn oscillators(layout: &Layout) -> Vec<(f64, f64, f64, f64, f64)> {
        (0..2)
            .map(|i| {
                let m = layout.mass[i];
                let c = m * layout.damping[(i, i)];
                let w = (layout.storeys[i].stiffness / m).sqrt();
                let zeta = c / (2.0 * m * w);
                (m, c, w, zeta, w * (1.0 - zeta * zeta).sqrt())
            })
            .collect()
    }

    /// Free damped vibration from (u₀, u̇₀): u̇ = e^{−ζωt}(P cos ω_d t +
    /// R sin ω_d t) with P = u̇₀, R = −u₀ω_d − ζω(u̇₀ + ζωu₀)/ω_d, so
    /// ∫ c u̇² dt = c[(P² + R²)/2 I₀ + (P² − R²)/2 I_c + PR I_s] with the
    /// integrals of e^{−2ζωt} against 1, cos 2ω_d t, sin 2ω_d t. Over one
    /// sub-step and over 3 s (several periods, many squarings), E_damp's
    /// form gives it to 1e-12, and E_in's is zero without ground.
    #[test]
    fn the_damping_form_is_the_closed_form_of_free_vibration() {
        let layout = pair();
        let system = System::of(&layout, &Config::at_rest(2, layout.pairs.len()));
        let a = augmented(&system, 0.0);
        let (u0, v0) = ([0.012, -0.004], [-0.05, 0.21]);
        for h in [1.0 / layout.rate, 3.0] {
            let forms = WorkForms::of(&a, &layout, h, layout.rate);
            let mut values = vec![0.0; forms.len()];
            let buffers = (&mut Vec::new(), &mut Vec::new());
            let zero = [0.0; 2];
            forms.on(
                (&u0, &v0),
                (0.0, 0.0),
                (&zero, &u0),
                (&[], &mut Rest::default()),
                buffers,
                &mut values,
            );
            let mut want = 0.0;
            for (i, &(_, c, omega, zeta, wd)) in oscillators(&layout).iter().enumerate() {
                let p = v0[i];
                let r = -u0[i] * wd - zeta * omega * (v0[i] + zeta * omega * u0[i]) / wd;
                let [i0, ic, is] = exponential_integrals(2.0 * zeta * omega, 2.0 * wd, h);
                want += c * (0.5 * (p * p + r * r) * i0 + 0.5 * (p * p - r * r) * ic + p * r * is);
            }
            let got = values[DAMPING];
            assert!(
                (got - want).abs() < 1e-12 * want,
                "h {h}: {got} against {want}"
            );
            assert!(values[INPUT].abs() < 1e-15 * want, "{}", values[INPUT]);
        }
    }

    /// From rest under a constant ground acceleration a: u̇ = −(a/ω_d)
    /// e^{−ζωt} sin ω_d t, so E_in = −∫ m u̇ a dt = (m a²/ω_d) ∫ e^{−ζωt}
    /// sin ω_d t dt; E_in's form (measured from the static displacement
    /// −a/ω², with the rest point's part from the end's u(h)) gives it to
    /// 1e-12, and the damping form c(a/ω_d)² ∫ e^{−2ζωt} sin² ω_d t dt the
    /// same.
    #[test]
    fn the_input_form_is_the_closed_form_of_a_step_in_the_ground() {
        let layout = pair();
        let system = System::of(&layout, &Config::at_rest(2, layout.pairs.len()));
        let a = augmented(&system, 0.0);
        let ground = 2.5;
        for h in [1.0 / layout.rate, 3.0] {
            let forms = WorkForms::of(&a, &layout, h, layout.rate);
            // u(h) = −(a/ω²)(1 − e^{−ζωh}(cos ω_d h + (ζω/ω_d) sin ω_d h)).
            let end: Vec<f64> = oscillators(&layout)
                .iter()
                .map(|&(_, _, omega, zeta, wd)| {
                    let decay = (-zeta * omega * h).exp();
                    let (s, c) = (wd * h).sin_cos();
                    -ground / (omega * omega) * (1.0 - decay * (c + zeta * omega / wd * s))
                })
                .collect();
            let mut values = vec![0.0; forms.len()];
            let buffers = (&mut Vec::new(), &mut Vec::new());
            let zero = [0.0; 2];
            forms.on(
                (&zero, &zero),
                (ground, 0.0),
                (&zero, &end),
                (&[], &mut Rest::default()),
                buffers,
                &mut values,
            );
            let (mut input, mut damping) = (0.0, 0.0);
            for &(m, c, omega, zeta, wd) in &oscillators(&layout) {
                let [_, _, is] = exponential_integrals(zeta * omega, wd, h);
                input += m * ground * ground / wd * is;
                let [i0, ic, _] = exponential_integrals(2.0 * zeta * omega, 2.0 * wd, h);
                damping += c * (ground / wd).powi(2) * 0.5 * (i0 - ic);
            }
            let (gi, gd) = (values[INPUT], values[DAMPING]);
            assert!(
                (gi - input).abs() < 1e-12 * input,
                "h {h}: {gi} against {input}"
            );
            assert!(
                (gd - damping).abs() < 1e-12 * damping,
                "h {h}: {gd} against {damping}"
            );
        }
    }
}
