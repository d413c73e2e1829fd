//! Recorded ground motions (SPEC §9), read once and shared while any run
//! holds them. Three formats, recognised by their content whatever the
//! file's name ([`Format::of`]):
//!
//! - [`at2`]: a PEER NGA `.AT2` accelerogram, in g;
//! - [`knet`]: a K-NET or KiK-net ASCII record (NIED), integer counts with a
//!   scale factor to gal, less the record's mean;
//! - [`columns`]: plain `time, acceleration` text in the unit named after `@`.
//!
//! Sample k is at t_k = k·DT; between samples the acceleration is linear,
//! after the last one it is zero.
//!
//! A record's samples are owned jointly by the runs driven by it: every
//! parameter set, suite member and excitation that names a record holds an
//! [`Arc<Record>`], so a sweep, an IDA or the explorer's reruns share one
//! copy of the samples and cloning a set costs a reference count, not the
//! record. The solvers borrow the samples for a run and never touch the
//! count per step.
//!
//! The registry that shares them ([`load`], [`intern`]) holds only weak
//! references: when the last run, suite or set that names a record is
//! dropped, its samples are freed, so a notebook kernel or a long explorer
//! session keeps only the records it still uses, not every one it ever read.
//! A file is keyed by its path as named together with its length and
//! modification time: a file changed since it was read is read again, and
//! the sets made afterwards get the new samples while runs already holding
//! the old ones keep them until they end.

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
use std::sync::{Arc, LazyLock, Mutex, MutexGuard, OnceLock, Weak};

/// Standard gravity, the unit of `.AT2` accelerations (m/s²).
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// A sampled ground acceleration with its exact integrals.
#[derive(Debug)]
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
    /// The circular frequency of [`Record::dominant_omega`], found the first
    /// time it is asked: a row's run never reads it, and its O(N²) sum is
    /// a record's largest cost to make.
    dominant: OnceLock<f64>,
}

