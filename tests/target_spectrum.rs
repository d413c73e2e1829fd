//! Target spectra (ASCE 7-16 §11.4.6, EN 1998-1 §3.2.2.2, a table
//! interpolated log-log): each branch at T = 0, at its corner periods and
//! between them equals the code's formula worked by hand, to 1e-12; bad
//! specs are refused in one line naming the value and what is allowed.

use pounding::model::target_spectrum::TargetSpectrum;

fn close(got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-12 * want.abs().max(1e-300),
        "{got} vs {want}"
    );
}

fn at(spec: &str, cases: &[(f64, f64)]) {
    let s = TargetSpectrum::parse(spec).unwrap();
    for &(t, want) in cases {
        close(s.sa(t).unwrap(), want);
    }
}

#[test]
fn asce7_design_and_mce_branches() {
    // S_DS = 1.0, S_D1 = 0.6, T_L = 8: T0 = 0.12 s, T_S = 0.6 s.
    let design = [
        (0.0, 0.4),                // 0.4 S_DS
        (0.06, 0.7),               // S_DS (0.4 + 0.6·0.06/0.12)
        (0.12, 1.0),               // T0: S_DS
        (0.3, 1.0),                // plateau
        (0.6, 1.0),                // T_S: S_DS = S_D1/T_S
        (2.0, 0.3),                // S_D1/T
        (8.0, 0.075),              // T_L: S_D1/T_L
        (10.0, 0.6 * 8.0 / 100.0), // S_D1 T_L/T²
    ];
    at("asce7:SDS=1.0,SD1=0.6,TL=8", &design);
    let mce: Vec<(f64, f64)> = design.iter().map(|&(t, v)| (t, 1.5 * v)).collect();
    at("asce7-mce:sds=1.0,sd1=0.6,tl=8", &mce);
    let s = TargetSpectrum::parse("asce7:SDS=1.0,SD1=0.6,TL=8").unwrap();
    assert_eq!(s.corners(), vec![0.6 * 0.2, 0.6, 8.0]);
    assert_eq!(s.periods(), (0.0, 10.0));
}

#[test]
fn ec8_type_1_ground_b_with_importance() {
    // a_gR = 0.3 g, γ_I = 1.2: a_g = 0.36 g; ground B type 1: S = 1.2,
    // T_B = 0.15, T_C = 0.5, T_D = 2; a_g S = 0.432 g, plateau 1.08 g.
    at(
        "ec8:ag=0.3,ground=B,type=1,importance=1.2",
        &[
            (0.0, 0.432),                       // a_g S
            (0.075, 0.432 * (1.0 + 0.5 * 1.5)), // (3.2) halfway to T_B
            (0.15, 1.08),                       // T_B
            (0.3, 1.08),                        // (3.3)
            (0.5, 1.08),                        // T_C
            (1.0, 1.08 * 0.5),                  // (3.4) T_C/T
            (2.0, 1.08 * 0.25),                 // T_D
            (3.0, 1.08 * 0.5 * 2.0 / 9.0),      // (3.5) T_C T_D/T²
            (4.0, 1.08 / 16.0),                 // the end of (3.5)
        ],
    );
}

#[test]
fn ec8_type_2_ground_d() {
    // a_g = 0.1 g; ground D type 2: S = 1.8, T_B = 0.1, T_C = 0.3, T_D = 1.2.
    at(
        "ec8:ag=0.1,ground=D,type=2",
        &[
            (0.0, 0.18),
            (0.05, 0.18 * 1.75),
            (0.1, 0.45),
            (0.2, 0.45),
            (0.3, 0.45),
            (0.6, 0.225),
            (1.2, 0.1125),
            (2.4, 0.45 * 0.3 * 1.2 / 5.76),
        ],
    );
}

