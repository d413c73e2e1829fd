//! One hash of a whole request, carried by each of its parts.
//!
//! It covers what decides the results and how they are reported: the
//! program's version and whether it was built with fused multiply-add, the command, and the resolved request (every
//! parameter, the grid or axes, the family, the method, and for suites the
//! records' samples themselves, not only their names), hashed from the
//! request's own values. Two parts merge only if their fingerprints are
//! equal, and a merge recomputes the fingerprint from the parts' command
//! line to check that the inputs it reads again have not changed.
//!
//! The hash is 128-bit FNV-1a: stable across machines and builds of the
//! same version, enough to tell requests apart by accident, not meant to
//! resist a forger.

use std::fmt;

const OFFSET: u128 = 0x6c62272e07bb014262b821756295c58d;
const PRIME: u128 = 0x0000000001000000000000000000013b;

/// A running fingerprint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fingerprint(u128);

impl Fingerprint {
    /// A fingerprint of the version and the command.
    pub fn new(command: &str) -> Fingerprint {
        let mut f = Fingerprint(OFFSET);
        f.add_str(env!("CARGO_PKG_VERSION"));
        // A build with fused multiply-add differs from one without in the
        // last bits (see the guide's getting-started chapter): their parts do not mix.
        f.add_str(if cfg!(target_feature = "fma") {
            "fma"
        } else {
            "no-fma"
        });
        f.add_str(command);
        f
    }

    pub fn add_bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u128::from(b);
            self.0 = self.0.wrapping_mul(PRIME);
        }
    }

    /// A string, with its length so that concatenations stay distinct.
    pub fn add_str(&mut self, s: &str) {
        self.add_bytes(&(s.len() as u64).to_le_bytes());
        self.add_bytes(s.as_bytes());
    }

    /// Numbers bit for bit.
    pub fn add_f64s(&mut self, values: &[f64]) {
        self.add_bytes(&(values.len() as u64).to_le_bytes());
        for v in values {
            self.add_bytes(&v.to_bits().to_le_bytes());
        }
    }

    /// A value by its `Debug` form, which names every field and writes
    /// every float in its shortest exact form.
    pub fn add_debug(&mut self, value: &impl fmt::Debug) {
        use fmt::Write as _;
        let _ = write!(self, "{value:?}");
        self.add_bytes(&[0xff]);
    }

    /// 32 hexadecimal digits.
    pub fn hex(&self) -> String {
        format!("{:032x}", self.0)
    }
}

impl fmt::Write for Fingerprint {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        self.add_bytes(s.as_bytes());
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differs_by_any_field() {
        let mut a = Fingerprint::new("map");
        a.add_debug(&(1.0, 2.0));
        let mut b = Fingerprint::new("map");
        b.add_debug(&(1.0, 2.0000000000000004));
        assert_ne!(a, b);
        assert_ne!(Fingerprint::new("map"), Fingerprint::new("spectrum"));
        assert_eq!(a.hex().len(), 32);
    }
}
