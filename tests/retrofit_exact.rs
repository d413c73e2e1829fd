//! Bumpers and links (SPEC §14) in the exact method: against a closed form,
//! against the bare row where the retrofit vanishes, an isolated bumper
//! impact's restitution, the energy balance, the mirror image (with a
//! linear link and with a fluid viscous damper), and the independent
//! reference.

mod common;

use common::{against_reference, linked, record_ground};
use nalgebra::{DMatrix, DVector};
use pounding::model::buildings::matrices::RowMatrices;
use pounding::model::buildings::{self, Ground, Row, parse};
use pounding::reference::row::reference_row;
use pounding::solver::buildings::{FloorPeaks, RowOptions, RowRun, run_row};

/// The state (u, u̇) at t of M ü + C u̇ + K u = −M 1 A sin ωt from rest, by
/// the matrix exponential of the augmented first-order system
/// (u, u̇, s, c) with s = sin ωt, c = cos ωt: ṡ = ωc, ċ = −ωs.
fn closed_form(
    m: &[f64],
    k: &DMatrix<f64>,
    c: &DMatrix<f64>,
    (amp, w): (f64, f64),
    t: f64,
) -> DVector<f64> {
    let n = m.len();
    let mut a = DMatrix::<f64>::zeros(2 * n + 2, 2 * n + 2);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -k[(i, j)] / m[i];
            a[(n + i, n + j)] = -c[(i, j)] / m[i];
        }
        a[(n + i, 2 * n)] = -amp;
    }
    a[(2 * n, 2 * n + 1)] = w;
    a[(2 * n + 1, 2 * n)] = -w;
    let mut y0 = DVector::zeros(2 * n + 2);
    y0[2 * n + 1] = 1.0;
    (a * t).exp() * y0
}

#[test]
fn a_linear_link_between_two_one_storey_buildings_is_the_closed_form() {
    let (kl, cl) = (1.5e6, 8e4);
    let row = linked(&format!("stiffness = {kl}\ndamping = {cl}\n"));
    let (amp, w, t_end) = (2.0, 7.0, 3.0);
    let ground = Ground::sine(amp, w, 10.0);
    let run = run_row(&row, &ground, &RowOptions::lasting(t_end)).unwrap();
    let mats = RowMatrices::of(&row);
    let mut k = mats.stiffness.clone();
    let mut c = mats.damping.clone();
    for (mat, x) in [(&mut k, kl), (&mut c, cl)] {
        mat[(0, 0)] += x;
        mat[(1, 1)] += x;
        mat[(0, 1)] -= x;
        mat[(1, 0)] -= x;
    }
    let m: Vec<f64> = mats.mass.iter().copied().collect();
    let y = closed_form(&m, &k, &c, (amp, w), t_end);
    let scale_u = y.rows(0, 2).amax();
    let scale_v = y.rows(2, 2).amax();
    for i in 0..2 {
        let du = (run.final_displacement[i] - y[i]).abs() / scale_u;
        let dv = (run.final_velocity[i] - y[2 + i]).abs() / scale_v;
        assert!(du < 1e-12 && dv < 1e-12, "floor {i}: {du:e} {dv:e}");
    }
    // The link's force at the end, and its peak at least that.
    let (du, dv) = (y[0] - y[1], y[2] - y[3]);
    let f = (kl * du + cl * dv).abs();
    assert!(run.links[0].max_force >= f * (1.0 - 1e-12));
    assert!(run.links[0].stroke >= du.abs() * (1.0 - 1e-12));
}

#[test]
fn a_link_of_no_stiffness_and_no_damping_is_refused() {
    let text = "[[building]]\nname = \"a\"\nstoreys = 1\nmass = 1e5\nstiffness = 4e6\n\
                [[building]]\nname = \"b\"\nstoreys = 1\nmass = 2e5\nstiffness = 2e7\n\
                [[joint]]\ngap = 0.01\nstiffness = 1e9\n[[link]]\njoint = 1\nfloor = 1\nstiffness = 0\ndamping = 0\n";
    let e = parse("l.toml", text).unwrap_err().to_string();
    assert_eq!(
        e,
        "l.toml: link1: `stiffness` = 0 and `damping` = 0: a link needs one of them > 0"
    );
}

fn peaks(run: &RowRun) -> Vec<f64> {
    run.floors
        .iter()
        .flatten()
        .flat_map(|f| [f.displacement, f.velocity, f.absolute_acceleration, f.drift])
        .collect()
}

fn impacts(run: &RowRun) -> Vec<usize> {
    run.pairs.iter().map(|p| p.impacts.len()).collect()
}

/// The bare block-and-frame row and `row` under the record, with the same
/// impacts at every floor pair.
fn beside_the_bare_row(row: &Row) -> (RowRun, RowRun) {
    let bare = buildings::load("block-and-frame").unwrap();
    let ground = record_ground(1.0);
    let options = RowOptions::lasting(ground.end() + 2.0);
    let a = run_row(&bare, &ground, &options).unwrap();
    let b = run_row(row, &ground, &options).unwrap();
    assert!(a.impacts() > 5);
    assert_eq!(impacts(&a), impacts(&b));
    (a, b)
}

