//! `pounding tui` (and `pounding` without a command): open the terminal explorer.

use std::path::PathBuf;

use clap::Args;

use super::CliError;
use super::params::user_preset_dir;
use crate::model::Preset;
use crate::tui::app::{App, Look};
use crate::tui::{explorer, terminal};

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
    let presets = App::load_presets(dir.as_ref());
    Ok(App::new(left, right, presets, dir, look))
}

pub fn execute(args: &TuiArgs) -> Result<(), CliError> {
    if let Some(why) = terminal::unusable() {
        return Err(CliError::Usage(why));
    }
    let app = app(args)?;
    explorer::run(app).map_err(|e| CliError::Failed(format!("terminal: {e}")))
}
