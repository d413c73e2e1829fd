//! `pounding figure ida|fragility|separation` end to end: each writes a
//! well-formed SVG with the series its suite study implies (one faint
//! curve per record, a median and a band with and without pounding; k/n
//! markers at every level for each limit state; an empirical step curve of
//! N records with its lognormal fit), axis labels that name the quantity
//! and its unit, and a PNG variant; bad input is one line and exit 2.

mod common;

use common::{fails, json, succeeds};

/// The preset and suite of every test: five or twenty simulated records
/// (made in memory), Sa(0.95 s), the two-buildings pair.
const SUITE: [&str; 6] = [
    "--preset",
    "two-buildings",
    "--suite",
    "synthetic:20",
    "--im",
    "sa:0.95",
];

/// The grey of the records' curves (`figure::render`), and the palette's
/// first two colours: blue (with pounding) and orange (the lognormal fit;
/// without pounding its darker shade).
const FAINT: &str = "#969696";
const BLUE: &str = "#0072B2";
const ORANGE: &str = "#D55E00";
const DARK_ORANGE: &str = "#753400";

/// What the tests count in an SVG: its texts, and its polylines (stroke,
/// number of points), polygons (fill), closed outlines and circles.
struct Svg {
    texts: Vec<String>,
    polylines: Vec<(String, usize)>,
    polygons: Vec<String>,
    /// The stroke of each closed polyline (first point = last): a hollow marker.
    outlines: Vec<String>,
    circles: usize,
}

impl Svg {
    fn read(path: &std::path::Path) -> Svg {
        let text = std::fs::read_to_string(path).unwrap();
        let doc = roxmltree::Document::parse(&text).expect("the SVG is well-formed XML");
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        let named = |name: &'static str| {
            doc.descendants()
                .filter(move |n| n.tag_name().name() == name)
        };
        Svg {
            texts: named("text")
                .map(|n| n.text().unwrap_or("").trim().to_string())
                .collect(),
            polylines: named("polyline")
                .map(|n| {
                    let points = n.attribute("points").unwrap_or("").split_whitespace();
                    (
                        n.attribute("stroke").unwrap_or("").to_string(),
                        points.count(),
                    )
                })
                .collect(),
            polygons: named("polygon")
                .map(|n| n.attribute("fill").unwrap_or("").to_string())
                .collect(),
            outlines: named("polyline")
                .filter(|n| {
                    let points: Vec<&str> = n
                        .attribute("points")
                        .unwrap_or("")
                        .split_whitespace()
                        .collect();
                    points.len() > 3 && points.first() == points.last()
                })
                .map(|n| n.attribute("stroke").unwrap_or("").to_string())
                .collect(),
            circles: named("circle").count(),
        }
    }

    /// The number of points of each polyline of `stroke` with more than
    /// three: whole curves. A legend sample has two points, and so has a
    /// dash, or three where it turns a corner of a curve of long segments.
    fn curves(&self, stroke: &str) -> Vec<usize> {
        self.polylines
            .iter()
            .filter(|(s, n)| s == stroke && *n > 3)
            .map(|(_, n)| *n)
            .collect()
    }

    /// Polylines of `stroke`: curves, dashes and legend samples.
    fn strokes(&self, stroke: &str) -> usize {
        self.polylines.iter().filter(|(s, _)| s == stroke).count()
    }

    fn has_text(&self, text: &str) -> bool {
        self.texts.iter().any(|t| t == text)
    }

    fn texts_starting(&self, start: &str) -> Vec<&String> {
        self.texts.iter().filter(|t| t.starts_with(start)).collect()
    }
}

/// Runs `figure NAME` with the suite and `extra`, writing `file` in a
/// temporary directory, and reads the SVG back.
fn draw(name: &str, extra: &[&str]) -> Svg {
    draw_study(name, &[&SUITE[..], extra].concat())
}

/// Runs `figure NAME` with `study` (buildings, suite, options), and reads
/// the SVG back.
fn draw_study(name: &str, study: &[&str]) -> Svg {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join(format!("{name}.svg"));
    let mut args = vec!["figure", name, "--out", out.to_str().unwrap()];
    args.extend(study);
    succeeds(&args);
    Svg::read(&out)
}

/// A row's study: block-and-frame under eight simulated records.
const ROW: [&str; 4] = ["--buildings", "block-and-frame", "--suite", "synthetic:8@2"];

