//! `pounding bench`: Work-precision table: run time against error for each method.

use clap::Args;

use super::CliError;

#[derive(Debug, Clone, Default, Args)]
pub struct BenchArgs {}

pub fn execute(_args: &BenchArgs) -> Result<(), CliError> {
    Err(CliError::Failed("`pounding bench` is not built yet".into()))
}
