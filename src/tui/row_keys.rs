//! What a key does in the buildings scene: the pane's rows (select, nudge,
//! type), the time cursor and playback, the exaggeration, the panel,
//! Kelvin against improved Kelvin, and recalling a row preset. Keys it does
//! not take fall through to the explorer's own (scenes, help, quit).

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;

use crossterm::event::{KeyCode, KeyEvent};

use super::app::{App, Mode};
use super::effects::Effect;
use super::fields::StepSize;
use super::layout;
use super::row_file::{RowFile, RowSnapshot};
use super::row_pane::RowPane;
use super::scene::Scene;
use super::text_field::{FieldKey, TextField};
use crate::model::buildings::{Ground, builtin};
use crate::model::simulated::Simulation;

/// The ground of a row opened from the explorer without `--buildings`.
pub const DEFAULT_GROUND: &str = "synthetic:2000";
/// The row opened then.
pub const DEFAULT_ROW: &str = "block-and-frame";

impl App {
    /// The row of the buildings scene, opened on the default row and ground
    /// when there is none yet.
    pub fn ensure_row(&mut self) {
        if self.row.is_some() {
            return;
        }
        let record = Simulation::synthetic(DEFAULT_GROUND, 2000).expect("2000 samples are valid");
        let ground = Arc::new(Ground::from_record(&record, 1.0));
        match RowPane::open(DEFAULT_ROW, ground, DEFAULT_GROUND, None) {
            Ok(pane) => self.row = Some(pane),
            Err(e) => self.status = Some(e),
        }
    }

    /// Opens the row preset `name` on the current ground, in the buildings scene.
    pub fn recall_row(&mut self, name: &str) {
        self.ensure_row();
        let Some(pane) = self.row.as_ref() else {
            return;
        };
        match pane.reopen(name) {
            Ok(next) => {
                self.status = Some(format!("row ← preset `{name}`"));
                self.row = Some(next);
                self.view.scene = Scene::Buildings;
            }
            Err(e) => self.status = Some(e),
        }
    }

    /// A key in the buildings scene; `None` when it is not the scene's.
    pub fn on_row_key(&mut self, key: KeyEvent, size: StepSize) -> Option<()> {
        let columns = layout::chart_columns(self.size);
        let pane = self.row.as_mut()?;
        let n = pane.fields().len();
        let outcome = match key.code {
            KeyCode::Up | KeyCode::Char('k') => {
                pane.selected = (pane.selected + n - 1) % n;
                Ok(())
            }
            KeyCode::Down | KeyCode::Char('j') => {
                pane.selected = (pane.selected + 1) % n;
                Ok(())
            }
            KeyCode::Left | KeyCode::Char('h') | KeyCode::Char('-') => pane.nudge(-1.0, size),
            KeyCode::Right | KeyCode::Char('l') | KeyCode::Char('+') | KeyCode::Char('=') => {
                pane.nudge(1.0, size)
            }
            KeyCode::Char('H') | KeyCode::Char('_') => pane.nudge(-1.0, StepSize::Coarse),
            KeyCode::Char('L') => pane.nudge(1.0, StepSize::Coarse),
            KeyCode::Char(',') => pane.nudge(-1.0, StepSize::Fine),
            KeyCode::Char('.') => pane.nudge(1.0, StepSize::Fine),
            KeyCode::Enter => {
                let fields = pane.fields();
                let text = fields[pane.selected.min(n - 1)]
                    .value
                    .trim_start_matches('~');
                self.mode = Mode::Editing(TextField::new(text, 64));
                Ok(())
            }
            KeyCode::Char(' ') => {
                pane.toggle_play(Instant::now());
                Ok(())
            }
            KeyCode::Esc => {
                pane.play.pause();
                Ok(())
            }
            KeyCode::Char('[') => {
                pane.move_cursor(-1.0, columns);
                Ok(())
            }
            KeyCode::Char(']') => {
                pane.move_cursor(1.0, columns);
                Ok(())
            }
            KeyCode::Char('{') => {
                pane.move_cursor(-10.0, columns);
                Ok(())
            }
            KeyCode::Char('}') => {
                pane.move_cursor(10.0, columns);
                Ok(())
            }
            KeyCode::Home => {
                pane.cursor = 0.0;
                Ok(())
            }
            KeyCode::End => {
                pane.cursor = pane.duration();
                Ok(())
            }
            KeyCode::Char(c @ ('<' | '>')) => {
                let shown = self
                    .jobs
                    .shown_row()
                    .map(|o| super::views::row::exaggeration(pane, o));
                if let Some(x) = shown {
                    pane.exaggeration = Some(if c == '>' { x * 2.0 } else { x / 2.0 });
                }
                Ok(())
            }
            KeyCode::Char('(') => {
                pane.play.step_speed(false);
                Ok(())
            }
            KeyCode::Char(')') => {
                pane.play.step_speed(true);
                Ok(())
            }
            KeyCode::Char('o') => {
                pane.panel = pane.panel.next();
                Ok(())
            }
            KeyCode::Char('|') => {
                pane.side_by_side = !pane.side_by_side;
                Ok(())
            }
            KeyCode::Char('b') if !pane.row.is_retrofitted() && !pane.bare => Err(
                "b: this row has no bumper or link to take away (try block-and-frame-retrofit)"
                    .to_string(),
            ),
            KeyCode::Char('b') => {
                pane.bare = !pane.bare;
                Ok(())
            }
            KeyCode::Char('m') => {
                let next = pane.row.model.toggled();
                pane.apply(vec![("model".into(), format!("\"{}\"", next.name()))])
            }
            KeyCode::Char('r') => {
                pane.reset();
                self.status = Some(format!("row reset to preset `{}`", pane.source));
                Ok(())
            }
            KeyCode::Char(c @ '1'..='9') => {
                let k = c as usize - '1' as usize;
                match builtin::names().get(k) {
                    Some(name) => self.recall_row(name),
                    None => {
                        self.status = Some(format!(
                            "no row preset {} (there are {})",
                            k + 1,
                            builtin::names().len()
                        ))
                    }
                }
                Ok(())
            }
            KeyCode::Tab | KeyCode::BackTab | KeyCode::Char('u') => {
                Err("one row: Tab and u act on the pair's scenes".to_string())
            }
            KeyCode::Char('e') => {
                self.ask_row_file(RowFile::Csv);
                Ok(())
            }
            KeyCode::Char('g') => {
                self.ask_row_file(RowFile::Figure);
                Ok(())
            }
            KeyCode::Char('s') => {
                let name = &pane.source;
                Err(format!(
                    "rows are presets of their own: s saves the pair's sets; the row's edits are --set NAME.KEY=V of pounding run --buildings {name}"
                ))
            }
            _ => return None,
        };
        if let Err(e) = outcome {
            self.status = Some(e);
        }
        Some(())
    }

