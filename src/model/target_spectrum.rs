//! The site's hazard as a target spectrum: the 5 %-damped elastic
//! acceleration spectrum Sa(T), in g, that a suite of records is scaled to
//! (SPEC §12). Three forms, parsed from one string ([`TargetSpectrum::parse`]):
//!
//! - `asce7:SDS=…,SD1=…,TL=…`: the design response spectrum of ASCE/SEI
//!   7-16 §11.4.6 (Figure 11.4-1), with T0 = 0.2·S_D1/S_DS and
//!   T_S = S_D1/S_DS:
//!
//!   ```text
//!   Sa = S_DS (0.4 + 0.6 T/T0)   T < T0            (11.4-5)
//!   Sa = S_DS                    T0 ≤ T ≤ T_S
//!   Sa = S_D1 / T                T_S < T ≤ T_L     (11.4-6)
//!   Sa = S_D1 T_L / T²           T > T_L           (11.4-7)
//!   ```
//!
//!   `asce7-mce:…` is the MCE_R response spectrum, 1.5 times the design
//!   one (§11.4.7), the target of Chapter 16 in 7-16 and 7-22;
//! - `ec8:ag=…,ground=A|B|C|D|E,type=1|2[,importance=…]`: the horizontal
//!   elastic response spectrum of EN 1998-1:2004 §3.2.2.2, eq. (3.2)–(3.5),
//!   with S, T_B, T_C, T_D from Table 3.2 (type 1) or 3.3 (type 2), η = 1
//!   at 5 % damping (eq. 3.6), and the design ground acceleration
//!   a_g = γ_I·a_gR (§3.2.1(3)), `ag` being a_gR on ground A in g and
//!   `importance` γ_I (1 unless given):
//!
//!   ```text
//!   Sa = a_g S (1 + T/T_B (2.5 η − 1))   0 ≤ T ≤ T_B      (3.2)
//!   Sa = a_g S η 2.5                     T_B ≤ T ≤ T_C    (3.3)
//!   Sa = a_g S η 2.5 T_C / T             T_C ≤ T ≤ T_D    (3.4)
//!   Sa = a_g S η 2.5 T_C T_D / T²        T_D ≤ T ≤ 4 s    (3.5)
//!   ```
//!
//! - `file:PATH`: two columns, T (s) and Sa (g), T strictly increasing and
//!   both positive; `#` lines and blank lines skipped; between two rows Sa
//!   is interpolated linearly in (ln T, ln Sa), and a row's period gives
//!   its value exactly. Outside its first and last period it is undefined.

use std::fmt;

use super::intensity::MAX_PERIOD;

/// A target spectrum (module doc).
#[derive(Debug, Clone, PartialEq)]
pub enum TargetSpectrum {
    Asce7(Asce7),
    Ec8(Ec8),
    File(TableSpectrum),
}

/// ASCE/SEI 7-16 §11.4.6 (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Asce7 {
    /// S_DS, the design spectral acceleration at short periods (g).
    pub sds: f64,
    /// S_D1, the design spectral acceleration at 1 s (g).
    pub sd1: f64,
    /// T_L, the long-period transition period (s).
    pub tl: f64,
    /// The MCE_R spectrum, 1.5 × the design one (§11.4.7).
    pub mce: bool,
}

/// EN 1998-1 ground types (Table 3.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ground {
    A,
    B,
    C,
    D,
    E,
}

/// EN 1998-1 §3.2.2.2(2)P: type 1 for the high-seismicity spectrum, type 2
/// where the earthquakes that contribute most have M_s ≤ 5.5.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ec8Type {
    One,
    Two,
}

/// EN 1998-1 §3.2.2.2 (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8 {
    /// a_gR, the reference peak ground acceleration on ground A (g).
    pub agr: f64,
    /// γ_I, the importance factor.
    pub importance: f64,
    pub ground: Ground,
    pub kind: Ec8Type,
}

/// A spectrum given as a table (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct TableSpectrum {
    /// The path as given after `file:`.
    pub path: String,
    /// Periods (s), strictly increasing, positive.
    pub periods: Vec<f64>,
    /// Sa (g) at each period, positive.
    pub values: Vec<f64>,
}

/// A target that could not be read: the spec as given, and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`{text}`: {message}")]
pub struct TargetError {
    pub text: String,
    pub message: String,
}

/// The longest period of the EC8 elastic spectrum (s): eq. (3.5) holds to 4 s.
pub const EC8_MAX_PERIOD: f64 = 4.0;

impl Ground {
    pub const NAMES: &'static str = "A, B, C, D, E";

