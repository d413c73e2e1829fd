//! One writer per output format. A command builds one typed report and
//! prints it in the format asked for: JSON from its `Serialize`, a table and
//! CSV rows from [`Report`]; the CSV and JSON encodings live here only.

use std::fmt::Write as _;

use serde::Serialize;

/// What a command reports, in every format.
pub trait Report: Serialize {
    /// The report for people: aligned lines, ending in a newline.
    fn table(&self) -> String;
    /// Column names of the CSV form.
    fn csv_header(&self) -> Vec<&'static str>;
    /// One CSV row per record, cells in the order of the header.
    fn csv_rows(&self) -> Vec<Vec<String>>;
}

/// Exactly one JSON object on one line.
pub fn json(report: &impl Serialize) -> Result<String, serde_json::Error> {
    serde_json::to_string(report).map(|s| s + "\n")
}

/// Serializes a float that may be infinite (an elastic yield displacement,
/// `gap = inf`) or NaN (a failed run's residual) the way [`Num`] writes it in
/// CSV and tables: JSON has neither, so it becomes the string `"inf"`,
/// `"-inf"` or `"nan"`; finite values stay numbers. Formats that are not
/// human-readable carry every `f64` as it is. The one definition: the
/// parameters' serde (`model::params`) writes through it too.
///
/// [`Num`]: crate::output::Num
pub fn float_or_inf<S: serde::Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    if v.is_finite() || !s.is_human_readable() {
        s.serialize_f64(*v)
    } else {
        s.serialize_str(&crate::output::Num(*v).to_string())
    }
}

/// [`float_or_inf`] for a value that may be missing: `null` when `None`.
pub fn option_float_or_inf<S: serde::Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(v) => float_or_inf(v, s),
        None => s.serialize_none(),
    }
}

/// A header line, then one line per row (RFC 4180 quoting where needed).
pub fn csv(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut out = String::new();
    let mut line = |cells: &mut dyn Iterator<Item = &str>| {
        for (i, cell) in cells.enumerate() {
            if i > 0 {
                out.push(',');
            }
            out.push_str(&csv_cell(cell));
        }
        out.push('\n');
    };
    line(&mut header.iter().copied());
    for row in rows {
        line(&mut row.iter().map(String::as_str));
    }
    out
}

/// A CSV column of rows of type `R`: its name in the header, and the cell
/// a row writes under it. A report lists its columns once, so that the
/// header and every row come from the same list and cannot drift apart.
pub type Column<R> = (&'static str, fn(&R) -> String);

/// A CSV header: the columns `head` every row leads with, then the names
/// of `columns`.
pub fn column_header<R>(head: &[&'static str], columns: &[Column<R>]) -> Vec<&'static str> {
    let mut header = head.to_vec();
    header.extend(columns.iter().map(|(name, _)| *name));
    header
}

/// The cells of `row` under `columns`, in order.
pub fn column_cells<'a, R>(
    columns: &'a [Column<R>],
    row: &'a R,
) -> impl Iterator<Item = String> + 'a {
    columns.iter().map(move |(_, cell)| cell(row))
}

/// One CSV row per item of `rows`: the cells `head`, then its own under
/// `columns` (the rows of [`column_header`]).
pub fn column_rows<'a, R: 'a>(
    head: &[String],
    columns: &[Column<R>],
    rows: impl IntoIterator<Item = &'a R>,
) -> Vec<Vec<String>> {
    let row = |r| {
        head.iter()
            .cloned()
            .chain(column_cells(columns, r))
            .collect()
    };
    rows.into_iter().map(row).collect()
}

/// A column of an aligned table of rows of type `R`: its heading, its
/// width in characters (right-aligned; a negative width left-aligns), and
/// the cell a row writes. Text after the last column (a verdict, a note)
/// is a column of width 0 whose heading and cells begin with a space.
pub type TableColumn<R> = (&'static str, isize, fn(&R) -> String);

/// The line of headings of `columns`, then one line per item of `rows`:
/// each cell padded to its column's width, one space between columns.
pub fn aligned<'a, R: 'a>(
    columns: &[TableColumn<R>],
    rows: impl IntoIterator<Item = &'a R>,
) -> String {
    let mut s = String::new();
    let mut line = |cell: &dyn Fn(&TableColumn<R>) -> String| {
        for (i, column) in columns.iter().enumerate() {
            let (text, width) = (cell(column), column.1.unsigned_abs());
            let gap = if i > 0 { " " } else { "" };
            let _ = if column.1 < 0 {
                write!(s, "{gap}{text:<width$}")
            } else {
                write!(s, "{gap}{text:>width$}")
            };
        }
        s.push('\n');
    };
    line(&|column| column.0.to_string());
    for row in rows {
        line(&|column| (column.2)(row));
    }
    s
}

/// A flag as the text after a table's last column: ` yes` or ` no`.
pub fn yes_no(flag: bool) -> String {
    if flag { " yes" } else { " no" }.into()
}

/// A CSV cell: quoted, with quotes doubled, if it holds a comma, quote or line break.
pub fn csv_cell(cell: &str) -> std::borrow::Cow<'_, str> {
    if cell.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", cell.replace('"', "\"\"")).into()
    } else {
        cell.into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_quotes_only_what_needs_it() {
        let rows = vec![vec!["1".to_string(), "a, \"b\"".to_string()]];
        assert_eq!(csv(&["x", "why"], &rows), "x,why\n1,\"a, \"\"b\"\"\"\n");
    }

    #[test]
    fn infinity_is_inf_in_json_and_csv() {
        #[derive(Serialize)]
        struct Gaps {
            #[serde(serialize_with = "float_or_inf")]
            a: f64,
            #[serde(serialize_with = "float_or_inf")]
            b: f64,
        }
        let j = json(&Gaps {
            a: f64::INFINITY,
            b: 0.010000000000000002,
        })
        .unwrap();
        assert_eq!(j, "{\"a\":\"inf\",\"b\":0.010000000000000002}\n");
        assert_eq!(crate::output::Num(f64::INFINITY).to_string(), "inf");
    }

    #[test]
    fn nan_is_nan_in_json_and_csv() {
        #[derive(Serialize)]
        struct Residuals {
            #[serde(serialize_with = "float_or_inf")]
            r: f64,
            #[serde(serialize_with = "float_or_inf")]
            down: f64,
        }
        let j = json(&Residuals {
            r: f64::NAN,
            down: f64::NEG_INFINITY,
        })
        .unwrap();
        assert_eq!(j, "{\"r\":\"nan\",\"down\":\"-inf\"}\n");
        assert_eq!(crate::output::Num(f64::NAN).to_string(), "nan");
        assert_eq!(crate::output::Num(-f64::NAN).to_string(), "nan");
    }
}
