//! Sub-command implementations, one module per capability.

pub mod bench_ik;
pub mod calibrate;
pub mod dynamics;
pub mod files;
pub mod interrupt;
mod json_lines;
#[cfg(test)]
mod option_props;
pub mod out;
pub mod outdir;
pub mod range;
pub mod simulate;
pub mod ssv;
#[cfg(feature = "view")]
pub mod view;
pub mod walk;
pub mod words;

use clap::Subcommand;
use std::process::ExitCode;

/// Error type of the CLI: one line that says what is wrong and where.
pub type CliResult = Result<ExitCode, Box<dyn std::error::Error>>;

/// `biped bench ...` sub-commands.
#[derive(Subcommand)]
pub enum BenchCommand {
    /// Median forward-dynamics time per algorithm (and per O(n) pass).
    Dynamics(dynamics::BenchArgs),
    /// Median and p99 time of one whole-body IK step, peer task set and full set.
    Ik(bench_ik::BenchIkArgs),
}

/// Dispatch `biped bench ...`.
pub fn run_bench(cmd: BenchCommand) -> CliResult {
    match cmd {
        BenchCommand::Dynamics(args) => dynamics::run_bench(args),
        BenchCommand::Ik(args) => bench_ik::run(args),
    }
}
