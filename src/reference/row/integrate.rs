//! The reference run of a row: adaptive Dormand–Prince 5(4) from event to
//! event, one ground piece at a time (so that the right-hand side is smooth
//! inside every step). After each accepted step, every event function
//! (yield, unloading, contact onset, separation) is checked at its end; if
//! one turned positive, its first instant is found by bisection, each trial
//! a step retaken from the step's start, and the step is retaken to it.
//! Peaks of |u|, |u̇|, |Δ| and of the floors' absolute accelerations
//! |ü + ü_g| = |F/m| inside a step are found the same way, where the
//! quantity's rate changes sign (for the acceleration, its rate
//! [`Motion::jerk`]); the acceleration is also taken at both ends of every
//! step in the mode of the step, so that a force that jumps where a mode
//! switches (Kelvin's damping term at contact onset) counts on both sides.

use crate::model::ContactLaw;
use crate::model::buildings::contact::{kelvin_or_hertz, reduced_mass};
use crate::model::buildings::{Ground, Row};

use super::motion::{Mode, Motion};
use super::rk::step;

/// Peaks and impact counts of a reference run.
#[derive(Debug, Clone, PartialEq)]
pub struct RowReference {
    /// Per building, per floor: max |u|, max |u̇|, max |Δ| of the storey below.
    pub displacement: Vec<Vec<f64>>,
    pub velocity: Vec<Vec<f64>>,
    pub drift: Vec<Vec<f64>>,
    /// Per building, per floor: max |ü + ü_g| (m/s²).
    pub absolute_acceleration: Vec<Vec<f64>>,
    /// Impacts per floor pair (the row's pairs in order).
    pub impacts: Vec<usize>,
    /// Contacts per bumper element (SPEC §14), joint by joint, bottom to top.
    pub bumper_contacts: Vec<usize>,
    /// Per link (file order): max |F| (N) and E_l = ∫ c_l|Δv|^(α+1) dt (J).
    pub link_force: Vec<f64>,
    pub link_energy: Vec<f64>,
    /// Accepted steps.
    pub steps: usize,
    /// (building, 1-based storey, time in s) of a collapse (SPEC §15), where
    /// the run stopped.
    pub collapse: Option<(usize, usize, f64)>,
}

/// Largest step (s): no event or turning point hides in one.
const MAX_STEP: f64 = 2e-3;

