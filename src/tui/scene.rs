//! What the scene area shows and where: the scene, the time cursor, the zoom
//! window, the set overlay and the units. Pure state with its own moves;
//! the app's dispatcher calls them.

use crate::model::ContactModel;
use crate::solver::Impact;

/// The scenes, each with the key that shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scene {
    /// Time histories of the active set.
    History,
    /// Force–drift loops (x_i, f_s,i) of both structures (SPEC §3).
    Loops,
    /// The active set under several contact laws (SPEC §4, §10).
    Laws,
    /// Set 1 against set 2.
    Sets,
    /// Π_u, Π_v against Π_ω1 with and without pounding (SPEC §7).
    Spectrum,
    /// The impacts of the active run and its energy terms.
    Impacts,
    /// The left structure's region (or Π_u1/Π_u1,free) over Π_ω1 and a
    /// second parameter (SPEC §7).
    Map,
    /// The active set's buildings over a suite: P(pounding) against the
    /// gap, the IDA of the left drift and the pounding fragility (SPEC §12).
    Risk,
    /// A row of shear buildings drawn in time, with its envelopes and
    /// impacts (SPEC §13).
    Buildings,
}

impl Scene {
    pub const ALL: [Scene; 9] = [
        Scene::History,
        Scene::Loops,
        Scene::Laws,
        Scene::Sets,
        Scene::Spectrum,
        Scene::Impacts,
        Scene::Map,
        Scene::Risk,
        Scene::Buildings,
    ];

    pub fn key(self) -> char {
        match self {
            Scene::History => 't',
            Scene::Loops => 'f',
            Scene::Laws => 'v',
            Scene::Sets => 'c',
            Scene::Spectrum => 'w',
            Scene::Impacts => 'i',
            Scene::Map => 'a',
            Scene::Risk => 'x',
            Scene::Buildings => 'd',
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            Scene::History => "time",
            Scene::Loops => "force-drift",
            Scene::Laws => "laws",
            Scene::Sets => "set 1 vs 2",
            Scene::Spectrum => "spectrum",
            Scene::Impacts => "impacts",
            Scene::Map => "map",
            Scene::Risk => "risk",
            Scene::Buildings => "buildings",
        }
    }

    /// Whether the scene has a time axis (cursor and zoom act on it).
    pub fn timed(self) -> bool {
        matches!(
            self,
            Scene::History | Scene::Laws | Scene::Sets | Scene::Impacts | Scene::Loops
        )
    }
}

/// Which contact laws the laws scene overlays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Laws {
    /// The paper's two: Kelvin and improved Kelvin.
    Paper,
    /// All six.
    All,
    /// The active set's own law against this one.
    Versus(ContactModel),
}

impl Laws {
    /// The laws shown when the set's own law is `own`, in [`ContactModel::ALL`]
    /// order (so each keeps its place whichever the set's is).
    pub fn shown(self, own: ContactModel) -> Vec<ContactModel> {
        let pick: Vec<ContactModel> = match self {
            Laws::Paper => ContactModel::PAPER.to_vec(),
            Laws::All => ContactModel::ALL.to_vec(),
            Laws::Versus(other) if other != own => vec![own, other],
            Laws::Versus(_) => vec![own, next_other(own, own)],
        };
        ContactModel::ALL
            .into_iter()
            .filter(|m| pick.contains(m))
            .collect()
    }

    /// The next choice: paper pair, all six, then the set's law against
    /// each other law in turn, and round again.
    pub fn next(self, own: ContactModel) -> Laws {
        let first = next_other(own, own);
        match self {
            Laws::Paper => Laws::All,
            Laws::All => Laws::Versus(first),
            Laws::Versus(m) => {
                let n = next_other(m, own);
                if n == first || m == own {
                    Laws::Paper
                } else {
                    Laws::Versus(n)
                }
            }
        }
    }

    pub fn title(self, own: ContactModel) -> String {
        match self {
            Laws::Paper => "paper pair".into(),
            Laws::All => "all six".into(),
            Laws::Versus(_) => {
                let s = self.shown(own);
                format!(
                    "{} vs {}",
                    own.name(),
                    s.iter().find(|m| **m != own).unwrap_or(&own).name()
                )
            }
        }
    }
}

/// The law after `m` in [`ContactModel::ALL`] that is not `own`.
fn next_other(m: ContactModel, own: ContactModel) -> ContactModel {
    let all = ContactModel::ALL;
    let i = all.iter().position(|x| *x == m).unwrap_or(0);
    (1..=all.len())
        .map(|k| all[(i + k) % all.len()])
        .find(|x| *x != own)
        .unwrap_or(m)
}

