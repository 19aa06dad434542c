//! `biped model`, `biped dynamics`, `biped bench dynamics`.

use super::CliResult;
use clap::Args;
use std::process::ExitCode;

/// Arguments of `biped model`.
#[derive(Args)]
pub struct ModelArgs {}

/// Arguments of `biped dynamics`.
#[derive(Args)]
pub struct DynamicsArgs {}

/// Arguments of `biped bench dynamics`.
#[derive(Args)]
pub struct BenchArgs {}

/// Run `biped model`.
pub fn run_model(_args: ModelArgs) -> CliResult {
    Ok(ExitCode::SUCCESS)
}

/// Run `biped dynamics`.
pub fn run_dynamics(_args: DynamicsArgs) -> CliResult {
    Ok(ExitCode::SUCCESS)
}

/// Run `biped bench dynamics`.
pub fn run_bench(_args: BenchArgs) -> CliResult {
    Ok(ExitCode::SUCCESS)
}
