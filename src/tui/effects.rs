//! All I/O the explorer does besides drawing, as values: the app returns an
//! [`Effect`], the main loop ([`super::explorer`]) runs it with
//! [`run`] and hands what came of it back to the app as a [`Done`].
//! Every file goes through [`crate::output`] (atomic, temporary files
//! removed on drop, signals and at the next start).

use std::path::{Path, PathBuf};

use super::export::{self, History};
use super::presets;
use crate::figure::{self, FigureName, Format, Options};
use crate::model::{Params, Preset};

/// Work for the main loop.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    Quit,
    /// Write `preset` to `path`; it becomes set `set`'s preset.
    Save {
        set: usize,
        preset: Box<Preset>,
        path: PathBuf,
    },
    /// Write a history of the run of `params` as CSV.
    Export {
        params: Params,
        path: PathBuf,
        history: History,
    },
    /// Draw a scene as SVG.
    Figure {
        name: FigureName,
        title: String,
        params: Params,
        path: PathBuf,
    },
    /// Write the row's CSV or figure.
    RowFile {
        snapshot: Box<super::row_file::RowSnapshot>,
        file: super::row_file::RowFile,
        path: PathBuf,
    },
    /// Read the user's presets again (another process may have saved some).
    ReloadPresets,
    /// Capture mouse buttons (click, wheel) or leave the mouse to the terminal.
    Mouse(bool),
}

/// What came of an effect.
#[derive(Debug, Clone)]
pub enum Done {
    /// A message for the status line.
    Status(String),
    Saved {
        set: usize,
        preset: Box<Preset>,
        message: String,
    },
    /// The user's presets as read now.
    Presets(Vec<Preset>),
}

/// Runs a file effect to its end (called on a thread for the slow ones).
pub fn run(effect: Effect, user_dir: Option<&Path>) -> Vec<Done> {
    match effect {
        Effect::Save { set, preset, path } => match preset.save(&path) {
            Ok(()) => vec![
                Done::Saved {
                    set,
                    preset,
                    message: format!("saved {}", crate::output::shown(&path)),
                },
                Done::Presets(presets::user_presets(user_dir)),
            ],
            Err(e) => vec![Done::Status(format!(
                "could not save {}: {e}",
                crate::output::shown(&path)
            ))],
        },
        Effect::Export {
            params,
            path,
            history,
        } => vec![Done::Status(export::write_history(
            &params, &path, &history,
        ))],
        Effect::Figure {
            name,
            title,
            params,
            path,
        } => vec![Done::Status(write_figure(name, &title, &params, &path))],
        Effect::RowFile {
            snapshot,
            file,
            path,
        } => vec![Done::Status(super::row_file::write(&snapshot, file, &path))],
        Effect::ReloadPresets => vec![Done::Presets(presets::user_presets(user_dir))],
        Effect::Quit | Effect::Mouse(_) => Vec::new(),
    }
}

/// Draws scene `name` of `params` with `crate::figure` and writes it as SVG.
fn write_figure(name: FigureName, title: &str, params: &Params, path: &Path) -> String {
    let options = Options {
        method: params.method,
        grid: None,
        scene: figure::Scene {
            name: title.to_string(),
            params: params.clone(),
            spectrum: None,
        },
        suite: None,
    };
    let bytes = figure::build(name, &options)
        .and_then(|fig| figure::encode(&fig, Format::Svg, (1200, 900)));
    match bytes {
        Ok(b) => match crate::output::write_file(path, &b) {
            Ok(()) => format!(
                "figure `{name}` written to {} ({} KB)",
                crate::output::shown(path),
                b.len().div_ceil(1024)
            ),
            Err(e) => format!("could not write the figure: {e}"),
        },
        Err(e) => format!("could not draw the figure: {e}"),
    }
}
