use std::cell::RefCell;

use super::Contact;
use crate::solver::buildings::config::Config;
use crate::solver::buildings::damper_collocation::Collocation;
use crate::solver::buildings::damper_collocation::tests::retrofit;

/// A collocated step so short that its basis in powers of 1/h overflows
/// (h = 1e-79: h⁻⁷ is past f64's range) is no step: [`Contact::retake`],
/// as an event placed next to a step's start asks for, falls back to
/// another method and returns a finite end, where it used to return NaN
/// and send the event's Newton's method a second past the step; and the
/// next step from the same start, 1 ms long, is collocated and finite,
/// its Newton's method not started from the short step's forces. On
/// block-and-frame-retrofit with its damper at α = 0.35, sliding at
/// Δv = 0.2 m/s under a constant ground.
#[test]
fn a_step_too_short_for_the_collocation_falls_back() {
    let (layout, system, dampers) = retrofit();
    let config = Config::at_rest(layout.storeys.len(), layout.pairs.len());
    let n = layout.dofs;
    let mut y0 = vec![0.0; 2 * n];
    y0[n + dampers[0].left] = 0.2;
    let ground = |_: f64| (0.5, 0.0, 0.0);
    let cache = RefCell::new(Collocation::default());
    let contact =
        Contact::new(&layout, &config, &system, |_| 0.5).with_collocation(&cache, &ground);
    let f0 = contact.rate(0.0, &y0);
    let scale = (1e-3, 0.2);
    let tiny = 1e-79;
    assert!(
        contact
            .collocated((&y0, &f0), (tiny, false), scale)
            .is_none()
    );
    let step = contact.retake((&y0, &f0), tiny, scale.1);
    assert!(step.y1.iter().all(|x| x.is_finite()), "{:?}", step.y1);
    let worst = step
        .y1
        .iter()
        .zip(&y0)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-60, "the retake moved the state by {worst:e}");
    let normal = contact
        .collocated((&y0, &f0), (1e-3, false), scale)
        .expect("collocates");
    assert!(normal.y1.iter().all(|x| x.is_finite()));
}
