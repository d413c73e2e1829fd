//! `pounding tui` (and `pounding` without a command, with the same flags):
//! open the terminal explorer.

use std::path::{Path, PathBuf};

use clap::Args;

use super::CliError;
use super::params::user_preset_dir;
use crate::model::Preset;
use crate::tui::app::{App, Exit, Look};
use crate::tui::{explorer, presets, terminal};

#[derive(Debug, Clone, Default, Args)]
pub struct TuiArgs {
    /// Preset (name or file) of the left pane, set 1 [default: set1].
    #[arg(long, value_name = "NAME|PATH")]
    pub left: Option<String>,
    /// Preset (name or file) of the right pane, set 2 [default: set2].
    #[arg(long, value_name = "NAME|PATH")]
    pub right: Option<String>,
    /// Plain ASCII drawing (automatic when the locale is not UTF-8).
    #[arg(long)]
    pub ascii: bool,
    /// Directory of the user's own presets [default: $XDG_CONFIG_HOME/pounding/presets].
    #[arg(long, value_name = "DIR")]
    pub presets: Option<PathBuf>,
}

/// Where exports and figures are proposed: the current directory when it
/// is a writable one other than `/`, else the home directory, else the
/// temporary directory.
fn export_dir() -> PathBuf {
    let writable = |d: &Path| {
        std::fs::metadata(d).is_ok_and(|m| m.is_dir() && !m.permissions().readonly())
            && tempfile::tempfile_in(d).is_ok()
    };
    let cwd = std::env::current_dir().ok();
    cwd.filter(|d| d != Path::new("/") && writable(d))
        .or_else(|| {
            std::env::var_os("HOME")
                .map(PathBuf::from)
                .filter(|d| writable(d))
        })
        .unwrap_or_else(std::env::temp_dir)
}

/// Builds the explorer's starting state from the arguments and the environment.
pub fn app(args: &TuiArgs) -> Result<App, CliError> {
    let dir = user_preset_dir(args.presets.as_ref());
    let dirs: Vec<PathBuf> = dir.iter().cloned().collect();
    let left = Preset::find(args.left.as_deref().unwrap_or("set1"), &dirs)?;
    let right = Preset::find(args.right.as_deref().unwrap_or("set2"), &dirs)?;
    let look = Look {
        ascii: args.ascii || !terminal::utf8_locale(),
        color: terminal::color_allowed(),
    };
    let list = presets::load(dir.as_deref());
    let mut app = App::new(left, right, list, dir, look);
    app.export_dir = export_dir();
    Ok(app)
}

pub fn execute(args: &TuiArgs) -> Result<(), CliError> {
    if let Some(why) = terminal::unusable() {
        return Err(CliError::Usage(why));
    }
    let app = app(args)?;
    match explorer::run(app) {
        Ok(Exit::Quit) => Ok(()),
        // Ended by a signal: the status a shell expects, 128 + its number.
        Ok(Exit::Signal(signal)) => {
            crate::output::temp::remove_live();
            std::process::exit(128 + signal)
        }
        Err(e) => Err(CliError::Failed(format!("terminal: {e}"))),
    }
}
