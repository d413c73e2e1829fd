//! The earthquake a record comes from, read from its header, so that a
//! selection can take at most K records of one event:
//!
//! - `.AT2` (PEER NGA): line 2 reads `EVENT, DATE, STATION, COMPONENT`
//!   (`Imperial Valley-06, 10/15/1979, El Centro Array #6, 140`; the older
//!   `IMPERIAL VALLEY 10/15/79 2316, EL CENTRO ARRAY #6, 140`): the event
//!   is the line without its last two comma-separated fields (the station
//!   and the component), or the whole line when it has fewer than three;
//! - K-NET / KiK-net: the `Origin Time` of the header, one time per event;
//! - plain columns name no event: `None`.

use std::path::Path;

use super::Format;
use super::knet::HEADER_LINES;

/// The event of the record in the file at `path`, from its header; `None`
/// when the file cannot be read or its format names no event.
pub fn of_file(path: &Path) -> Option<String> {
    let bytes = std::fs::read(path).ok()?;
    // The header is in the first few lines: cut there, the samples can be long.
    let head: Vec<u8> = bytes
        .split(|&b| b == b'\n')
        .take(HEADER_LINES + 1)
        .collect::<Vec<_>>()
        .join(&b'\n');
    of_text(path.to_str().unwrap_or(""), &String::from_utf8_lossy(&head))
}

/// The event of the record whose text (or its header) is `text`.
pub fn of_text(path: &str, text: &str) -> Option<String> {
    match Format::of(path, text) {
        Format::At2 => {
            let line = text.lines().nth(1)?.trim();
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            let event = if fields.len() >= 3 {
                fields[..fields.len() - 2].join(", ")
            } else {
                line.to_string()
            };
            (!event.is_empty()).then_some(event)
        }
        Format::Knet => text
            .lines()
            .take(HEADER_LINES)
            .find_map(|l| l.trim_start().strip_prefix("Origin Time"))
            .map(|t| format!("origin {}", t.trim()))
            .filter(|t| t.len() > "origin ".len()),
        Format::Columns => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at2_event_is_line_two_less_station_and_component() {
        let text = "PEER NGA STRONG MOTION DATABASE RECORD\n\
                    Imperial Valley-06, 10/15/1979, El Centro Array #6, 140\n\
                    ACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0 0\n";
        assert_eq!(
            of_text("x.AT2", text).as_deref(),
            Some("Imperial Valley-06, 10/15/1979")
        );
        let old = text.replace(
            "Imperial Valley-06, 10/15/1979, El Centro Array #6, 140",
            "IMPERIAL VALLEY 10/15/79 2316, EL CENTRO ARRAY #6, 140",
        );
        assert_eq!(
            of_text("x.AT2", &old).as_deref(),
            Some("IMPERIAL VALLEY 10/15/79 2316")
        );
    }

    #[test]
    fn knet_event_is_the_origin_time() {
        let text = "Origin Time       2011/03/11 14:46:00\nLat.              38.103\n";
        assert_eq!(
            of_text("x.NS", text).as_deref(),
            Some("origin 2011/03/11 14:46:00")
        );
        assert_eq!(of_text("x.txt", "0 0\n0.01 1\n"), None);
    }
}
