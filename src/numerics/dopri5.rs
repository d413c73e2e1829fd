//! The Dormand–Prince 5(4) Runge–Kutta pair with its 4th-order dense output
//! (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4–II.6; the coefficients
//! of their code `DOPRI5`).
//!
//! One step from (t, y) with size h computes seven stages kᵢ = f(t + cᵢh, y + hΣ aᵢⱼkⱼ);
//! the 5th-order solution is y₁ = y + h Σ bᵢkᵢ (b = the last row of a, so the
//! last stage is f(t+h, y₁): "first same as last"), and the embedded error
//! estimate is h Σ eᵢkᵢ with eᵢ = bᵢ − b̂ᵢ. The state is a [`State`]: a fixed-size array or a vector;
//! nothing here knows about structures or contact.

/// Dimension of the state: (x1, ẋ1, x2, ẋ2).
pub const DIM: usize = 4;
pub type Vector = [f64; DIM];

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;

const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;

const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;

const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// A state the pair can step: a fixed array (the SDOF pair's four
/// components) or a vector sized at run time (a row's 2n).
pub trait State: Clone + AsRef<[f64]> + AsMut<[f64]> {}

impl<T: Clone + AsRef<[f64]> + AsMut<[f64]>> State for T {}

/// y + h Σ cⱼ kⱼ over the given (coefficient, stage) pairs.
#[inline]
fn combine<S: State>(y: &S, h: f64, terms: &[(f64, &S)]) -> S {
    let mut out = y.clone();
    for (i, o) in out.as_mut().iter_mut().enumerate() {
        *o += h * terms.iter().map(|(c, k)| c * k.as_ref()[i]).sum::<f64>();
    }
    out
}

/// h Σ cⱼ kⱼ (a combination of stages alone), shaped like `like`.
#[inline]
fn stages<S: State>(like: &S, h: f64, terms: &[(f64, &S)]) -> S {
    let mut zero = like.clone();
    zero.as_mut().fill(0.0);
    combine(&zero, h, terms)
}

/// a·x + b·y, component by component.
#[inline]
fn axpby<S: State>(a: f64, x: &S, b: f64, y: &S) -> S {
    let mut out = x.clone();
    for (o, &yi) in out.as_mut().iter_mut().zip(y.as_ref()) {
        *o = a * *o + b * yi;
    }
    out
}

/// One attempted step: the 5th-order solution, f at its end, the error estimate
/// and the dense-output polynomial.
#[derive(Debug, Clone)]
pub struct Step<S = Vector> {
    pub t0: f64,
    pub h: f64,
    pub y1: S,
    /// f(t0 + h, y1), the first stage of the next step.
    pub f1: S,
    /// Embedded local error estimate h Σ eᵢ kᵢ.
    pub error: S,
    dense: [S; 5],
}

impl<S: State + Copy> Copy for Step<S> {}

/// Takes one step of size `h` from (t0, y0); `f0` = f(t0, y0).
pub fn step<S: State>(f: &impl Fn(f64, &S) -> S, t0: f64, y0: &S, f0: &S, h: f64) -> Step<S> {
    let k1 = f0.clone();
    let k2 = f(t0 + C2 * h, &combine(y0, h, &[(A21, &k1)]));
    let k3 = f(t0 + C3 * h, &combine(y0, h, &[(A31, &k1), (A32, &k2)]));
    let k4 = f(
        t0 + C4 * h,
        &combine(y0, h, &[(A41, &k1), (A42, &k2), (A43, &k3)]),
    );
    let k5 = f(
        t0 + C5 * h,
        &combine(y0, h, &[(A51, &k1), (A52, &k2), (A53, &k3), (A54, &k4)]),
    );
    let k6 = f(
        t0 + h,
        &combine(
            y0,
            h,
            &[(A61, &k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)],
        ),
    );
    let y1 = combine(
        y0,
        h,
        &[(A71, &k1), (A73, &k3), (A74, &k4), (A75, &k5), (A76, &k6)],
    );
    let k7 = f(t0 + h, &y1);
    let error = stages(
        y0,
        h,
        &[
            (E1, &k1),
            (E3, &k3),
            (E4, &k4),
            (E5, &k5),
            (E6, &k6),
            (E7, &k7),
        ],
    );
    // Dense output (Hairer's CONTD5): y(θ) = r₁ + θ(r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ) r₅))).
    let r2 = axpby(1.0, &y1, -1.0, y0);
    let r3 = axpby(h, &k1, -1.0, &r2);
    let r4 = axpby(1.0, &axpby(1.0, &r2, -h, &k7), -1.0, &r3);
    let r5 = stages(
        y0,
        h,
        &[
            (D1, &k1),
            (D3, &k3),
            (D4, &k4),
            (D5, &k5),
            (D6, &k6),
            (D7, &k7),
        ],
    );
    Step {
        t0,
        h,
        y1,
        f1: k7,
        error,
        dense: [y0.clone(), r2, r3, r4, r5],
    }
}

