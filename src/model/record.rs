//! Recorded ground motions (SPEC §9): a PEER NGA `.AT2` accelerogram, read
//! once and kept for the life of the process.
//!
//! An `.AT2` file is four header lines, the fourth giving the number of
//! points and the sample interval (`NPTS=  4000, DT=   .0100 SEC`, or in the
//! older form `4000  0.0100  NPTS, DT`), then the accelerations in g
//! (9.80665 m/s²), several to a line. Sample k is at t_k = k·DT; between
//! samples the acceleration is linear, after the last one it is zero.
//!
//! A parameter set is `Copy` (it is copied freely by sweeps, the explorer and
//! the solvers), so it cannot own the samples. A record is instead read once,
//! leaked into a `&'static Record` and interned by path: a set holds that
//! reference, which is `Copy`, costs no lookup on the solvers' hot path, and
//! is shared by every set that names the same file. The memory of each
//! distinct file read stays until the process ends, which for a command or
//! an explorer session is a handful of records.

use std::fmt;
use std::path::Path;
use std::sync::Mutex;

/// Standard gravity, the unit of `.AT2` accelerations (m/s²).
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// A sampled ground acceleration with its exact integrals.
#[derive(Debug, PartialEq)]
pub struct Record {
    /// The path as the user wrote it (`record:PATH` names it so).
    pub path: String,
    /// `record:PATH`, the excitation's name in presets and output.
    pub spec: String,
    /// Sample interval DT in seconds.
    pub dt: f64,
    /// Accelerations a(t_k) in m/s².
    pub acceleration: Vec<f64>,
    /// Ground velocity at t_k from rest (m/s): the trapezoid rule, exact for
    /// a piecewise-linear acceleration.
    pub velocity: Vec<f64>,
    /// Ground displacement at t_k from rest (m): exact for a piecewise-linear
    /// acceleration, u_{k+1} = u_k + DT u̇_k + DT² (2a_k + a_{k+1})/6.
    pub displacement: Vec<f64>,
    /// Peak |a| (m/s²), the default a_p.
    pub peak: f64,
    /// Circular frequency (rad/s) of the largest Fourier amplitude of the
    /// record, the default ω_p.
    pub dominant_omega: f64,
}

/// A record that could not be read: the file, the line (1-based; 0 when the
/// file itself could not be opened) and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct RecordError {
    pub path: String,
    pub line: usize,
    pub message: String,
}

impl fmt::Display for RecordError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "record `{}`: {}", self.path, self.message)
        } else {
            write!(
                f,
                "record `{}` line {}: {}",
                self.path, self.line, self.message
            )
        }
    }
}

/// Most samples a record may have (a 10-minute record at 200 Hz is 1.2e5).
pub const MAX_SAMPLES: usize = 2_000_000;

impl Record {
    /// Builds a record from accelerations in m/s² at interval `dt` seconds.
    pub fn from_samples(path: &str, dt: f64, acceleration: Vec<f64>) -> Record {
        let n = acceleration.len();
        let mut velocity = vec![0.0; n];
        let mut displacement = vec![0.0; n];
        for k in 1..n {
            let (a0, a1) = (acceleration[k - 1], acceleration[k]);
            velocity[k] = velocity[k - 1] + 0.5 * dt * (a0 + a1);
            displacement[k] =
                displacement[k - 1] + dt * velocity[k - 1] + dt * dt * (2.0 * a0 + a1) / 6.0;
        }
        let peak = acceleration.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        Record {
            path: path.to_string(),
            spec: format!("record:{path}"),
            dt,
            dominant_omega: dominant_omega(&acceleration, dt),
            acceleration,
            velocity,
            displacement,
            peak,
        }
    }

    /// Duration of the samples, (N − 1)·DT seconds.
    pub fn duration(&self) -> f64 {
        (self.acceleration.len().saturating_sub(1)) as f64 * self.dt
    }

