//! Newmark-β for a row (SPEC §5 and §13): γ = ½, β = ¼, Newton on the whole
//! row each step with the consistent tangent (storeys' return-map tangents,
//! the contact tangent ∂f/∂δ + γ/(βΔt) ∂f/∂δ̇), and every contact onset and
//! separation located inside its step and the step split there, so that
//! the method stays second order and v₀ is the onset's own. A collapse
//! (SPEC §15) is located the same way, and the run stops there.
//!
//! With u the unknown at t_{n+1}:
//!
//! ```text
//! ü_{n+1} = (u − u_n)/(βΔt²) − u̇_n/(βΔt) − (1/(2β) − 1) ü_n,
//! u̇_{n+1} = u̇_n + Δt((1 − γ) ü_n + γ ü_{n+1}),
//! R(u) = M ü_{n+1} + C u̇_{n+1} + F_s(u) ± f_p + M 1 ü_g(t_{n+1}) = 0.
//! ```

use nalgebra::{DMatrix, DVector};

use crate::model::buildings::contact::{element_law, reduced_mass};
use crate::model::buildings::matrices::{RowMatrices, periods};
use crate::model::buildings::retrofit::{dashpot_velocity, dashpot_velocity_slope};
use crate::model::buildings::{Ground, Row};
use crate::model::params::echo;
use crate::model::params::table::STEPS_PER_PERIOD;
use crate::model::{Bilinear, ContactLaw, SpringState};

use super::driver::RowError;
use super::layout::Layout;
use super::link::{self, LinkResult};
use super::peaks::{Envelope, raise};
use super::result::{Collapse, FloorPeaks, PairImpact, PairResult, RowRun};

const GAMMA: f64 = 0.5;
const BETA: f64 = 0.25;

/// Where one Newmark step ends.
#[derive(Clone)]
struct Point {
    t: f64,
    u: DVector<f64>,
    v: DVector<f64>,
    a: DVector<f64>,
    springs: Vec<SpringState>,
}

struct Newmark<'a> {
    ground: &'a Ground,
    layout: Layout,
    mass: DVector<f64>,
    damping: DMatrix<f64>,
    springs: Vec<Bilinear>,
    laws: Vec<Option<ContactLaw>>,
}