/// Records are equal when their samples and names are: the dominant
/// frequency follows from the samples, found or not yet.
impl PartialEq for Record {
    fn eq(&self, other: &Self) -> bool {
        self.path == other.path
            && self.spec == other.spec
            && self.dt == other.dt
            && self.acceleration == other.acceleration
            && self.velocity == other.velocity
            && self.displacement == other.displacement
            && self.peak == other.peak
    }
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
            dominant: OnceLock::new(),
            acceleration,
            velocity,
            displacement,
            peak,
        }
    }

    /// Circular frequency (rad/s) of the largest Fourier amplitude of the
    /// record, the default ω_p (the pair's Π-groups, SPEC §12).
    pub fn dominant_omega(&self) -> f64 {
        *self
            .dominant
            .get_or_init(|| dominant_omega(&self.acceleration, self.dt))
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

/// Weak references to the records in use, by key, pruned of the dead ones
/// as it grows: a record is freed when its last holder drops it, and its
/// entry goes at the next pruning, so the table stays within twice the
/// number of records live at its last pruning (and at least
/// [`Registry::FLOOR`] entries before any).
struct Registry<K, V> {
    entries: HashMap<K, V>,
    /// The length at which the dead entries are pruned next.
    prune_at: usize,
}

impl<K: std::hash::Hash + Eq, V: Entry> Registry<K, V> {
    /// Entries held before the first pruning.
    const FLOOR: usize = 64;

    fn new() -> Self {
        Registry {
            entries: HashMap::new(),
            prune_at: Self::FLOOR,
        }
    }

    /// Inserts `value` at `key` (replacing what was there), first dropping
    /// the dead entries if the table has reached its pruning length.
    fn insert(&mut self, key: K, value: V) {
        if self.entries.len() >= self.prune_at {
            self.entries.retain(|_, v| v.is_live());
            self.prune_at = (2 * self.entries.len()).max(Self::FLOOR);
        }
        self.entries.insert(key, value);
    }

    fn live(&self) -> usize {
        self.entries.values().map(Entry::live).sum()
    }
}

/// What a registry holds per key: one weak record or several.
trait Entry {
    /// How many of the records are still held by a run.
    fn live(&self) -> usize;
    fn is_live(&self) -> bool {
        self.live() > 0
    }
}

impl Entry for FileEntry {
    fn live(&self) -> usize {
        usize::from(self.1.strong_count() > 0)
    }
}

impl Entry for Vec<Weak<Record>> {
    fn live(&self) -> usize {
        self.iter().filter(|w| w.strong_count() > 0).count()
    }
}

/// A record read from a file, with the stamp of the file it was read from.
type FileEntry = (Stamp, Weak<Record>);

/// Records read from files, by `PATH` or `PATH@UNIT` as named.
type Files = Registry<String, FileEntry>;

static FILES: LazyLock<Mutex<Files>> = LazyLock::new(|| Mutex::new(Registry::new()));

/// Records built in memory ([`intern`]), by their `record:` name; equal
/// records share one entry of the list under their name.
static BUILT: LazyLock<Mutex<Registry<String, Vec<Weak<Record>>>>> =
    LazyLock::new(|| Mutex::new(Registry::new()));

/// A registry's lock, taken even if a thread panicked while holding it
/// (the tables stay consistent: each change is one insertion or one prune).
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// The record at `path`, read on first use and shared afterwards while any
/// run holds it, and read again when the file has changed since (its
/// length or modification time) or when every holder has dropped it.
///
/// The file is read with the registry unlocked: reading runs on rayon's
/// pool (the dominant frequency's transform), whose workers may be waiting
/// for a lock on another thread's behalf, so a read under the lock could
/// wait for them for ever. Two threads reading the same file at once both
/// read it, and the first to register it is kept.
pub fn load(path: &str) -> Result<Arc<Record>, RecordError> {
    let now = stamp(path);
    let registered = |files: &Files| {
        files
            .entries
            .get(path)
            .filter(|(then, _)| then.is_some() && *then == now)
            .and_then(|(_, r)| r.upgrade())
    };
    if let Some(r) = registered(&lock(&FILES)) {
        return Ok(r);
    }
    let record = read(path)?;
    let mut files = lock(&FILES);
    if let Some(r) = registered(&files) {
        return Ok(r);
    }
    let record = Arc::new(record);
    files.insert(path.to_string(), (now, Arc::downgrade(&record)));
    Ok(record)
}

/// Shares a record built in memory (tests, generated motions): an equal
/// record still held by a run is shared rather than kept twice; once every
/// holder has dropped it, it is freed, and an equal one built later is new.
pub fn intern(record: Record) -> Arc<Record> {
    let mut built = lock(&BUILT);
    if let Some(r) = built
        .entries
        .get(&record.spec)
        .into_iter()
        .flatten()
        .filter_map(Weak::upgrade)
        .find(|r| **r == record)
    {
        return r;
    }
    let key = record.spec.clone();
    let record = Arc::new(record);
    let mut same_name: Vec<Weak<Record>> = built
        .entries
        .remove(&key)
        .unwrap_or_default()
        .into_iter()
        .filter(|w| w.strong_count() > 0)
        .collect();
    same_name.push(Arc::downgrade(&record));
    built.insert(key, same_name);
    record
}

/// How many records, read from files or built in memory, some run, suite
/// or parameter set still holds: the records whose memory is in use.
pub fn live_records() -> usize {
    lock(&FILES).live() + lock(&BUILT).live()
}

/// How many entries the registries keep, live or dead (a dead one awaits
/// the next pruning): bounded by twice the live records at the last
/// pruning, never by every record the process has read.
pub fn registry_len() -> usize {
    lock(&FILES).entries.len() + lock(&BUILT).entries.len()
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

    /// A record finds its dominant frequency when first asked (4π for a
    /// 2 Hz sine), and two records of the same samples are equal whether
    /// or not one of them has been asked.
    #[test]
    fn the_dominant_frequency_is_found_when_asked() {
        let a: Vec<f64> = (0..1000)
            .map(|k| (4.0 * std::f64::consts::PI * k as f64 * 0.01).sin())
            .collect();
        let (asked, fresh) = (
            Record::from_samples("sine", 0.01, a.clone()),
            Record::from_samples("sine", 0.01, a),
        );
        assert!(asked.dominant.get().is_none());
        let w = asked.dominant_omega();
        assert!((w - 4.0 * std::f64::consts::PI).abs() < 1e-9, "{w}");
        assert_eq!(asked.dominant.get(), Some(&w));
        assert_eq!(asked, fresh);
        let mut other = fresh.acceleration.clone();
        other[3] += 1e-9;
        assert_ne!(asked, Record::from_samples("sine", 0.01, other));
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
        assert!(Arc::ptr_eq(&first, &load(path).unwrap()));
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
        assert!(Arc::ptr_eq(&second, &load(path).unwrap()));
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