/// The second axis of the map scene: a key of the parameter table or `mu`.
pub const MAP_Y: [&str; 4] = ["mu", "gap", "mass_ratio", "restitution"];

/// The scene shown and the reading aids on it.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    pub scene: Scene,
    /// The time cursor τ, when shown.
    pub cursor: Option<f64>,
    /// The zoom window [τ0, τ1]; `None` is the whole run.
    pub zoom: Option<[f64; 2]>,
    /// Set 1 and set 2 on common charts (scene `c`) instead of side by side.
    pub overlay: bool,
    /// Physical units instead of Π-groups (for a set with a `[physical]` table).
    pub physical: bool,
    /// The spectrum shows peak velocities Π_v instead of displacements Π_u.
    pub velocity: bool,
    /// The laws the laws scene overlays.
    pub laws: Laws,
    /// The map's y axis, an index into [`MAP_Y`].
    pub map_y: usize,
    /// The map shows Π_u1/Π_u1,free instead of the region.
    pub map_ratio: bool,
    /// The map cell under the cursor (column, row from the top); `None`:
    /// the set's own point.
    pub map_cursor: Option<(usize, usize)>,
    /// The risk scene's design level (g).
    pub risk_level: f64,
    /// The risk scene scales records to their PGA instead of Sa(T1).
    pub risk_pga: bool,
    /// What the risk scene is of: 0 the active set's pair, j ≥ 1 joint j
    /// of the buildings scene's row.
    pub risk_joint: usize,
}

/// Zoom factor of one `z`.
const ZOOM: f64 = 4.0;

impl Default for View {
    fn default() -> Self {
        View {
            scene: Scene::History,
            cursor: None,
            zoom: None,
            overlay: false,
            physical: false,
            velocity: false,
            laws: Laws::Paper,
            map_y: 0,
            map_ratio: false,
            map_cursor: None,
            risk_level: super::risk_job::DESIGN_LEVEL,
            risk_pga: false,
            risk_joint: 0,
        }
    }
}

impl View {
    /// The visible time window of a run ending at `tau_end`.
    pub fn window(&self, tau_end: f64) -> [f64; 2] {
        match self.zoom {
            Some([a, b]) if a < tau_end => [a.max(0.0), b.min(tau_end)],
            _ => [0.0, tau_end],
        }
    }

    /// Zooms in ×4 around the cursor (placing it mid-window if hidden).
    pub fn zoom_in(&mut self, tau_end: f64) {
        let [a, b] = self.window(tau_end);
        let center = self
            .cursor
            .filter(|c| (a..=b).contains(c))
            .unwrap_or(0.5 * (a + b));
        let half = 0.5 * (b - a) / ZOOM;
        self.set_zoom([center - half, center + half], tau_end);
        self.cursor = Some(center);
    }

    /// Zooms out ×4; back to the whole run when that covers it.
    pub fn zoom_out(&mut self, tau_end: f64) {
        let [a, b] = self.window(tau_end);
        let center = 0.5 * (a + b);
        let half = 0.5 * (b - a) * ZOOM;
        if 2.0 * half > 0.5 * tau_end {
            self.zoom = None;
            return;
        }
        self.set_zoom([center - half, center + half], tau_end);
    }

    /// Shows `[a, b]` (moved inside the run, at least a few samples wide).
    pub fn set_zoom(&mut self, [a, b]: [f64; 2], tau_end: f64) {
        let span = (b - a).max(1e-3);
        if span >= tau_end {
            self.zoom = None;
            return;
        }
        let start = a.clamp(0.0, tau_end - span);
        self.zoom = Some([start, start + span]);
    }

    /// Moves the cursor by `columns` plot columns of `width` (shows it first).
    pub fn move_cursor(&mut self, columns: f64, width: u16, tau_end: f64) {
        let [a, b] = self.window(tau_end);
        let step = (b - a) / f64::from(width.max(1));
        let c = match self.cursor {
            Some(c) if (a..=b).contains(&c) => c + columns * step,
            _ => 0.5 * (a + b),
        };
        self.cursor = Some(c.clamp(a, b));
        // Past the window's edge, the window follows.
        if (c < a || c > b)
            && let Some(z) = self.zoom
        {
            let shift = c - c.clamp(a, b);
            self.set_zoom([z[0] + shift, z[1] + shift], tau_end);
            self.cursor = Some(c.clamp(0.0, tau_end));
        }
    }