#[test]
fn ec8_tables_3_2_and_3_3() {
    // (ground, type, S, T_B, T_C, T_D) of EN 1998-1 Tables 3.2 and 3.3:
    // a_g = 1 gives S at T = 0, 2.5 S on the plateau and the corners.
    let table = [
        ("A", 1, 1.0, 0.15, 0.4, 2.0),
        ("B", 1, 1.2, 0.15, 0.5, 2.0),
        ("C", 1, 1.15, 0.20, 0.6, 2.0),
        ("D", 1, 1.35, 0.20, 0.8, 2.0),
        ("E", 1, 1.4, 0.15, 0.5, 2.0),
        ("A", 2, 1.0, 0.05, 0.25, 1.2),
        ("B", 2, 1.35, 0.05, 0.25, 1.2),
        ("C", 2, 1.5, 0.10, 0.25, 1.2),
        ("D", 2, 1.8, 0.10, 0.30, 1.2),
        ("E", 2, 1.6, 0.05, 0.25, 1.2),
    ];
    for (ground, kind, s, tb, tc, td) in table {
        let spec = format!("ec8:ag=1,ground={ground},type={kind}");
        let t = TargetSpectrum::parse(&spec).unwrap();
        assert_eq!(t.corners(), vec![tb, tc, td], "{spec}");
        close(t.sa(0.0).unwrap(), s);
        close(t.sa(tb).unwrap(), 2.5 * s);
        close(t.sa(tc).unwrap(), 2.5 * s);
        close(t.sa(td).unwrap(), 2.5 * s * tc / td);
    }
}

#[test]
fn a_table_is_interpolated_log_log_and_exact_at_its_rows() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("target.txt");
    std::fs::write(&path, "# T Sa\n0.1 1.0\n1.0, 0.1\n\n2.0 0.1\n").unwrap();
    let s = TargetSpectrum::parse(&format!("file:{}", path.display())).unwrap();
    close(s.sa(0.1).unwrap(), 1.0);
    close(s.sa(1.0).unwrap(), 0.1);
    // Sa ∝ 1/T between the first two rows: Sa(T) = 0.1/T.
    close(s.sa(0.25).unwrap(), 0.4);
    close(s.sa(1.5).unwrap(), 0.1);
    assert_eq!(s.sa(0.05), None);
    assert_eq!(s.sa(2.5), None);
    assert_eq!(s.periods(), (0.1, 2.0));
}

#[test]
fn bad_targets_are_refused_naming_the_value_and_the_allowed() {
    let dir = tempfile::tempdir().unwrap();
    let file = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        format!("file:{}", p.display())
    };
    let cases = [
        (
            "nbc:SDS=1".to_string(),
            vec!["unknown code `nbc`", "asce7:"],
        ),
        (
            "ec8:ag=0.3,ground=F,type=1".into(),
            vec!["ground `F`", "A, B, C, D, E"],
        ),
        (
            "ec8:ag=0.3,ground=B,type=3".into(),
            vec!["type `3`", "1 or 2"],
        ),
        (
            "ec8:ag=0,ground=B,type=1".into(),
            vec!["a_g = `0`", "positive"],
        ),
        ("ec8:ag=0.3,ground=B".into(), vec!["type is missing"]),
        (
            "asce7:SDS=0,SD1=0.6,TL=8".into(),
            vec!["S_DS = `0`", "positive"],
        ),
        (
            "asce7:SDS=1,SD1=-0.6,TL=8".into(),
            vec!["S_D1 = `-0.6`", "positive"],
        ),
        (
            "asce7:SDS=1,SD1=0.6,TL=0.5".into(),
            vec!["T_L = 0.5 s", "T_S = S_D1/S_DS = 0.6 s"],
        ),
        (
            "asce7:SDS=1,SD1=0.6,TL=8,X=1".into(),
            vec!["unknown key `x`"],
        ),
        (
            file("down.txt", "1 0.5\n0.5 0.4\n"),
            vec!["line 2", "must increase"],
        ),
        (file("one.txt", "1 0.5 3\n"), vec!["line 1", "two columns"]),
        (
            file("neg.txt", "1 0.5\n2 -0.4\n"),
            vec!["line 2", "Sa `-0.4`", "positive"],
        ),
        (file("short.txt", "1 0.5\n"), vec!["at least two rows"]),
        ("file:/no/such/file".into(), vec!["No such file"]),
    ];
    for (spec, fragments) in cases {
        let e = TargetSpectrum::parse(&spec).unwrap_err().to_string();
        assert_eq!(e.lines().count(), 1, "{e}");
        for f in fragments {
            assert!(e.contains(f), "`{f}` missing from: {e}");
        }
    }
}