    fn parse(text: &str) -> Option<Ground> {
        Some(match text.trim().to_ascii_uppercase().as_str() {
            "A" => Ground::A,
            "B" => Ground::B,
            "C" => Ground::C,
            "D" => Ground::D,
            "E" => Ground::E,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Ground::A => "A",
            Ground::B => "B",
            Ground::C => "C",
            Ground::D => "D",
            Ground::E => "E",
        }
    }
}

impl Ec8 {
    /// (S, T_B, T_C, T_D) of EN 1998-1 Table 3.2 (type 1) or 3.3 (type 2),
    /// the recommended values.
    pub fn parameters(&self) -> (f64, f64, f64, f64) {
        match (self.kind, self.ground) {
            (Ec8Type::One, Ground::A) => (1.0, 0.15, 0.4, 2.0),
            (Ec8Type::One, Ground::B) => (1.2, 0.15, 0.5, 2.0),
            (Ec8Type::One, Ground::C) => (1.15, 0.20, 0.6, 2.0),
            (Ec8Type::One, Ground::D) => (1.35, 0.20, 0.8, 2.0),
            (Ec8Type::One, Ground::E) => (1.4, 0.15, 0.5, 2.0),
            (Ec8Type::Two, Ground::A) => (1.0, 0.05, 0.25, 1.2),
            (Ec8Type::Two, Ground::B) => (1.35, 0.05, 0.25, 1.2),
            (Ec8Type::Two, Ground::C) => (1.5, 0.10, 0.25, 1.2),
            (Ec8Type::Two, Ground::D) => (1.8, 0.10, 0.30, 1.2),
            (Ec8Type::Two, Ground::E) => (1.6, 0.05, 0.25, 1.2),
        }
    }

    /// a_g = γ_I·a_gR (g), §3.2.1(3).
    pub fn ag(&self) -> f64 {
        self.importance * self.agr
    }

    /// a_g·S (g): the spectrum at T = 0, and the floor of EN 1998-1
    /// §3.2.3.1.2(4)b on the suite's mean zero-period value.
    pub fn ag_s(&self) -> f64 {
        self.ag() * self.parameters().0
    }

    /// Eq. (3.2)–(3.5) with η = 1 (5 % damping).
    pub fn sa(&self, t: f64) -> f64 {
        let (s, tb, tc, td) = self.parameters();
        let (ag, eta) = (self.ag(), 1.0);
        if t <= tb {
            ag * s * (1.0 + t / tb * (eta * 2.5 - 1.0))
        } else if t <= tc {
            ag * s * eta * 2.5
        } else if t <= td {
            ag * s * eta * 2.5 * (tc / t)
        } else {
            ag * s * eta * 2.5 * (tc * td / (t * t))
        }
    }
}

impl Asce7 {
    /// (T0, T_S) = (0.2 S_D1/S_DS, S_D1/S_DS), s.
    pub fn corners(&self) -> (f64, f64) {
        let ts = self.sd1 / self.sds;
        (0.2 * ts, ts)
    }

    /// Eq. (11.4-5)–(11.4-7), times 1.5 for the MCE_R spectrum.
    pub fn sa(&self, t: f64) -> f64 {
        let (t0, ts) = self.corners();
        let design = if t < t0 {
            self.sds * (0.4 + 0.6 * t / t0)
        } else if t <= ts {
            self.sds
        } else if t <= self.tl {
            self.sd1 / t
        } else {
            self.sd1 * self.tl / (t * t)
        };
        if self.mce { 1.5 * design } else { design }
    }
}

impl TableSpectrum {
    /// Log-log interpolation (module doc); `None` outside the table.
    pub fn sa(&self, t: f64) -> Option<f64> {
        let (p, v) = (&self.periods, &self.values);
        if !(t >= p[0] && t <= p[p.len() - 1]) {
            return None;
        }
        // The first row whose period is ≥ t.
        let i = p.partition_point(|&x| x < t);
        if p[i] == t {
            return Some(v[i]);
        }
        let (t0, t1) = (p[i - 1], p[i]);
        let w = (t / t0).ln() / (t1 / t0).ln();
        Some((v[i - 1].ln() + w * (v[i] / v[i - 1]).ln()).exp())
    }

