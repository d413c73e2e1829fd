//! Numbers and parts in the few columns a summary line or a bar label has,
//! shared by the summary line and the impact scene.

/// A number in at most 6 characters.
pub fn num(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".into()
    } else if !v.is_finite() {
        format!("{v}")
    } else if !(1e-3..1e5).contains(&a) {
        format!("{v:.0e}")
    } else if a >= 1000.0 {
        format!("{v:.0}")
    } else if a >= 100.0 {
        format!("{v:.1}")
    } else if a >= 10.0 {
        format!("{v:.2}")
    } else {
        format!("{v:.3}")
    }
}

/// Joins `parts` with spaces, as many as fit in `width`.
pub fn fit(parts: &[String], width: usize) -> String {
    let mut out = String::new();
    for p in parts {
        let extra = p.chars().count() + usize::from(!out.is_empty());
        if out.chars().count() + extra > width {
            break;
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(p);
    }
    out
}

/// `name left/right`, each number in at most 6 characters.
pub fn pair(name: &str, left: f64, right: f64) -> String {
    format!("{name} {}/{}", num(left), num(right))
}
