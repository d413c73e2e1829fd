//! The explorer's state and what each key does to it. Pure: no terminal, no
//! threads. The main loop feeds it events, asks [`App::job`] what to compute,
//! and runs the [`Effect`]s it returns.

use std::path::PathBuf;

use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseEvent, MouseEventKind};

use super::fields::{FIELDS, StepSize, nudged_text};
use super::worker::{Job, Output, RunOutput, RunSpec, Slot, SpectrumSpec};
use crate::analysis::spectrum::SpectrumPoint;
use crate::model::preset::{self, Preset};
use crate::model::{ContactModel, Params};

/// The scenes, each with the key that shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scene {
    /// Time histories of the active set.
    History,
    /// Force–drift loops (x_i, f_s,i) of both structures (SPEC §3).
    Loops,
    /// The active set under Kelvin and improved Kelvin (SPEC §4).
    Kelvin,
    /// Set 1 against set 2.
    Sets,
    /// Π_u, Π_v against Π_ω1 with and without pounding (SPEC §7).
    Spectrum,
}

impl Scene {
    pub const ALL: [Scene; 5] = [
        Scene::History,
        Scene::Loops,
        Scene::Kelvin,
        Scene::Sets,
        Scene::Spectrum,
    ];

    pub fn key(self) -> char {
        match self {
            Scene::History => 't',
            Scene::Loops => 'f',
            Scene::Kelvin => 'v',
            Scene::Sets => 'c',
            Scene::Spectrum => 'w',
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            Scene::History => "time",
            Scene::Loops => "force-drift",
            Scene::Kelvin => "kelvin vs improved",
            Scene::Sets => "set 1 vs 2",
            Scene::Spectrum => "spectrum",
        }
    }
}

/// One parameter pane: the values being explored and the preset they came from.
#[derive(Debug, Clone)]
pub struct SetState {
    pub preset: Preset,
    pub params: Params,
}

impl SetState {
    pub fn new(preset: Preset) -> Self {
        SetState {
            params: preset.params,
            preset,
        }
    }
}

/// What the keyboard currently drives.
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    Normal,
    /// Typing an exact value into the selected field; `error` is the last rejection.
    Editing {
        text: String,
        error: Option<String>,
    },
    Help,
    /// Choosing a preset for the active set.
    Picker {
        selected: usize,
    },
    /// Typing a name to save the active set under.
    SaveName {
        text: String,
        error: Option<String>,
    },
    /// A user preset of that name exists: y overwrites it.
    ConfirmOverwrite {
        name: String,
    },
}

/// Work for the main loop, outside the pure state.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    Quit,
    /// Write the full history of a run as CSV to `path`.
    Export {
        params: Params,
        path: PathBuf,
    },
}

/// How the screen may be drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Look {
    /// Plain ASCII characters only (`--ascii`, or a locale that is not UTF-8).
    pub ascii: bool,
    /// Colours allowed (off with NO_COLOR).
    pub color: bool,
}

/// Progressive spectrum: the grid and the points computed so far.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumState {
    pub spec: SpectrumSpec,
    pub points: Vec<Option<SpectrumPoint>>,
}

impl SpectrumState {
    pub fn done(&self) -> usize {
        self.points.iter().filter(|p| p.is_some()).count()
    }
}

/// Results kept for reuse (switching scenes or sets back does not recompute).
const CACHE: usize = 12;

/// Π_ω1 grid of the spectrum scene.
pub fn spectrum_grid() -> Vec<f64> {
    (0..=56).map(|i| 0.2 + 0.05 * i as f64).collect()
}