#[test]
fn a_row_ida_has_a_panel_per_building_with_every_record_median_and_band() {
    let levels = ["0.1", "0.3", "0.5"];
    let svg = draw_study(
        "ida",
        &[&ROW[..], &["--levels", &levels.join(",")]].concat(),
    );
    // Per building, each record's curve with pounding from the origin
    // through every level: eight in each of the two panels.
    assert_eq!(svg.curves(FAINT), vec![1 + levels.len(); 2 * 8]);
    assert_eq!(svg.curves(BLUE), vec![1 + levels.len(); 2]);
    assert!(svg.strokes(DARK_ORANGE) > 2 * 2, "dashed medians apart");
    assert_eq!(svg.polygons, vec![BLUE, ORANGE, BLUE, ORANGE]);
    for text in [
        "Largest storey drift ratio of block (%)",
        "Largest storey drift ratio of frame (%)",
        "PGA (g)",
        "median, with pounding",
        "median, without pounding (gap = ∞)",
    ] {
        assert!(svg.has_text(text), "`{text}` in {:?}", svg.texts);
    }
}

/// The first number after `key` in `text` (up to a space or comma).
fn number_after(text: &str, key: &str) -> f64 {
    let rest = &text[text.find(key).unwrap_or_else(|| panic!("{key} in {text}")) + key.len()..];
    let end = rest.find([' ', ',']).unwrap_or(rest.len());
    rest[..end].parse().unwrap()
}

#[test]
fn a_row_fragility_draws_the_fits_ida_buildings_reports() {
    let study = [
        &ROW[..],
        &[
            "--levels",
            "0.1:1.0:0.1",
            "--drift",
            "0.005,frame:0.01,0.02",
        ],
    ]
    .concat();
    let svg = draw_study("fragility", &study);
    let report: serde_json::Value = serde_json::from_slice(
        &succeeds(&[&["ida", "--format", "json"][..], &study].concat()).stdout,
    )
    .unwrap();
    let curves = report["fragility"].as_array().unwrap();
    let states: Vec<&str> = curves
        .iter()
        .map(|c| c["limit_state"].as_str().unwrap())
        .collect();
    assert_eq!(
        states,
        [
            "pounding (any)",
            "drift>0.005 (any)",
            "drift>0.01 (frame)",
            "drift>0.02 (any)"
        ]
    );
    let mut fitted = 0;
    for c in curves {
        let state = c["limit_state"].as_str().unwrap();
        for (key, style) in [
            ("fragility", "with pounding"),
            ("no_pounding_fragility", "without pounding"),
        ] {
            let fit = &c[key];
            if fit["outcome"] != "fitted" {
                continue;
            }
            let legend = svg.texts_starting(&format!("{state}, {style}: "));
            assert_eq!(legend.len(), 1, "{state}, {style} in {:?}", svg.texts);
            // The legend's θ (4 digits) and β (3 decimals) are the report's.
            let theta = fit["theta"].as_f64().unwrap();
            let beta = fit["beta"].as_f64().unwrap();
            assert!((number_after(legend[0], "θ = ") - theta).abs() <= 5e-4 * theta);
            assert!((number_after(legend[0], "β = ") - beta).abs() <= 5e-4);
            fitted += 1;
        }
    }
    assert!(fitted >= 4, "fits to compare: {fitted}");
    // Ten levels: a marker at each for pounding (circles), and its legend's.
    assert_eq!(svg.circles, 10 + 1);
}

