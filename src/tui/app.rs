//! The explorer's dispatcher: it routes each key, click and result to the
//! part of the state it concerns and returns the [`Effect`] to run, if any.
//! Pure: no terminal, no threads, no files. The parts live beside it:
//! the scene and its reading aids in [`super::scene`], text entry in
//! [`super::text_field`], the computations in [`super::jobs`], the I/O in
//! [`super::effects`].

use std::path::PathBuf;

use crossterm::event::{
    KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};

use super::effects::{Done, Effect};
use super::export::{self, History};
use super::fields::{FIELDS, StepSize, nudged_text};
use super::jobs::{Jobs, Need};
use super::layout;
use super::map_grid;
use super::physical::{self, Base};
use super::presets;
use super::risk_job::{self, RiskSpec};
use super::row_pane::RowPane;
use super::scene::MAP_Y;
use super::scene::{Scene, View};
use super::text_field::{FieldKey, TextField};
use super::worker::{Job, MapSpec, Output, RunOutput, RunSpec, Slot, SpectrumSpec};
use crate::analysis::map::{Axis, MapPlan};
use crate::figure::FigureName;
use crate::model::Method;
use crate::model::grid::Grid;
use crate::model::preset::{self, Preset};
use crate::model::{ContactModel, Params};

pub use super::look::Look;

/// One parameter pane: the values being explored, the preset they came
/// from, and the physical base when the preset has a `[physical]` table.
#[derive(Debug, Clone)]
pub struct SetState {
    pub preset: Preset,
    pub params: Params,
    pub base: Option<Base>,
}

impl SetState {
    pub fn new(preset: Preset) -> Self {
        SetState {
            params: preset.params.clone(),
            base: Base::of(&preset),
            preset,
        }
    }

    /// The keys whose value differs from the preset's, in table order.
    pub fn modified(&self) -> Vec<&'static str> {
        FIELDS
            .iter()
            .filter(|f| f.text(&self.params) != f.text(&self.preset.params))
            .map(|f| f.key)
            .collect()
    }
}

/// Longest preset name.
pub const NAME_MAX: usize = 64;
/// Longest typed value.
const VALUE_MAX: usize = 32;
/// Longest path typed for an export or a figure.
const PATH_MAX: usize = 1024;
/// A full export above this many bytes asks once more, naming its size.
pub const LARGE_EXPORT: f64 = 5e6;

/// What the keyboard currently drives.
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    Normal,
    /// Typing an exact value into the selected row.
    Editing(TextField),
    /// The key list, scrolled to its line `top` where it is taller than the screen.
    Help {
        top: usize,
    },
    /// Choosing a preset for the active set.
    Picker {
        selected: usize,
    },
    /// Typing a name to save the active set under.
    SaveName(TextField),
    /// A user preset of that name exists: y overwrites it.
    ConfirmOverwrite {
        name: String,
    },
    /// A set has changes that are not saved: y quits anyway.
    ConfirmQuit,
    /// Where to export, and which history; `confirmed` once a large size was shown.
    Export {
        path: TextField,
        full: bool,
        confirmed: bool,
    },
    /// Where to write the scene as SVG.
    Figure {
        path: TextField,
    },
    /// Where to write the row's CSV or figure (buildings scene).
    RowFile {
        path: TextField,
        file: super::row_file::RowFile,
    },
}

/// One line of the preset picker.
#[derive(Debug, Clone, PartialEq)]
pub struct PickerEntry {
    pub name: String,
    /// `built-in`, `yours` or `row`.
    pub kind: &'static str,
    pub description: String,
}

/// How the process should end (the exit status follows the signal).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Exit {
    Quit,
    /// SIGTERM, SIGHUP or SIGINT: 128 + the signal number.
    Signal(i32),
}

/// Π_ω1 grid of the spectrum scene: the CLI's default, 0.10…3.00 by 0.01
/// (291 points), each value rounded to its two decimals.
pub fn spectrum_grid() -> Vec<f64> {
    (10..=300).map(|i| i as f64 / 100.0).collect()
}

/// History buckets of the force–drift scene: fine enough that the trace
/// through each bucket's last sample follows the loop (SPEC §3).
pub const LOOP_BUCKETS: usize = 2048;

