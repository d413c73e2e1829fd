//! How a message shows what the user wrote: numbers in their shortest
//! round-trip form (`1e-300`, not 300 digits), text on one line (control
//! characters escaped) and cut to a readable length.

/// Longest echo of a user's text, in characters, before it is cut.
pub const MAX_ECHO: usize = 40;

/// The shortest text that reads back as `v`: `0.5`, `50`, `1e300`, `inf`, `NaN`.
pub fn number(v: f64) -> String {
    if v.is_nan() {
        return "NaN".into();
    }
    if v.is_infinite() {
        return if v > 0.0 { "inf" } else { "-inf" }.into();
    }
    // Both `{:e}` and `{:?}` print the shortest digits that round-trip; the
    // exponent form is used outside 1e-4..1e6, as `%g` does.
    if v != 0.0 && !(1e-4..1e6).contains(&v.abs()) {
        return format!("{v:e}");
    }
    let s = format!("{v:?}");
    s.strip_suffix(".0").map_or(s.clone(), str::to_string)
}

/// A number as `%.4g` would print it, for stated bounds: `0.3142`, `1e-06`
/// is written `1e-6`, `1000`.
pub fn g4(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return number(v);
    }
    let exp = v.abs().log10().floor() as i32;
    if (-4..6).contains(&exp) {
        let decimals = (3 - exp).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{v:.3e}");
        let (mantissa, e) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{e}")
    }
}

/// A user's text on one line: control characters escaped (`\n`), cut after
/// [`MAX_ECHO`] characters with the full length stated.
pub fn text(s: &str) -> String {
    let count = s.chars().count();
    let mut out = crate::output::escape_controls(s.chars().take(MAX_ECHO));
    if count > MAX_ECHO {
        out += &format!("… ({count} characters)");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_shortest() {
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(50.0), "50");
        assert_eq!(number(1e300), "1e300");
        assert_eq!(number(1e15), "1e15");
        assert_eq!(number(1234.5), "1234.5");
        assert_eq!(number(1.5e-7), "1.5e-7");
        assert_eq!(number(1e-300), "1e-300");
        assert_eq!(number(-0.0), "-0");
        assert_eq!(number(f64::NEG_INFINITY), "-inf");
        assert_eq!(g4(std::f64::consts::TAU / 20.0), "0.3142");
        assert_eq!(g4(1e-6), "1e-6");
        assert_eq!(g4(1000.0), "1000");
        assert_eq!(g4(1e6), "1e6");
        assert_eq!(g4(0.001), "0.001");
        assert_eq!(g4(6.6e-10), "6.6e-10");
    }

    #[test]
    fn text_is_one_short_line() {
        assert_eq!(text("a\nb"), "a\\nb");
        let long = "x".repeat(1_000_000);
        let e = text(&long);
        assert!(e.len() < 80 && e.ends_with("(1000000 characters)"), "{e}");
    }
}
