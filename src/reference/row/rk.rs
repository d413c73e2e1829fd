//! One Dormand–Prince 5(4) step on a state of any size (Hairer, Nørsett &
//! Wanner, *Solving ODEs I*, §II.5): the 5th-order solution and the embedded
//! error estimate. The reference retakes a step to any instant it needs
//! (an event, a turning point), so it needs no dense output.

const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// b − b̂: the 5th-order weights less the embedded 4th-order ones.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// (y(t0 + h), error estimate) from y0 = y(t0).
pub fn step(
    f: &impl Fn(f64, &[f64], &mut [f64]),
    t0: f64,
    y0: &[f64],
    h: f64,
) -> (Vec<f64>, Vec<f64>) {
    let n = y0.len();
    let mut k = vec![vec![0.0; n]; 7];
    let mut y = vec![0.0; n];
    for s in 0..7 {
        for i in 0..n {
            y[i] = y0[i] + h * (0..s).map(|j| A[s][j] * k[j][i]).sum::<f64>();
        }
        let (done, rest) = k.split_at_mut(s);
        let _ = done;
        f(t0 + C[s] * h, &y, &mut rest[0]);
    }
    // The last stage is evaluated at the 5th-order solution itself.
    let error = (0..n)
        .map(|i| h * (0..7).map(|s| E[s] * k[s][i]).sum::<f64>())
        .collect();
    (y, error)
}
