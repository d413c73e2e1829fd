//! `pounding similarity`: Physical units in and out: dimensional spectra at several excitation levels and their master curve.

use clap::Args;

use super::CliError;

#[derive(Debug, Clone, Default, Args)]
pub struct SimilarityArgs {}

pub fn execute(_args: &SimilarityArgs) -> Result<(), CliError> {
    Err(CliError::Failed(
        "`pounding similarity` is not built yet".into(),
    ))
}
