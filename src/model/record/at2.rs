//! PEER NGA `.AT2` accelerograms (SPEC §9): four header lines, the fourth
//! giving the number of points and the sample interval (`NPTS=  4000, DT=
//! .0100 SEC`, or in the older form `4000  0.0100  NPTS, DT`), then the
//! accelerations in g (9.80665 m/s²), several to a line.

use super::{MAX_SAMPLES, Record, RecordError, STANDARD_GRAVITY, cut};

/// Whether `text` looks like an `.AT2` file: PEER's name on the first line,
/// or `NPTS` on the fourth.
pub fn recognises(text: &str) -> bool {
    let mut lines = text.lines();
    let first = lines.next().unwrap_or("").to_ascii_uppercase();
    let fourth = lines.nth(2).unwrap_or("").to_ascii_uppercase();
    first.contains("PEER") || fourth.contains("NPTS")
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
}