/// The whole explorer state.
#[derive(Debug)]
pub struct App {
    pub sets: [SetState; 2],
    /// Index of the active set (0 or 1).
    pub active: usize,
    /// Selected row of the panes, an index into [`FIELDS`].
    pub selected: usize,
    pub scene: Scene,
    pub mode: Mode,
    /// Built-in presets, then the user's.
    pub presets: Vec<Preset>,
    pub user_dir: Option<PathBuf>,
    /// A one-line message (saved, exported, an error).
    pub status: Option<String>,
    /// Terminal size (columns, rows).
    pub size: (u16, u16),
    pub look: Look,
    /// Generation of the newest job; older outputs are dropped.
    pub generation: u64,
    /// What the newest job was asked for (the whole need, cached parts included).
    requested: Option<(Vec<RunSpec>, Option<SpectrumSpec>)>,
    /// Whether the newest job is still running.
    pub computing: bool,
    /// Finished runs, newest last.
    pub results: Vec<RunOutput>,
    pub spectrum: Option<SpectrumState>,
    pub quit: bool,
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
            scene: Scene::History,
            mode: Mode::Normal,
            presets,
            user_dir,
            status: None,
            size: (80, 24),
            look,
            generation: 0,
            requested: None,
            computing: false,
            results: Vec::new(),
            spectrum: None,
            quit: false,
        }
    }

    /// The built-in presets followed by the user's own in `dir`.
    pub fn load_presets(dir: Option<&PathBuf>) -> Vec<Preset> {
        let mut all = preset::builtins();
        if let Some(d) = dir {
            for name in preset::user_preset_names(d) {
                if preset::is_builtin(&name) {
                    continue;
                }
                if let Ok(p) = Preset::load(&d.join(format!("{name}.toml"))) {
                    all.push(p);
                }
            }
        }
        all
    }

    pub fn active_params(&self) -> &Params {
        &self.sets[self.active].params
    }

    // ----- what to compute -----

    /// History buckets for the current layout: the time chart's width in Braille dots.
    fn history_buckets(&self) -> usize {
        let columns = super::ui::chart_columns(self.size);
        (columns as usize * 2).max(16)
    }

    /// The runs and spectrum the visible scene needs.
    pub fn needed(&self) -> (Vec<RunSpec>, Option<SpectrumSpec>) {
        let buckets = self.history_buckets();
        let set = |i: usize, buckets: usize| RunSpec {
            slot: Slot::Set(i),
            params: self.sets[i].params,
            buckets,
        };
        let active = set(self.active, buckets);
        match self.scene {
            Scene::History => (vec![active], None),
            Scene::Loops => (vec![set(self.active, LOOP_BUCKETS)], None),
            Scene::Kelvin => {
                let mut twin = active;
                twin.slot = Slot::Twin;
                twin.params.model = twin.params.model.toggled();
                (vec![active, twin], None)
            }
            Scene::Sets => (vec![set(0, buckets), set(1, buckets)], None),
            Scene::Spectrum => {
                let p = self.active_params();
                let mu = p.mu();
                let spec = SpectrumSpec {
                    params: Params {
                        omega1: 1.0,
                        omega2: mu,
                        ..*p
                    },
                    mu,
                    grid: spectrum_grid(),
                };
                (vec![active], mu.is_finite().then_some(spec))
            }
        }
    }

    /// A new job when what the scene needs changed since the last request;
    /// parts already computed are left out. Bumps the generation.
    pub fn job(&mut self) -> Option<Job> {
        let need = self.needed();
        if self.requested.as_ref() == Some(&need) {
            return None;
        }
        self.generation += 1;
        self.requested = Some(need.clone());
        let (runs, spectrum) = need;
        let runs: Vec<RunSpec> = runs
            .into_iter()
            .filter(|s| self.cached(s).is_none())
            .collect();
        let spectrum = spectrum.filter(|s| {
            let complete = self
                .spectrum
                .as_ref()
                .is_some_and(|st| st.spec == *s && st.done() == st.points.len());
            !complete
        });
        if let Some(s) = &spectrum {
            if self.spectrum.as_ref().is_none_or(|st| st.spec != *s) {
                self.spectrum = Some(SpectrumState {
                    spec: s.clone(),
                    points: vec![None; s.grid.len()],
                });
            } else if let Some(st) = &mut self.spectrum {
                st.points.iter_mut().for_each(|p| *p = None);
            }
        }
        self.computing = !runs.is_empty() || spectrum.is_some();
        if !self.computing {
            return None;
        }
        Some(Job {
            generation: self.generation,
            runs,
            spectrum,
        })
    }

    fn cached(&self, spec: &RunSpec) -> Option<&RunOutput> {
        self.results.iter().rev().find(|o| o.spec == *spec)
    }

    /// The run to show for a slot: the exact one if computed, else the latest
    /// of that slot (shown while the new one computes).
    pub fn shown(&self, slot: Slot) -> Option<&RunOutput> {
        let (runs, _) = self.requested.clone().unwrap_or_default();
        runs.iter()
            .find(|s| s.slot == slot)
            .and_then(|s| self.cached(s))
            .or_else(|| self.results.iter().rev().find(|o| o.spec.slot == slot))
    }

    /// Takes a worker output; those of an older generation are dropped.
    pub fn on_output(&mut self, out: Output) {
        if out.generation() != self.generation {
            return;
        }
        match out {
            Output::Run { output, .. } => {
                self.results.retain(|o| o.spec != output.spec);
                self.results.push(*output);
                if self.results.len() > CACHE {
                    self.results.remove(0);
                }
            }
            Output::Point { index, point, .. } => {
                if let Some(p) = self.spectrum.as_mut().and_then(|s| s.points.get_mut(index)) {
                    *p = Some(point);
                }
            }
            Output::Done { .. } => self.computing = false,
        }
    }

    // ----- input -----

    pub fn on_resize(&mut self, columns: u16, rows: u16) {
        self.size = (columns, rows);
    }

    pub fn on_mouse(&mut self, m: MouseEvent) {
        if self.mode != Mode::Normal {
            return;
        }
        match m.kind {
            MouseEventKind::ScrollUp => self.nudge(1.0, StepSize::Normal),
            MouseEventKind::ScrollDown => self.nudge(-1.0, StepSize::Normal),
            MouseEventKind::Down(_) => {
                if let Some((set, row)) = super::ui::pane_hit(self.size, m.column, m.row) {
                    self.active = set;
                    self.selected = row;
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
            self.quit = true;
            return Some(Effect::Quit);
        }
        match self.mode.clone() {
            Mode::Normal => return self.on_normal_key(key),
            Mode::Help => self.mode = Mode::Normal,
            Mode::Editing { text, .. } => self.on_edit_key(key, text),
            Mode::Picker { selected } => self.on_picker_key(key, selected),
            Mode::SaveName { text, .. } => self.on_save_key(key, text),
            Mode::ConfirmOverwrite { name } => {
                self.mode = Mode::Normal;
                if matches!(key.code, KeyCode::Char('y') | KeyCode::Char('Y')) {
                    self.save(&name);
                } else {
                    self.status = Some(format!("not saved: `{name}` kept as it was"));
                }
            }
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
        self.status = None;
        match key.code {
            KeyCode::Char('q') | KeyCode::Esc => {
                self.quit = true;
                return Some(Effect::Quit);
            }
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
                let text = super::fields::value_text(self.active_params(), &FIELDS[self.selected]);
                self.mode = Mode::Editing { text, error: None };
            }
            KeyCode::Tab | KeyCode::BackTab => self.active = 1 - self.active,
            KeyCode::Char('m') => {
                let p = &mut self.sets[self.active].params;
                p.model = p.model.toggled();
            }
            KeyCode::Char('r') => {
                let s = &mut self.sets[self.active];
                s.params = s.preset.params;
                self.status = Some(format!(
                    "set {} reset to preset `{}`",
                    self.active + 1,
                    s.preset.name
                ));
            }
            KeyCode::Char('?') => self.mode = Mode::Help,
            KeyCode::Char('p') => self.mode = Mode::Picker { selected: 0 },
            KeyCode::Char('s') => {
                self.mode = Mode::SaveName {
                    text: String::new(),
                    error: None,
                }
            }
            KeyCode::Char('e') => return Some(self.export()),
            KeyCode::Char(c @ '1'..='9') => self.recall(c as usize - '1' as usize),
            KeyCode::Char(c) => {
                if let Some(s) = Scene::ALL.iter().find(|s| s.key() == c) {
                    self.scene = *s;
                }
            }
            _ => {}
        }
        None
    }

    fn select(&mut self, delta: isize) {
        let n = FIELDS.len() as isize;
        self.selected = (self.selected as isize + delta).rem_euclid(n) as usize;
    }

    /// Moves the selected field of the active set by one step of `size`.
    pub fn nudge(&mut self, direction: f64, size: StepSize) {
        let field = &FIELDS[self.selected];
        let params = &mut self.sets[self.active].params;
        match nudged_text(params, field, direction, size) {
            None => {
                self.status = Some(format!(
                    "`{}` is inf: press Enter to type a finite value",
                    field.key
                ))
            }
            Some(text) => {
                let mut next = *params;
                match next.set(field.key, &text).and_then(|_| next.validate()) {
                    Ok(()) => *params = next,
                    Err(e) => self.status = Some(e.to_string()),
                }
            }
        }
    }

    fn on_edit_key(&mut self, key: KeyEvent, mut text: String) {
        match key.code {
            KeyCode::Esc => self.mode = Mode::Normal,
            KeyCode::Enter => {
                let field = &FIELDS[self.selected];
                let mut next = self.sets[self.active].params;
                match next.set(field.key, &text).and_then(|_| next.validate()) {
                    Ok(()) => {
                        self.sets[self.active].params = next;
                        self.mode = Mode::Normal;
                    }
                    Err(e) => {
                        self.mode = Mode::Editing {
                            text,
                            error: Some(e.to_string()),
                        }
                    }
                }
            }
            KeyCode::Backspace => {
                text.pop();
                self.mode = Mode::Editing { text, error: None };
            }
            KeyCode::Char(c) if text.chars().count() < 32 => {
                text.push(c);
                self.mode = Mode::Editing { text, error: None };
            }
            _ => {}
        }
    }

    fn on_picker_key(&mut self, key: KeyEvent, selected: usize) {
        let n = self.presets.len().max(1);
        match key.code {
            KeyCode::Up | KeyCode::Char('k') => {
                self.mode = Mode::Picker {
                    selected: (selected + n - 1) % n,
                }
            }
            KeyCode::Down | KeyCode::Char('j') => {
                self.mode = Mode::Picker {
                    selected: (selected + 1) % n,
                }
            }
            KeyCode::Enter => {
                self.mode = Mode::Normal;
                self.recall(selected);
            }
            KeyCode::Char(c @ '1'..='9') => {
                self.mode = Mode::Normal;
                self.recall(c as usize - '1' as usize);
            }
            _ => self.mode = Mode::Normal,
        }
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

    fn on_save_key(&mut self, key: KeyEvent, mut text: String) {
        match key.code {
            KeyCode::Esc => self.mode = Mode::Normal,
            KeyCode::Enter => match self.check_save_name(&text) {
                Err(error) => {
                    self.mode = Mode::SaveName {
                        text,
                        error: Some(error),
                    }
                }
                Ok(path) if path.is_file() => self.mode = Mode::ConfirmOverwrite { name: text },
                Ok(_) => {
                    self.mode = Mode::Normal;
                    self.save(&text);
                }
            },
            KeyCode::Backspace => {
                text.pop();
                self.mode = Mode::SaveName { text, error: None };
            }
            KeyCode::Char(c) if text.chars().count() < 40 => {
                text.push(c);
                self.mode = Mode::SaveName { text, error: None };
            }
            _ => {}
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

    /// Saves the active set as user preset `name` (atomically) and makes it the set's preset.
    fn save(&mut self, name: &str) {
        let path = match self.check_save_name(name) {
            Ok(p) => p,
            Err(e) => {
                self.status = Some(e);
                return;
            }
        };
        let base = &self.sets[self.active].preset;
        let preset = Preset {
            name: name.to_string(),
            description: format!("saved from the explorer, based on {}", base.name),
            params: self.sets[self.active].params,
            spectrum: base.spectrum.clone(),
            physical: base.physical.clone(),
            path: Some(path.clone()),
            lines: Default::default(),
        };
        match preset.save(&path) {
            Ok(()) => {
                self.status = Some(format!("saved {}", path.display()));
                self.sets[self.active].preset = preset;
                self.presets = App::load_presets(self.user_dir.as_ref());
            }
            Err(e) => self.status = Some(format!("could not save {}: {e}", path.display())),
        }
    }

    fn export(&mut self) -> Effect {
        let set = &self.sets[self.active];
        let stamp = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs());
        let path = PathBuf::from(format!("pounding-{}-{stamp}.csv", set.preset.name));
        self.status = Some(format!("exporting {} ...", path.display()));
        Effect::Export {
            params: set.params,
            path,
        }
    }

    /// The contact model of the active set.
    pub fn model(&self) -> ContactModel {
        self.active_params().model
    }
}

/// History buckets of the force–drift scene: fine enough that a bucket's
/// midpoint traces the loop (SPEC §3).
pub const LOOP_BUCKETS: usize = 2048;

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
