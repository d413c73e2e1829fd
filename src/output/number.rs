//! How a number is written in every table, CSV and message: the shortest
//! text that reads back to the same `f64`.

use std::fmt;

/// A float in its shortest round-trip form: plain decimals from 1e-5 to
/// 1e16 (`0.2`, `3.2224489`), exponent form outside (`1e-300`, not three
/// hundred zeros), `inf`/`-inf` for infinities (as the parameter keys take
/// them), `nan` for NaN (as JSON writes it, see [`crate::output::report::float_or_inf`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        let a = v.abs();
        if v.is_nan() {
            f.write_str("nan")
        } else if v.is_infinite() {
            f.write_str(if v > 0.0 { "inf" } else { "-inf" })
        } else if a == 0.0 || (1e-5..1e16).contains(&a) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Num;

    #[test]
    fn shortest_forms_read_back_exactly() {
        for (v, text) in [
            (0.0, "0"),
            (0.2, "0.2"),
            (-3.25, "-3.25"),
            (1e-300, "1e-300"),
            (1.5e-7, "1.5e-7"),
            (2.5e20, "2.5e20"),
            (f64::INFINITY, "inf"),
            (f64::NEG_INFINITY, "-inf"),
        ] {
            assert_eq!(Num(v).to_string(), text);
        }
        for v in [
            std::f64::consts::PI,
            1.0 / 3.0,
            1e-5,
            9.999e15,
            5e-324,
            f64::MAX,
        ] {
            let back: f64 = Num(v).to_string().parse().unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v}");
        }
    }
}
