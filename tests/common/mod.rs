//! What the command-line tests share: the real `pounding` binary run with
//! arguments, its output as text or JSON, and the checks every command's
//! success and every refusal must pass (one line on stderr naming the
//! problem, exit 2 for bad input with nothing on stdout, 1 for a failed run
//! or write, never a panic); and the one parameter set of an isolated
//! impact that the solver tests share.

// Each test crate uses the part it needs.
#![allow(dead_code)]

use pounding::model::{ContactModel, Params, SET1};
use std::ffi::OsStr;
use std::fmt::Debug;
use std::path::Path;
use std::process::{Child, Command, Output, Stdio};

/// The binary under test, built by Cargo for the integration tests.
pub const BIN: &str = env!("CARGO_BIN_EXE_pounding");

/// Runs the binary with `args`, stdin closed, stdout and stderr captured.
pub fn pounding<S: AsRef<OsStr>>(args: &[S]) -> Output {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("the binary runs")
}

/// Starts the binary with `args`, stdin closed, stdout and stderr piped.
pub fn spawn<S: AsRef<OsStr>>(args: &[S]) -> Child {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts")
}

/// Bytes as text, invalid UTF-8 replaced.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Stdout as text; the program only ever writes UTF-8 there.
pub fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).expect("stdout is UTF-8")
}

pub fn stderr(o: &Output) -> String {
    text(&o.stderr)
}

