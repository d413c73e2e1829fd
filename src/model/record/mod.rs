//! Recorded ground motions (SPEC §9), read once and kept for the life of the
//! process. Three formats, recognised by their content whatever the file's
//! name ([`Format::of`]):
//!
//! - [`at2`]: a PEER NGA `.AT2` accelerogram, in g;
//! - [`knet`]: a K-NET or KiK-net ASCII record (NIED), integer counts with a
//!   scale factor to gal, less the record's mean;
//! - [`columns`]: plain `time, acceleration` text in the unit named after `@`.
//!
//! Sample k is at t_k = k·DT; between samples the acceleration is linear,
//! after the last one it is zero.
//!
//! A parameter set is `Copy` (it is copied freely by sweeps, the explorer and
//! the solvers), so it cannot own the samples. A record is instead read once,
//! leaked into a `&'static Record` and interned by path: a set holds that
//! reference, which is `Copy`, costs no lookup on the solvers' hot path, and
//! is shared by every set that names the same file. The registry keeps each
//! file's length and modification time beside its record: a file changed
//! since it was read (a notebook kernel or an explorer session that outlives
//! an edit) is read again, and the sets made afterwards get the new samples.
//! The memory of each version read stays until the process ends.

pub mod at2;
pub mod columns;
pub mod event;
pub mod knet;

pub use at2::parse_at2;
pub use columns::parse_columns;
pub use knet::parse_knet;

use std::collections::HashMap;
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

    /// Whether every sample is zero (peak 0): such a record cannot be
    /// scaled to an intensity.
    pub fn is_silent(&self) -> bool {
        self.peak == 0.0
    }

    /// Duration of the samples, (N − 1)·DT seconds.
    pub fn duration(&self) -> f64 {
        (self.acceleration.len().saturating_sub(1)) as f64 * self.dt
    }

    /// Reads an `.AT2` file (accelerations in g, converted to m/s²).
    pub fn read_at2(path: &str) -> Result<Record, RecordError> {
        parse_at2(path, &read_text(path)?)
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

/// The format of a record file, told by its content.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// PEER NGA `.AT2` (in g).
    At2,
    /// K-NET / KiK-net ASCII (counts, scale factor to gal).
    Knet,
    /// Plain `time, acceleration` columns.
    Columns,
}

impl Format {
    /// The format of `text`, the contents of the file at `path`: K-NET when
    /// its header keys open it, AT2 when PEER's header is there or the name
    /// ends in `.at2`, plain columns otherwise.
    pub fn of(path: &str, text: &str) -> Format {
        let at2_name = Path::new(path)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("at2"));
        if knet::recognises(text) {
            Format::Knet
        } else if at2_name || at2::recognises(text) {
            Format::At2
        } else {
            Format::Columns
        }
    }

    /// The name, for messages.
    pub fn name(self) -> &'static str {
        match self {
            Format::At2 => "an .AT2 record",
            Format::Knet => "a K-NET record",
            Format::Columns => "a plain record",
        }
    }
}