impl<S: State> Step<S> {
    /// A step of length h from y0 to y1 taken by another method, with f at
    /// its end and its error estimate; its dense output is the line from
    /// y0 to y1 (first order).
    pub fn linear(h: f64, y0: &S, y1: S, f1: S, error: S) -> Step<S> {
        let rise = axpby(1.0, &y1, -1.0, y0);
        let mut zero = y0.clone();
        zero.as_mut().fill(0.0);
        Step {
            t0: 0.0,
            h,
            y1,
            f1,
            error,
            dense: [y0.clone(), rise, zero.clone(), zero.clone(), zero],
        }
    }

    /// The dense-output state at θ ∈ [0, 1] (t = t0 + θh), 4th order.
    #[inline]
    pub fn at(&self, theta: f64) -> S {
        let [r1, r2, r3, r4, r5] = &self.dense;
        let s = 1.0 - theta;
        let mut out = r1.clone();
        let (r2, r3, r4, r5) = (r2.as_ref(), r3.as_ref(), r4.as_ref(), r5.as_ref());
        for (i, o) in out.as_mut().iter_mut().enumerate() {
            *o += theta * (r2[i] + s * (r3[i] + theta * (r4[i] + s * r5[i])));
        }
        out
    }

    /// Scaled RMS error norm with atol = rtol = `tolerance` (≤ 1: accept).
    pub fn error_norm(&self, y0: &S, tolerance: f64) -> f64 {
        let (y0, y1, error) = (y0.as_ref(), self.y1.as_ref(), self.error.as_ref());
        let sum: f64 = (0..y0.len())
            .map(|i| {
                let scale = tolerance * (1.0 + y0[i].abs().max(y1[i].abs()));
                (error[i] / scale).powi(2)
            })
            .sum();
        (sum / y0.len() as f64).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Harmonic oscillator y'' = −y from (1, 0): one step of h = 0.1 is
    /// accurate to O(h⁶), and the dense output to O(h⁵) everywhere inside.
    #[test]
    fn step_and_dense_output_match_cosine() {
        let f = |_t: f64, y: &Vector| [y[1], -y[0], 0.0, 0.0];
        let y0 = [1.0, 0.0, 0.0, 0.0];
        let h = 0.1;
        let s = step(&f, 0.0, &y0, &f(0.0, &y0), h);
        assert!((s.y1[0] - h.cos()).abs() < 1e-8, "{}", s.y1[0] - h.cos());
        assert!((s.y1[1] + h.sin()).abs() < 1e-8);
        for k in 0..=10 {
            let th = k as f64 / 10.0;
            let y = s.at(th);
            assert!((y[0] - (th * h).cos()).abs() < 1e-8, "θ={th}");
            assert!((y[1] + (th * h).sin()).abs() < 1e-8, "θ={th}");
        }
        // The error estimate is of the size of the true error's order (h⁵).
        assert!(s.error[0].abs() < 1e-6);
    }

    /// Halving h divides the dense-output error at θ = 1/2 by about 2⁵ = 32.
    #[test]
    fn dense_output_is_fourth_order() {
        let f = |t: f64, y: &Vector| [y[1], -y[0] + t.sin(), 0.0, 0.0];
        let y0 = [0.3, 0.7, 0.0, 0.0];
        // Exact: y = A cos t + B sin t − ½ t cos t, with A = 0.3, B − ½ = 0.7.
        let exact = |t: f64| 0.3 * t.cos() + 1.2 * t.sin() - 0.5 * t * t.cos();
        let err = |h: f64| {
            let s = step(&f, 0.0, &y0, &f(0.0, &y0), h);
            (s.at(0.5)[0] - exact(0.5 * h)).abs()
        };
        let ratio = err(0.2) / err(0.1);
        assert!(ratio > 20.0 && ratio < 80.0, "ratio {ratio}");
    }
}
