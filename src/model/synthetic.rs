//! The synthetic accelerogram shipped as `presets/synthetic.at2`, so that a
//! record runs from a fresh clone without a network: Kanai–Tajimi filtered
//! white noise under a Shinozuka–Sato envelope, from a fixed seed.
//!
//! White noise w (unit variance per sample, held over each sample interval)
//! drives the ground filter
//!
//! ```text
//! ÿ + 2ζ_g ω_g ẏ + ω_g² y = −w,   a = −(2ζ_g ω_g ẏ + ω_g² y),
//! ```
//!
//! (ω_g = 5π rad/s, ζ_g = 0.6: a firm soil), integrated by RK4 with four
//! sub-steps per sample; a is multiplied by the envelope
//! e(t) = (e^{−0.4t} − e^{−1.2t})/max, and scaled to a peak of 0.3 g.

/// Samples, interval (s), seed and peak (g) of the shipped record.
pub const SAMPLES: usize = 1000;
pub const DT: f64 = 0.01;
pub const SEED: u64 = 20_250_901;
pub const PEAK_G: f64 = 0.3;

/// SplitMix64, then Box–Muller: standard normal deviates from a seed.
struct Normal(u64);

impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn next(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

/// The accelerogram in g, sample k at t = k·DT.
pub fn accelerogram() -> Vec<f64> {
    let (wg, zg) = (5.0 * std::f64::consts::PI, 0.6);
    let mut noise = Normal(SEED);
    let (mut y, mut v) = (0.0f64, 0.0f64);
    let rate = |y: f64, v: f64, w: f64| (v, -w - 2.0 * zg * wg * v - wg * wg * y);
    let envelope = |t: f64| (-0.4 * t).exp() - (-1.2 * t).exp();
    // Peak of the envelope at t = ln 3 / 0.8.
    let top = envelope(3f64.ln() / 0.8);
    let h = DT / 4.0;
    let mut out = Vec::with_capacity(SAMPLES);
    for k in 0..SAMPLES {
        let t = k as f64 * DT;
        out.push(-(2.0 * zg * wg * v + wg * wg * y) * envelope(t) / top);
        let w = noise.next();
        for _ in 0..4 {
            let (k1y, k1v) = rate(y, v, w);
            let (k2y, k2v) = rate(y + 0.5 * h * k1y, v + 0.5 * h * k1v, w);
            let (k3y, k3v) = rate(y + 0.5 * h * k2y, v + 0.5 * h * k2v, w);
            let (k4y, k4v) = rate(y + h * k3y, v + h * k3v, w);
            y += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        }
    }
    let peak = out.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    out.iter().map(|a| a * PEAK_G / peak).collect()
}

/// The accelerogram as the text of a PEER `.AT2` file (values in g, five per line).
pub fn at2_text() -> String {
    let mut s = String::from(
        "PEER NGA STRONG MOTION DATABASE RECORD (format); synthetic, not a recording\n\
         Kanai-Tajimi filtered white noise (wg = 5pi rad/s, zg = 0.6), Shinozuka-Sato envelope, seed 20250901, PGA 0.3 g\n\
         ACCELERATION TIME SERIES IN UNITS OF G\n",
    );
    s.push_str(&format!("NPTS=  {SAMPLES}, DT=   {DT:.4} SEC\n"));
    for chunk in accelerogram().chunks(5) {
        let line: Vec<String> = chunk.iter().map(|a| format!("{a:15.7E}")).collect();
        s.push_str(&line.join(""));
        s.push('\n');
    }
    s
}