/// Runs `args` and asserts exit 0 (stderr shown otherwise).
pub fn succeeds<S: AsRef<OsStr> + Debug>(args: &[S]) -> Output {
    let o = pounding(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    o
}

/// The one JSON object a successful run of `args` prints on stdout.
pub fn json<S: AsRef<OsStr> + Debug>(args: &[S]) -> serde_json::Value {
    parse_json(&succeeds(args).stdout)
}

/// `bytes` (a report on stdout, or on stderr beside a history on stdout) as JSON.
pub fn parse_json(bytes: &[u8]) -> serde_json::Value {
    serde_json::from_slice(bytes).unwrap_or_else(|e| panic!("not JSON ({e}): {:.300}", text(bytes)))
}

/// The arguments of a one-cycle `run` that writes its history to `target`.
pub fn history_into(target: &Path) -> [&str; 5] {
    let path = target.to_str().expect("a UTF-8 path");
    ["run", "--cycles", "1", "--history", path]
}

/// The JSON summary of a successful [`history_into`] run.
pub fn history_json(target: &Path) -> serde_json::Value {
    json(&[&history_into(target)[..], &["--format", "json"]].concat())
}

/// Exactly one line on stderr, holding every fragment, and no panic.
pub fn assert_one_line(o: &Output, fragments: &[&str]) {
    let err = stderr(o);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(err.lines().count(), 1, "one line expected:\n{err}");
    for f in fragments {
        assert!(err.contains(f), "`{f}` missing from: {err}");
    }
}

/// Runs `args` and asserts it fails with exit `code` and one line on
/// stderr holding every fragment; bad input (exit 2) also prints nothing on stdout.
pub fn fails<S: AsRef<OsStr> + Debug>(args: &[S], code: i32, fragments: &[&str]) -> Output {
    let o = pounding(args);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(code), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert_eq!(
        err.lines().count(),
        1,
        "{args:?}: one line expected:\n{err}"
    );
    for f in fragments {
        assert!(err.contains(f), "{args:?}: `{f}` missing from: {err}");
    }
    if code == 2 {
        assert!(o.stdout.is_empty(), "{args:?}: {}", stdout(&o));
    }
    o
}

/// An isolated impact: two free, undamped masses (Π_ω = 0) closing a gap of
/// 0.05 for one cycle, with contact law `model`, restitution `e` and mass
/// ratio `mass_ratio`; run with no excitation and ẋ1 = 1 at rest otherwise.
pub fn isolated_impact(model: ContactModel, e: f64, mass_ratio: f64) -> Params {
    let p = Params {
        mass_ratio,
        omega1: 0.0,
        omega2: 0.0,
        damping: 0.0,
        restitution: e,
        gap: 0.05,
        model,
        cycles: 1,
        ..SET1
    };
    p.validate().unwrap();
    p
}

/// NIED's 17-line K-NET header (scale factor 7845 gal / 8223790 counts,
/// 100 Hz), as the record tests write it.
pub const KNET_HEADER: &str = "Origin Time       2008/06/14 08:43:00
Lat.              39.030
Long.             140.880
Depth. (km)       8
Mag.              7.2
Station Code      IWT010
Station Lat.      39.0100
Station Long.     140.8983
Station Height(m) 280
Record Time       2008/06/14 08:43:53
Sampling Freq(Hz) 100Hz
Duration Time(s)  60
Dir.              E-W
Scale Factor      7845(gal)/8223790
Max. Acc. (gal)   1433.283
Last Correction   2008/06/14 08:43:38
Memo.
";

/// A K-NET file of `counts` under [`KNET_HEADER`], eight to a line as NIED writes them.
pub fn knet_text(counts: &[i64]) -> String {
    let mut text = KNET_HEADER.to_string();
    for line in counts.chunks(8) {
        let cells: Vec<String> = line.iter().map(|c| format!("{c:>8}")).collect();
        text.push_str(&cells.join(""));
        text.push('\n');
    }
    text
}

/// Two one-storey buildings, elastic and apart, joined by a link whose
/// keys are `link` (SPEC §14).
pub fn linked(link: &str) -> pounding::model::buildings::Row {
    let text = format!(
        "model = \"kelvin\"\n\
         [[building]]\nname = \"a\"\nstoreys = 1\nmass = 1e5\nstiffness = 4e6\nheight = 3\ndamping = 0.05\n\
         [[building]]\nname = \"b\"\nstoreys = 1\nmass = 2e5\nstiffness = 2e7\nheight = 3\ndamping = 0.02\n\
         [[joint]]\ngap = \"inf\"\nstiffness = 1e9\n\
         [[link]]\njoint = 1\nfloor = 1\n{link}\n"
    );
    pounding::model::buildings::parse("linked.toml", &text).unwrap()
}

/// The shipped simulated record `presets/synthetic.at2`, scaled.
pub fn record_ground(scale: f64) -> pounding::model::buildings::Ground {
    let record = pounding::model::record::read("presets/synthetic.at2").unwrap();
    pounding::model::buildings::Ground::from_record(&record, scale)
}

/// The shipped retrofit row with its dashpot a damper of exponent α, and
/// more `--set`s.
pub fn damped(alpha: f64, more: &[&str]) -> pounding::model::buildings::Row {
    let mut sets = vec![format!("link1.exponent={alpha}")];
    sets.extend(more.iter().map(|s| s.to_string()));
    pounding::model::buildings::load_with("block-and-frame-retrofit", &sets).unwrap()
}

/// A row's exact run against the reference: the largest difference of the
/// floors' peaks |u| and |ü + ü_g|, each relative to its building's
/// largest, and of the first link's peak force relative to itself.
pub fn against_reference(
    exact: &pounding::solver::buildings::RowRun,
    reference: &pounding::reference::row::RowReference,
) -> f64 {
    let mut worst = 0.0f64;
    for (b, floors) in exact.floors.iter().enumerate() {
        let scale = |v: &Vec<f64>| v.iter().fold(0.0f64, |m, x| m.max(*x));
        let (su, sa) = (
            scale(&reference.displacement[b]),
            scale(&reference.absolute_acceleration[b]),
        );
        for (i, f) in floors.iter().enumerate() {
            worst = worst
                .max((f.displacement - reference.displacement[b][i]).abs() / su)
                .max((f.absolute_acceleration - reference.absolute_acceleration[b][i]).abs() / sa);
        }
    }
    let (fe, fr) = (exact.links[0].max_force, reference.link_force[0]);
    worst.max((fe - fr).abs() / fr)
}

/// A random row and record of the solver's proptests: the inputs of
/// [`scaled_block_and_frame`] (Kelvin or improved Kelvin), the seed of a
/// simulated record of 2 s sampled at 5 ms, and its scale.
#[derive(Debug, Clone, Copy)]
pub struct RandomRow {
    pub stiffness: f64,
    pub yield_factor: f64,
    pub gap: f64,
    pub kelvin: bool,
    pub seed: u64,
    pub scale: f64,
}

proptest::prop_compose! {
    /// Stiffness × 0.5–2, yield drift × 0.3–3, gaps 2–50 mm, either law,
    /// records 1–999 at scales 0.3–3.
    pub fn random_row()(
        stiffness in 0.5f64..2.0,
        yield_factor in 0.3f64..3.0,
        gap in 0.002f64..0.05,
        kelvin in proptest::prelude::any::<bool>(),
        seed in 1u64..1000,
        scale in 0.3f64..3.0,
    ) -> RandomRow {
        RandomRow { stiffness, yield_factor, gap, kelvin, seed, scale }
    }
}

impl RandomRow {
    /// The row and its ground.
    pub fn make(
        &self,
    ) -> (
        pounding::model::buildings::Row,
        pounding::model::buildings::Ground,
    ) {
        let model = if self.kelvin {
            ContactModel::Kelvin
        } else {
            ContactModel::ImprovedKelvin
        };
        let row = scaled_block_and_frame(self.stiffness, self.yield_factor, self.gap, model);
        let record = pounding::model::simulated::Simulation {
            dt: 0.005,
            duration: 2.0,
            ..Default::default()
        }
        .record("random", self.seed, 1);
        let ground = pounding::model::buildings::Ground::from_record(&record, self.scale);
        (row, ground)
    }
}

/// block-and-frame with every storey's stiffness and yield drift scaled by
/// `stiffness` and `yield_factor`, every joint's gap `gap` (m) and the
/// contact law `model`: the random rows of the solver's proptests.
pub fn scaled_block_and_frame(
    stiffness: f64,
    yield_factor: f64,
    gap: f64,
    model: ContactModel,
) -> pounding::model::buildings::Row {
    let mut row = pounding::model::buildings::load("block-and-frame").expect("shipped");
    for b in &mut row.buildings {
        for k in &mut b.stiffness {
            *k *= stiffness;
        }
        for y in &mut b.yield_drift {
            *y *= yield_factor;
        }
    }
    for j in &mut row.joints {
        j.gap = gap;
    }
    row.model = model;
    row
}

/// |a − b| relative to the larger of the two (0 when both are 0).
pub fn relative(a: f64, b: f64) -> f64 {
    if a == b {
        return 0.0;
    }
    (a - b).abs() / a.abs().max(b.abs())
}

/// The largest differences of two runs' motions, `a` from `b`: of the peaks (relative), of the
/// residual drifts (m), and of the end state (relative to the peaks).
pub fn motion_differences(
    a: &pounding::solver::buildings::RowRun,
    b: &pounding::solver::buildings::RowRun,
) -> (f64, f64, f64) {
    let pick: [fn(&pounding::solver::buildings::FloorPeaks) -> f64; 6] = [
        |f| f.displacement,
        |f| f.velocity,
        |f| f.absolute_acceleration,
        |f| f.drift,
        |f| f.drift_ratio,
        |f| f.ductility,
    ];
    let floors = || a.floors.iter().flatten().zip(b.floors.iter().flatten());
    let mut peaks = floors()
        .flat_map(|(x, y)| pick.map(|p| relative(p(x), p(y))))
        .fold(0.0, f64::max);
    for (x, y) in a.max_relative.iter().zip(&b.max_relative) {
        peaks = peaks.max(relative(*x, *y));
    }
    for (x, y) in a.links.iter().zip(&b.links) {
        for (p, q) in [
            (x.max_force, y.max_force),
            (x.stroke, y.stroke),
            (x.max_rate, y.max_rate),
        ] {
            peaks = peaks.max(relative(p, q));
        }
    }
    let residual = floors()
        .map(|(x, y)| (x.residual_drift - y.residual_drift).abs())
        .fold(0.0, f64::max);
    let largest = |f: fn(&pounding::solver::buildings::FloorPeaks) -> f64| {
        b.floors
            .iter()
            .flatten()
            .map(f)
            .fold(f64::MIN_POSITIVE, f64::max)
    };
    let end = |x: &[f64], y: &[f64], scale: f64| {
        x.iter()
            .zip(y)
            .map(|(p, q)| (p - q).abs() / scale)
            .fold(0.0, f64::max)
    };
    let state = end(
        &a.final_displacement,
        &b.final_displacement,
        largest(|f| f.displacement),
    )
    .max(end(
        &a.final_velocity,
        &b.final_velocity,
        largest(|f| f.velocity),
    ));
    (peaks, residual, state)
}
