use super::*;

fn building(ductility: f64, acceleration_g: f64, drift_ratio: Option<f64>) -> BuildingDemand {
    BuildingDemand {
        peak_drift_m: 0.0,
        drift_ratio,
        ductility,
        acceleration_g,
        collapsed: false,
        cut_short: false,
    }
}

fn joint(impacts: usize, max_force_kn: f64) -> JointDemand {
    JointDemand {
        impacts,
        max_force_kn,
        min_gap_m: 0.0,
    }
}

/// The pair's run: μ 1.5 and 3, A 0.4 g and 0.7 g, no impact.
fn pair() -> [BuildingDemand; 2] {
    [building(1.5, 0.4, None), building(3.0, 0.7, None)]
}

fn row() -> Row {
    crate::model::buildings::load("block-and-frame").unwrap()
}

/// A row's two buildings at drift ratios `drift`, one joint of `impacts`.
fn rows(drift: [f64; 2], impacts: usize) -> (Vec<BuildingDemand>, Vec<JointDemand>) {
    (
        drift
            .iter()
            .map(|&d| building(d / 0.01, 10.0 * d, Some(d)))
            .collect(),
        vec![joint(impacts, 100.0 * impacts as f64)],
    )
}

fn side(index: usize) -> Target {
    Target::Building {
        index,
        name: ["left", "right"][index].into(),
    }
}

#[test]
fn parses_the_pairs_documented_forms() {
    let p = LimitParser::pair();
    let either = |value| LimitState::Ductility {
        building: Target::Either,
        value,
    };
    assert_eq!(p.ductility("2,4").unwrap(), [either(2.0), either(4.0)]);
    assert_eq!(
        p.ductility(" left:2 , right: 4,either:3").unwrap(),
        [
            LimitState::Ductility {
                building: side(0),
                value: 2.0
            },
            LimitState::Ductility {
                building: side(1),
                value: 4.0
            },
            either(3.0)
        ]
    );
    assert_eq!(p.ductility("0.5").unwrap(), [either(0.5)]);
    let acc = p.acceleration("0.3g,right:1g,9.80665").unwrap();
    let g = |building, g| LimitState::Acceleration { building, g };
    assert_eq!(
        acc,
        [
            g(Target::Either, 0.3),
            g(side(1), 1.0),
            g(Target::Either, 1.0)
        ]
    );
    let kn = |kn| LimitState::Force {
        building: Target::Either,
        kn,
    };
    assert_eq!(p.force("500, 250").unwrap(), [kn(500.0), kn(250.0)]);
}

#[test]
fn the_pair_refuses_with_the_flag_item_and_what_is_allowed() {
    let p = LimitParser::pair();
    let err = |r: Result<Vec<LimitState>, LimitStateError>| r.unwrap_err().to_string();
    assert_eq!(
        err(p.ductility("2,0")),
        "--ductility `0`: must be a ductility > 0, e.g. 2,4 or left:2,right:4"
    );
    assert_eq!(
        err(p.ductility("middle:2")),
        "--ductility `middle:2`: must be left:, right: or either: (or no side), then a value > 0"
    );
    for bad in ["", "inf", "NaN", "-1", "2,", "two", "left:", "any:2"] {
        assert!(p.ductility(bad).is_err(), "{bad:?}");
    }
    assert_eq!(
        err(p.acceleration("0g")),
        "--acceleration `0g`: must be an acceleration > 0 like 0.5g, or in m/s², e.g. 0.5g,1g or right:0.3g"
    );
    assert!(p.acceleration("left:-0.5g").is_err());
    assert_eq!(
        err(p.force("left:500")),
        "--force `left:500`: must be a force > 0 in kN, e.g. 500 or 250,500"
    );
    assert!(p.force("1e999").is_err());
    assert_eq!(
        err(p.drift("0.01")),
        "--drift: applies to a row of buildings; give --buildings PRESET \
         (a pair's limit states are --ductility, --acceleration, --force)"
    );
}

