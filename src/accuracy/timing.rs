//! Wall time per run: the median of repeated runs in one process, after a
//! warm-up run that is not counted (SciMLBenchmarks' practice).

use std::time::Instant;

/// How long the repeated runs of one row may take together, roughly.
pub const ROW_BUDGET_MS: f64 = 150.0;
/// Fewest and most timed runs per row.
pub const MIN_REPEATS: usize = 5;
pub const MAX_REPEATS: usize = 200;

/// Median milliseconds of `run`, and its last result. The number of repeats
/// fills [`ROW_BUDGET_MS`] within [`MIN_REPEATS`]..=[`MAX_REPEATS`].
pub fn median_ms<T>(mut run: impl FnMut() -> T) -> (f64, T) {
    let start = Instant::now();
    let mut out = run();
    let warm_up = start.elapsed().as_secs_f64() * 1e3;
    let repeats = ((ROW_BUDGET_MS / warm_up.max(1e-3)) as usize).clamp(MIN_REPEATS, MAX_REPEATS);
    let mut times = Vec::with_capacity(repeats);
    for _ in 0..repeats {
        let t = Instant::now();
        out = std::hint::black_box(run());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    (median(times), out)
}

/// The median of a list of durations in milliseconds (0 for an empty list).
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(|a, b| a.total_cmp(b));
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}
