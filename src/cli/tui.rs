//! `pounding tui` (and `pounding` without a command, with the same flags):
//! open the terminal explorer.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use clap::Args;

use super::CliError;
use super::buildings::BuildingsArgs;
use super::params::user_preset_dir;
use crate::model::Preset;
use crate::tui::app::{App, Exit, Look};
use crate::tui::row_keys::DEFAULT_GROUND;
use crate::tui::row_pane::RowPane;
use crate::tui::scene::Scene;
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
    /// Open the buildings scene on this row of shear buildings (SPEC §13):
    /// a built-in row (two-buildings, block-and-frame, three-in-series, block-and-frame-pdelta,
    /// block-and-frame-retrofit) or a path to a row preset.
    #[arg(long, value_name = "NAME|PATH")]
    pub buildings: Option<String>,
    /// The row's ground: synthetic:N, record:PATH, sine, pulse-a, pulse-b, pulse-c1 or pulse-c2 [default: synthetic:2000].
    #[arg(long, value_name = "GROUND")]
    pub excitation: Option<String>,
    /// Scale factor on the row's ground.
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub scale: Option<f64>,
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
    if let Some(source) = &args.buildings {
        app.row = Some(row_pane(args, source)?);
        app.view.scene = Scene::Buildings;
        // The risk scene studies the row's first joint.
        app.view.risk_joint = 1;
    } else if args.excitation.is_some() || args.scale.is_some() {
        return Err(CliError::Usage(
            "--excitation and --scale of the explorer apply to a row: give --buildings".into(),
        ));
    }
    Ok(app)
}

/// The row of `--buildings` on its ground, checked as `run --buildings` checks them.
fn row_pane(args: &TuiArgs, source: &str) -> Result<RowPane, CliError> {
    let buildings = BuildingsArgs {
        buildings: Some(source.to_string()),
        scale: args.scale,
        ..BuildingsArgs::default()
    };
    let row = buildings.row(&[], None)?;
    let excitation = args.excitation.as_deref().unwrap_or(DEFAULT_GROUND);
    let (ground, name, _) = buildings.ground(Some(excitation), None, &row)?;
    RowPane::open(source, Arc::new(ground), &name, None).map_err(CliError::Usage)
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
