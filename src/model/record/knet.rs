//! K-NET and KiK-net ASCII records (NIED; SPEC §9): one component of one
//! station.
//!
//! Seventeen header lines, each a key in the first 18 columns and its value
//! after them:
//!
//! ```text
//! Origin Time       2011/03/11 14:46:00
//! Lat.              38.103
//! Long.             142.860
//! Depth. (km)       24
//! Mag.              9.0
//! Station Code      MYG004
//! Station Lat.      38.7312
//! Station Long.     141.0217
//! Station Height(m) 240
//! Record Time       2011/03/11 14:46:55
//! Sampling Freq(Hz) 100Hz
//! Duration Time(s)  300
//! Dir.              N-S
//! Scale Factor      3920(gal)/6182761
//! Max. Acc. (gal)   2699.7
//! Last Correction   2011/03/11 14:46:40
//! Memo.
//! ```
//!
//! then the samples as integer counts, several to a line. As NIED instructs,
//! the acceleration in gal is counts × X/Y (the scale factor `X(gal)/Y`)
//! less the mean of the whole record: a_k = c_k X/Y − (1/N) Σ_j c_j X/Y,
//! and 1 gal = 0.01 m/s². The sample interval is 1/(sampling frequency).

use super::{MAX_SAMPLES, Record, RecordError, cut};

/// Header lines before the counts.
pub const HEADER_LINES: usize = 17;

/// Whether `text` opens with K-NET's first header key.
pub fn recognises(text: &str) -> bool {
    text.trim_start_matches('\u{feff}')
        .lines()
        .next()
        .is_some_and(|l| l.trim_start().starts_with("Origin Time"))
}

/// The value after `key` on its header line: (1-based line, value).
fn header_value<'a>(lines: &[&'a str], key: &str) -> Option<(usize, &'a str)> {
    lines
        .iter()
        .take(HEADER_LINES)
        .enumerate()
        .find_map(|(i, l)| Some((i + 1, l.trim_start().strip_prefix(key)?.trim())))
}

/// Parses the text of a K-NET / KiK-net ASCII file named `path` (for messages).
pub fn parse_knet(path: &str, text: &str) -> Result<Record, RecordError> {
    let fail = |line: usize, message: String| RecordError {
        path: path.to_string(),
        line,
        message,
    };
    let lines: Vec<&str> = text.lines().collect();
    let required = |key: &str, line: usize| {
        header_value(&lines, key).ok_or_else(|| {
            fail(
                line.min(lines.len() + 1),
                format!("missing `{key}` in the {HEADER_LINES}-line K-NET header"),
            )
        })
    };
    let (freq_line, freq) = required("Sampling Freq(Hz)", 11)?;
    let hz = freq
        .strip_suffix("Hz")
        .unwrap_or(freq)
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|f| f.is_finite() && *f >= 0.1 && *f <= 1e6)
        .ok_or_else(|| {
            fail(
                freq_line,
                format!(
                    "sampling frequency `{}`: must be a number of Hz in [0.1, 1e6], as `100Hz`",
                    cut(freq)
                ),
            )
        })?;
    let (scale_line, scale) = required("Scale Factor", 14)?;
    let factor = scale_factor(scale).ok_or_else(|| {
        fail(
            scale_line,
            format!(
                "scale factor `{}`: must be `X(gal)/Y` with X and Y positive numbers",
                cut(scale)
            ),
        )
    })?;
    let memo = header_value(&lines, "Memo.").map_or(HEADER_LINES, |(line, _)| line);
    let mut counts: Vec<i64> = Vec::new();
    for (i, line) in lines.iter().enumerate().skip(memo) {
        for token in line.split_whitespace() {
            let count = token.parse::<i64>().map_err(|_| {
                fail(
                    i + 1,
                    format!("`{}` is not a whole number of counts", cut(token)),
                )
            })?;
            if counts.len() == MAX_SAMPLES {
                return Err(fail(i + 1, format!("more than {MAX_SAMPLES} samples")));
            }
            counts.push(count);
        }
    }
    if counts.is_empty() {
        return Err(fail(
            lines.len().max(memo) + 1,
            format!("no samples after the {HEADER_LINES}-line K-NET header"),
        ));
    }
    let gal: Vec<f64> = counts.iter().map(|&c| c as f64 * factor).collect();
    let mean = gal.iter().sum::<f64>() / gal.len() as f64;
    let acceleration = gal.iter().map(|a| (a - mean) * GAL).collect();
    Ok(Record::from_samples(path, 1.0 / hz, acceleration))
}

/// One gal in m/s².
pub const GAL: f64 = 0.01;

/// X/Y from `X(gal)/Y`.
fn scale_factor(text: &str) -> Option<f64> {
    let (x, y) = text.split_once('/')?;
    let x = x.trim();
    let x = x.strip_suffix("(gal)").unwrap_or(x).trim();
    let (x, y) = (x.parse::<f64>().ok()?, y.trim().parse::<f64>().ok()?);
    let positive = |v: f64| v.is_finite() && v > 0.0;
    (positive(x) && positive(y) && positive(x / y)).then_some(x / y)
}

#[cfg(test)]
mod tests {
    use super::*;

    pub const HEADER: &str = "Origin Time       2011/03/11 14:46:00\n\
Lat.              38.103\nLong.             142.860\nDepth. (km)       24\n\
Mag.              9.0\nStation Code      MYG004\nStation Lat.      38.7312\n\
Station Long.     141.0217\nStation Height(m) 240\nRecord Time       2011/03/11 14:46:55\n\
Sampling Freq(Hz) 100Hz\nDuration Time(s)  300\nDir.              N-S\n\
Scale Factor      3920(gal)/6182761\nMax. Acc. (gal)   2699.7\n\
Last Correction   2011/03/11 14:46:40\nMemo.\n";

    #[test]
    fn counts_scale_to_gal_less_the_mean() {
        let text = format!("{HEADER}  100  -200  300\n  0\n");
        assert!(recognises(&text));
        let r = parse_knet("x.NS", &text).unwrap();
        assert_eq!(r.dt, 0.01);
        let f = 3920.0 / 6182761.0;
        let gal = [100.0 * f, -200.0 * f, 300.0 * f, 0.0];
        let mean = gal.iter().sum::<f64>() / 4.0;
        let want: Vec<f64> = gal.iter().map(|a| (a - mean) * 0.01).collect();
        assert_eq!(r.acceleration, want);
    }

    #[test]
    fn malformed_files_name_the_line() {
        let good = format!("{HEADER}1 2 3\n");
        let cases = [
            (
                good.replace("3920(gal)/6182761", "3920(gal)/0"),
                14,
                "scale factor",
            ),
            (good.replace("3920(gal)/6182761", "abc"), 14, "scale factor"),
            (good.replace("100Hz", "fastHz"), 11, "sampling frequency"),
            (good.replace("100Hz", "0Hz"), 11, "sampling frequency"),
            (
                good.replace("1 2 3", "1 2.5 3"),
                18,
                "`2.5` is not a whole number",
            ),
            (HEADER.to_string(), 18, "no samples"),
            (
                good.replace("Scale Factor", "Scale"),
                14,
                "missing `Scale Factor`",
            ),
        ];
        for (text, line, what) in cases {
            let e = parse_knet("bad.EW", &text).unwrap_err();
            assert_eq!(e.line, line, "{e}");
            assert!(e.to_string().contains(what), "{e}");
            assert!(e.to_string().starts_with("record `bad.EW` line "), "{e}");
        }
    }
}
