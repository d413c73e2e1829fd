//! Simulated ground motions for suites (SPEC §12): filtered white noise
//! under an envelope, scaled to a target PGA, reproducible from a seed.
//!
//! **Noise.** Record j (1-based) of seed S draws standard normal deviates
//! w_k (`rand_distr::StandardNormal`) from `ChaCha20Rng::seed_from_u64(S)`
//! set to stream j, so record j is the same whatever the number of records
//! asked for (`synthetic:20@7` is a prefix of `synthetic:44@7`) and on any
//! machine: ChaCha is defined bit for bit, and the ziggurat sampler uses
//! `exp`/`ln` only in its rare wedge and tail draws, where a last-bit
//! difference between platforms' maths libraries would change a draw only
//! if a uniform fell within one ulp of the density. w_k is held over
//! [t_k, t_{k+1}).
//!
//! **Filter.** Kanai–Tajimi (ground y driven by the noise; the output is
//! its absolute acceleration):
//!
//! ```text
//! ÿ + 2ζ_g ω_g ẏ + ω_g² y = −w,        a_KT = −(2ζ_g ω_g ẏ + ω_g² y),
//! ```
//!
//! and for Clough–Penzien a second oscillator driven by a_KT whose own
//! acceleration is the output, which removes the low frequencies that
//! Kanai–Tajimi leaves in the ground velocity and displacement:
//!
//! ```text
//! ẍ_f + 2ζ_f ω_f ẋ_f + ω_f² x_f = a_KT,   a_CP = ẍ_f = a_KT − 2ζ_f ω_f ẋ_f − ω_f² x_f.
//! ```
//!
//! The filters start at rest and are integrated by the classical Runge–Kutta
//! method, with at least four sub-steps per sample and more when
//! ω(1 + ζ)·DT is large (ω(1 + ζ)·h ≤ 0.1): arithmetic only, so the
//! output does not depend on the platform's libm.
//!
//! **Envelope.** The Jennings, Housner and Tsai (1968) trapezoid over the
//! duration D: e = (t/t₁)² for t < t₁ = 0.1 D, 1 up to t₂ = 0.5 D, then
//! e^{−c(t − t₂)} with c = ln 20 / (D − t₂), so e(D) = 0.05 (`libm`'s exp and
//! log, the same on every machine).
//!
//! **Scale.** a_k = filter output × e(t_k) at t_k = k·DT, k = 0 … round(D/DT),
//! then multiplied by PGA / max |a_k|, in g.
//!
//! **Memory and files agree bit for bit.** The `.AT2` text writes each value
//! in g in its shortest round-trip form (Rust's `{}`), so reading it back
//! gives the same f64; [`Simulation::record`] builds the record in memory through the
//! same g → m/s² product as the `.AT2` reader.

use std::fmt;

use rand_chacha::ChaCha20Rng;
use rand_chacha::rand_core::SeedableRng;
use rand_distr::{Distribution, StandardNormal};

use super::record::{MAX_SAMPLES, Record, STANDARD_GRAVITY};

/// The seed of `synthetic:N` and `records synth` when none is given.
pub const DEFAULT_SEED: u64 = 1;

/// Most records one suite or one `records synth` may generate.
pub const MAX_COUNT: usize = 1000;

/// The ground filter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Filter {
    /// Kanai–Tajimi: one oscillator (ω_g, ζ_g).
    KanaiTajimi,
    /// Clough–Penzien: Kanai–Tajimi, then a high-pass oscillator (ω_f, ζ_f).
    CloughPenzien { omega_f: f64, zeta_f: f64 },
}

impl Filter {
    /// The name `--filter` takes.
    pub fn name(&self) -> &'static str {
        match self {
            Filter::KanaiTajimi => "kanai-tajimi",
            Filter::CloughPenzien { .. } => "clough-penzien",
        }
    }
}

/// Everything but the seed and the record's number that a simulated record
/// depends on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Simulation {
    /// Duration D (s).
    pub duration: f64,
    /// Sample interval DT (s).
    pub dt: f64,
    /// Target peak ground acceleration (g).
    pub pga: f64,
    pub filter: Filter,
    /// Ground filter frequency ω_g (rad/s).
    pub omega_g: f64,
    /// Ground filter damping ratio ζ_g.
    pub zeta_g: f64,
}

/// Firm soil: ω_g = 5π rad/s (2.5 Hz), ζ_g = 0.6; 20 s at 100 Hz, PGA 0.3 g.
impl Default for Simulation {
    fn default() -> Simulation {
        Simulation {
            duration: 20.0,
            dt: 0.01,
            pga: 0.3,
            filter: Filter::KanaiTajimi,
            omega_g: DEFAULT_OMEGA_G,
            zeta_g: DEFAULT_ZETA_G,
        }
    }
}

pub const DEFAULT_OMEGA_G: f64 = 5.0 * std::f64::consts::PI;
pub const DEFAULT_ZETA_G: f64 = 0.6;
/// Clough–Penzien's high-pass defaults: ω_f = ω_g/10 = π/2 rad/s, ζ_f = ζ_g.
pub const DEFAULT_OMEGA_F: f64 = 0.5 * std::f64::consts::PI;
pub const DEFAULT_ZETA_F: f64 = 0.6;