#[test]
fn the_pairs_exceedance_by_side() {
    let p = LimitParser::pair();
    let o = pair();
    let none = [joint(0, 0.0)];
    let duct = |t: &str| p.ductility(t).unwrap()[0].exceeded(&o, &none);
    assert!(!duct("left:2") && duct("right:2") && duct("either:2"));
    assert!(!duct("3"), "strictly above");
    let acc = |t: &str| p.acceleration(t).unwrap()[0].exceeded(&o, &none);
    assert!(acc("left:0.3g") && !acc("left:0.5g") && acc("0.5g"));
    assert!(!p.pounding().exceeded(&o, &none));
    assert!(!p.force("1").unwrap()[0].exceeded(&o, &none));
    let hit = [joint(3, 600.0)];
    assert!(p.pounding().exceeded(&o, &hit));
    assert!(p.force("500").unwrap()[0].exceeded(&o, &hit));
    assert!(!p.force("600").unwrap()[0].exceeded(&o, &hit));
}

/// An elastic structure never exceeds a ductility: not through the run's
/// μ = ∞, nor through a NaN.
#[test]
fn an_elastic_structure_never_exceeds_a_ductility() {
    let p = LimitParser::pair();
    let none = [joint(0, 0.0)];
    for elastic in [f64::INFINITY, f64::NAN] {
        let o = [building(elastic, 0.4, None), building(elastic, 0.7, None)];
        for side in ["left:0.1", "right:0.1", "either:0.1"] {
            assert!(!p.ductility(side).unwrap()[0].exceeded(&o, &none));
        }
    }
    let nan = [building(1.0, f64::NAN, None), building(1.0, f64::NAN, None)];
    let nan_force = [joint(1, f64::NAN)];
    assert!(!p.acceleration("0.1g").unwrap()[0].exceeded(&nan, &nan_force));
    assert!(!p.force("1").unwrap()[0].exceeded(&nan, &nan_force));
}

#[test]
fn the_pairs_labels() {
    let p = LimitParser::pair();
    assert_eq!(p.pounding().label(), "pounding");
    assert_eq!(p.ductility("2").unwrap()[0].label(), "ductility>2 (either)");
    assert_eq!(
        p.acceleration("left:0.5g").unwrap()[0].label(),
        "acceleration>0.5g (left)"
    );
    assert_eq!(p.force("500").unwrap()[0].to_string(), "force>500kN");
}

#[test]
fn reads_a_rows_names_and_the_default_building() {
    let p = LimitParser::row(&row())
        .with_building(Some("frame"))
        .unwrap();
    let frame = Target::Building {
        index: 1,
        name: "frame".into(),
    };
    let block = Target::Building {
        index: 0,
        name: "block".into(),
    };
    let drift = |building, ratio| LimitState::Drift { building, ratio };
    assert_eq!(
        p.drift("0.005, block:0.01 ,any:0.02").unwrap(),
        [
            drift(frame, 0.005),
            drift(block, 0.01),
            drift(Target::Any, 0.02)
        ]
    );
    assert_eq!(p.pounding().label(), "pounding (frame)");
    assert_eq!(
        p.acceleration("1g").unwrap()[0].label(),
        "acceleration>1g (frame)"
    );
    let any = LimitParser::row(&row());
    assert_eq!(any.force("500").unwrap()[0].label(), "force>500kN (any)");
    assert_eq!(any.pounding().label(), "pounding (any)");
}

#[test]
fn a_row_refuses_with_the_flag_the_item_and_what_is_allowed() {
    let p = LimitParser::row(&row());
    let err = |r: Result<Vec<LimitState>, LimitStateError>| r.unwrap_err().to_string();
    assert_eq!(
        err(p.drift("0.01,0")),
        "--drift `0`: must be a storey drift ratio in (0, 1), e.g. 0.005,0.01,0.02 or frame:0.01"
    );
    assert_eq!(
        err(p.drift("tower:0.01")),
        "--drift `tower:0.01`: must be NAME:VALUE with NAME a building of the row (block, frame) or any"
    );
    for bad in [
        "",
        "1",
        "-0.01",
        "nan",
        "inf",
        "0.01,",
        "block:",
        "either:0.01",
    ] {
        assert!(p.drift(bad).is_err(), "{bad:?}");
    }
    assert!(p.acceleration("0g").is_err() && p.force("frame:-5").is_err());
    assert_eq!(
        LimitParser::row(&row())
            .with_building(Some("tower"))
            .unwrap_err()
            .to_string(),
        "--building `tower`: must be a building of the row (block, frame) or any"
    );
    assert_eq!(
        err(p.ductility("2")),
        "--ductility 2: a row's storeys take --drift (storey drift ratio, e.g. 0.01); drop --ductility"
    );
}

