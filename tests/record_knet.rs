//! K-NET / KiK-net ASCII records (NIED) and the recognition of every record
//! format by its content: a K-NET file named `.EW`, an `.AT2` named `.txt`,
//! and malformed K-NET files refused with one line naming the file and line.

mod common;

use std::fs;

use common::{KNET_HEADER as HEADER, fails, json, knet_text};
use pounding::model::record::{self, Format, STANDARD_GRAVITY};

/// Counts of a decaying tone, eight to a line as NIED writes them.
fn counts() -> Vec<i64> {
    (0..300)
        .map(|k| {
            let t = k as f64 * 0.01;
            (250_000.0 * (-0.8 * t).exp() * (11.0 * t).sin()).round() as i64 + 1234
        })
        .collect()
}

#[test]
fn a_knet_file_named_ew_reads_back_to_its_counts_scaled_less_the_mean() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("IWT0100806140843.EW");
    let c = counts();
    fs::write(&path, knet_text(&c)).unwrap();
    let path = path.to_str().unwrap();
    let r = record::read(path).unwrap();
    let factor = 7845.0 / 8223790.0;
    let gal: Vec<f64> = c.iter().map(|&c| c as f64 * factor).collect();
    let mean = gal.iter().sum::<f64>() / gal.len() as f64;
    let want: Vec<f64> = gal.iter().map(|a| (a - mean) * 0.01).collect();
    assert_eq!(r.acceleration, want);
    assert_eq!(r.dt, 0.01);
    assert_eq!(r.spec, format!("record:{path}"));
    // The mean is removed: the offset of 1234 counts is gone.
    let sum: f64 = r.acceleration.iter().sum();
    assert!(sum.abs() < 1e-9, "{sum}");
    // A unit is refused, as for an .AT2 file.
    let e = record::read(&format!("{path}@g")).unwrap_err().to_string();
    assert!(e.contains("a K-NET record is in gal"), "{e}");
}

#[test]
fn formats_are_told_by_content_not_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let at2 = "PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic\n\
               ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    4, DT=   .0200 SEC\n\
               0.0 0.1 -0.2 0.05\n";
    let txt = dir.path().join("quake.txt");
    fs::write(&txt, at2).unwrap();
    let r = record::read(txt.to_str().unwrap()).unwrap();
    assert_eq!(r, record::parse_at2(txt.to_str().unwrap(), at2).unwrap());
    assert_eq!(r.acceleration[1], 0.1 * STANDARD_GRAVITY);
    assert_eq!(Format::of("x.txt", at2), Format::At2);
    assert_eq!(Format::of("x.EW", &knet_text(&[1, 2])), Format::Knet);
    assert_eq!(Format::of("x.at2", "garbage"), Format::At2);
    assert_eq!(Format::of("x.csv", "0,1\n0.01,2\n"), Format::Columns);
}

#[test]
fn a_knet_record_runs_through_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("station.NS");
    fs::write(&path, knet_text(&counts())).unwrap();
    let spec = format!("record:{}", path.display());
    let v = json(&[
        "run",
        "--method",
        "exact",
        "--format",
        "json",
        "--excitation",
        &spec,
    ]);
    assert_eq!(v["excitation"].as_str().unwrap(), spec);
}

#[test]
fn malformed_knet_files_exit_2_naming_the_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let good = knet_text(&[10, 20, 30]);
    let cases = [
        (
            good.replace("7845(gal)/8223790", "7845(gal)/zero"),
            "line 14",
            "scale factor",
        ),
        (
            good.replace("100Hz", "-5Hz"),
            "line 11",
            "sampling frequency",
        ),
        (good.replace("      20", "    20.5"), "line 18", "`20.5`"),
        (HEADER.to_string(), "line 18", "no samples"),
    ];
    for (i, (text, line, what)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("bad{i}.UD"));
        fs::write(&path, text).unwrap();
        let name = path.display().to_string();
        fails(
            &["run", "--excitation", &format!("record:{name}")],
            2,
            &[&name, line, what],
        );
    }
}