#[test]
fn a_row_separation_has_a_panel_per_joint_with_what_gap_buildings_reports() {
    let study = [
        "--buildings",
        "three-in-series",
        "--suite",
        "synthetic:8@2",
        "--level",
        "0.3g",
    ];
    let svg = draw_study("separation", &study);
    let report: serde_json::Value = serde_json::from_slice(
        &succeeds(&[&["gap", "--format", "json"][..], &study].concat()).stdout,
    )
    .unwrap();
    let joints = report["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 2);
    for (j, joint) in joints.iter().enumerate() {
        let (left, right) = (
            joint["left"].as_str().unwrap(),
            joint["right"].as_str().unwrap(),
        );
        let title = format!(
            "({}) Joint {left}–{right}: each record's gap that prevents pounding (SPEC §13)",
            ["a", "b"][j]
        );
        assert!(svg.has_text(&title), "`{title}` in {:?}", svg.texts);
        // The lognormal fit's median (mm, 4 digits) and β (3 decimals), and
        // ABS on the median peaks (mm): the report's.
        let fit = &joint["study"]["lognormal"];
        let median = 1e3 * fit["median"].as_f64().unwrap();
        let beta = fit["dispersion"].as_f64().unwrap();
        let legend = svg
            .texts_starting(&format!("{left}–{right}: lognormal fit: median "))
            .into_iter()
            .find(|t| (number_after(t, "median ") - median).abs() <= 5e-4 * median)
            .unwrap_or_else(|| panic!("a fit of median {median} mm in {:?}", svg.texts));
        assert!((number_after(legend, "β = ") - beta).abs() <= 5e-4);
        let abs = 1e3
            * joint["study"]["rules"][0]["at_median_peaks"]
                .as_f64()
                .unwrap();
        assert!(
            svg.texts_starting(&format!("{left}–{right}: ABS on the median peaks: "))
                .iter()
                .any(|t| (number_after(t, "peaks: ") - abs).abs() <= 5e-4 * abs),
            "ABS at {abs} mm in {:?}",
            svg.texts
        );
    }
    // Each joint's records as a step curve: a riser and a tread per record.
    assert_eq!(svg.curves(BLUE).len(), 2, "{:?}", svg.curves(BLUE));
    assert!(svg.has_text("records (empirical, N = 8)"));
}

#[test]
fn ida_has_a_curve_per_record_and_a_median_and_band_in_each_style() {
    let levels = ["0.1", "0.2", "0.4", "0.6"];
    let svg = draw("ida", &["--levels", &levels.join(",")]);
    // Each record's curve with pounding is one grey polyline from the
    // origin through every level; without pounding, grey dashes.
    let records = svg.curves(FAINT);
    assert_eq!(records, vec![1 + levels.len(); 20], "{records:?}");
    assert!(
        svg.strokes(FAINT) > 2 * 20,
        "dashed records without pounding"
    );
    // The median with pounding: one blue curve; without: orange dashes.
    assert_eq!(svg.curves(BLUE), vec![1 + levels.len()]);
    assert!(svg.strokes(DARK_ORANGE) > 2);
    // The two 16–84 % bands, blue and orange.
    assert_eq!(svg.polygons, vec![BLUE, ORANGE]);
    for entry in [
        "each record, with pounding",
        "each record, without pounding (gap = ∞)",
        "median, with pounding",
        "median, without pounding (gap = ∞)",
        "16–84 %, with pounding",
        "16–84 %, without pounding (gap = ∞)",
    ] {
        assert!(svg.has_text(entry), "legend `{entry}` in {:?}", svg.texts);
    }
    // IM vertical in g, drift horizontal in mm; the gap marked.
    assert!(svg.has_text("Sa(T = 0.95 s, ξ = 5 %) (g)"));
    assert!(svg.has_text("Peak drift of the left structure u1,max (mm)"));
    assert!(svg.has_text("gap 25 mm"), "{:?}", svg.texts);
}

#[test]
fn fragility_has_markers_at_every_level_and_a_legend_per_state_and_style() {
    let svg = draw(
        "fragility",
        &["--levels", "0.1:1.0:0.1", "--ductility", "2"],
    );
    // Pounding (with pounding only): ten circles, and one in its legend
    // entry. Ductility > 2 in squares, so that markers on one point stay
    // apart: filled with pounding, hollow without (a closed outline of
    // five points), ten each and one in each legend entry.
    assert_eq!(svg.circles, 10 + 1);
    assert_eq!(svg.polygons.iter().filter(|f| *f == ORANGE).count(), 10 + 1);
    let hollow = svg.outlines.iter().filter(|s| *s == DARK_ORANGE).count();
    assert_eq!(hollow, 10 + 1);
    let pounding = svg.texts_starting("pounding: ");
    let with = svg.texts_starting("ductility>2 (either), with pounding: ");
    let without = svg.texts_starting("ductility>2 (either), without pounding: ");
    assert_eq!((pounding.len(), with.len(), without.len()), (1, 1, 1));
    // Both ductility fits exist for this suite (`pounding ida` gives θ and
    // β): a fitted curve each, solid orange and dashed dark orange.
    assert!(with[0].contains("θ = ") && without[0].contains("θ = "));
    assert_eq!(svg.curves(ORANGE), vec![240]);
    assert!(svg.strokes(DARK_ORANGE) > 10);
    // Pounding happens at every level above the first: no fit, said why.
    assert!(pounding[0].contains("no fit"), "{}", pounding[0]);
    assert!(svg.has_text("P(exceed)"));
    assert!(svg.has_text("Sa(T = 0.95 s, ξ = 5 %) (g)"));
}

#[test]
fn separation_has_the_step_curve_the_fit_and_every_guide() {
    let svg = draw(
        "separation",
        &["--level", "0.3", "--probability", "0.5,0.9"],
    );
    // The empirical distribution of 20 records: from (0, 0), a riser and a
    // tread per record, out to the edge (none needs 0 or ∞ here).
    assert_eq!(svg.curves(BLUE), vec![2 + 2 * 20]);
    // The lognormal fit, and a marker at each probability's gap (and one
    // in the legend).
    assert_eq!(svg.curves(ORANGE), vec![301]);
    assert_eq!(svg.circles, 2 + 1);
    for tag in ["ABS", "SRSS", "DDC", "gap"] {
        assert!(svg.has_text(tag), "tag `{tag}` in {:?}", svg.texts);
    }
    for start in ["p = 0.5: ", "p = 0.9: ", "ABS on the median peaks: "] {
        assert_eq!(svg.texts_starting(start).len(), 1, "`{start}`");
    }
    assert_eq!(svg.texts_starting("the preset's gap: 25 mm").len(), 1);
    assert!(svg.has_text("Separation d (mm)"));
    assert!(
        svg.has_text("P(Π_d,min ≤ d): share of records that do not pound"),
        "{:?}",
        svg.texts
    );
}

#[test]
fn png_variant_writes_a_png_of_the_requested_size() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("separation.png");
    let mut args = vec![
        "figure",
        "separation",
        "--out",
        out.to_str().unwrap(),
        "--width",
        "900",
        "--height",
        "600",
    ];
    args.extend(SUITE);
    succeeds(&args);
    let img = image::open(&out).expect("PNG decodes").to_rgb8();
    assert_eq!((img.width(), img.height()), (900, 600));
    assert!(img.pixels().any(|p| p.0 != [255, 255, 255]));
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    let suite = ["--suite", "synthetic:5"];
    let physical = ["--preset", "two-buildings"];
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            [&["figure", "ida", "--levels", "0.1,0.2"][..], &suite].concat(),
            "has no [physical] table",
        ),
        (
            [
                &["figure", "ida", "--levels", "0.2,0.1"][..],
                &suite,
                &physical,
            ]
            .concat(),
            "--levels 0.2,0.1: levels must be strictly ascending",
        ),
        (
            [&["figure", "fragility"][..], &suite, &physical].concat(),
            "figure fragility: needs --levels",
        ),
        (
            [&["figure", "ida", "--levels", "0.1"][..], &physical].concat(),
            "figure ida: needs --suite",
        ),
        (
            [
                &["figure", "separation", "--levels", "0.1"][..],
                &suite,
                &physical,
            ]
            .concat(),
            "--levels applies to figure ida, fragility, not separation",
        ),
        (
            [
                &["figure", "ida", "--levels", "0.1", "--ductility", "2"][..],
                &suite,
                &physical,
            ]
            .concat(),
            "--ductility applies to figure fragility, not ida",
        ),
        (
            [
                &["figure", "fragility", "--levels", "0.1", "--ductility", "x"][..],
                &suite,
                &physical,
            ]
            .concat(),
            "--ductility",
        ),
        (
            [
                &["figure", "separation", "--probability", "1.5"][..],
                &suite,
                &physical,
            ]
            .concat(),
            "--probability `1.5`",
        ),
        (
            vec!["figure", "fig3", "--suite", "synthetic:5"],
            "--suite applies to figure ida, fragility, separation, not fig3",
        ),
        (
            [
                &["figure", "separation", "--level", "0.3", "--drift", "0.01"][..],
                &ROW,
            ]
            .concat(),
            "--drift applies to figure fragility, not separation",
        ),
        (
            [
                &["figure", "ida", "--levels", "0.1", "--scale", "2"][..],
                &ROW,
            ]
            .concat(),
            "--scale applies to figure buildings, not ida",
        ),
        (
            [
                &["figure", "fragility", "--levels", "0.1", "--ductility", "2"][..],
                &ROW,
            ]
            .concat(),
            "--ductility 2: a row's storeys take --drift",
        ),
        (
            [
                &["figure", "fragility", "--levels", "0.1", "--drift", "0.01"][..],
                &suite,
                &physical,
            ]
            .concat(),
            "--drift: applies to a row of buildings",
        ),
        (
            vec!["figure", "history", "--buildings", "block-and-frame"],
            "--buildings applies to figure buildings, ida, fragility and separation, not history",
        ),
        (
            [
                &[
                    "figure",
                    "ida",
                    "--levels",
                    "0.1",
                    "--preset",
                    "two-buildings",
                ][..],
                &ROW,
            ]
            .concat(),
            "--preset: not with --buildings",
        ),
    ];
    for (args, expected) in cases {
        fails(&args, 2, &[expected]);
    }
}