/// Reads the record a `record:` spec names: `PATH` or `PATH@UNIT`. The
/// format is told by the content ([`Format::of`]): an `.AT2` file is in g
/// and a K-NET file in gal by definition (a unit is refused); any other
/// file is plain two-column text, time in seconds and acceleration in UNIT
/// (g when not named), separated by commas or white space ([`parse_columns`]).
pub fn read(spec: &str) -> Result<Record, RecordError> {
    let (path, units) = match unit_of(spec) {
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
    let text = read_text(path)?;
    match (Format::of(path, &text), units) {
        (Format::Columns, units) => {
            let mut record = parse_columns(path, &text, units.unwrap_or(Units::G))?;
            record.spec = format!("record:{spec}");
            Ok(record)
        }
        (format, Some(_)) => Err(RecordError {
            path: path.to_string(),
            line: 0,
            message: format!(
                "{} is in {} by definition; drop the `@UNIT`",
                format.name(),
                if format == Format::At2 { "g" } else { "gal" }
            ),
        }),
        (Format::At2, None) => parse_at2(path, &text),
        (Format::Knet, None) => parse_knet(path, &text),
    }
}

/// `PATH@UNIT` split at its `@`; `None` for a plain path (a file whose own
/// name holds an `@` is read as it is).
fn unit_of(spec: &str) -> Option<(&str, &str)> {
    spec.rsplit_once('@')
        .filter(|(_, unit)| Units::parse(unit).is_some() || !Path::new(spec).is_file())
}

/// The text of the file at `path` (invalid UTF-8 replaced).
fn read_text(path: &str) -> Result<String, RecordError> {
    let bytes = std::fs::read(Path::new(path)).map_err(|e| RecordError {
        path: path.to_string(),
        line: 0,
        message: format!("cannot be read: {e}"),
    })?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// A token cut for a one-line message.
pub(crate) fn cut(token: &str) -> String {
    token
        .chars()
        .take(24)
        .flat_map(char::escape_default)
        .collect()
}

/// The circular frequency 2πk/(N·DT), k ≥ 1, of the largest amplitude of the
/// discrete Fourier transform of the samples (a direct sum over at most 4096
/// frequencies spread over (0, Nyquist]; the first of equal largest).
///
/// Each amplitude |Σ a_m e^{iωm}|², ω = 2πk/N, is summed with the phase
/// advanced by a rotation. Frequencies are taken [`LANES`] at a time, one
/// lane each with exactly the scalar operations (so each amplitude is the
/// same to the bit as summed alone), which lets the rotations' dependent
/// chains overlap; groups run in parallel.
fn dominant_omega(a: &[f64], dt: f64) -> f64 {
    use rayon::prelude::*;
    let n = a.len();
    if n < 2 {
        return 2.0 * std::f64::consts::PI;
    }
    let total = n as f64 * dt;
    let half = n / 2;
    let stride = half.div_ceil(4096).max(1);
    let ks: Vec<usize> = (1..=half).step_by(stride).collect();
    let best = ks
        .par_chunks(LANES)
        .map(|group| {
            let amps = amplitudes(a, group, n);
            group
                .iter()
                .zip(amps)
                .fold((0.0, usize::MAX), |b, (&k, amp)| pick(b, (amp, k)))
        })
        .reduce(|| (0.0, usize::MAX), pick);
    let k = if best.1 == usize::MAX { 1 } else { best.1 };
    2.0 * std::f64::consts::PI * k as f64 / total
}

/// Frequencies summed together by [`dominant_omega`].
const LANES: usize = 4;

/// The larger amplitude, the lower frequency of equal ones.
fn pick(a: (f64, usize), b: (f64, usize)) -> (f64, usize) {
    if b.0 > a.0 || (b.0 == a.0 && b.1 < a.1 && b.0 > 0.0) {
        b
    } else {
        a
    }
}

/// |Σ a_m e^{i 2πk m/N}|² for each k of `group` (at most [`LANES`]).
fn amplitudes(a: &[f64], group: &[usize], n: usize) -> [f64; LANES] {
    let mut step = [(0.0f64, 1.0f64); LANES];
    for (l, &k) in group.iter().enumerate() {
        step[l] = (2.0 * std::f64::consts::PI * k as f64 / n as f64).sin_cos();
    }
    let (mut s, mut c) = ([0.0f64; LANES], [1.0f64; LANES]);
    let (mut re, mut im) = ([0.0f64; LANES], [0.0f64; LANES]);
    for &x in a {
        for l in 0..LANES {
            re[l] += x * c[l];
            im[l] += x * s[l];
            let (step_s, step_c) = step[l];
            (s[l], c[l]) = (s[l] * step_c + c[l] * step_s, c[l] * step_c - s[l] * step_s);
        }
    }
    let mut amp = [0.0; LANES];
    for l in 0..group.len() {
        amp[l] = re[l] * re[l] + im[l] * im[l];
    }
    amp
}

/// What a file was when it was read: its length and modification time.
type Stamp = Option<(u64, std::time::SystemTime)>;

/// The stamp of the file a `record:` spec names now (`None` if it cannot be
/// told, which never matches: such a file is read every time).
fn stamp(spec: &str) -> Stamp {
    let path = unit_of(spec).map_or(spec, |(path, _)| path);
    let meta = std::fs::metadata(path).ok()?;
    Some((meta.len(), meta.modified().ok()?))
}

/// Records read from files, by `PATH` or `PATH@UNIT` as named, each with
/// the stamp of the file it was read from.
static FILES: Mutex<Option<HashMap<String, (Stamp, &'static Record)>>> = Mutex::new(None);

/// Records built in memory ([`intern`]).
static BUILT: Mutex<Vec<&'static Record>> = Mutex::new(Vec::new());

/// The record at `path`, read on first use and shared afterwards, and read
/// again when the file has changed since (its length or modification time).
///
/// The file is read with the registry unlocked: reading runs on rayon's
/// pool (the dominant frequency's transform), whose workers may be waiting
/// for a lock on another thread's behalf, so a read under the lock could
/// wait for them for ever. Two threads reading the same file at once both
/// read it, and the first to register it is kept.
pub fn load(path: &str) -> Result<&'static Record, RecordError> {
    let now = stamp(path);
    let registered = |files: &Option<HashMap<String, (Stamp, &'static Record)>>| {
        files
            .as_ref()?
            .get(path)
            .filter(|(then, _)| then.is_some() && *then == now)
            .map(|(_, r)| *r)
    };
    if let Some(r) = registered(&FILES.lock().unwrap_or_else(|e| e.into_inner())) {
        return Ok(r);
    }
    let record = read(path)?;
    let mut files = FILES.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(r) = registered(&files) {
        return Ok(r);
    }
    let record: &'static Record = Box::leak(Box::new(record));
    files
        .get_or_insert_with(HashMap::new)
        .insert(path.to_string(), (now, record));
    Ok(record)
}

/// Interns a record built in memory (tests, generated motions); an equal
/// record interned before is shared rather than kept twice.
pub fn intern(record: Record) -> &'static Record {
    let mut built = BUILT.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(r) = built.iter().find(|r| ***r == record) {
        return r;
    }
    let record: &'static Record = Box::leak(Box::new(record));
    built.push(record);
    record
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dominant_frequency_of_a_sampled_sine() {
        // 2 Hz sine sampled at 100 Hz for 10 s: ω = 4π.
        let a: Vec<f64> = (0..1000)
            .map(|k| (4.0 * std::f64::consts::PI * k as f64 * 0.01).sin())
            .collect();
        let w = dominant_omega(&a, 0.01);
        assert!((w - 4.0 * std::f64::consts::PI).abs() < 1e-9, "{w}");
    }

    /// A record file edited between two loads in one process is read
    /// again: the second load gives the new samples (it gave the first
    /// file's, bit for bit, for the life of the process), and a file left
    /// as it was is not read again.
    #[test]
    fn a_file_changed_since_it_was_read_is_read_again() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("rec.csv");
        std::fs::write(&path, "0 0.5\n0.01 -1\n").unwrap();
        let path = path.to_str().unwrap();
        let first = load(path).unwrap();
        assert_eq!(
            first.acceleration,
            [0.5 * STANDARD_GRAVITY, -STANDARD_GRAVITY]
        );
        assert!(std::ptr::eq(first, load(path).unwrap()));
        std::fs::write(path, "0 0.25\n0.01 -1\n0.02 0.75\n").unwrap();
        let second = load(path).unwrap();
        assert_eq!(
            second.acceleration,
            [
                0.25 * STANDARD_GRAVITY,
                -STANDARD_GRAVITY,
                0.75 * STANDARD_GRAVITY
            ]
        );
        assert!(std::ptr::eq(second, load(path).unwrap()));
        // Through the excitation, as a run names it.
        let crate::model::excitation::Excitation::Record(m) =
            crate::model::excitation::Excitation::parse(&format!("record:{path}")).unwrap()
        else {
            panic!("not a record");
        };
        assert_eq!(m.record.acceleration.len(), 3);
        // An edit of the same length is told by its modification time.
        let later = std::time::SystemTime::now() + std::time::Duration::from_secs(5);
        std::fs::write(path, "0 0.75\n0.01 -1\n0.02 0.75\n").unwrap();
        std::fs::File::options()
            .write(true)
            .open(path)
            .unwrap()
            .set_modified(later)
            .unwrap();
        assert_eq!(load(path).unwrap().acceleration[0], 0.75 * STANDARD_GRAVITY);
    }

    #[test]
    fn an_at_sign_in_a_file_name_is_not_a_unit() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("quake@site.csv");
        std::fs::write(&path, "0 0.5\n0.01 -1\n").unwrap();
        let path = path.to_str().unwrap();
        let r = read(path).unwrap();
        assert_eq!(r.acceleration, [0.5 * STANDARD_GRAVITY, -STANDARD_GRAVITY]);
        assert_eq!(
            read(&format!("{path}@m/s2")).unwrap().acceleration,
            [0.5, -1.0]
        );
        let e = read(&format!("{path}@furlongs")).unwrap_err().to_string();
        assert!(e.contains("unknown unit `furlongs`"), "{e}");
    }
}

#[cfg(test)]
mod dominant_tests {
    use super::dominant_omega;

    /// The plain one-frequency-at-a-time sum, kept as the reference.
    fn scalar(a: &[f64], dt: f64) -> f64 {
        let n = a.len();
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
        2.0 * std::f64::consts::PI * best.1 as f64 / (n as f64 * dt)
    }

    #[test]
    fn lanes_and_threads_give_the_scalar_frequency_to_the_bit() {
        for n in [2usize, 3, 7, 100, 1001, 9000] {
            let a: Vec<f64> = (0..n)
                .map(|m| {
                    (0.37 * m as f64).sin() + 0.5 * (1.91 * m as f64).cos() + (m % 7) as f64 * 0.01
                })
                .collect();
            assert_eq!(dominant_omega(&a, 0.01), scalar(&a, 0.01), "n = {n}");
        }
        // All zeros: the first frequency, as before.
        assert_eq!(dominant_omega(&[0.0; 10], 0.1), scalar(&[0.0; 10], 0.1));
    }
}