/// The whole explorer state.
#[derive(Debug)]
pub struct App {
    pub sets: [SetState; 2],
    /// Index of the active set (0 or 1).
    pub active: usize,
    /// Selected row of the panes: an index into [`FIELDS`], or into
    /// [`physical::ROWS`] in the physical view.
    pub selected: usize,
    pub view: View,
    pub mode: Mode,
    /// Built-in presets, then the user's, in stable slots.
    pub presets: Vec<Preset>,
    pub user_dir: Option<PathBuf>,
    /// Where exports and figures go unless the user types another path.
    pub export_dir: PathBuf,
    /// A one-line message (saved, exported, an error).
    pub status: Option<String>,
    /// Terminal size (columns, rows).
    pub size: (u16, u16),
    pub look: Look,
    pub jobs: Jobs,
    /// Whether mouse buttons are captured.
    pub mouse: bool,
    /// The row of buildings of the buildings scene, once opened.
    pub row: Option<RowPane>,
}

impl App {
    pub fn new(
        left: Preset,
        right: Preset,
        presets: Vec<Preset>,
        user_dir: Option<PathBuf>,
        look: Look,
    ) -> App {
        App {
            sets: [SetState::new(left), SetState::new(right)],
            active: 0,
            selected: 0,
            view: View::default(),
            mode: Mode::Normal,
            presets,
            user_dir,
            export_dir: PathBuf::from("."),
            status: None,
            size: (80, 24),
            look,
            jobs: Jobs::default(),
            mouse: true,
            row: None,
        }
    }

    /// The built-in presets followed by the user's own in `dir`.
    pub fn load_presets(dir: Option<&PathBuf>) -> Vec<Preset> {
        presets::load(dir.map(|d| d.as_path()))
    }

    pub fn active_params(&self) -> &Params {
        &self.sets[self.active].params
    }

    /// The contact model of the active set.
    pub fn model(&self) -> ContactModel {
        self.active_params().model
    }

    /// The scene shown.
    pub fn scene(&self) -> Scene {
        self.view.scene
    }

    /// Whether the panes show physical quantities (the view is on and the
    /// active set has a `[physical]` table).
    pub fn physical_view(&self) -> bool {
        self.view.physical && self.sets[self.active].base.is_some()
    }

    /// Rows of the panes.
    pub fn pane_rows(&self) -> usize {
        if let Some(pane) = self
            .row
            .as_ref()
            .filter(|_| self.scene() == Scene::Buildings)
        {
            pane.fields().len()
        } else if self.physical_view() {
            physical::ROWS.len()
        } else {
            FIELDS.len()
        }
    }

    /// The active run's end τ.
    fn tau_end(&self) -> f64 {
        self.active_params().tau_end()
    }

    /// Whether a set differs from its preset (what quitting would lose).
    pub fn unsaved(&self) -> Vec<usize> {
        (0..2)
            .filter(|&i| self.sets[i].params != self.sets[i].preset.params)
            .collect()
    }

    // ----- what to compute -----

    /// The runs and spectrum the visible scene needs.
    pub fn needed(&self) -> Need {
        let buckets = (layout::chart_columns(self.size) as usize * 2).max(16);
        let set = |i: usize, buckets: usize| {
            let params = self.sets[i].params.clone();
            RunSpec {
                slot: Slot::Set(i),
                buckets,
                window: self.view.window(params.tau_end()),
                params,
            }
        };
        let active = set(self.active, buckets);
        match self.view.scene {
            Scene::History | Scene::Impacts => Need::runs(vec![active]),
            Scene::Loops => Need::runs(vec![set(self.active, LOOP_BUCKETS)]),
            Scene::Laws => {
                let own = self.model();
                let runs = self
                    .view
                    .laws
                    .shown(own)
                    .into_iter()
                    .map(|law| {
                        let mut run = active.clone();
                        if law != own {
                            run.slot = Slot::Law(law);
                            run.params.model = law;
                        }
                        run
                    })
                    .collect();
                Need::runs(runs)
            }
            Scene::Sets => Need::runs(vec![set(0, buckets), set(1, buckets)]),
            // The summary under the map shows the set's own run, as under a spectrum.
            Scene::Map => Need {
                map: self.map_spec(),
                ..Need::runs(vec![active])
            },
            Scene::Risk => Need {
                risk: Some(self.risk_spec()),
                ..Need::runs(vec![active])
            },
            // The row alone: the pair's runs are not on screen.
            Scene::Buildings => Need {
                row: self.row.as_ref().map(|p| p.spec()),
                ..Need::default()
            },
            Scene::Spectrum => {
                let p = self.active_params();
                let mu = p.mu();
                let spec = SpectrumSpec {
                    params: Params {
                        omega1: 1.0,
                        omega2: mu,
                        ..p.clone()
                    },
                    mu,
                    grid: spectrum_grid(),
                };
                Need {
                    spectrum: mu.is_finite().then_some(spec),
                    ..Need::runs(vec![active])
                }
            }
        }
    }