    /// Reads an `.AT2` file (accelerations in g, converted to m/s²).
    pub fn read_at2(path: &str) -> Result<Record, RecordError> {
        let text = std::fs::read(Path::new(path)).map_err(|e| RecordError {
            path: path.to_string(),
            line: 0,
            message: format!("cannot be read: {e}"),
        })?;
        let text = String::from_utf8_lossy(&text);
        parse_at2(path, &text)
    }
}

/// The unit of a plain file's accelerations, named after `@` in
/// `record:PATH@UNIT`; g when not named.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Units {
    G,
    MetresPerSecondSquared,
    CentimetresPerSecondSquared,
}

impl Units {
    /// The accepted names, for messages.
    pub const NAMES: &'static str = "g, m/s2, cm/s2";

    pub fn parse(text: &str) -> Option<Units> {
        match text.trim() {
            "g" => Some(Units::G),
            "m/s2" | "m/s^2" => Some(Units::MetresPerSecondSquared),
            "cm/s2" | "cm/s^2" | "gal" => Some(Units::CentimetresPerSecondSquared),
            _ => None,
        }
    }

    /// One unit in m/s².
    pub fn in_si(self) -> f64 {
        match self {
            Units::G => STANDARD_GRAVITY,
            Units::MetresPerSecondSquared => 1.0,
            Units::CentimetresPerSecondSquared => 0.01,
        }
    }
}

