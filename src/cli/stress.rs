//! `pounding stress`: Numerical stress test over corner and random parameter sets.

use clap::Args;

use super::CliError;

#[derive(Debug, Clone, Default, Args)]
pub struct StressArgs {}

pub fn execute(_args: &StressArgs) -> Result<(), CliError> {
    Err(CliError::Failed(
        "`pounding stress` is not built yet".into(),
    ))
}
