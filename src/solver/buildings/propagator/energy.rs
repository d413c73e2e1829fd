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
//! Per step the forms cost one product w_i w_j per pair i ≤ j, and one sum
//! of as many terms per form ([`WorkForms::on`]).

use nalgebra::DMatrix;

use super::super::bound::scaled;
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
        WorkForms { size: d, packed }
    }

    /// The forms' values w₀ᵀWw₀ at the step's start w₀ = (u, u̇, a_g, ȧ_g,
    /// M⁻¹q), into `out` (one per form), with `pairs` a buffer for the
    /// products w_i w_j.
    pub fn on(&self, w: &[f64], pairs: &mut Vec<f64>, out: &mut [f64]) {
        let d = self.size;
        debug_assert_eq!(w.len(), d);
        pairs.clear();
        for i in 0..d {
            pairs.extend(w[i..].iter().map(|x| w[i] * x));
        }
        let len = pairs.len();
        for (form, out) in self.packed.chunks_exact(len).zip(out) {
            *out = dot(form, pairs);
        }
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