/// Reads the record a `record:` spec names: `PATH` or `PATH@UNIT`. An
/// `.AT2` file is read as PEER's (in g; a unit is refused); any other file
/// as plain two-column text, time in seconds and acceleration in UNIT,
/// separated by commas or white space ([`parse_columns`]).
pub fn read(spec: &str) -> Result<Record, RecordError> {
    let (path, units) = match spec.rsplit_once('@') {
        Some((path, unit)) => {
            let units = Units::parse(unit).ok_or_else(|| RecordError {
                path: path.to_string(),
                line: 0,
                message: format!(
                    "unknown unit `{}` after `@`: must be one of {}",
                    cut(unit),
                    Units::NAMES
                ),
            })?;
            (path, Some(units))
        }
        None => (spec, None),
    };
    let is_at2 = Path::new(path)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("at2"));
    if is_at2 {
        if units.is_some() {
            return Err(RecordError {
                path: path.to_string(),
                line: 0,
                message: "an .AT2 record is in g by definition; drop the `@UNIT`".into(),
            });
        }
        return Record::read_at2(path);
    }
    let bytes = std::fs::read(Path::new(path)).map_err(|e| RecordError {
        path: path.to_string(),
        line: 0,
        message: format!("cannot be read: {e}"),
    })?;
    let mut record = parse_columns(
        path,
        &String::from_utf8_lossy(&bytes),
        units.unwrap_or(Units::G),
    )?;
    record.spec = format!("record:{spec}");
    Ok(record)
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
        let fields: Vec<&str> = t
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|f| !f.is_empty())
            .collect();
        let numbers: Vec<Option<f64>> = fields
            .iter()
            .map(|f| f.parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect();
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

/// Parses the text of an `.AT2` file named `path` (for messages).
pub fn parse_at2(path: &str, text: &str) -> Result<Record, RecordError> {
    let fail = |line: usize, message: String| RecordError {
        path: path.to_string(),
        line,
        message,
    };
    let lines: Vec<&str> = text.lines().collect();
    if lines.iter().all(|l| l.trim().is_empty()) {
        return Err(fail(
            1,
            "the file is empty; an AT2 record has 4 header lines, then the samples".into(),
        ));
    }
    if lines.len() < 4 {
        return Err(fail(
            lines.len() + 1,
            "the header ends early: line 4 must give NPTS and DT".into(),
        ));
    }
    let (npts, dt) = header_counts(lines[3]).map_err(|m| fail(4, m))?;
    if !(1..=MAX_SAMPLES).contains(&npts) {
        return Err(fail(
            4,
            format!("NPTS = {npts}: must be in [1, {MAX_SAMPLES}]"),
        ));
    }
    if !(dt.is_finite() && dt > 0.0 && dt <= 10.0) {
        return Err(fail(
            4,
            format!("DT = {dt}: must be a number of seconds in (0, 10]"),
        ));
    }
    let mut acceleration = Vec::with_capacity(npts);
    for (i, line) in lines.iter().enumerate().skip(4) {
        for token in line.split_whitespace() {
            let a: f64 = token
                .parse()
                .ok()
                .filter(|a: &f64| a.is_finite())
                .ok_or_else(|| fail(i + 1, format!("`{}` is not a number", cut(token))))?;
            if acceleration.len() == npts {
                return Err(fail(
                    i + 1,
                    format!("more samples than NPTS = {npts} (line 4)"),
                ));
            }
            acceleration.push(a * STANDARD_GRAVITY);
        }
    }
    if acceleration.len() != npts {
        return Err(fail(
            lines.len(),
            format!("{} samples, but NPTS = {npts} (line 4)", acceleration.len()),
        ));
    }
    Ok(Record::from_samples(path, dt, acceleration))
}

/// A token cut for a one-line message.
fn cut(token: &str) -> String {
    token
        .chars()
        .take(24)
        .flat_map(char::escape_default)
        .collect()
}

/// NPTS and DT from the fourth header line, in either PEER form.
fn header_counts(line: &str) -> Result<(usize, f64), String> {
    let upper = line.to_ascii_uppercase();
    let after = |key: &str| -> Option<&str> {
        let at = upper.find(key)?;
        let rest = line[at + key.len()..].trim_start();
        let rest = rest.strip_prefix('=').unwrap_or(rest).trim_start();
        let end = rest
            .find(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E')))
            .unwrap_or(rest.len());
        Some(&rest[..end])
    };
    if upper.contains("NPTS=") || upper.contains("NPTS =") {
        let npts = after("NPTS").ok_or("missing NPTS")?;
        let npts: usize = npts
            .parse()
            .map_err(|_| format!("NPTS `{}` is not a whole number", cut(npts)))?;
        let dt =
            after("DT").ok_or_else(|| "missing DT (expected `NPTS= n, DT= s SEC`)".to_string())?;
        let dt: f64 = dt
            .parse()
            .map_err(|_| format!("DT `{}` is not a number", cut(dt)))?;
        return Ok((npts, dt));
    }
    // Older form: "4000  0.0100  NPTS, DT".
    let mut tokens = line.split_whitespace();
    let npts = tokens
        .next()
        .and_then(|t| t.trim_end_matches(',').parse::<usize>().ok())
        .ok_or("missing NPTS (expected `NPTS= n, DT= s SEC`)")?;
    let dt = tokens
        .next()
        .and_then(|t| t.trim_end_matches(',').parse::<f64>().ok())
        .ok_or("missing DT (expected `NPTS= n, DT= s SEC`)")?;
    Ok((npts, dt))
}

/// The circular frequency 2πk/(N·DT), k ≥ 1, of the largest amplitude of the
/// discrete Fourier transform of the samples (a direct sum over at most 4096
/// frequencies spread over (0, Nyquist]).
fn dominant_omega(a: &[f64], dt: f64) -> f64 {
    let n = a.len();
    if n < 2 {
        return 2.0 * std::f64::consts::PI;
    }
    let total = n as f64 * dt;
    let half = n / 2;
    let stride = half.div_ceil(4096).max(1);
    let mut best = (0.0, 1usize);
    let mut k = 1;
    while k <= half {
        let w = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
        let (step_s, step_c) = w.sin_cos();
        let (mut s, mut c) = (0.0f64, 1.0f64);
        let (mut re, mut im) = (0.0, 0.0);
        for &x in a {
            re += x * c;
            im += x * s;
            (s, c) = (s * step_c + c * step_s, c * step_c - s * step_s);
        }
        let amp = re * re + im * im;
        if amp > best.0 {
            best = (amp, k);
        }
        k += stride;
    }
    2.0 * std::f64::consts::PI * best.1 as f64 / total
}

/// Records read so far, by path.
static REGISTRY: Mutex<Vec<&'static Record>> = Mutex::new(Vec::new());

/// The record at `path`, read on first use and shared afterwards.
pub fn load(path: &str) -> Result<&'static Record, RecordError> {
    let mut registry = REGISTRY.lock().unwrap_or_else(|e| e.into_inner());
    let spec = format!("record:{path}");
    if let Some(r) = registry.iter().find(|r| r.spec == spec) {
        return Ok(r);
    }
    let record: &'static Record = Box::leak(Box::new(read(path)?));
    registry.push(record);
    Ok(record)
}

/// Interns a record built in memory (tests, generated motions).
pub fn intern(record: Record) -> &'static Record {
    let mut registry = REGISTRY.lock().unwrap_or_else(|e| e.into_inner());
    let record: &'static Record = Box::leak(Box::new(record));
    registry.push(record);
    record
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = "PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic\n\
        ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    5, DT=   .0100 SEC\n\
        0.0 0.1 -0.2\n0.05 0.0\n";

    #[test]
    fn reads_samples_in_g_and_integrates_exactly() {
        let r = parse_at2("x.at2", GOOD).unwrap();
        assert_eq!(r.acceleration.len(), 5);
        assert!((r.acceleration[2] + 0.2 * STANDARD_GRAVITY).abs() < 1e-15);
        assert!((r.peak - 0.2 * STANDARD_GRAVITY).abs() < 1e-15);
        // v(0.01) = ½·0.01·(0 + 0.1g); u(0.01) = 0.01²·(0 + 0.1g)/6.
        let g = STANDARD_GRAVITY;
        assert!((r.velocity[1] - 0.0005 * g).abs() < 1e-15);
        assert!((r.displacement[1] - 1e-4 * 0.1 * g / 6.0).abs() < 1e-18);
        let old = GOOD.replace("NPTS=    5, DT=   .0100 SEC", "5   0.0100   NPTS, DT");
        assert_eq!(
            parse_at2("x.at2", &old).unwrap().acceleration,
            r.acceleration
        );
    }

    #[test]
    fn malformed_files_name_the_line() {
        let cases = [
            ("", 1, "empty"),
            ("a\nb\nc\n", 4, "header ends early"),
            (
                &GOOD.replace("NPTS=    5", "NPTS=    6") as &str,
                6,
                "5 samples, but NPTS = 6",
            ),
            (
                &GOOD.replace("NPTS=    5", "NPTS=    4"),
                6,
                "more samples than NPTS = 4",
            ),
            (&GOOD.replace(", DT=   .0100 SEC", ""), 4, "missing DT"),
            (&GOOD.replace("-0.2", "-0.2x"), 5, "`-0.2x` is not a number"),
            (&GOOD.replace("0.05", "nan"), 6, "`nan` is not a number"),
        ];
        for (text, line, what) in cases {
            let e = parse_at2("bad.at2", text).unwrap_err();
            assert_eq!(e.line, line, "{e}");
            assert!(e.to_string().contains(what), "{e}");
            assert!(e.to_string().starts_with("record `bad.at2` line "), "{e}");
        }
    }

    #[test]
    fn dominant_frequency_of_a_sampled_sine() {
        // 2 Hz sine sampled at 100 Hz for 10 s: ω = 4π.
        let a: Vec<f64> = (0..1000)
            .map(|k| (4.0 * std::f64::consts::PI * k as f64 * 0.01).sin())
            .collect();
        let w = dominant_omega(&a, 0.01);
        assert!((w - 4.0 * std::f64::consts::PI).abs() < 1e-9, "{w}");
    }
}
