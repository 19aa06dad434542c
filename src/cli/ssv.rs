//! `biped ssv query|model|fit|bench`: the SSV distance library on the command line.

mod bench;
mod fit;
mod model;
mod query;

use super::CliResult;
use clap::Subcommand;

/// `biped ssv ...` sub-commands.
#[derive(Subcommand)]
pub enum SsvCommand {
    /// Read JSON Lines queries `{"a": S, "b": S}` from stdin, write one JSON result per line.
    #[command(long_about = QUERY_HELP)]
    Query,
    /// Load a collision-model file and print every segment pair's distance in a posture.
    Model(model::ModelArgs),
    /// Fit a collision model (SSVs containing each link's shapes, sampled pairs) to a URDF.
    #[command(long_about = fit::FIT_HELP)]
    Fit(fit::FitArgs),
    /// Time the six distance functions on random inputs (thesis Table 6.9).
    Bench {
        /// Print one JSON object `{"PP": ns, ...}` instead of the table.
        #[arg(long)]
        json: bool,
    },
}

/// The input and output formats of `biped ssv query`.
const QUERY_HELP: &str = "\
Read JSON Lines queries from stdin and write one JSON result line per query, in order.

Each input line is {\"a\": S, \"b\": S} with two swept-sphere volumes S, coordinates in metres:
  {\"point\": [x, y, z], \"radius\": r}                         point-swept sphere (a sphere)
  {\"line\": [[x, y, z], [x, y, z]], \"radius\": r}             line-swept sphere (a capsule)
  {\"triangle\": [[x, y, z], [x, y, z], [x, y, z]], \"radius\": r} triangle-swept sphere
The radius is >= 0.

Each output line is {\"distance\": d, \"point_a\": [..], \"point_b\": [..]}: the signed
distance between the surfaces (negative when the volumes overlap) and the closest surface
points. A bad line is answered with {\"error\": \"line N: ...\"} and the others are still
answered; the exit status is then 1. Blank lines are skipped.

Example:
  echo '{\"a\": {\"point\": [0,0,0], \"radius\": 1}, \"b\": {\"line\": [[3,-1,0],[3,1,0]], \"radius\": 0.5}}' | biped ssv query";

/// Run an `ssv` sub-command.
pub fn run(cmd: SsvCommand) -> CliResult {
    match cmd {
        SsvCommand::Query => query::run(),
        SsvCommand::Bench { json } => bench::run(json),
        SsvCommand::Model(args) => model::run(args),
        SsvCommand::Fit(args) => fit::run(args),
    }
}