impl Newmark<'_> {
    /// Storey forces on the floors, their tangent, and the trial spring states.
    fn storeys(
        &self,
        p: &Point,
        u: &DVector<f64>,
        f: &mut DVector<f64>,
        k: &mut DMatrix<f64>,
    ) -> Vec<SpringState> {
        let mut out = Vec::with_capacity(self.springs.len());
        for ((s, b), from) in self
            .layout
            .storeys
            .iter()
            .zip(&self.springs)
            .zip(&p.springs)
        {
            let d = u[s.upper] - s.lower.map_or(0.0, |l| u[l]);
            let r = b.respond(*from, d);
            // P-Δ (SPEC §15): the storey loses (P/h)Δ of its shear.
            let force = r.force - s.geometric * d;
            let tangent = r.tangent - s.geometric;
            f[s.upper] += force;
            k[(s.upper, s.upper)] += tangent;
            if let Some(l) = s.lower {
                f[l] -= force;
                k[(l, l)] += tangent;
                k[(l, s.upper)] -= tangent;
                k[(s.upper, l)] -= tangent;
            }
            out.push(r.state);
        }
        out
    }

    /// The links' forces on the floors (SPEC §14) and their tangent: the
    /// spring k_l Δu of every link, and the linear dashpot c_l Δv (tangent
    /// γ/(βΔt) c_l). A fluid viscous damper's dashpot (α < 1) is not here:
    /// [`Self::step`] carries its force as an unknown of its own.
    fn links(
        &self,
        u: &DVector<f64>,
        v: &DVector<f64>,
        c2: f64,
        f: &mut DVector<f64>,
        k: &mut DMatrix<f64>,
    ) {
        for l in &self.layout.links {
            let (i, j) = (l.pair.left_dof, l.pair.right_dof);
            let linear = l.is_linear();
            let force = l.link.stiffness * (u[i] - u[j])
                + if linear {
                    l.link.damping * (v[i] - v[j])
                } else {
                    0.0
                };
            let kt = l.link.stiffness + if linear { c2 * l.link.damping } else { 0.0 };
            f[i] += force;
            f[j] -= force;
            k[(i, i)] += kt;
            k[(j, j)] += kt;
            k[(i, j)] -= kt;
            k[(j, i)] -= kt;
        }
    }

    /// The residual f(u) of the step from `p` to p.t + dt at the trial
    /// displacements `u` (Newmark's a and u̇ from u), its tangent, and u̇.
    fn residual(
        &self,
        p: &Point,
        u: &DVector<f64>,
        dt: f64,
    ) -> (DVector<f64>, DMatrix<f64>, DVector<f64>) {
        let n = self.layout.dofs;
        let ag = self.ground.at(p.t + dt);
        let c1 = 1.0 / (BETA * dt * dt);
        let c2 = GAMMA / (BETA * dt);
        let a = c1 * (u - &p.u) - &p.v / (BETA * dt) - (0.5 / BETA - 1.0) * &p.a;
        let v = &p.v + dt * ((1.0 - GAMMA) * &p.a + GAMMA * &a);
        let mut f = self.mass.component_mul(&a) + &self.damping * &v;
        let mut k = c2 * &self.damping;
        for i in 0..n {
            f[i] += self.mass[i] * ag;
            k[(i, i)] += c1 * self.mass[i];
        }
        self.storeys(p, u, &mut f, &mut k);
        self.links(u, &v, c2, &mut f, &mut k);
        for ((pair, law), &gap) in self
            .layout
            .pairs
            .iter()
            .zip(&self.laws)
            .zip(&self.layout.gaps)
        {
            let Some(law) = law else { continue };
            let (i, j) = (pair.left_dof, pair.right_dof);
            let c = law.force(u[i] - u[j] - gap, v[i] - v[j]);
            let kt = c.d_penetration + c2 * c.d_rate;
            f[i] += c.force;
            f[j] -= c.force;
            k[(i, i)] += kt;
            k[(j, j)] += kt;
            k[(i, j)] -= kt;
            k[(j, i)] -= kt;
        }
        (f, k, v)
    }

    /// One step from `p` to p.t + dt with the current contact laws, by
    /// Newton's method on [`Self::residual`].
    ///
    /// A fluid viscous damper (α < 1) would put its slope c_l α|Δv|^(α−1)
    /// into the tangent, which has no bound as Δv → 0; and from rest Δv
    /// starts at 0, where Newton's steps on u overshoot by orders of
    /// magnitude. So each damper's force F_d is an unknown beside u, with
    /// its law written the other way round,
    ///
    /// ```text
    /// Δv(u) − sgn(F_d) |F_d/c_l|^(1/α) = 0,
    /// ```
    ///
    /// whose slope (1/(c_l α)) |F_d/c_l|^(1/α − 1) is bounded and
    /// continuous (1/α > 1): the tangent of the mixed system is a saddle
    /// point matrix, regular also at F_d = 0, and neither the force nor
    /// its slope is regularised. The law's row is scaled by m/(βΔt)·(β/γ)
    /// to the size of the floors' rows.
    fn step(&self, p: &Point, dt: f64) -> Result<Point, RowError> {
        let n = self.layout.dofs;
        let t = p.t + dt;
        let c1 = 1.0 / (BETA * dt * dt);
        let c2 = GAMMA / (BETA * dt);
        let mut u = &p.u + dt * &p.v + 0.5 * dt * dt * &p.a;
        let scale = p.u.amax().max(1e-6);
        let dampers: Vec<_> = self
            .layout
            .links
            .iter()
            .filter(|l| !l.is_linear())
            .collect();
        let nd = dampers.len();
        // Each damper's force at the start of the step.
        let mut forces: Vec<f64> = dampers
            .iter()
            .map(|l| {
                let (i, j) = (l.pair.left_dof, l.pair.right_dof);
                let dv = p.v[i] - p.v[j];
                l.link.damping * dv.abs().powf(l.link.exponent) * dv.signum()
            })
            .collect();
        for _ in 0..100 {
            let (mut f, k, v) = self.residual(p, &u, dt);
            let (du, df) = if nd == 0 {
                (
                    k.lu().solve(&(-&f)).ok_or(RowError::Unconverged(t))?,
                    Vec::new(),
                )
            } else {
                let mut big = DMatrix::<f64>::zeros(n + nd, n + nd);
                big.view_mut((0, 0), (n, n)).copy_from(&k);
                let mut r = DVector::<f64>::zeros(n + nd);
                for (d, (l, &fd)) in dampers.iter().zip(&forces).enumerate() {
                    let (i, j) = (l.pair.left_dof, l.pair.right_dof);
                    let (c, alpha) = (l.link.damping, l.link.exponent);
                    let row = n + d;
                    let w = c1 * self.mass[i].max(self.mass[j]) / c2;
                    f[i] += fd;
                    f[j] -= fd;
                    big[(i, row)] = 1.0;
                    big[(j, row)] = -1.0;
                    r[row] = w * ((v[i] - v[j]) - dashpot_velocity(c, alpha, fd));
                    big[(row, i)] = w * c2;
                    big[(row, j)] = -w * c2;
                    big[(row, row)] = -w * dashpot_velocity_slope(c, alpha, fd);
                }
                r.rows_mut(0, n).copy_from(&f);
                let z = big.lu().solve(&(-r)).ok_or(RowError::Unconverged(t))?;
                (
                    z.rows(0, n).into_owned(),
                    z.iter().skip(n).copied().collect(),
                )
            };
            u += &du;
            for (fd, d) in forces.iter_mut().zip(&df) {
                *fd += d;
            }
            if du.amax() <= 1e-13 * scale.max(u.amax()) {
                let a = c1 * (&u - &p.u) - &p.v / (BETA * dt) - (0.5 / BETA - 1.0) * &p.a;
                let v = &p.v + dt * ((1.0 - GAMMA) * &p.a + GAMMA * &a);
                // The accepted spring states, at the converged displacements.
                let springs =
                    self.storeys(p, &u, &mut DVector::zeros(n), &mut DMatrix::zeros(n, n));
                return Ok(Point {
                    t,
                    u,
                    v,
                    a,
                    springs,
                });
            }
        }
        Err(RowError::Unconverged(t))
    }

    /// δ of every pair at a point.
    fn penetration(&self, p: &Point, i: usize) -> (f64, f64) {
        let pair = &self.layout.pairs[i];
        (
            p.u[pair.left_dof] - p.u[pair.right_dof] - self.layout.gaps[i],
            p.v[pair.left_dof] - p.v[pair.right_dof],
        )
    }

    /// The first pair whose contact state changes in (p, q], and the fraction θ
    /// of the step where it does (the root of the cubic Hermite of δ).
    fn change(&self, p: &Point, q: &Point, dt: f64) -> Option<(usize, f64)> {
        let mut first: Option<(usize, f64)> = None;
        for i in 0..self.layout.pairs.len() {
            let (d0, r0) = self.penetration(p, i);
            let (d1, r1) = self.penetration(q, i);
            let closed = self.laws[i].is_some();
            let crosses = if closed { d1 <= 0.0 } else { d1 > 0.0 };
            if !crosses {
                continue;
            }
            let sign = if closed { -1.0 } else { 1.0 };
            let hi = first_rise((sign * d0, sign * r0), (sign * d1, sign * r1), dt);
            if first.is_none_or(|(_, th)| hi < th) {
                first = Some((i, hi));
            }
        }
        first
    }

    /// The first storey of a building with P-Δ whose |Δ| reaches its
    /// collapse drift in (p, q] (SPEC §15), and the fraction θ of the step
    /// where it does (the root of the cubic Hermite of ±Δ − Δ_c).
    fn collapse(&self, p: &Point, q: &Point, dt: f64) -> Option<(usize, f64)> {
        let mut first: Option<(usize, f64)> = None;
        for (k, s) in self.layout.storeys.iter().enumerate() {
            let c = s.collapse_drift;
            let d1 = self.layout.drift(s, q.u.as_slice());
            if d1.abs() < c || d1.is_nan() {
                continue;
            }
            let sign = d1.signum();
            let d0 = sign * self.layout.drift(s, p.u.as_slice()) - c;
            let r0 = sign * self.layout.drift(s, p.v.as_slice());
            let r1 = sign * self.layout.drift(s, q.v.as_slice());
            let th = first_rise((d0, r0), (sign * d1 - c, r1), dt);
            if first.is_none_or(|(_, at)| th < at) {
                first = Some((k, th));
            }
        }
        first
    }
}