#[test]
fn a_vanishing_link_gives_the_bare_rows_peaks() {
    let row = buildings::load_with(
        "block-and-frame-retrofit",
        &[
            "joint1.bumper.thickness=0.004".into(),
            "link1.damping=1e-300".into(),
        ],
    )
    .unwrap();
    let mut row = row;
    row.joints[0].bumper = None;
    let (a, b) = beside_the_bare_row(&row);
    for (x, y) in peaks(&a).iter().zip(peaks(&b)) {
        assert!((x - y).abs() <= 1e-12 * x.abs(), "{x} {y}");
    }
    assert!(b.links[0].max_force < 1e-290);
}

#[test]
fn a_bumper_one_nanometre_thick_gives_the_bare_rows_impacts() {
    let row = buildings::load_with(
        "block-and-frame",
        &[
            "joint1.bumper.thickness=1e-9".into(),
            "joint1.bumper.stiffness=1".into(),
            "joint1.bumper.restitution=0.65".into(),
        ],
    )
    .unwrap();
    let (a, b) = beside_the_bare_row(&row);
    for (pa, pb) in a.pairs.iter().zip(&b.pairs) {
        for (x, y) in pa.impacts.iter().zip(&pb.impacts) {
            assert!((x.start - y.start).abs() < 1e-6, "{x:?} {y:?}");
            assert!((x.max_force - y.max_force).abs() < 1e-6 * x.max_force);
        }
    }
    // Each bumper closes just before its pair's hard contact.
    let bumper_contacts: Vec<usize> = b.bumpers.iter().map(|p| p.impacts.len()).collect();
    assert_eq!(bumper_contacts, impacts(&a));
}

/// A stiff bumper on two soft one-storey buildings: under the Kelvin law
/// the floors separate at e_b times their approach velocity (the law's own
/// restitution, SPEC §4); under every law of the Kelvin family the bumper's
/// impact is the one the joint's own element makes with the bumper's gap,
/// stiffness and restitution.
#[test]
fn an_isolated_impact_on_a_bumper_returns_its_restitution() {
    let row_text = |model: &str, joint: &str| {
        format!(
            "model = \"{model}\"\nrestitution = 0.5\n\
             [[building]]\nname = \"soft\"\nstoreys = 1\nmass = 1e5\nstiffness = 1e6\nheight = 3\ndamping = 0\n\
             [[building]]\nname = \"stiff\"\nstoreys = 3\nmass = 1e5\nstiffness = 4e7\nheight = 3\ndamping = 0\n\
             [[joint]]\n{joint}\n"
        )
    };
    let ground = Ground::sine(2.0, 2.0 * std::f64::consts::PI, 1.0);
    let options = RowOptions::lasting(1.5);
    for model in ["kelvin", "improved-kelvin"] {
        for eb in [0.4, 0.8] {
            let with = format!(
                "gap = 0.005\nstiffness = 1e14\nbumper = {{ thickness = 0.004, stiffness = 1e13, restitution = {eb} }}"
            );
            let row = parse("bumper.toml", &row_text(model, &with)).unwrap();
            let r = run_row(&row, &ground, &options).unwrap();
            let first = r.bumpers[0].impacts[0];
            assert!(first.approach_velocity > 0.01, "{first:?}");
            // It does not bottom out: the compression stays below t, and
            // the joint's own element never closes.
            assert!(first.max_penetration < 0.004, "{first:?}");
            assert!(r.pairs[0].impacts.is_empty());
            let achieved = first.separation_velocity / first.approach_velocity;
            if model == "kelvin" {
                assert!(
                    (achieved - eb).abs() < 1e-4 * eb,
                    "{model}, e_b = {eb}: achieved {achieved}"
                );
            }
            let alone = "gap = 0.001\nstiffness = 1e13\n";
            let alone = parse(
                "alone.toml",
                &row_text(model, alone)
                    .replace("restitution = 0.5", &format!("restitution = {eb}")),
            )
            .unwrap();
            let hard = run_row(&alone, &ground, &options).unwrap().pairs[0].impacts[0];
            let same = hard.separation_velocity / hard.approach_velocity;
            assert!(
                (achieved - same).abs() < 1e-9,
                "{model}, e_b = {eb}: {achieved} against {same}"
            );
        }
    }
}

