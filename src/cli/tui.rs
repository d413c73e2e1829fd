//! `pounding tui`: Open the terminal explorer.

use clap::Args;

use super::CliError;

#[derive(Debug, Clone, Default, Args)]
pub struct TuiArgs {}

pub fn execute(_args: &TuiArgs) -> Result<(), CliError> {
    Err(CliError::Failed("`pounding tui` is not built yet".into()))
}
