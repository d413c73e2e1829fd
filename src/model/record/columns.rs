//! Plain records: two columns `time, acceleration`, in the unit named after
//! `@` in `record:PATH@UNIT` (g when not named).

use super::{MAX_SAMPLES, Record, RecordError, Units, cut};

/// Whether any line of `text` (not a comment) is two numbers, as a plain
/// record's samples are: a file without one is not a record at all.
pub fn has_samples(text: &str) -> bool {
    text.lines().any(|line| {
        let t = line.trim();
        !(t.starts_with('#') || t.starts_with('%')) && matches!(numbers(t)[..], [Some(_), Some(_)])
    })
}

/// The fields of a line (commas or white space), each a finite number or not.
fn numbers(line: &str) -> Vec<Option<f64>> {
    line.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|f| !f.is_empty())
        .map(|f| f.parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect()
}

/// Parses a plain record: one sample a line, `time, acceleration` (commas
/// or white space), time in seconds from any start, equally spaced;
/// a first line that is not two numbers is a header, and lines starting
/// with `#` or `%` are comments.
pub fn parse_columns(path: &str, text: &str, units: Units) -> Result<Record, RecordError> {
    let fail = |line: usize, message: String| RecordError {
        path: path.to_string(),
        line,
        message,
    };
    let mut samples: Vec<(usize, f64, f64)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') || t.starts_with('%') {
            continue;
        }
        let numbers = numbers(t);
        match numbers.as_slice() {
            [Some(time), Some(a)] => {
                if samples.len() == MAX_SAMPLES {
                    return Err(fail(i + 1, format!("more than {MAX_SAMPLES} samples")));
                }
                samples.push((i + 1, *time, *a * units.in_si()));
            }
            _ if samples.is_empty() && numbers.iter().any(Option::is_none) => {} // a header
            _ => {
                return Err(fail(
                    i + 1,
                    format!(
                        "expected two numbers `time, acceleration`, found `{}`",
                        cut(t)
                    ),
                ));
            }
        }
    }
    if samples.len() < 2 {
        return Err(fail(
            text.lines().count().max(1),
            format!(
                "{} sample(s): a record needs at least two lines `time, acceleration`",
                samples.len()
            ),
        ));
    }
    let (t0, t1) = (samples[0].1, samples[1].1);
    let dt = t1 - t0;
    if !(dt.is_finite() && dt > 0.0 && dt <= 10.0) {
        return Err(fail(
            samples[1].0,
            format!("time step {dt}: must be a number of seconds in (0, 10]"),
        ));
    }
    for (k, (line, time, _)) in samples.iter().enumerate() {
        let expected = t0 + k as f64 * dt;
        if (time - expected).abs() > 1e-6 * dt.max(expected.abs() * 1e-3) {
            return Err(fail(
                *line,
                format!(
                    "time {time} s: samples must be equally spaced by {dt} s (expected {expected} s)"
                ),
            ));
        }
    }
    let acceleration = samples.into_iter().map(|(_, _, a)| a).collect();
    Ok(Record::from_samples(path, dt, acceleration))
}
