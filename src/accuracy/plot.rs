//! Error against run time on log–log axes, drawn in Braille for a terminal
//! (each character cell holds 2×4 dots, U+2800 + dot bits). Lines join each
//! method's points; the points themselves carry the method's marker letter.

use std::fmt::Write as _;

/// One curve: a marker letter, a legend label and its (time, error) points.
pub struct Series {
    pub marker: char,
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// Braille dot bit of the dot at column `dx` ∈ {0,1}, row `dy` ∈ 0..4 of a cell.
fn dot_bit(dx: usize, dy: usize) -> u8 {
    const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
    BITS[dx][dy]
}

/// Renders the series into a `width`×`height` character plot with axis labels.
pub fn render(series: &[Series], width: usize, height: usize) -> String {
    let points: Vec<(f64, f64)> = series
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .filter(|&(x, y)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite())
        .map(|(x, y)| (x.log10(), y.log10()))
        .collect();
    if points.is_empty() || width < 4 || height < 2 {
        return "(nothing to plot)\n".into();
    }
    let bounds = |f: fn(&(f64, f64)) -> f64| {
        let lo = points.iter().map(f).fold(f64::INFINITY, f64::min).floor();
        let hi = points
            .iter()
            .map(f)
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil();
        (lo, if hi > lo { hi } else { lo + 1.0 })
    };
    let (x_lo, x_hi) = bounds(|p| p.0);
    let (y_lo, y_hi) = bounds(|p| p.1);
    let (dots_w, dots_h) = (2 * width, 4 * height);
    let to_dot = |(x, y): (f64, f64)| {
        let col = ((x.log10() - x_lo) / (x_hi - x_lo) * (dots_w - 1) as f64).round();
        let row = ((y_hi - y.log10()) / (y_hi - y_lo) * (dots_h - 1) as f64).round();
        (
            col.clamp(0.0, (dots_w - 1) as f64) as i64,
            row.clamp(0.0, (dots_h - 1) as f64) as i64,
        )
    };
    let mut cells = vec![0u8; width * height];
    let mut marks: Vec<Option<char>> = vec![None; width * height];
    let set = |c: i64, r: i64, cells: &mut Vec<u8>| {
        let (c, r) = (c as usize, r as usize);
        cells[(r / 4) * width + c / 2] |= dot_bit(c % 2, r % 4);
    };
    for s in series {
        let pts: Vec<_> = s
            .points
            .iter()
            .copied()
            .filter(|&(x, y)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite())
            .map(to_dot)
            .collect();
        for pair in pts.windows(2) {
            let ((c0, r0), (c1, r1)) = (pair[0], pair[1]);
            let n = (c1 - c0).abs().max((r1 - r0).abs()).max(1);
            for k in 0..=n {
                let c = c0 + (c1 - c0) * k / n;
                let r = r0 + (r1 - r0) * k / n;
                set(c, r, &mut cells);
            }
        }
        for &(c, r) in &pts {
            marks[(r as usize / 4) * width + c as usize / 2] = Some(s.marker);
        }
    }
    let mut out = String::new();
    for row in 0..height {
        let label = if row == 0 {
            format!("1e{:<4}", y_hi as i64)
        } else if row == height - 1 {
            format!("1e{:<4}", y_lo as i64)
        } else {
            " ".repeat(6)
        };
        let _ = write!(out, "{label}│");
        for col in 0..width {
            let i = row * width + col;
            out.push(
                marks[i].unwrap_or_else(|| char::from_u32(0x2800 + cells[i] as u32).unwrap_or(' ')),
            );
        }
        out.push('\n');
    }
    let _ = writeln!(out, "{}└{}", " ".repeat(6), "─".repeat(width));
    let left = format!("1e{} ms", x_lo as i64);
    let right = format!("1e{} ms", x_hi as i64);
    let pad = (width + 1).saturating_sub(left.len() + right.len());
    let _ = writeln!(out, "{}{left}{}{right}", " ".repeat(7), " ".repeat(pad));
    let _ = writeln!(
        out,
        "{}max relative peak error (up) against ms per run (right)",
        " ".repeat(7)
    );
    for s in series {
        let _ = writeln!(out, "{}{}  {}", " ".repeat(7), s.marker, s.label);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diagonal_line_reaches_both_corners() {
        let s = Series {
            marker: 'A',
            label: "a".into(),
            points: vec![(1.0, 1e-8), (10.0, 1e-7), (100.0, 1e-6)],
        };
        let text = render(&[s], 20, 5);
        let lines: Vec<&str> = text.lines().collect();
        // First point (fast, accurate) bottom-left, last (slow, inaccurate) top-right.
        assert!(lines[4].chars().nth(7) == Some('A'), "{text}");
        assert!(lines[0].ends_with('A'), "{text}");
        assert!(text.contains('⠀') || text.chars().any(|c| ('\u{2801}'..='\u{28ff}').contains(&c)));
    }
}
