//! `biped calibrate`: encoder-offset calibration from jig measurements (thesis 3.5).

use super::CliResult;
use clap::Args;
use std::process::ExitCode;

/// Arguments of `biped calibrate`.
#[derive(Args)]
pub struct CalibrateArgs {}

/// Run `biped calibrate`.
pub fn run(_args: CalibrateArgs) -> CliResult {
    Ok(ExitCode::SUCCESS)
}