    /// The risk picture the risk scene asks for: the active set's
    /// buildings (its preset's base, or the reference one) at the design level.
    pub fn risk_spec(&self) -> RiskSpec {
        if let Some(pane) = self.row.as_ref()
            && self.view.risk_joint > 0
        {
            let joint = (self.view.risk_joint - 1).min(pane.row.joints.len() - 1);
            return risk_job::row_spec(&pane.row, joint, self.view.risk_level, self.view.risk_pga);
        }
        let s = &self.sets[self.active];
        risk_job::spec_of(&s.params, s.base, self.view.risk_level, self.view.risk_pga)
    }

    /// The map the map scene asks for: Π_ω1 across as many columns as the
    /// plot has, the chosen parameter down (two rows per terminal row with
    /// colours), around the active set (exact method).
    pub fn map_spec(&self) -> Option<MapSpec> {
        let p = self.active_params();
        let mu = p.mu();
        if !mu.is_finite() {
            return None;
        }
        let (columns, rows) = map_grid::grid_size(layout::scene(self.size), self.look);
        let key = MAP_Y[self.view.map_y % MAP_Y.len()];
        let [lo, hi] = map_grid::y_range(key, p);
        let axis = |key: &'static str, lo: f64, hi: f64, n: usize| Axis {
            key,
            grid: Grid {
                start: lo,
                stop: hi,
                step: (hi - lo) / (n.max(2) - 1) as f64,
            },
        };
        let [x0, x1] = map_grid::X_RANGE;
        Some(MapSpec {
            plan: MapPlan {
                base: Params {
                    method: Method::Exact,
                    ..p.clone()
                },
                mu,
                x: axis("omega1", x0, x1, columns),
                y: axis(key, lo, hi, rows),
            },
        })
    }

    /// A new job when what the scene needs changed since the last request.
    pub fn job(&mut self) -> Option<Job> {
        let need = self.needed();
        self.jobs.job(need)
    }

    /// The run to show for a slot (the previous one while a new one computes).
    pub fn shown(&self, slot: Slot) -> Option<&RunOutput> {
        self.jobs.shown(slot)
    }

    pub fn on_output(&mut self, out: Output) {
        self.jobs.on_output(out);
    }

    /// What came of an effect.
    pub fn on_done(&mut self, done: Done) {
        match done {
            Done::Status(s) => self.status = Some(s),
            Done::Saved {
                set,
                preset,
                message,
            } => {
                self.sets[set].preset = *preset;
                self.status = Some(message);
            }
            Done::Presets(user) => self.presets = presets::merge(&self.presets, user),
        }
    }

    // ----- input -----

    pub fn on_resize(&mut self, columns: u16, rows: u16) {
        self.size = (columns, rows);
    }

    /// A click selects a pane row or puts the cursor on the time axis; the
    /// wheel nudges only over the panes.
    pub fn on_mouse(&mut self, m: MouseEvent) {
        if self.mode != Mode::Normal || self.scene() == Scene::Buildings {
            return;
        }
        let pane = layout::pane_hit(self.size, self.pane_rows(), self.selected, m.column, m.row);
        match m.kind {
            MouseEventKind::ScrollUp | MouseEventKind::ScrollDown => {
                if let Some((set, row)) = pane {
                    self.active = set;
                    self.selected = row;
                    let up = m.kind == MouseEventKind::ScrollUp;
                    self.nudge(if up { 1.0 } else { -1.0 }, StepSize::Normal);
                }
            }
            MouseEventKind::Down(MouseButton::Left) => {
                if let Some((set, row)) = pane {
                    self.active = set;
                    self.selected = row;
                } else if self.view.scene.timed()
                    && self.view.scene != Scene::Loops
                    && let Some(f) = layout::time_fraction(self.size, m.column, m.row)
                {
                    let [a, b] = self.view.window(self.tau_end());
                    self.view.cursor = Some(a + f * (b - a));
                }
            }
            _ => {}
        }
    }

    /// What a key does.
    pub fn on_key(&mut self, key: KeyEvent) -> Option<Effect> {
        if key.kind == KeyEventKind::Release {
            return None;
        }
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        if ctrl && key.code == KeyCode::Char('c') {
            return Some(Effect::Quit);
        }
        match std::mem::replace(&mut self.mode, Mode::Normal) {
            Mode::Normal => return self.on_normal_key(key),
            Mode::Help { top } => {
                // ↑↓ (and the page keys) scroll a help taller than the
                // screen; any other key closes it.
                let max = super::keys::help_top_max(self.size.1);
                let top = match key.code {
                    KeyCode::Down | KeyCode::Char('j') => Some(top + 1),
                    KeyCode::Up | KeyCode::Char('k') => Some(top.saturating_sub(1)),
                    KeyCode::PageDown | KeyCode::Char(' ') => Some(top + 10),
                    KeyCode::PageUp => Some(top.saturating_sub(10)),
                    _ => None,
                };
                if let Some(top) = top {
                    self.mode = Mode::Help { top: top.min(max) };
                }
            }
            Mode::Editing(field) => self.on_edit_key(key, field),
            Mode::Picker { selected } => self.on_picker_key(key, selected),
            Mode::SaveName(field) => return self.on_save_key(key, field),
            Mode::ConfirmOverwrite { name } => {
                if matches!(key.code, KeyCode::Char('y' | 'Y')) {
                    return self.save(&name);
                }
                self.status = Some(format!("not saved: `{name}` kept as it was"));
            }
            Mode::ConfirmQuit => {
                if matches!(key.code, KeyCode::Char('y' | 'Y' | 'q')) {
                    return Some(Effect::Quit);
                }
                self.status = Some("not quitting".into());
            }
            Mode::Export {
                path,
                full,
                confirmed,
            } => return self.on_export_key(key, path, full, confirmed),
            Mode::Figure { path } => return self.on_figure_key(key, path),
            Mode::RowFile { path, file } => return self.on_row_file_key(key, path, file),
        }
        None
    }

    fn on_normal_key(&mut self, key: KeyEvent) -> Option<Effect> {
        let shift = key.modifiers.contains(KeyModifiers::SHIFT);
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        let size = if shift {
            StepSize::Coarse
        } else if ctrl {
            StepSize::Fine
        } else {
            StepSize::Normal
        };
        // Ctrl with a letter means nothing here (Ctrl-E is not `e`).
        if ctrl && matches!(key.code, KeyCode::Char(_)) {
            return None;
        }
        self.status = None;
        if self.scene() == Scene::Buildings && self.on_row_key(key, size).is_some() {
            return None;
        }
        let tau_end = self.tau_end();
        let columns = layout::chart_columns(self.size);
        match key.code {
            KeyCode::Char('q') => {
                if self.unsaved().is_empty() {
                    return Some(Effect::Quit);
                }
                self.mode = Mode::ConfirmQuit;
            }
            // Esc never quits: it hides the cursor.
            KeyCode::Esc => self.view.cursor = None,
            KeyCode::Up | KeyCode::Char('k') => self.select(-1),
            KeyCode::Down | KeyCode::Char('j') => self.select(1),
            KeyCode::Left | KeyCode::Char('h') | KeyCode::Char('-') => self.nudge(-1.0, size),
            KeyCode::Right | KeyCode::Char('l') | KeyCode::Char('+') | KeyCode::Char('=') => {
                self.nudge(1.0, size)
            }
            KeyCode::Char('H') | KeyCode::Char('_') => self.nudge(-1.0, StepSize::Coarse),
            KeyCode::Char('L') => self.nudge(1.0, StepSize::Coarse),
            KeyCode::Char(',') => self.nudge(-1.0, StepSize::Fine),
            KeyCode::Char('.') => self.nudge(1.0, StepSize::Fine),
            KeyCode::Enter => {
                let text = self.row_text(self.active, self.selected);
                self.mode = Mode::Editing(TextField::new(&text, VALUE_MAX));
            }
            KeyCode::Tab | KeyCode::BackTab => {
                self.active = 1 - self.active;
                self.selected = self.selected.min(self.pane_rows() - 1);
            }
            KeyCode::Char('m') => {
                let p = &mut self.sets[self.active].params;
                p.model = p.model.toggled();
            }
            KeyCode::Char('r') => {
                let s = &mut self.sets[self.active];
                s.params = s.preset.params.clone();
                s.base = Base::of(&s.preset);
                self.status = Some(format!(
                    "set {} reset to preset `{}`",
                    self.active + 1,
                    s.preset.name
                ));
            }
            KeyCode::Char('p') => {
                self.mode = Mode::Picker { selected: 0 };
                return Some(Effect::ReloadPresets);
            }
            KeyCode::Char('s') => self.mode = Mode::SaveName(TextField::new("", NAME_MAX)),
            KeyCode::Char('e') => {
                let path = self.default_path("csv");
                self.mode = Mode::Export {
                    path: TextField::new(&path, PATH_MAX),
                    full: true,
                    confirmed: false,
                };
            }
            KeyCode::Char('g') if self.view.scene == Scene::Risk => {
                self.status = Some(
                    "no SVG of the risk scene: pounding ida and pounding gap --suite give its numbers"
                        .into(),
                );
            }
            KeyCode::Char('g') => {
                let path = self.default_path("svg");
                self.mode = Mode::Figure {
                    path: TextField::new(&path, PATH_MAX),
                };
            }
            KeyCode::Char('?') => self.mode = Mode::Help { top: 0 },
            KeyCode::Char('b') if self.view.scene == Scene::Laws => {
                self.view.laws = self.view.laws.next(self.model());
            }
            KeyCode::Char('o') if self.view.scene == Scene::Map => {
                self.view.map_ratio = !self.view.map_ratio;
            }
            KeyCode::Char('y') if self.view.scene == Scene::Map => {
                self.view.map_y = (self.view.map_y + 1) % MAP_Y.len();
                self.view.map_cursor = None;
            }
            KeyCode::Char(c @ ('[' | ']' | '{' | '}')) if self.view.scene == Scene::Map => {
                self.move_map_cursor(c);
            }
            KeyCode::Char(c @ ('[' | ']')) if self.view.scene == Scene::Risk => {
                self.view.risk_level = risk_job::stepped(self.view.risk_level, c == ']');
            }
            KeyCode::Char('o') if self.view.scene == Scene::Risk => {
                self.view.risk_pga = !self.view.risk_pga;
            }
            // The pair, then each joint of the row, in turn.
            KeyCode::Char('y') if self.view.scene == Scene::Risk => {
                let joints = self.row.as_ref().map_or(0, |p| p.row.joints.len());
                self.view.risk_joint = (self.view.risk_joint + 1) % (joints + 1);
                self.status = Some(if joints == 0 {
                    "risk of the pair: open a row of buildings (d, p) to study its joints".into()
                } else if self.view.risk_joint == 0 {
                    "risk of the active set's pair".into()
                } else {
                    format!("risk at joint {} of the row", self.view.risk_joint)
                });
            }
            KeyCode::Char('o') if self.view.scene == Scene::Spectrum => {
                self.view.velocity = !self.view.velocity;
            }
            KeyCode::Char('o') => {
                self.view.overlay = !self.view.overlay;
                self.view.scene = Scene::Sets;
            }
            KeyCode::Char('u') => {
                if self.sets.iter().all(|s| s.base.is_none()) {
                    self.status = Some(
                        "physical units: neither set's preset has a [physical] table \
                         (try preset two-buildings)"
                            .into(),
                    );
                } else {
                    self.view.physical = !self.view.physical;
                    self.selected = 0;
                }
            }
            KeyCode::Char('M') => {
                self.mouse = !self.mouse;
                self.status = Some(if self.mouse {
                    "mouse on: click selects, wheel nudges a pane row".into()
                } else {
                    "mouse off: the terminal selects text (M turns it back on)".into()
                });
                return Some(Effect::Mouse(self.mouse));
            }
            KeyCode::Char('[') => self.view.move_cursor(-1.0, columns, tau_end),
            KeyCode::Char(']') => self.view.move_cursor(1.0, columns, tau_end),
            KeyCode::Char('{') => self.view.move_cursor(-10.0, columns, tau_end),
            KeyCode::Char('}') => self.view.move_cursor(10.0, columns, tau_end),
            KeyCode::Char('n') | KeyCode::Char('N') => {
                let forward = key.code == KeyCode::Char('n');
                let found = self
                    .shown(Slot::Set(self.active))
                    .map(|r| r.result.impacts.clone())
                    .and_then(|impacts| self.view.jump_impact(&impacts, forward, tau_end));
                if found.is_none() {
                    let which = if forward { "after" } else { "before" };
                    self.status = Some(format!("no impact {which} the cursor"));
                }
            }
            KeyCode::Char('z') => {
                let impact = (self.view.scene == Scene::Impacts)
                    .then(|| self.shown(Slot::Set(self.active)))
                    .flatten()
                    .and_then(|r| {
                        let i = self.view.selected_impact(&r.result.impacts)?;
                        r.result.impacts.get(i).copied()
                    });
                match impact {
                    Some(i) => {
                        self.view.zoom_impact(&i, tau_end);
                        self.view.scene = Scene::History;
                    }
                    None => self.view.zoom_in(tau_end),
                }
            }
            KeyCode::Char('Z') => self.view.zoom_out(tau_end),
            KeyCode::Char(c @ '1'..='9') => self.recall(c as usize - '1' as usize),
            KeyCode::Char(c) => {
                if let Some(s) = Scene::ALL.iter().find(|s| s.key() == c) {
                    self.view.scene = *s;
                    if *s == Scene::Buildings {
                        self.ensure_row();
                    }
                }
            }
            _ => {}
        }
        None
    }

    /// Moves the map's cell cursor: `[ ]` along Π_ω1, `{ }` along y (up is `}`).
    fn move_map_cursor(&mut self, key: char) {
        let Some(spec) = self.map_spec() else {
            return;
        };
        let (nx, ny) = (spec.columns(), spec.rows());
        let (c, r) = self
            .view
            .map_cursor
            .unwrap_or_else(|| map_grid::own_cell(&spec, self.active_params()));
        let (c, r) = match key {
            '[' => (c.saturating_sub(1), r),
            ']' => ((c + 1).min(nx - 1), r),
            '{' => (c, r.saturating_sub(1)),
            _ => (c, (r + 1).min(ny - 1)),
        };
        self.view.map_cursor = Some((c, r));
    }

    /// `DIR/pounding-PRESET-SCENE.EXT` in the export folder.
    fn default_path(&self, extension: &str) -> String {
        let name = format!(
            "pounding-{}-{}.{extension}",
            self.sets[self.active].preset.name,
            self.view.scene.title().replace(' ', "-")
        );
        self.export_dir.join(name).display().to_string()
    }

    fn select(&mut self, delta: isize) {
        let n = self.pane_rows() as isize;
        self.selected = (self.selected as isize + delta).rem_euclid(n) as usize;
    }

    /// The text of a pane row of set `i`.
    pub fn row_text(&self, i: usize, row: usize) -> String {
        let s = &self.sets[i];
        match (&s.base, self.physical_view()) {
            (Some(base), true) => physical::value_text(base, &s.params, &physical::ROWS[row]),
            (None, true) => "-".into(),
            (_, false) => FIELDS[row].text(&s.params),
        }
    }

    /// Takes new parameters for the active set; warns when Δτ cannot
    /// resolve a contact (the rule `pounding run` applies).
    fn accept(&mut self, next: Params) {
        if let Some(w) = next.coarse_dt_warning() {
            self.status = Some(w);
        }
        self.sets[self.active].params = next;
    }

    /// Moves the selected row of the active set by one step of `size`.
    pub fn nudge(&mut self, direction: f64, size: StepSize) {
        if self.physical_view() {
            let steps = direction
                * match size {
                    StepSize::Fine => 0.2,
                    StepSize::Normal => 1.0,
                    StepSize::Coarse => 10.0,
                };
            let s = &self.sets[self.active];
            let base = s.base.expect("physical view has a base");
            match physical::nudged(&base, &s.params, self.selected, steps) {
                Ok((next, base)) => {
                    self.sets[self.active].base = Some(base);
                    self.accept(next);
                }
                Err(e) => self.status = Some(e),
            }
            return;
        }
        let field = &FIELDS[self.selected];
        let params = self.sets[self.active].params.clone();
        match nudged_text(&params, field, direction, size) {
            None => {
                self.status = Some(format!(
                    "`{}` is inf: press Enter to type a finite value",
                    field.key
                ))
            }
            Some(text) => {
                let mut next = params;
                match next.set(field.key, &text).and_then(|_| next.validate()) {
                    Ok(()) => self.accept(next),
                    Err(e) => self.status = Some(e.to_string()),
                }
            }
        }
    }

    fn on_edit_key(&mut self, key: KeyEvent, mut field: TextField) {
        match field.on_key(key) {
            FieldKey::Cancel => return,
            FieldKey::Submit => {}
            FieldKey::Edited | FieldKey::Other => {
                self.mode = Mode::Editing(field);
                return;
            }
        }
        let text = field.text();
        if self.scene() == Scene::Buildings {
            if let Err(e) = self.on_row_edit(&text) {
                field.error = Some(e);
                self.mode = Mode::Editing(field);
            }
            return;
        }
        let s = &self.sets[self.active];
        let outcome = if self.physical_view() {
            let base = s.base.expect("physical view has a base");
            physical::apply(&base, &s.params, self.selected, &text).map(|(p, b)| (p, Some(b)))
        } else {
            let mut next = s.params.clone();
            next.set(FIELDS[self.selected].key, &text)
                .and_then(|_| next.validate())
                .map(|()| (next, s.base))
                .map_err(|e| e.to_string())
        };
        match outcome {
            Ok((next, base)) => {
                self.sets[self.active].base = base;
                self.accept(next);
            }
            Err(e) => {
                field.error = Some(e);
                self.mode = Mode::Editing(field);
            }
        }
    }

    /// The picker's entries: in the buildings scene the row presets, else
    /// the pair's presets followed by the rows.
    pub fn picker_entries(&self) -> Vec<PickerEntry> {
        let rows = crate::model::buildings::builtin::names()
            .into_iter()
            .map(|name| PickerEntry {
                name: name.to_string(),
                kind: "row",
                description: crate::model::buildings::builtin::description(name)
                    .unwrap_or_default(),
            });
        if self.scene() == Scene::Buildings {
            return rows.collect();
        }
        self.presets
            .iter()
            .map(|p| PickerEntry {
                name: p.name.clone(),
                kind: if p.path.is_some() {
                    "yours"
                } else {
                    "built-in"
                },
                description: p.description.clone(),
            })
            .chain(rows)
            .collect()
    }

    /// Loads picker entry `index`: a row preset opens the buildings scene.
    fn pick(&mut self, index: usize) {
        let entries = self.picker_entries();
        match entries.get(index) {
            Some(e) if e.kind == "row" => self.recall_row(&e.name.clone()),
            _ => self.recall(index),
        }
    }

    fn on_picker_key(&mut self, key: KeyEvent, selected: usize) {
        let n = self.picker_entries().len().max(1);
        let next = match key.code {
            KeyCode::Up | KeyCode::Char('k') => (selected + n - 1) % n,
            KeyCode::Down | KeyCode::Char('j') => (selected + 1) % n,
            KeyCode::Home => 0,
            KeyCode::End => n - 1,
            KeyCode::PageUp => selected.saturating_sub(5),
            KeyCode::PageDown => (selected + 5).min(n - 1),
            KeyCode::Enter => return self.pick(selected),
            KeyCode::Char(c @ '1'..='9') => return self.pick(c as usize - '1' as usize),
            _ => return,
        };
        self.mode = Mode::Picker { selected: next };
    }

    /// Loads preset number `index` (0-based) into the active set.
    pub fn recall(&mut self, index: usize) {
        match self.presets.get(index) {
            Some(p) => {
                self.sets[self.active] = SetState::new(p.clone());
                self.status = Some(format!("set {} ← preset `{}`", self.active + 1, p.name));
            }
            None => {
                self.status = Some(format!(
                    "no preset {} (there are {})",
                    index + 1,
                    self.presets.len()
                ))
            }
        }
    }

    fn on_save_key(&mut self, key: KeyEvent, mut field: TextField) -> Option<Effect> {
        match field.on_key(key) {
            FieldKey::Cancel => None,
            FieldKey::Submit => {
                let name = field.text();
                match self.check_save_name(&name) {
                    Err(error) => {
                        field.error = Some(error);
                        self.mode = Mode::SaveName(field);
                        None
                    }
                    Ok(path) if path.is_file() => {
                        self.mode = Mode::ConfirmOverwrite { name };
                        None
                    }
                    Ok(_) => self.save(&name),
                }
            }
            _ => {
                self.mode = Mode::SaveName(field);
                None
            }
        }
    }

    /// Where a user preset of this name goes, or why it cannot be saved.
    fn check_save_name(&self, name: &str) -> Result<PathBuf, String> {
        let ok = !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !ok {
            return Err(format!("name `{name}`: use letters, digits, - and _ only"));
        }
        if preset::is_builtin(name) {
            return Err(format!(
                "`{name}` is a built-in preset: choose another name"
            ));
        }
        let dir = self
            .user_dir
            .as_ref()
            .ok_or("no preset directory (set XDG_CONFIG_HOME or --presets)")?;
        Ok(dir.join(format!("{name}.toml")))
    }

    /// The effect that saves the active set as user preset `name`.
    fn save(&mut self, name: &str) -> Option<Effect> {
        let path = match self.check_save_name(name) {
            Ok(p) => p,
            Err(e) => {
                self.status = Some(e);
                return None;
            }
        };
        let s = &self.sets[self.active];
        let preset = Preset {
            name: name.to_string(),
            description: format!("saved from the explorer, based on {}", s.preset.name),
            params: s.params.clone(),
            spectrum: s.preset.spectrum.clone(),
            physical: s.base.map(|b| physical::table(&b, &s.params)),
            path: Some(path.clone()),
            lines: Default::default(),
        };
        self.status = Some(format!("saving {} ...", crate::output::shown(&path)));
        Some(Effect::Save {
            set: self.active,
            preset: Box::new(preset),
            path,
        })
    }

    fn on_export_key(
        &mut self,
        key: KeyEvent,
        mut path: TextField,
        mut full: bool,
        mut confirmed: bool,
    ) -> Option<Effect> {
        match path.on_key(key) {
            FieldKey::Cancel => return None,
            FieldKey::Other if key.code == KeyCode::Tab || key.code == KeyCode::BackTab => {
                full = !full;
                confirmed = false;
            }
            FieldKey::Submit => {
                let params = self.active_params().clone();
                let bytes = export::full_bytes(&params);
                if full && bytes > LARGE_EXPORT && !confirmed {
                    path.error = Some(format!(
                        "the full history is about {}: Enter again writes it, Tab picks the on-screen one",
                        export::size_text(bytes)
                    ));
                    self.mode = Mode::Export {
                        path,
                        full,
                        confirmed: true,
                    };
                    return None;
                }
                let history = if full {
                    History::Full
                } else {
                    match self.shown(Slot::Set(self.active)) {
                        Some(r) => History::Shown(Box::new(r.history.clone())),
                        None => {
                            self.status = Some("nothing on screen yet to export".into());
                            return None;
                        }
                    }
                };
                let target = PathBuf::from(path.text());
                self.status = Some(format!("exporting {} ...", crate::output::shown(&target)));
                return Some(Effect::Export {
                    params,
                    path: target,
                    history,
                });
            }
            _ => {}
        }
        self.mode = Mode::Export {
            path,
            full,
            confirmed,
        };
        None
    }

    fn on_figure_key(&mut self, key: KeyEvent, path: TextField) -> Option<Effect> {
        let mut path = path;
        match path.on_key(key) {
            FieldKey::Cancel => None,
            FieldKey::Submit => {
                let (name, params) = self.figure_of_scene();
                let target = PathBuf::from(path.text());
                self.status = Some(format!("drawing {} ...", crate::output::shown(&target)));
                Some(Effect::Figure {
                    name,
                    title: self.sets[self.active].preset.name.clone(),
                    params,
                    path: target,
                })
            }
            _ => {
                self.mode = Mode::Figure { path };
                None
            }
        }
    }

    /// The figure of the visible scene: the same quantities as the screen.
    pub fn figure_of_scene(&self) -> (FigureName, Params) {
        let p = self.active_params().clone();
        let name = match self.view.scene {
            Scene::History | Scene::Sets | Scene::Impacts => FigureName::History,
            Scene::Loops => FigureName::Loops,
            Scene::Laws => FigureName::ContactLaws,
            Scene::Map => FigureName::Map,
            Scene::Spectrum => FigureName::Spectrum,
            // No figure of their own (`g` says so): the set's histories.
            Scene::Risk | Scene::Buildings => FigureName::History,
        };
        (name, p)
    }
}

impl App {
    /// Computes what the visible scene needs on the calling thread (tests,
    /// benchmarks): the same job the worker would run, with the same outputs.
    pub fn compute_blocking(&mut self) {
        if let Some(job) = self.job() {
            let outputs = std::cell::RefCell::new(Vec::new());
            let send = |o: Output| outputs.borrow_mut().push(o);
            super::worker::run_job(&job, &|| true, &send);
            for o in outputs.into_inner() {
                self.on_output(o);
            }
            self.on_output(Output::Done {
                generation: job.generation,
                cancelled: false,
            });
        }
    }
}
