//! A row run's cost against the dense floor ([`pounding::accuracy::row_floor`]),
//! side by side in one process, with its profile: block-and-frame (3 + 8
//! storeys) under the simulated 2,000-sample record at scales 1, 2 and 3
//! (the frame yields from scale 2), under Kelvin and improved Kelvin
//! contact. `cargo bench --bench row_speed`; medians of repeated runs
//! after a warm-up. Last, the retrofitted row with its damper a fluid
//! viscous one (α = 0.35, SPEC §14) beside the bare row under the same
//! record, with its collocated steps' profile.

use pounding::accuracy::row_floor::RowFloor;
use pounding::accuracy::row_speed::row_speed;
use pounding::accuracy::timing::median_ms;
use pounding::model::ContactModel;
use pounding::model::buildings::matrices::default_tail;
use pounding::model::buildings::{self, Ground};
use pounding::model::simulated::Simulation;
use pounding::solver::buildings::profile::CAUSES;
use pounding::solver::buildings::{RowOptions, run_row};

fn main() {
    let record = Simulation::synthetic("synthetic:2000", 2000).expect("a record");
    let base = buildings::load("block-and-frame").expect("a shipped row");
    let duration = Ground::from_record(&record, 1.0).end() + default_tail(&base);
    let floor = RowFloor::new(&base, &Ground::from_record(&record, 1.0), duration);
    println!(
        "block-and-frame synthetic:2000, {duration:.3} s; floor: {} intervals of {} states; causes: {}",
        floor.intervals(),
        floor.states(),
        CAUSES.join(", ")
    );
    println!(
        "{:>5} {:>16} {:>8} {:>8} {:>6} {:>7} {:>6} {:>5} {:>5} {:>6} {:>5} {:>26} {:>26} {:>8} {:>8} {:>8}",
        "scale",
        "law",
        "ms",
        "floor",
        "×",
        "impacts",
        "map",
        "loc.",
        "held",
        "series",
        "maps",
        "sub-steps by cause",
        "series steps by cause",
        "map ms",
        "ser. ms",
        "exp ms"
    );
    for scale in [1.0, 2.0, 3.0] {
        let ground = Ground::from_record(&record, scale);
        for model in [ContactModel::Kelvin, ContactModel::ImprovedKelvin] {
            let row = buildings::Row {
                model,
                ..base.clone()
            };
            let s = row_speed(&row, &ground, duration).expect("runs");
            let p = &s.profile;
            let list = |c: &[usize]| {
                c.iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join("/")
            };
            println!(
                "{:>5} {:>16} {:>8.3} {:>8.3} {:>6.1} {:>7} {:>6} {:>5} {:>5} {:>6} {:>5} {:>26} {:>26} {:>8.3} {:>8.3} {:>8.3}",
                scale,
                format!("{model:?}"),
                s.ms,
                s.floor_ms,
                s.ratio,
                s.impacts,
                p.map_steps,
                p.located,
                p.held,
                p.series.total(),
                p.maps_made,
                list(&p.careful.0),
                list(&p.series.0),
                p.map_seconds * 1e3,
                p.series_seconds * 1e3,
                p.exponential_seconds * 1e3,
            );
        }
    }
    let damped = buildings::load_with("block-and-frame-retrofit", &["link1.exponent=0.35".into()])
        .expect("a shipped row");
    let ground = Ground::from_record(&record, 1.0);
    let options = RowOptions::lasting(duration);
    let (bare_ms, _) = median_ms(|| run_row(&base, &ground, &options).expect("runs"));
    let (damper_ms, _) = median_ms(|| run_row(&damped, &ground, &options).expect("runs"));
    let profiled = RowOptions {
        profile: true,
        ..options
    };
    let p = run_row(&damped, &ground, &profiled).expect("runs").profile;
    let c = &p.collocation;
    println!(
        "fluid viscous damper (block-and-frame-retrofit, α = 0.35), scale 1: {damper_ms:.3} ms against the bare row's {bare_ms:.3} ms, {:.1}×; collocated steps {} accepted, {} rejected, {} solves, {} Newton iterations, {} response sets; {} series steps with the damper's force in them",
        damper_ms / bare_ms,
        c.accepted,
        c.rejected,
        c.solves,
        c.newton,
        c.responses,
        c.series
    );
}