/// A parameter out of its range: its key, its value and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct SimulationError {
    /// The key (`omega_g`); the command line's flag is `--omega-g`.
    pub key: &'static str,
    pub value: f64,
    pub allowed: String,
}

impl fmt::Display for SimulationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}: must be {}", self.key, self.value, self.allowed)
    }
}

impl Simulation {
    /// Checks every parameter against its range.
    pub fn validate(&self) -> Result<(), SimulationError> {
        let check = |key: &'static str, value: f64, low: f64, high: f64, unit: &str| {
            if value > low && value <= high {
                Ok(())
            } else {
                Err(SimulationError {
                    key,
                    value,
                    allowed: format!("in ({low}, {high}]{unit}"),
                })
            }
        };
        check("duration", self.duration, 0.0, 600.0, " s")?;
        check("dt", self.dt, 0.0, 0.1, " s")?;
        check("pga", self.pga, 0.0, 10.0, " g")?;
        check("omega_g", self.omega_g, 0.0, 1000.0, " rad/s")?;
        check("zeta_g", self.zeta_g, 0.0, 5.0, "")?;
        if let Filter::CloughPenzien { omega_f, zeta_f } = self.filter {
            check("omega_f", omega_f, 0.0, 1000.0, " rad/s")?;
            check("zeta_f", zeta_f, 0.0, 5.0, "")?;
        }
        let samples = self.duration / self.dt;
        if !(10.0..=(MAX_SAMPLES - 1) as f64).contains(&samples) {
            return Err(SimulationError {
                key: "dt",
                value: self.dt,
                allowed: format!(
                    "such that duration/dt is in [10, {}] (duration = {} s)",
                    MAX_SAMPLES - 1,
                    self.duration
                ),
            });
        }
        Ok(())
    }

    /// Number of samples, round(D/DT) + 1.
    pub fn samples(&self) -> usize {
        (self.duration / self.dt).round() as usize + 1
    }

    /// The envelope e(t) of the module doc.
    pub fn envelope(&self, t: f64) -> f64 {
        let (t1, t2) = (0.1 * self.duration, 0.5 * self.duration);
        if t < t1 {
            (t / t1) * (t / t1)
        } else if t <= t2 {
            1.0
        } else {
            libm::exp(-libm::log(20.0) * (t - t2) / (self.duration - t2))
        }
    }

    /// Record `index` (1-based) of `seed`, in g, sample k at t = k·DT.
    /// `self` must be valid ([`Simulation::validate`]).
    pub fn accelerogram(&self, seed: u64, index: usize) -> Vec<f64> {
        let mut rng = ChaCha20Rng::seed_from_u64(seed);
        rng.set_stream(index as u64);
        let (wg, zg) = (self.omega_g, self.zeta_g);
        let (wf, zf) = match self.filter {
            Filter::KanaiTajimi => (0.0, 0.0),
            Filter::CloughPenzien { omega_f, zeta_f } => (omega_f, zeta_f),
        };
        let high_pass = matches!(self.filter, Filter::CloughPenzien { .. });
        // State [y, ẏ, x_f, ẋ_f] and its rate under the held noise w.
        let ground = |s: &[f64; 4]| -(2.0 * zg * wg * s[1] + wg * wg * s[0]);
        let output = |s: &[f64; 4]| {
            let a = ground(s);
            if high_pass {
                a - 2.0 * zf * wf * s[3] - wf * wf * s[2]
            } else {
                a
            }
        };
        let rate = |s: &[f64; 4], w: f64| {
            let a = ground(s);
            [
                s[1],
                -w + a,
                s[3],
                a - 2.0 * zf * wf * s[3] - wf * wf * s[2],
            ]
        };
        let fastest = (wg * (1.0 + zg)).max(wf * (1.0 + zf));
        let substeps = ((fastest * self.dt / 0.1).ceil() as usize).max(4);
        let h = self.dt / substeps as f64;
        let n = self.samples();
        let mut state = [0.0f64; 4];
        let mut out = Vec::with_capacity(n);
        for k in 0..n {
            // + 0.0: the first sample, at rest, is +0 rather than −0.
            out.push(output(&state) * self.envelope(k as f64 * self.dt) + 0.0);
            let w: f64 = StandardNormal.sample(&mut rng);
            for _ in 0..substeps {
                state = rk4(&state, h, |s| rate(s, w));
            }
        }
        let peak = out.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        let scale = self.pga / peak;
        out.iter().map(|a| a * scale).collect()
    }

    /// `synthetic:N`: one record of `samples` ≥ 11 samples at DT = 0.005 s
    /// with the default filter, PGA and envelope, record 1 of the default
    /// seed (as `records synth`), named `name`.
    pub fn synthetic(name: &str, samples: usize) -> Result<Record, SimulationError> {
        let simulation = Simulation {
            dt: 0.005,
            duration: 0.005 * samples.saturating_sub(1) as f64,
            ..Default::default()
        };
        simulation.validate()?;
        Ok(simulation.record(name, DEFAULT_SEED, 1))
    }

    /// Record `index` of `seed` as a [`Record`] named `name`, built exactly
    /// as the `.AT2` reader builds it from [`Simulation::at2_text`].
    pub fn record(&self, name: &str, seed: u64, index: usize) -> Record {
        let g = self.accelerogram(seed, index);
        Record::from_samples(
            name,
            self.dt,
            g.iter().map(|a| a * STANDARD_GRAVITY).collect(),
        )
    }

    /// Record `index` of `seed` as the text of a PEER-like `.AT2` file: four
    /// header lines stating the generator and its parameters, then the
    /// values in g, five to a line, each in its shortest round-trip form.
    pub fn at2_text(&self, seed: u64, index: usize) -> String {
        let g = self.accelerogram(seed, index);
        let filter = match self.filter {
            Filter::KanaiTajimi => format!(
                "Kanai-Tajimi filter (omega_g = {} rad/s, zeta_g = {})",
                self.omega_g, self.zeta_g
            ),
            Filter::CloughPenzien { omega_f, zeta_f } => format!(
                "Clough-Penzien filter (omega_g = {} rad/s, zeta_g = {}, omega_f = {} rad/s, zeta_f = {})",
                self.omega_g, self.zeta_g, omega_f, zeta_f
            ),
        };
        let mut s = format!(
            "PEER NGA STRONG MOTION DATABASE RECORD (format); simulated, not a recording: pounding records synth, seed {seed}, record {index}\n\
             White noise (ChaCha20, stream {index}), {filter}, Jennings trapezoid envelope, duration {} s, PGA {} g\n\
             ACCELERATION TIME SERIES IN UNITS OF G\n\
             NPTS= {}, DT= {} SEC\n",
            self.duration,
            self.pga,
            g.len(),
            self.dt
        );
        for chunk in g.chunks(5) {
            let line: Vec<String> = chunk.iter().map(|a| format!("{a}")).collect();
            s.push_str(&line.join("  "));
            s.push('\n');
        }
        s
    }
}

