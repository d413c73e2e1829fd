//! Axis ticks at round values (1, 2 or 5 × 10ⁿ) and their labels: at most
//! [`LABEL_WIDTH`] characters each, with a common power of ten taken out
//! into the axis title when the plain numbers would be longer.

/// Widest tick label, in characters.
pub const LABEL_WIDTH: usize = 5;

/// Ticks of one axis: the bounds snapped outward to whole steps, the tick
/// values, their labels and the power of ten the labels are scaled by.
#[derive(Debug, Clone, PartialEq)]
pub struct Ticks {
    pub bounds: [f64; 2],
    pub values: Vec<f64>,
    pub labels: Vec<String>,
    /// The labels show value / 10^exponent (0: plain values).
    pub exponent: i32,
}

/// The round step (1, 2 or 5 × 10ⁿ) nearest above `raw`.
pub fn round_step(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(raw.log10().floor());
    let m = raw / p;
    let nice = if m <= 1.0 + 1e-9 {
        1.0
    } else if m <= 2.0 + 1e-9 {
        2.0
    } else if m <= 5.0 + 1e-9 {
        5.0
    } else {
        10.0
    };
    nice * p
}

/// Decimals needed to print multiples of `step` exactly.
fn decimals(step: f64) -> usize {
    let d = -(step.log10() - 1e-9).floor();
    d.clamp(0.0, 12.0) as usize
}

fn plain(v: f64, step: f64) -> String {
    let text = format!("{:.*}", decimals(step), v);
    // "-0" and "-0.0" are zero.
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        text.trim_start_matches('-').to_string()
    } else {
        text
    }
}

/// Ticks for data in `[lo, hi]`, about `count` of them. `snap` widens the
/// bounds to whole steps (a y axis); without it the bounds are kept and the
/// ticks fall inside (a time axis).
pub fn ticks(lo: f64, hi: f64, count: usize, snap: bool) -> Ticks {
    let (mut lo, mut hi) = if lo.is_finite() && hi.is_finite() {
        (lo, hi)
    } else {
        (0.0, 1.0)
    };
    if hi - lo <= f64::EPSILON * hi.abs().max(lo.abs()).max(1e-300) {
        let pad = if lo == 0.0 { 1.0 } else { lo.abs() * 0.1 };
        lo -= pad;
        hi += pad;
    }
    // A value within round-off of zero is zero (a force that is 0 up to
    // 1e-12 should not open a whole step below the axis).
    let tiny = 1e-9 * (hi - lo);
    if lo.abs() < tiny {
        lo = 0.0;
    }
    if hi.abs() < tiny {
        hi = 0.0;
    }
    let step = round_step((hi - lo) / count.max(1) as f64);
    if snap {
        // Outward to whole steps; a bound within round-off of a step stays
        // on it (0 stays 0, so a count axis does not open a step below zero).
        lo = (lo / step + 1e-9).floor() * step;
        hi = (hi / step - 1e-9).ceil() * step;
    }
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    let values: Vec<f64> = (first..=last)
        .map(|k| {
            let v = k as f64 * step;
            if v.abs() < step * 1e-9 { 0.0 } else { v }
        })
        .collect();
    let mut exponent = 0;
    let mut labels: Vec<String> = values.iter().map(|v| plain(*v, step)).collect();
    if labels.iter().any(|l| l.len() > LABEL_WIDTH) {
        let biggest = values.iter().fold(0f64, |m, v| m.max(v.abs())).max(step);
        exponent = biggest.log10().floor() as i32;
        let scale = 10f64.powi(exponent);
        labels = values
            .iter()
            .map(|v| plain(v / scale, step / scale))
            .collect();
        if labels.iter().any(|l| l.len() > LABEL_WIDTH) {
            // A tiny span about a large value: three significant digits of the step.
            exponent = (step.log10().floor()) as i32;
            let scale = 10f64.powi(exponent);
            labels = values.iter().map(|v| format!("{:.0}", v / scale)).collect();
        }
    }
    Ticks {
        bounds: [lo, hi],
        values,
        labels,
        exponent,
    }
}

/// The scale note for an axis title: `` or ` ×1e-3`.
pub fn scale_note(exponent: i32) -> String {
    if exponent == 0 {
        String::new()
    } else {
        format!(" ×1e{exponent}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_one_two_or_five_times_a_power_of_ten() {
        assert_eq!(round_step(0.3), 0.5);
        assert_eq!(round_step(1.0), 1.0);
        assert_eq!(round_step(1.2), 2.0);
        assert_eq!(round_step(7.0), 10.0);
        assert!((round_step(0.00013) - 0.0002).abs() < 1e-15);
    }

    #[test]
    fn y_ticks_snap_outward_and_read_plainly() {
        let t = ticks(-2.93, 3.22, 4, true);
        assert_eq!(t.bounds, [-4.0, 4.0]);
        assert_eq!(t.labels, ["-4", "-2", "0", "2", "4"]);
        assert_eq!(t.exponent, 0);
    }

    #[test]
    fn large_and_small_values_move_a_power_of_ten_into_the_title() {
        let t = ticks(0.0, 63000.0, 3, true);
        assert_eq!(t.exponent, 5);
        assert!(t.labels.iter().all(|l| l.len() <= LABEL_WIDTH), "{t:?}");
        let t = ticks(-7.5e-6, 4e-5, 3, true);
        assert!(t.labels.iter().all(|l| l.len() <= LABEL_WIDTH), "{t:?}");
        assert_eq!(t.exponent, -5);
        assert!(t.labels.contains(&"0".to_string()));
    }

    #[test]
    fn a_bound_on_a_step_stays_there_even_with_one_tick() {
        let t = ticks(0.0, 39.0, 1, true);
        assert_eq!(t.bounds, [0.0, 50.0]);
        assert_eq!(t.labels, ["0", "50"]);
        let t = ticks(-20.0, 40.0, 3, true);
        assert_eq!(t.bounds, [-20.0, 40.0]);
    }

    #[test]
    fn time_ticks_stay_inside_unsnapped_bounds() {
        let t = ticks(0.0, 50.27, 6, false);
        assert_eq!(t.bounds, [0.0, 50.27]);
        assert_eq!(t.labels, ["0", "10", "20", "30", "40", "50"]);
    }
}