/// A row IDA to collapse (SPEC §15): each record that collapses ends at the
/// flatline with one marker (filled with pounding, hollow without), as
/// many as `ida --buildings --collapse` reports collapsed records, and the
/// flatline is tagged.
#[test]
fn a_row_ida_to_collapse_marks_each_collapsed_record_at_the_flatline() {
    let study = [
        "--buildings",
        "block-and-frame-pdelta",
        "--suite",
        "synthetic:6@3",
        "--levels",
        "0.6,1.0,1.4",
    ];
    let report = json(&[&["ida"], &study[..], &["--collapse", "--format", "json"]].concat());
    let levels = report["levels"].as_array().unwrap();
    let collapsed = |key: &str| {
        (0..6)
            .filter(|&j| {
                levels
                    .iter()
                    .any(|l| l["records"][j][key][1]["collapsed"] == true)
            })
            .count()
    };
    let (with, without) = (collapsed("buildings"), collapsed("no_pounding"));
    assert!(with > 0 && without > 0, "{with} {without}");
    let svg = draw_study("ida", &study);
    // One filled marker per record that collapsed with pounding, and the legend's.
    assert_eq!(svg.circles, with + 1);
    assert_eq!(
        svg.outlines.iter().filter(|s| *s == DARK_ORANGE).count(),
        without + 1
    );
    assert!(svg.has_text("collapse"), "{:?}", svg.texts);
    assert!(svg.has_text("collapse, with pounding"));
}