/// The fraction θ ∈ (0, 1] of a step of length `dt` where the cubic
/// Hermite through (g, ġ) at its two ends first turns positive, g(0) ≤ 0 <
/// g(1), by bisection.
fn first_rise((d0, r0): (f64, f64), (d1, r1): (f64, f64), dt: f64) -> f64 {
    let h = |th: f64| {
        let (h00, h10, h01, h11) = (
            2.0 * th.powi(3) - 3.0 * th * th + 1.0,
            th.powi(3) - 2.0 * th * th + th,
            -2.0 * th.powi(3) + 3.0 * th * th,
            th.powi(3) - th * th,
        );
        h00 * d0 + h10 * dt * r0 + h01 * d1 + h11 * dt * r1
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if h(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// Newmark's default step for a run of `row` lasting `duration` seconds
/// under `ground` (s).
///
/// The average-acceleration rule lengthens every period by (ωΔt)²/12, so the
/// phase a mode loses by time t, and with it the error of a peak at t, grows
/// as Δt²·t: over a long record it is this drift, not the local error, that
/// sets the accuracy. The default keeps the drift of 5e-5 s over 10 s,
///
/// ```text
/// Δt = 5e-5 s · √(10 s / duration),  at most 5e-5 s,
/// ```
///
/// halved on a row with a fluid viscous damper (α < 1, SPEC §14): its force
/// c|Δv|^α sgn Δv has an unbounded slope at each reversal of Δv, so the
/// acceleration of the floors it joins has a cusp there, and a peak read at
/// the steps' ends misses it by more than the drift (measured on the
/// retrofitted block-and-frame row with α = 0.35 under `synthetic:2000`:
/// the block's roof acceleration 1.7e-5 off at 4.1e-5 s, 7.8e-6 at half
/// that, 2.0e-6 at a quarter, every other peak within 7.5e-7);
///
/// shortened under a record so that a whole number of steps fills each
/// sample interval: a step that straddles a sample misses the kink of the
/// piecewise-linear ground and costs first order (measured: 1.3e-3 at
/// Δt = 2.37e-5 s under a DT = 5 ms record, against 3.8e-5 at 5e-5 s).
pub fn default_step(row: &Row, duration: f64, ground: &Ground) -> f64 {
    const STEP: f64 = 5e-5;
    const OVER: f64 = 10.0;
    let mut step = if duration > OVER {
        STEP * (OVER / duration).sqrt()
    } else {
        STEP
    };
    if row.has_fluid_damper() {
        step *= 0.5;
    }
    match ground {
        Ground::Samples { dt, .. } if *dt > 0.0 && dt.is_finite() => dt / (dt / step).ceil(),
        _ => step,
    }
}

/// The longest step Newmark may take on `row` under `ground` (s), and what
/// sets it, for a message. As for the pair (`Params::validate`, SPEC §5),
/// at least [`STEPS_PER_PERIOD`] steps per period of the motion (a sine's
/// or a pulse's 2π/ω), of every mode of every building and, for the
/// linear laws of the Kelvin family, of every floor pair's contact element
/// 2π/√(k̄/m̄) (the Hertz-type laws have no one period); under a record, at
/// most its sample interval too, so that a step straddles no more than one
/// kink of the piecewise-linear ground. Average acceleration is stable at
/// any step, but a step beyond these misses the response it is asked for,
/// and Newton on a contact it cannot resolve stops converging: on the
/// block-and-frame row (contact period 19 ms) under the synthetic record,
/// Δt = 5 ms fails at its first hard impact (1.55 s), where it should be
/// refused.
pub fn max_step(row: &Row, ground: &Ground) -> (f64, String) {
    let (mut shortest, mut whose) = (f64::INFINITY, String::new());
    let mut shorter = |t: f64, what: &dyn Fn() -> String| {
        if t < shortest {
            (shortest, whose) = (t, what());
        }
    };
    for b in &row.buildings {
        let t = *periods(b).last().expect("a building has a storey");
        shorter(t, &|| format!("building `{}`", b.name));
    }
    if !row.model.is_hertzian() {
        for e in row.contact_elements() {
            let pair = e.pair;
            let t = std::f64::consts::TAU / (e.stiffness / reduced_mass(row, &pair)).sqrt();
            let what = if e.thickness.is_some() {
                "bumper"
            } else {
                "contact"
            };
            shorter(t, &|| format!("the {what} of {}", row.pair_name(&pair)));
        }
    }
    for l in row
        .link_elements()
        .iter()
        .filter(|l| l.link.stiffness > 0.0)
    {
        let pair = l.pair;
        let t = std::f64::consts::TAU / (l.link.stiffness / reduced_mass(row, &pair)).sqrt();
        shorter(t, &|| format!("the link of {}", row.pair_name(&pair)));
    }
    if let Ground::Sine { omega, .. } = ground {
        shorter(std::f64::consts::TAU / omega, &|| "the motion".to_string());
    }
    let by_period = shortest / STEPS_PER_PERIOD;
    let why = format!(
        "{STEPS_PER_PERIOD} steps per shortest period, {} s of {whose}",
        echo::g4(shortest)
    );
    match ground {
        Ground::Samples { dt, .. } if *dt < by_period => (
            *dt,
            format!(
                "the record's sample interval; {why} allows {}",
                echo::g4(by_period)
            ),
        ),
        _ => (by_period, why),
    }
}

/// Runs Newmark with step `dt` on `row` under `ground` for `duration` seconds.
pub fn run_newmark(row: &Row, ground: &Ground, duration: f64, dt: f64) -> Result<RowRun, RowError> {
    let layout = Layout::of(row);
    let m = RowMatrices::of(row);
    let n = layout.dofs;
    let springs = layout
        .storeys
        .iter()
        .map(|s| Bilinear {
            stiffness: s.stiffness,
            yield_displacement: s.yield_drift,
            alpha: s.alpha,
        })
        .collect();
    let mut nm = Newmark {
        ground,
        mass: m.mass.clone(),
        damping: m.damping.clone(),
        springs,
        laws: vec![None; layout.pairs.len()],
        layout,
    };
    // At rest on the ground, or against it when the ground starts moving
    // (SPEC §9, type B pulse): u̇(0) = −u̇_g(0), ü(0) = −M⁻¹C u̇(0) − ü_g(0).
    let v0 = DVector::from_element(n, -ground.initial_velocity());
    let a0 =
        -(&nm.damping * &v0).component_div(&nm.mass) - DVector::from_element(n, ground.at(0.0));
    let mut p = Point {
        t: 0.0,
        u: DVector::zeros(n),
        v: v0,
        a: a0,
        springs: vec![SpringState::default(); nm.layout.storeys.len()],
    };
    let mut env = Envelope::new(n, nm.layout.storeys.len(), nm.layout.facing.len());
    let mut pairs = vec![PairResult::default(); nm.layout.pairs.len()];
    let mut links = vec![LinkResult::new(); nm.layout.links.len()];
    // E_l by the trapezoidal rule on the steps (second order, as the method).
    let mut power = vec![0.0; nm.layout.links.len()];
    let mut last_t = 0.0;
    let steps = (duration / dt).ceil().max(1.0) as usize;
    let h = duration / steps as f64;
    let mut record = |p: &Point, nm: &Newmark, pairs: &mut [PairResult]| {
        let ag = ground.at(p.t);
        link::record_point(&nm.layout.links, p.u.as_slice(), p.v.as_slice(), &mut links);
        for ((l, r), w) in nm.layout.links.iter().zip(&mut links).zip(&mut power) {
            let now = l.dissipation(p.v[l.pair.left_dof] - p.v[l.pair.right_dof]);
            r.energy = r.energy.max(0.0) + 0.5 * (p.t - last_t) * (*w + now);
            *w = now;
        }
        last_t = p.t;
        for i in 0..n {
            raise(&mut env.displacement[i], p.u[i]);
            raise(&mut env.velocity[i], p.v[i]);
            raise(&mut env.acceleration[i], p.a[i] + ag);
        }
        for (k, s) in nm.layout.storeys.iter().enumerate() {
            raise(&mut env.drift[k], nm.layout.drift(s, p.u.as_slice()));
        }
        for (k, f) in nm.layout.facing.iter().enumerate() {
            env.relative[k] = env.relative[k].max(p.u[f.left_dof] - p.u[f.right_dof]);
        }
        for (i, law) in nm.laws.iter().enumerate() {
            if let (Some(law), Some(last)) = (law, pairs[i].impacts.last_mut()) {
                let (d, r) = nm.penetration(p, i);
                last.max_penetration = last.max_penetration.max(d);
                last.max_force = last.max_force.max(law.force(d, r).force);
            }
        }
    };
    record(&p, &nm, &mut pairs);
    // The motion's end, where ü_g drops to 0 (a pulse's end jumps), is a
    // step's end too, so that no step straddles the jump.
    let motion_end = ground.end();
    let mut ended = !(motion_end > 0.0 && motion_end < duration);
    let mut collapse = None;
    'steps: for k in 0..steps {
        let step_end = if k + 1 == steps {
            duration
        } else {
            (k + 1) as f64 * h
        };
        let mut t_end = step_end;
        if !ended && motion_end <= step_end {
            t_end = motion_end;
        }
        // Split the step at each contact change inside it.
        for _ in 0..1000 {
            if !ended && p.t >= motion_end {
                // ü = M⁻¹F − ü_g: the same forces, without the ground.
                p.a.add_scalar_mut(ground.at(motion_end));
                ended = true;
                t_end = step_end;
            }
            let dt = t_end - p.t;
            if dt <= 1e-15 * t_end.max(1.0) {
                break;
            }
            let q = nm.step(&p, dt)?;
            let contact = nm.change(&p, &q, dt);
            if let Some((storey, theta)) = nm.collapse(&p, &q, dt)
                && contact.is_none_or(|(_, at)| theta <= at)
            {
                p = nm.step(&p, theta * dt)?;
                record(&p, &nm, &mut pairs);
                let (building, storey) = nm.layout.building_storey(storey);
                collapse = Some(Collapse {
                    building,
                    storey,
                    time: p.t,
                });
                break 'steps;
            }
            match contact {
                None => {
                    p = q;
                    record(&p, &nm, &mut pairs);
                    if t_end == step_end {
                        break;
                    }
                }
                Some((i, theta)) => {
                    p = nm.step(&p, theta * dt)?;
                    record(&p, &nm, &mut pairs);
                    let (_, rate) = nm.penetration(&p, i);
                    if nm.laws[i].is_some() {
                        nm.laws[i] = None;
                        if let Some(last) = pairs[i].impacts.last_mut() {
                            last.end = p.t;
                            last.separation_velocity = -rate;
                        }
                    } else {
                        nm.laws[i] = Some(element_law(row, &nm.layout.elements[i], rate));
                        pairs[i].impacts.push(PairImpact {
                            start: p.t,
                            end: f64::NAN,
                            approach_velocity: rate,
                            separation_velocity: f64::NAN,
                            max_force: 0.0,
                            max_penetration: 0.0,
                        });
                    }
                }
            }
        }
    }
    let mut floors = Vec::new();
    let mut at = 0;
    for (b, &o) in row.buildings.iter().zip(&row.offsets()) {
        let mut list = Vec::new();
        for i in 0..b.storeys() {
            let s = &nm.layout.storeys[at];
            let drift = env.drift[at];
            let spring = p.springs[at];
            list.push(FloorPeaks {
                displacement: env.displacement[o + i],
                velocity: env.velocity[o + i],
                absolute_acceleration: env.acceleration[o + i],
                drift,
                drift_ratio: drift / s.height,
                ductility: drift / s.yield_drift,
                residual_drift: (1.0 - s.alpha) * (spring.x - spring.z),
            });
            at += 1;
        }
        floors.push(list);
    }
    let bumpers = pairs.split_off(nm.layout.hard);
    Ok(RowRun {
        floors,
        pairs,
        bumpers,
        links,
        duration,
        final_displacement: p.u.iter().copied().collect(),
        final_velocity: p.v.iter().copied().collect(),
        energy: None,
        max_relative: env.relative.clone(),
        maps_made: 0,
        map_steps: 0,
        series_steps: 0,
        configurations: 0,
        trace: None,
        forces: None,
        collapse,
        profile: Default::default(),
    })
}