#[test]
fn the_energy_balance_closes_with_links_and_bumpers() {
    let row = buildings::load("block-and-frame-retrofit").unwrap();
    let ground = record_ground(1.0);
    let duration = ground.end() + 2.0;
    let options = RowOptions {
        energy: true,
        ..RowOptions::lasting(duration)
    };
    let run = run_row(&row, &ground, &options).unwrap();
    let e = run.energy.unwrap();
    assert!(e.residual() < 1e-9, "residual {:e}", e.residual());
    assert!(e.link > 0.0 && e.bumper != 0.0, "{e:?}");
    assert!(run.bumpers.iter().map(|b| b.impacts.len()).sum::<usize>() > 0);
    // E_l against ∫ c|Δv|^(α+1) dt carried by the reference with its motion.
    let reference = reference_row(&row, &ground, duration, 1e-12);
    let (mine, theirs) = (run.links[0].energy, reference.link_energy[0]);
    assert!(
        (mine - theirs).abs() < 1e-8 * theirs,
        "E_l = {mine} against {theirs}"
    );
    // A linear dashpot without a spring does all its link work as dissipation.
    assert!((e.link - mine).abs() < 1e-8 * mine, "{} {mine}", e.link);
}

/// The row reversed and the record negated: the same peaks, bumper forces
/// and link forces, with a linear link (to 1e-12) and with a fluid viscous
/// damper of exponent 0.35 (to 1e-9: its adaptive steps see the mirrored
/// state's rounding, and its tolerance is 1e-12 a step). Floor peaks are
/// compared in the norm the reference tests hold the method to, each
/// building's largest peak: the two runs take different step sequences,
/// so a small peak carries the rounding of the building's scale, not its
/// own (the block's first floor, 9.3 mm, under a 0.145 m scale).
#[test]
fn the_mirror_image_gives_the_same_peaks_and_retrofit_forces() {
    for (exponent, tolerance) in [(1.0, 1e-12), (0.35, 1e-9)] {
        let row = buildings::load_with(
            "block-and-frame-retrofit",
            &[
                "joint1.bumper.floors=[2, 3]".into(),
                "link1.stiffness=5e6".into(),
                format!("link1.exponent={exponent}"),
            ],
        )
        .unwrap();
        let ground = record_ground(1.5);
        let options = RowOptions::lasting(ground.end() + 2.0);
        let a = run_row(&row, &ground, &options).unwrap();
        let b = run_row(&row.mirrored(), &ground.negated(), &options).unwrap();
        assert!(a.impacts() + a.bumpers.iter().map(|p| p.impacts.len()).sum::<usize>() > 5);
        let close = |p: f64, q: f64| (p - q).abs() <= tolerance * p.abs().max(1e-3);
        let mut worst = 0.0f64;
        for (fa, fb) in a.floors.iter().zip(b.floors.iter().rev()) {
            let largest = |f: fn(&FloorPeaks) -> f64| fa.iter().map(f).fold(0.0, f64::max);
            let (su, sa) = (
                largest(|x| x.displacement),
                largest(|x| x.absolute_acceleration),
            );
            for (x, y) in fa.iter().zip(fb) {
                let (du, da) = (
                    (x.displacement - y.displacement).abs() / su,
                    (x.absolute_acceleration - y.absolute_acceleration).abs() / sa,
                );
                assert!(
                    du <= tolerance && da <= tolerance,
                    "α = {exponent}: {du:e} {da:e}"
                );
                worst = worst.max(du).max(da);
            }
        }
        println!("α = {exponent}: floor peaks within {worst:e} of their building's largest");
        assert_eq!(a.bumpers.len(), 2);
        assert_eq!(b.bumpers.len(), 2);
        for (x, y) in a.bumpers.iter().zip(&b.bumpers) {
            assert_eq!(x.impacts.len(), y.impacts.len(), "α = {exponent}");
            assert!(
                close(x.max_force(), y.max_force()),
                "{} {}",
                x.max_force(),
                y.max_force()
            );
        }
        let (x, y) = (a.links[0], b.links[0]);
        assert!(close(x.max_force, y.max_force), "{x:?} {y:?}");
        assert!(close(x.stroke, y.stroke));
        assert!(close(x.max_rate, y.max_rate));
    }
}

/// The exact method against the reference with a bumper and a link, under
/// both laws of the Kelvin family: peaks within 1e-9 of each building's
/// largest, equal hard impacts and bumper contacts at every floor pair,
/// and the link's peak force.
#[test]
fn bumpers_and_links_match_the_reference() {
    for model in ["kelvin", "improved-kelvin"] {
        let row = buildings::load_with(
            "block-and-frame-retrofit",
            &[format!("model={model}"), "link1.stiffness=2e6".into()],
        )
        .unwrap();
        let ground = record_ground(1.5);
        let duration = ground.end() + 2.0;
        let exact = run_row(&row, &ground, &RowOptions::lasting(duration)).unwrap();
        let reference = reference_row(&row, &ground, duration, 1e-13);
        assert_eq!(impacts(&exact), reference.impacts, "{model}: impacts");
        let bumpers: Vec<usize> = exact.bumpers.iter().map(|p| p.impacts.len()).collect();
        assert_eq!(
            bumpers, reference.bumper_contacts,
            "{model}: bumper contacts"
        );
        assert!(bumpers.iter().sum::<usize>() > 0);
        let worst = against_reference(&exact, &reference);
        assert!(worst < 1e-9, "{model}: worst relative difference {worst:e}");
        println!("{model}: {worst:e}");
    }
}