// `figure ida|fragility|separation --buildings ROW --compare ROW2,…`: the
// variants overlaid on one SVG, one palette colour per variant and every
// legend entry naming its variant by its file stem, the values in the
// legend those of `ida` and `gap --suite` on each row alone; and the
// refusals, one line each, exit 2.

const ROWS: [&str; 2] = ["block-and-frame", "block-and-frame-retrofit"];

/// Runs `figure NAME --buildings ROWS[0] --compare compare` with `study`,
/// and reads the SVG back.
fn draw_compared(name: &str, compare: &str, study: &[&str]) -> Svg {
    let rows = ["--buildings", ROWS[0], "--compare", compare];
    draw_study(name, &[&rows[..], study].concat())
}

const LEVELS: [&str; 4] = [
    "--suite",
    "synthetic:5",
    "--levels",
    "0.1,0.15,0.2,0.25,0.3",
];

#[test]
fn compared_fragility_curves_are_each_row_s_ida_fits_one_colour_a_variant() {
    let svg = draw_compared(
        "fragility",
        ROWS[1],
        &[&LEVELS[..], &["--drift", "0.004"]].concat(),
    );
    let mut fitted = 0;
    for name in ROWS {
        let mut args = vec![
            "ida",
            "--buildings",
            name,
            "--format",
            "json",
            "--drift",
            "0.004",
        ];
        args.extend(LEVELS);
        let report = json(&args);
        for c in report["fragility"].as_array().unwrap() {
            let state = c["limit_state"].as_str().unwrap();
            for (key, style) in [
                ("fragility", ", with pounding"),
                ("no_pounding_fragility", ", without pounding"),
            ] {
                let Some(fit) = c.get(key) else { continue };
                // The pounding limit state has its one fit, unnamed.
                let style = if c.get("no_pounding_fragility").is_some() {
                    style
                } else {
                    ""
                };
                let legend = svg.texts_starting(&format!("{name}: {state}{style}: "));
                assert_eq!(legend.len(), 1, "{name}: {state}{style} in {:?}", svg.texts);
                if fit["outcome"] == "fitted" {
                    // θ to 4 digits and β to 3 decimals, as the legend writes them.
                    let theta = fit["theta"].as_f64().unwrap();
                    let beta = fit["beta"].as_f64().unwrap();
                    assert!((number_after(legend[0], "θ = ") - theta).abs() <= 5e-4 * theta);
                    assert!((number_after(legend[0], "β = ") - beta).abs() <= 5e-4);
                    fitted += 1;
                }
            }
        }
    }
    assert!(fitted >= 2, "fits to compare: {fitted}");
    // The first row's fit with pounding (drift) is a solid curve in its
    // colour; the retrofit's fit apart is dashed in the darker shade of its.
    assert!(!svg.curves(BLUE).is_empty(), "{:?}", svg.polylines);
    assert!(svg.polylines.iter().any(|(s, _)| s == DARK_ORANGE));
}

