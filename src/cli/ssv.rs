//! `biped ssv query|bench`: the SSV distance library on the command line.

mod bench;
mod model;
mod query;

use super::CliResult;
use clap::Subcommand;

/// `biped ssv ...` sub-commands.
#[derive(Subcommand)]
pub enum SsvCommand {
    /// Read JSON Lines queries `{"a": S, "b": S}` from stdin, write one JSON result per line.
    Query,
    /// Load a collision-model file and print every segment pair's distance in a posture.
    Model(model::ModelArgs),
    /// Time the six distance functions on random inputs (thesis Table 6.9).
    Bench {
        /// Print one JSON object `{"PP": ns, ...}` instead of the table.
        #[arg(long)]
        json: bool,
    },
}

/// Run an `ssv` sub-command.
pub fn run(cmd: SsvCommand) -> CliResult {
    match cmd {
        SsvCommand::Query => query::run(),
        SsvCommand::Bench { json } => bench::run(json),
        SsvCommand::Model(args) => model::run(args),
    }
}