    /// Reads the table of `text` (the file at `path`); errors name the line.
    pub fn parse(path: &str, text: &str) -> Result<TableSpectrum, String> {
        let mut periods = Vec::new();
        let mut values = Vec::new();
        for (i, line) in text.lines().enumerate() {
            let t = line.trim();
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            let fields: Vec<&str> = t
                .split(|c: char| c.is_whitespace() || c == ',')
                .filter(|f| !f.is_empty())
                .collect();
            let at = |message: String| format!("line {}: {message}", i + 1);
            let [period, value] = fields.as_slice() else {
                return Err(at(format!(
                    "expected two columns `T Sa`, found `{}`",
                    super::record::cut(t)
                )));
            };
            let number = |f: &str, what: &str| {
                f.parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && *v > 0.0)
                    .ok_or_else(|| {
                        at(format!(
                            "{what} `{}` must be a positive number",
                            super::record::cut(f)
                        ))
                    })
            };
            let (period, value) = (number(period, "T")?, number(value, "Sa")?);
            if periods.last().is_some_and(|&last| period <= last) {
                return Err(at(format!(
                    "T = {period} s is not above the line before; the periods must increase"
                )));
            }
            periods.push(period);
            values.push(value);
        }
        if periods.len() < 2 {
            return Err("the file must hold at least two rows `T Sa` (s, g)".into());
        }
        Ok(TableSpectrum {
            path: path.to_string(),
            periods,
            values,
        })
    }
}

/// One `KEY=VALUE` list of a code spectrum, read once: each key at most
/// once, and only those allowed.
struct Keys<'a> {
    pairs: Vec<(String, &'a str)>,
}

impl<'a> Keys<'a> {
    fn parse(text: &'a str, allowed: &[&str]) -> Result<Keys<'a>, String> {
        let mut pairs: Vec<(String, &str)> = Vec::new();
        for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let Some((key, value)) = item.split_once('=') else {
                return Err(format!(
                    "`{item}` must be KEY=VALUE, with KEY one of {}",
                    allowed.join(", ")
                ));
            };
            let key = key.trim().to_ascii_lowercase();
            if !allowed.contains(&key.as_str()) {
                return Err(format!(
                    "unknown key `{}`; must be one of {}",
                    key,
                    allowed.join(", ")
                ));
            }
            if pairs.iter().any(|(k, _)| *k == key) {
                return Err(format!("`{key}` is given twice"));
            }
            pairs.push((key, value.trim()));
        }
        Ok(Keys { pairs })
    }

    fn get(&self, key: &str) -> Option<&'a str> {
        self.pairs.iter().find(|(k, _)| k == key).map(|(_, v)| *v)
    }

    /// A required positive, finite number; `name` as the message shows it.
    fn positive(&self, key: &str, name: &str) -> Result<f64, String> {
        let v = self
            .get(key)
            .ok_or_else(|| format!("{name} is missing; give {key}=…"))?;
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite() && *x > 0.0)
            .ok_or_else(|| format!("{name} = `{v}`: must be a positive number"))
    }
}

impl TargetSpectrum {
    /// What [`TargetSpectrum::parse`] takes, for messages.
    pub const FORMS: &'static str = "asce7:SDS=…,SD1=…,TL=…, asce7-mce:SDS=…,SD1=…,TL=…, \
         ec8:ag=…,ground=A|B|C|D|E,type=1|2[,importance=…] or file:PATH";

    /// Parses a target (module doc); a `file:` is read here.
    pub fn parse(text: &str) -> Result<TargetSpectrum, TargetError> {
        let fail = |message: String| TargetError {
            text: crate::output::escape_controls(text.chars().take(120)),
            message,
        };
        let t = text.trim();
        let (code, rest) = t
            .split_once(':')
            .ok_or_else(|| fail(format!("must be {}", Self::FORMS)))?;
        match code.trim().to_ascii_lowercase().as_str() {
            "asce7" | "asce7-mce" => {
                let keys = Keys::parse(rest, &["sds", "sd1", "tl"]).map_err(fail)?;
                let sds = keys.positive("sds", "S_DS").map_err(fail)?;
                let sd1 = keys.positive("sd1", "S_D1").map_err(fail)?;
                let tl = keys.positive("tl", "T_L").map_err(fail)?;
                let spectrum = Asce7 {
                    sds,
                    sd1,
                    tl,
                    mce: code.trim().eq_ignore_ascii_case("asce7-mce"),
                };
                let ts = spectrum.corners().1;
                if tl <= ts {
                    return Err(fail(format!(
                        "T_L = {tl} s must be above T_S = S_D1/S_DS = {ts} s"
                    )));
                }
                Ok(TargetSpectrum::Asce7(spectrum))
            }
            "ec8" => {
                let keys =
                    Keys::parse(rest, &["ag", "ground", "type", "importance"]).map_err(fail)?;
                let agr = keys.positive("ag", "a_g").map_err(fail)?;
                let ground = keys.get("ground").ok_or_else(|| {
                    fail("the ground type is missing; give ground=A|B|C|D|E".into())
                })?;
                let ground = Ground::parse(ground).ok_or_else(|| {
                    fail(format!(
                        "ground `{ground}`: must be one of {} (EN 1998-1 Table 3.1)",
                        Ground::NAMES
                    ))
                })?;
                let kind = match keys.get("type").map(str::trim) {
                    Some("1") => Ec8Type::One,
                    Some("2") => Ec8Type::Two,
                    Some(other) => {
                        return Err(fail(format!("type `{other}`: must be 1 or 2")));
                    }
                    None => return Err(fail("the spectrum type is missing; give type=1|2".into())),
                };
                let importance = match keys.get("importance") {
                    None => 1.0,
                    Some(_) => keys
                        .positive("importance", "the importance factor γ_I")
                        .map_err(fail)?,
                };
                Ok(TargetSpectrum::Ec8(Ec8 {
                    agr,
                    importance,
                    ground,
                    kind,
                }))
            }
            "file" => {
                let path = rest.trim();
                let bytes = std::fs::read(path).map_err(|e| fail(crate::output::reason(&e)))?;
                let text = String::from_utf8_lossy(&bytes);
                TableSpectrum::parse(path, &text)
                    .map(TargetSpectrum::File)
                    .map_err(|m| fail(format!("{m} (two increasing positive columns T s, Sa g)")))
            }
            other => Err(fail(format!(
                "unknown code `{}`; must be {}",
                crate::output::escape_controls(other.chars().take(20)),
                Self::FORMS
            ))),
        }
    }