/// The file name of record `index`: `synthetic-001.at2`.
pub fn file_name(index: usize) -> String {
    format!("{}.at2", member_name(index))
}

/// The name of record `index` in a suite: `synthetic-001`.
pub fn member_name(index: usize) -> String {
    format!("synthetic-{index:03}")
}

/// One classical Runge–Kutta step of ṡ = f(s).
fn rk4(s: &[f64; 4], h: f64, f: impl Fn(&[f64; 4]) -> [f64; 4]) -> [f64; 4] {
    let add = |a: &[f64; 4], k: &[f64; 4], c: f64| std::array::from_fn(|i| a[i] + c * k[i]);
    let k1 = f(s);
    let k2 = f(&add(s, &k1, 0.5 * h));
    let k3 = f(&add(s, &k2, 0.5 * h));
    let k4 = f(&add(s, &k3, h));
    std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::record::parse_at2;

    #[test]
    fn reaches_the_target_pga_and_reads_back_bit_for_bit() {
        let sim = Simulation::default();
        sim.validate().unwrap();
        let g = sim.accelerogram(7, 2);
        assert_eq!(g.len(), 2001);
        let peak = g.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        assert!((peak - 0.3).abs() < 1e-15, "{peak}");
        let back = parse_at2("x.at2", &sim.at2_text(7, 2)).unwrap();
        let memory = sim.record("x.at2", 7, 2);
        assert_eq!(back, memory);
    }

    #[test]
    fn records_depend_on_seed_and_index_only() {
        let sim = Simulation::default();
        assert_eq!(sim.accelerogram(7, 3), sim.accelerogram(7, 3));
        assert_ne!(sim.accelerogram(7, 3), sim.accelerogram(7, 4));
        assert_ne!(sim.accelerogram(7, 3), sim.accelerogram(8, 3));
    }

    #[test]
    fn clough_penzien_removes_the_drift_of_the_ground_displacement() {
        // Kanai–Tajimi leaves low frequencies that make the ground drift
        // (metres after 20 s); the high-pass brings it down tenfold.
        let kt = Simulation::default();
        let cp = Simulation {
            filter: Filter::CloughPenzien {
                omega_f: DEFAULT_OMEGA_F,
                zeta_f: DEFAULT_ZETA_F,
            },
            ..kt
        };
        cp.validate().unwrap();
        let drift = |s: &Simulation| -> f64 {
            (1..=8)
                .map(|j| s.record("x", 3, j).displacement.last().unwrap().abs())
                .sum()
        };
        let (free, filtered) = (drift(&kt), drift(&cp));
        assert!(filtered < 0.3 * free, "{filtered} vs {free}");
    }

    #[test]
    fn out_of_range_parameters_name_the_key() {
        let bad = Simulation {
            zeta_g: -1.0,
            ..Simulation::default()
        };
        assert_eq!(
            bad.validate().unwrap_err().to_string(),
            "zeta_g = -1: must be in (0, 5]"
        );
        let short = Simulation {
            dt: 0.05,
            duration: 0.1,
            ..Simulation::default()
        };
        assert_eq!(short.validate().unwrap_err().key, "dt");
    }
}