    /// Moves the cursor to the start of the next (`forward`) or previous
    /// impact; the index of that impact, or `None` when there is none.
    pub fn jump_impact(
        &mut self,
        impacts: &[Impact],
        forward: bool,
        tau_end: f64,
    ) -> Option<usize> {
        let now = self
            .cursor
            .unwrap_or(if forward { -1.0 } else { f64::INFINITY });
        let eps = 1e-9;
        let index = if forward {
            impacts.iter().position(|i| i.start > now + eps)
        } else {
            impacts.iter().rposition(|i| i.start < now - eps)
        }?;
        self.show_impact(&impacts[index], tau_end);
        Some(index)
    }

    /// Puts the cursor on an impact's start, moving a zoom window to it.
    pub fn show_impact(&mut self, impact: &Impact, tau_end: f64) {
        self.cursor = Some(impact.start);
        if let Some([a, b]) = self.zoom
            && !(a..=b).contains(&impact.start)
        {
            let half = 0.5 * (b - a);
            self.set_zoom([impact.start - half, impact.start + half], tau_end);
        }
    }

    /// Zooms onto one impact with some time either side.
    pub fn zoom_impact(&mut self, impact: &Impact, tau_end: f64) {
        let duration = (impact.end - impact.start).max(0.0);
        let pad = (4.0 * duration).max(0.2);
        self.set_zoom([impact.start - pad, impact.end + pad], tau_end);
        self.cursor = Some(impact.start);
    }

    /// The impact under or after the cursor (the impact table's selection).
    pub fn selected_impact(&self, impacts: &[Impact]) -> Option<usize> {
        let c = self.cursor?;
        impacts
            .iter()
            .position(|i| i.end >= c - 1e-9)
            .or(impacts.len().checked_sub(1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn impact(start: f64) -> Impact {
        Impact {
            start,
            end: start + 0.06,
            approach_velocity: 1.0,
            separation_velocity: 0.4,
            restitution: 0.4,
            peak_force: 10.0,
            max_penetration: 0.01,
            ended: true,
        }
    }

    #[test]
    fn the_law_choice_cycles_through_every_pair_and_back() {
        use ContactModel::*;
        let own = ImprovedKelvin;
        let mut l = Laws::Paper;
        let mut seen = vec![l.shown(own)];
        for _ in 0..7 {
            l = l.next(own);
            seen.push(l.shown(own));
        }
        assert_eq!(seen[0], [Kelvin, ImprovedKelvin]);
        assert_eq!(seen[1].len(), 6);
        // Own law against each of the five others, then the paper pair again.
        assert_eq!(seen[2], [ImprovedKelvin, Hertz]);
        assert_eq!(seen[6], [Kelvin, ImprovedKelvin]);
        assert_eq!(seen[7], [Kelvin, ImprovedKelvin]);
        assert!(seen[2..7].iter().all(|s| s.len() == 2 && s.contains(&own)));
        assert_eq!(l, Laws::Paper);
    }

    #[test]
    fn zoom_stays_inside_the_run_and_returns_to_it() {
        let mut v = View {
            cursor: Some(1.0),
            ..View::default()
        };
        v.zoom_in(40.0);
        assert_eq!(v.zoom, Some([0.0, 10.0]));
        v.zoom_in(40.0);
        assert_eq!(v.zoom, Some([0.0, 2.5]));
        v.zoom_out(40.0);
        v.zoom_out(40.0);
        assert_eq!(v.zoom, None);
        assert_eq!(v.window(40.0), [0.0, 40.0]);
    }

    #[test]
    fn impact_jumps_walk_the_impacts_in_order() {
        let impacts = [impact(3.0), impact(7.0), impact(11.0)];
        let mut v = View::default();
        assert_eq!(v.jump_impact(&impacts, true, 50.0), Some(0));
        assert_eq!(v.jump_impact(&impacts, true, 50.0), Some(1));
        assert_eq!(v.cursor, Some(7.0));
        assert_eq!(v.jump_impact(&impacts, false, 50.0), Some(0));
        assert_eq!(v.jump_impact(&impacts, false, 50.0), None);
        v.zoom_impact(&impacts[2], 50.0);
        let [a, b] = v.zoom.unwrap();
        assert!(a < 11.0 && b > 11.06 && b - a < 1.0, "{a} {b}");
    }
}