    /// Sa(T) in g, or `None` outside the periods it is defined on
    /// ([`TargetSpectrum::periods`]).
    pub fn sa(&self, t: f64) -> Option<f64> {
        let (low, high) = self.periods();
        if !(t >= low && t <= high) {
            return None;
        }
        match self {
            TargetSpectrum::Asce7(s) => Some(s.sa(t)),
            TargetSpectrum::Ec8(s) => Some(s.sa(t)),
            TargetSpectrum::File(s) => s.sa(t),
        }
    }

    /// The periods the spectrum is defined on (s): [0, 10] for ASCE 7 (the
    /// longest Sa of SPEC §12), [0, 4] for EC8, the table's first to last.
    pub fn periods(&self) -> (f64, f64) {
        match self {
            TargetSpectrum::Asce7(_) => (0.0, MAX_PERIOD),
            TargetSpectrum::Ec8(_) => (0.0, EC8_MAX_PERIOD),
            TargetSpectrum::File(s) => (s.periods[0], s.periods[s.periods.len() - 1]),
        }
    }

    /// The periods where the spectrum's formula changes (T0, T_S, T_L;
    /// T_B, T_C, T_D; a table's rows): where a mean spectrum is most likely
    /// to dip below it, so a check grid includes them.
    pub fn corners(&self) -> Vec<f64> {
        match self {
            TargetSpectrum::Asce7(s) => {
                let (t0, ts) = s.corners();
                vec![t0, ts, s.tl]
            }
            TargetSpectrum::Ec8(s) => {
                let (_, tb, tc, td) = s.parameters();
                vec![tb, tc, td]
            }
            TargetSpectrum::File(s) => s.periods.clone(),
        }
    }

    /// The spectrum as [`TargetSpectrum::parse`] reads it, with every value
    /// given: `ec8:ag=0.3,ground=B,type=1,importance=1`.
    pub fn label(&self) -> String {
        match self {
            TargetSpectrum::Asce7(s) => format!(
                "asce7{}:SDS={},SD1={},TL={}",
                if s.mce { "-mce" } else { "" },
                s.sds,
                s.sd1,
                s.tl
            ),
            TargetSpectrum::Ec8(s) => format!(
                "ec8:ag={},ground={},type={},importance={}",
                s.agr,
                s.ground.name(),
                match s.kind {
                    Ec8Type::One => 1,
                    Ec8Type::Two => 2,
                },
                s.importance
            ),
            TargetSpectrum::File(s) => format!("file:{}", s.path),
        }
    }

    /// The clause the spectrum comes from, for headers and the guide.
    pub fn clause(&self) -> &'static str {
        match self {
            TargetSpectrum::Asce7(s) if s.mce => "ASCE/SEI 7-16 §11.4.7 (1.5 × §11.4.6)",
            TargetSpectrum::Asce7(_) => "ASCE/SEI 7-16 §11.4.6",
            TargetSpectrum::Ec8(_) => "EN 1998-1 §3.2.2.2, Tables 3.2/3.3",
            TargetSpectrum::File(_) => "a table, interpolated log-log",
        }
    }
}

impl fmt::Display for TargetSpectrum {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}
