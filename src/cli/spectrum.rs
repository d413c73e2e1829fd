//! `pounding spectrum`: Compute response spectra (peak response against Π_ω1, with and without pounding).

use clap::Args;

use super::CliError;

#[derive(Debug, Clone, Default, Args)]
pub struct SpectrumArgs {}

pub fn execute(_args: &SpectrumArgs) -> Result<(), CliError> {
    Err(CliError::Failed(
        "`pounding spectrum` is not built yet".into(),
    ))
}
