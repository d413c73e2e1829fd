//! The tables the suite studies print, for a pair and for a row: the
//! statistics of a suite's demands (SPEC §12), the fragility of each limit
//! state with the counts per level, and a name cut to a column.

use std::fmt::Write as _;

use crate::analysis::fragility::describe;
use crate::analysis::ida::LimitStateFragility;
use crate::analysis::suite_statistics::SuiteStatistics;
use crate::model::params::echo::g4;

/// The statistics over a suite's records (SPEC §12), with their heading.
pub fn over_suite_table(s: &mut String, st: &SuiteStatistics) {
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "statistics over {} records ({} pounded): median, 16th and 84th percentiles, \
         lognormal dispersion β",
        st.records, st.pounded
    );
    statistics_table(s, st);
}

/// The statistics of a suite (SPEC §12), one line per demand.
pub fn statistics_table(s: &mut String, st: &SuiteStatistics) {
    let width = st
        .demands
        .iter()
        .map(|d| d.demand.len() + d.unit.len() + 3)
        .max()
        .unwrap_or(10);
    let _ = writeln!(
        s,
        "{:<width$} {:>10} {:>10} {:>10} {:>7}  excluded from β",
        "demand", "median", "p16", "p84", "β"
    );
    for d in &st.demands {
        let name = if d.unit.is_empty() {
            d.demand.clone()
        } else {
            format!("{} ({})", d.demand, d.unit)
        };
        let _ = writeln!(
            s,
            "{:<width$} {:>10} {:>10} {:>10} {:>7}  {}",
            name,
            g4(d.summary.median),
            g4(d.summary.p16),
            g4(d.summary.p84),
            if d.summary.dispersion.is_nan() {
                "-".to_string()
            } else {
                format!("{:.3}", d.summary.dispersion)
            },
            d.summary.excluded()
        );
    }
}

/// The closing tables of `ida`, for a pair or a row: the fragility of each
/// limit state, the statistics at the highest of `levels` (g, with each
/// level's statistics) and the wall time.
pub fn closing_tables(
    s: &mut String,
    fragility: &[LimitStateFragility],
    levels: &[(f64, &SuiteStatistics)],
    elapsed_ms: f64,
) {
    let level_values: Vec<f64> = levels.iter().map(|l| l.0).collect();
    fragility_table(s, fragility, &level_values);
    if let Some((level, statistics)) = levels.last() {
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "statistics at the highest level, {} g ({} pounded):",
            g4(*level),
            statistics.pounded
        );
        statistics_table(s, statistics);
    }
    let _ = writeln!(s, "elapsed {elapsed_ms:.0} ms");
}

/// The fragility of each limit state (SPEC §12), with pounding and
/// without, and the records exceeding it at each of `levels` (g).
fn fragility_table(s: &mut String, fragility: &[LimitStateFragility], levels: &[f64]) {
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "fragility P(exceed | IM = x) = Φ(ln(x/θ)/β), maximum likelihood over all levels (SPEC §12)"
    );
    let width = fragility
        .iter()
        .map(|f| f.limit_state.chars().count())
        .max()
        .unwrap_or(11)
        .max(11);
    let _ = writeln!(
        s,
        "{:<width$}  {:<36}  without pounding (gap = ∞)",
        "limit state", "with pounding"
    );
    for f in fragility {
        let _ = writeln!(
            s,
            "{:<width$}  {:<36}  {}",
            f.limit_state,
            describe(&f.fragility),
            f.no_pounding_fragility
                .as_ref()
                .map_or("-".to_string(), describe)
        );
    }
    let _ = writeln!(s);
    let _ = writeln!(s, "records exceeding each limit state, per level:");
    let _ = write!(s, "{:<width$}", "level g");
    for l in levels {
        let _ = write!(s, " {:>6}", g4(*l));
    }
    let _ = writeln!(s);
    for f in fragility {
        let _ = write!(s, "{:<width$}", f.limit_state);
        for c in &f.counts {
            let _ = write!(s, " {:>6}", format!("{}/{}", c.exceeded, c.runs));
        }
        let _ = writeln!(s);
        if let Some(free) = &f.no_pounding_counts {
            let _ = write!(s, "{:<width$}", "  without pounding");
            for c in free {
                let _ = write!(s, " {:>6}", format!("{}/{}", c.exceeded, c.runs));
            }
            let _ = writeln!(s);
        }
    }
}

/// The demand `key` of `st` (scaled by `unit`) as `median (p16–p84)`, or
/// nothing where the statistics have no such demand.
pub fn band(st: &SuiteStatistics, key: &str, unit: f64) -> String {
    summary(st, key).map_or(String::new(), |d| {
        format!(
            "{} ({}–{})",
            g4(d.median * unit),
            g4(d.p16 * unit),
            g4(d.p84 * unit)
        )
    })
}

/// The median of the demand `key` of `st` (scaled by `unit`), or nothing
/// where the statistics have no such demand.
pub fn median(st: &SuiteStatistics, key: &str, unit: f64) -> String {
    summary(st, key).map_or(String::new(), |d| g4(d.median * unit))
}

/// The summary of the demand `key` of `st`.
fn summary(st: &SuiteStatistics, key: &str) -> Option<crate::analysis::statistics::Summary> {
    st.demands
        .iter()
        .find(|d| d.demand == key)
        .map(|d| d.summary)
}

/// The width of a column of record names: the longest name's, from 6 to
/// 40 characters (a longer name is [`clip`]ped).
pub fn name_width<'a>(names: impl Iterator<Item = &'a str>) -> usize {
    names
        .map(|n| n.chars().count())
        .max()
        .unwrap_or(6)
        .clamp(6, 40)
}

/// `text` cut to `width` characters, ending in "…" where cut.
pub fn clip(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        text.to_string()
    } else {
        let mut t: String = text.chars().take(width.saturating_sub(1)).collect();
        t.push('…');
        t
    }
}
