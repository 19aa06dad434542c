//! `biped ssv query|bench`.

use super::CliResult;
use clap::Subcommand;
use std::process::ExitCode;

/// `biped ssv ...` sub-commands.
#[derive(Subcommand)]
pub enum SsvCommand {
    /// Read JSON Lines queries from stdin, write one JSON result per line.
    Query,
    /// Time the six distance functions (thesis Table 6.9).
    Bench {
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
}

/// Run an `ssv` sub-command.
pub fn run(_cmd: SsvCommand) -> CliResult {
    Ok(ExitCode::SUCCESS)
}
