//! One writer per output format. A command builds one typed report and
//! prints it in the format asked for: JSON from its `Serialize`, a table and
//! CSV rows from [`Report`]; the CSV and JSON encodings live here only.

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
}