#[test]
fn compared_ida_draws_each_variant_s_medians_in_its_colour_in_each_building_s_panel() {
    let svg = draw_compared("ida", ROWS[1], &LEVELS);
    for name in ROWS {
        for style in ["median, with pounding", "median, every joint open"] {
            let legend = svg.texts_starting(&format!("{name}: {style}"));
            assert_eq!(legend.len(), 1, "{name}: {style} in {:?}", svg.texts);
        }
    }
    // Per building panel (block, frame) and variant: the median with
    // pounding, solid in the variant's colour, from 0 through 5 levels.
    assert_eq!(svg.curves(BLUE), vec![6, 6]);
    assert_eq!(svg.curves(ORANGE), vec![6, 6]);
}

#[test]
fn a_compared_row_given_as_a_path_is_named_by_its_file_stem() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("retro.toml");
    std::fs::copy("presets/buildings/block-and-frame-retrofit.toml", &path).unwrap();
    let study = [
        "--suite",
        "synthetic:5",
        "--level",
        "0.3",
        "--probability",
        "0.5",
    ];
    let svg = draw_compared("separation", path.to_str().unwrap(), &study);
    for (name, row) in [
        ("block-and-frame", ROWS[0]),
        ("retro", path.to_str().unwrap()),
    ] {
        let legend = svg.texts_starting(&format!("{name}: records (empirical, N = 5)"));
        assert_eq!(legend.len(), 1, "{name} in {:?}", svg.texts);
        // Its gap at p = 0.5 is `gap --suite`'s on that row, to 4 digits.
        let mut args = vec!["gap", "--buildings", row, "--format", "json"];
        args.extend(study);
        let report = json(&args);
        let want = report["joints"][0]["study"]["at_probability"][0]["empirical"]
            .as_f64()
            .unwrap()
            * 1e3;
        let legend = svg.texts_starting(&format!("{name}: gap d_(⌈pN⌉) "));
        assert_eq!(legend.len(), 1, "{name} in {:?}", svg.texts);
        let drawn = number_after(legend[0], "d_(⌈pN⌉) ");
        assert!(
            (drawn - want).abs() <= 5e-4 * want,
            "{drawn} mm against {want} mm"
        );
    }
    // Each variant's empirical step curve in its colour.
    assert_eq!(svg.curves(BLUE).len(), 1, "{:?}", svg.polylines);
    assert_eq!(svg.curves(ORANGE).len(), 1, "{:?}", svg.polylines);
}

#[test]
fn compared_figures_are_refused_in_one_line_where_they_cannot_compare() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("f.svg");
    let out = out.to_str().unwrap();
    let base = [
        "figure",
        "fragility",
        "--out",
        out,
        "--suite",
        "synthetic:2",
    ];
    let levels = ["--levels", "0.1,0.2"];
    // A variant with other buildings.
    let args = [
        &base[..],
        &levels,
        &["--buildings", ROWS[0], "--compare", "three-in-series"],
    ];
    fails(
        &args.concat(),
        2,
        &[
            "--compare three-in-series",
            "block, mid, tall",
            "block, frame",
        ],
    );
    // On the pair.
    let args = [
        &base[..],
        &levels,
        &["--preset", "two-buildings", "--compare", ROWS[1]],
    ];
    fails(&args.concat(), 2, &["--compare", "--buildings ROW"]);
    // On a figure that is not a suite study.
    fails(
        &["figure", "fig3", "--out", out, "--compare", ROWS[1]],
        2,
        &["--compare", "ida, fragility and separation"],
    );
    assert!(!std::path::Path::new(out).exists());
}