#[test]
fn a_row_is_exceeded_by_the_building_named_or_any() {
    let p = LimitParser::row(&row());
    let (b, j) = rows([0.004, 0.012], 0);
    let drift = |t: &str| p.drift(t).unwrap()[0].exceeded(&b, &j);
    assert!(drift("0.01") && drift("frame:0.01") && !drift("block:0.01"));
    assert!(!drift("0.012"), "strictly above");
    assert!(!p.pounding().exceeded(&b, &j));
    let (b1, j1) = rows([0.0; 2], 1);
    assert!(p.pounding().exceeded(&b1, &j1));
    assert!(p.force("50").unwrap()[0].exceeded(&b1, &j1));
    assert!(!p.force("100").unwrap()[0].exceeded(&b1, &j1));
    // With every joint open, nothing pounds.
    assert!(!p.pounding().exceeded(&b1, &[]));
    let (nan, jn) = rows([f64::NAN; 2], 0);
    assert!(!p.drift("0.001").unwrap()[0].exceeded(&nan, &jn));
}

/// Building i's joints are i − 1 and i: the middle one of three touches
/// both, the outer ones one each.
#[test]
fn a_buildings_joints_are_those_on_either_side() {
    let row = crate::model::buildings::load("three-in-series").unwrap();
    let p = LimitParser::row(&row);
    let b: Vec<BuildingDemand> = (0..3).map(|_| building(1.0, 0.1, Some(0.001))).collect();
    let j = [joint(0, 0.0), joint(2, 300.0)];
    let names: Vec<&str> = row.buildings.iter().map(|b| b.name.as_str()).collect();
    let pounded = |name: &str| {
        LimitParser::row(&row)
            .with_building(Some(name))
            .unwrap()
            .pounding()
            .exceeded(&b, &j)
    };
    assert_eq!(
        names.iter().map(|n| pounded(n)).collect::<Vec<_>>(),
        [false, true, true]
    );
    let force = |name: &str| p.force(&format!("{name}:250")).unwrap()[0].exceeded(&b, &j);
    assert!(!force(names[0]) && force(names[1]) && force(names[2]));
}

/// A building that collapsed exceeds every limit state of its own, and
/// none of its neighbour's (SPEC §15).
#[test]
fn a_collapsed_building_exceeds_every_limit_state_of_its_own() {
    let mut row = row();
    row.buildings[1].p_delta = Some(crate::model::buildings::PDelta {
        gravity_mass: vec![1.0; 8],
        collapse_drift_ratio: 0.1,
    });
    let p = LimitParser::row(&row);
    let collapses = p.collapses(&row);
    assert_eq!(collapses.len(), 1);
    assert_eq!(collapses[0].label(), "collapse (frame)");
    let (mut b, j) = rows([0.001, 0.001], 0);
    b[1].collapsed = true;
    b[0].cut_short = true;
    assert!(collapses[0].exceeded(&b, &j));
    for state in [
        p.drift("frame:0.5").unwrap()[0].clone(),
        p.acceleration("frame:100g").unwrap()[0].clone(),
        p.force("frame:1e9").unwrap()[0].clone(),
        LimitParser::row(&row)
            .with_building(Some("frame"))
            .unwrap()
            .pounding(),
    ] {
        assert!(state.exceeded(&b, &j), "{state}");
    }
    for state in [
        p.drift("block:0.5").unwrap()[0].clone(),
        LimitParser::row(&row)
            .with_building(Some("block"))
            .unwrap()
            .pounding(),
    ] {
        assert!(!state.exceeded(&b, &j), "{state}");
    }
    let (b3, j3) = rows([0.5, 0.5], 3);
    assert!(!collapses[0].exceeded(&b3, &j3));
}