/// Runs the reference on `row` under `ground` for `duration` seconds, with
/// local error tolerance `tolerance` (absolute in m and m/s, and relative).
pub fn reference_row(row: &Row, ground: &Ground, duration: f64, tolerance: f64) -> RowReference {
    let motion = Motion::new(row, ground);
    let n = motion.n;
    let mut mode = Mode {
        branch: vec![0; motion.storeys.len()],
        plastic: vec![0.0; motion.storeys.len()],
        laws: vec![None; motion.pairs.len()],
        turn: vec![0.0; motion.links.len()],
    };
    let size = 2 * n + motion.links.len();
    // u = 0, and u̇ = −u̇_g(0): the floors stand still while the ground,
    // under a type B pulse, starts moving (SPEC §9).
    let mut y = vec![0.0; size];
    for v in &mut y[n..2 * n] {
        *v = -ground.initial_velocity();
    }
    let mut peak_u = vec![0.0f64; n];
    let mut peak_v: Vec<f64> = y[n..2 * n].iter().map(|v| v.abs()).collect();
    let mut peak_f = vec![0.0f64; motion.links.len()];
    let mut peak_d = vec![0.0f64; motion.storeys.len()];
    let mut peak_a = vec![0.0f64; n];
    let mut impacts = vec![0; motion.pairs.len()];
    let mut steps = 0;
    let mut h: f64 = 1e-4;
    let mut collapse = None;
    'pieces: for piece in ground.pieces(duration) {
        let mut t = piece.t0;
        while t < piece.t1 {
            let f = |tt: f64, yy: &[f64], out: &mut [f64]| motion.rhs(&mode, tt, yy, out);
            let hh = h.min(piece.t1 - t).min(MAX_STEP);
            let (y1, err) = step(&f, t, &y, hh);
            let norm = (0..size)
                .map(|i| {
                    let s = tolerance * (1.0 + y[i].abs().max(y1[i].abs()));
                    (err[i] / s).powi(2)
                })
                .sum::<f64>()
                .sqrt()
                / (size as f64).sqrt();
            if norm > 1.0 {
                h = hh * (0.9 * norm.powf(-0.2)).max(0.2);
                continue;
            }
            // Accepted: is there an event inside?
            let armed: Vec<bool> = events(&motion, &mode, &y)
                .iter()
                .map(|&g| g <= 0.0)
                .collect();
            let fires = |yy: &[f64]| {
                events(&motion, &mode, yy)
                    .iter()
                    .zip(&armed)
                    .any(|(&g, &a)| a && g > 0.0)
            };
            let (mut end, mut y_end) = (hh, y1.clone());
            if fires(&y1) {
                let (mut lo, mut hi) = (0.0, hh);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if fires(&step(&f, t, &y, mid).0) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                end = hi;
                y_end = step(&f, t, &y, hi).0;
            }
            // Turning points inside [t, t + end].
            let mut f0 = vec![0.0; size];
            let mut f1 = vec![0.0; size];
            f(t, &y, &mut f0);
            f(t + end, &y_end, &mut f1);
            let locate = |rate: &dyn Fn(&[f64], &[f64]) -> f64, value: &dyn Fn(&[f64]) -> f64| {
                let (r0, r1) = (rate(&y, &f0), rate(&y_end, &f1));
                if (r0 > 0.0) == (r1 > 0.0) {
                    return 0.0;
                }
                let (mut lo, mut hi) = (0.0, end);
                let mut fy = vec![0.0; size];
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    let ym = step(&f, t, &y, mid).0;
                    f(t + mid, &ym, &mut fy);
                    if (rate(&ym, &fy) > 0.0) == (r0 > 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                value(&step(&f, t, &y, 0.5 * (lo + hi)).0).abs()
            };
            for i in 0..n {
                let u_i = |yy: &[f64]| yy[i];
                let v_i = |yy: &[f64], _: &[f64]| yy[n + i];
                peak_u[i] = peak_u[i].max(y_end[i].abs()).max(locate(&v_i, &u_i));
                let w_i = |yy: &[f64]| yy[n + i];
                let a_i = |_: &[f64], ff: &[f64]| ff[n + i];
                peak_v[i] = peak_v[i].max(y_end[n + i].abs()).max(locate(&a_i, &w_i));
            }
            let (start, stop) = (motion.forces(&mode, &y), motion.forces(&mode, &y_end));
            for i in 0..n {
                let m = motion.mass[i];
                let a_i = |yy: &[f64]| motion.forces(&mode, yy)[i] / m;
                let j_i = |yy: &[f64], ff: &[f64]| motion.jerk(&mode, i, yy, ff);
                peak_a[i] = peak_a[i]
                    .max((start[i] / m).abs())
                    .max((stop[i] / m).abs())
                    .max(locate(&j_i, &a_i));
            }
            for (k, s) in motion.storeys.iter().enumerate() {
                let d = |yy: &[f64]| motion.drift(s, &yy[..n]);
                let r = |yy: &[f64], _: &[f64]| motion.drift(s, &yy[n..2 * n]);
                peak_d[k] = peak_d[k].max(d(&y_end).abs()).max(locate(&r, &d));
            }
            for (k, l) in motion.links.iter().enumerate() {
                let force = |yy: &[f64]| {
                    l.force(yy[l.left] - yy[l.right], yy[n + l.left] - yy[n + l.right])
                };
                let rate = |yy: &[f64], ff: &[f64]| motion.link_rate(l, yy, ff);
                peak_f[k] = peak_f[k]
                    .max(force(&y).abs())
                    .max(force(&y_end).abs())
                    .max(locate(&rate, &force));
            }
            // Switch the mode where an event fired.
            if end < hh {
                let g = events(&motion, &mode, &y_end);
                let ns = motion.storeys.len();
                let np = motion.pairs.len();
                let nc = ns + np + motion.storeys.len();
                for (j, (&gj, &a)) in g.iter().zip(&armed).enumerate() {
                    if !(a && gj > 0.0) {
                        continue;
                    }
                    if j >= nc {
                        mode.turn[j - nc] = -mode.turn[j - nc];
                    } else if j >= ns + np {
                        let s = &motion.storeys[j - ns - np];
                        collapse = Some((s.building, s.storey, t + end));
                    } else if j < ns {
                        let s = &motion.storeys[j];
                        let d = motion.drift(s, &y_end[..n]);
                        if mode.branch[j] == 0 {
                            mode.branch[j] = if d - mode.plastic[j] > 0.0 { 1 } else { -1 };
                        } else {
                            let z = f64::from(mode.branch[j]) * s.yield_drift;
                            mode.plastic[j] = d - z;
                            mode.branch[j] = 0;
                        }
                    } else {
                        let pi = j - ns;
                        let p = &motion.pairs[pi];
                        if mode.laws[pi].is_some() {
                            mode.laws[pi] = None;
                        } else {
                            let v0 = y_end[n + p.left_dof] - y_end[n + p.right_dof];
                            mode.laws[pi] = Some(law(row, &motion, pi, v0));
                            impacts[pi] += 1;
                        }
                    }
                }
            }
            // A damper's sign, once its Δv has one: the kink where Δv
            // next changes sign is an event.
            for (turn, l) in mode.turn.iter_mut().zip(&motion.links) {
                let dv = y_end[n + l.left] - y_end[n + l.right];
                if *turn == 0.0 && l.exponent < 1.0 && dv != 0.0 {
                    *turn = dv.signum();
                }
            }
            t = if end >= piece.t1 - t {
                piece.t1
            } else {
                t + end
            };
            y = y_end;
            steps += 1;
            if collapse.is_some() {
                break 'pieces;
            }
            h = hh * (0.9 * norm.max(1e-10).powf(-0.2)).min(5.0);
        }
    }
    let offsets = row.offsets();
    let split = |v: &[f64]| -> Vec<Vec<f64>> {
        row.buildings
            .iter()
            .zip(&offsets)
            .map(|(b, &o)| v[o..o + b.storeys()].to_vec())
            .collect()
    };
    let bumper_contacts = impacts.split_off(motion.hard);
    RowReference {
        bumper_contacts,
        link_force: peak_f,
        link_energy: y[2 * n..].to_vec(),
        displacement: split(&peak_u),
        velocity: split(&peak_v),
        drift: split(&peak_d),
        absolute_acceleration: split(&peak_a),
        impacts,
        steps,
        collapse,
    }
}

