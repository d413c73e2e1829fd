//! The explorer's risk scene on a row (SPEC §12 with §13): block-and-frame,
//! pounding counted at its joint, records scaled to Sa at the frame's T1,
//! at the scene's default design level. The time from the request to the
//! full picture (the coarse pass, then every record at every level), as
//! the scene's worker makes it ([`run_risk`]), is printed as the median of
//! three runs after a warm-up. `cargo bench --bench row_risk`

use std::cell::Cell;
use std::time::Instant;

use pounding::accuracy::timing::median;
use pounding::model::buildings;
use pounding::tui::risk_job::{DESIGN_LEVEL, RiskOutput, row_spec, run_risk};

fn main() {
    let row = buildings::load("block-and-frame").expect("a shipped row");
    let spec = row_spec(&row, 0, DESIGN_LEVEL, false);
    let full = |first: &Cell<f64>, start: Instant| {
        let done = Cell::new(false);
        run_risk(&spec, &|| true, &|out| match out {
            RiskOutput::Picture { full, .. } => {
                if first.get() == 0.0 {
                    first.set(start.elapsed().as_secs_f64());
                }
                done.set(done.get() || full);
            }
            RiskOutput::Error(e) => panic!("{e}"),
        });
        assert!(done.get(), "no full picture");
    };
    full(&Cell::new(0.0), Instant::now());
    let (mut total, mut coarse) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        let first = Cell::new(0.0);
        let start = Instant::now();
        full(&first, start);
        total.push(start.elapsed().as_secs_f64());
        coarse.push(first.get());
    }
    println!(
        "row risk scene (block-and-frame, joint 1, {} g): first picture {:.3} s, full picture {:.3} s (medians of 3)",
        DESIGN_LEVEL,
        median(coarse),
        median(total)
    );
}