    /// Typed text for the selected row of the buildings scene: taken, or
    /// kept in the field with the CLI's line on why not.
    pub fn on_row_edit(&mut self, text: &str) -> Result<(), String> {
        match self.row.as_mut() {
            Some(pane) => pane.type_value(text),
            None => Ok(()),
        }
    }

    /// When the next frame of playback is due.
    pub fn frame_due(&self) -> Option<Instant> {
        self.row
            .as_ref()
            .filter(|_| self.view.scene == Scene::Buildings)
            .and_then(|p| p.play.due())
    }

    /// Moves playback on to `now`; whether the screen changed.
    pub fn on_tick(&mut self, now: Instant) -> bool {
        if self.view.scene != Scene::Buildings {
            return false;
        }
        self.row.as_mut().is_some_and(|p| p.tick(now))
    }
}

/// Longest path typed.
const PATH_MAX: usize = 1024;

impl App {
    /// `e` or `g` in the buildings scene: asks where, in the export folder
    /// by default (`pounding-ROW-buildings.csv|svg`).
    pub fn ask_row_file(&mut self, file: RowFile) {
        let Some(pane) = self.row.as_ref() else {
            return;
        };
        let name = format!(
            "pounding-{}-buildings.{}",
            pane.row.name.replace([' ', '/'], "-"),
            file.extension()
        );
        let path = self.export_dir.join(name).display().to_string();
        self.mode = Mode::RowFile {
            path: TextField::new(&path, PATH_MAX),
            file,
        };
    }

    /// A key in the prompt of [`App::ask_row_file`].
    pub fn on_row_file_key(
        &mut self,
        key: KeyEvent,
        mut path: TextField,
        file: RowFile,
    ) -> Option<Effect> {
        match path.on_key(key) {
            FieldKey::Cancel => None,
            FieldKey::Submit => {
                let pane = self.row.as_ref()?;
                let snapshot = RowSnapshot {
                    row: pane.row.clone(),
                    ground: pane.ground.clone(),
                    ground_name: pane.ground_name.clone(),
                    duration: pane.duration(),
                };
                let target = PathBuf::from(path.text());
                self.status = Some(format!("writing {} ...", crate::output::shown(&target)));
                Some(Effect::RowFile {
                    snapshot: Box::new(snapshot),
                    file,
                    path: target,
                })
            }
            _ => {
                self.mode = Mode::RowFile { path, file };
                None
            }
        }
    }
}