/// Event functions (an event where one turns positive): per storey, then
/// per pair, then per storey its collapse, |Δ| − Δ_c (SPEC §15).
fn events(motion: &Motion, mode: &Mode, y: &[f64]) -> Vec<f64> {
    let n = motion.n;
    let mut g = Vec::with_capacity(motion.storeys.len() + motion.pairs.len());
    for (i, s) in motion.storeys.iter().enumerate() {
        let d = motion.drift(s, &y[..n]);
        let rate = motion.drift(s, &y[n..]);
        g.push(match mode.branch[i] {
            0 => (d - mode.plastic[i]).abs() - s.yield_drift,
            b => -f64::from(b) * rate,
        });
    }
    for ((p, law), &gap) in motion.pairs.iter().zip(&mode.laws).zip(&motion.gaps) {
        let delta = y[p.left_dof] - y[p.right_dof] - gap;
        g.push(if law.is_some() { -delta } else { delta });
    }
    for s in &motion.storeys {
        g.push(motion.drift(s, &y[..n]).abs() - s.collapse_drift);
    }
    for (l, &turn) in motion.links.iter().zip(&mode.turn) {
        g.push(-turn * (y[n + l.left] - y[n + l.right]));
    }
    g
}

/// The law of contact element `pi` (a joint's own or a bumper's) begun at
/// approach velocity v0, from its own stiffness and restitution.
fn law(row: &Row, motion: &Motion, pi: usize, v0: f64) -> ContactLaw {
    let (k, e) = motion.laws[pi];
    let m_bar = reduced_mass(row, &motion.pairs[pi]);
    kelvin_or_hertz(row, k, e, m_bar, v0)
}
