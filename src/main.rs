//! `biped`: command-line front end of the biped toolkit.
//!
//! Each capability owns one module under `cli/`; this file only wires the sub-commands.

mod cli;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Efficient algorithms for biped robots (Schwienbacher 2014), in Rust.
#[derive(Parser)]
#[command(name = "biped", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Swept-sphere-volume distance queries and benchmarks (thesis ch. 6).
    #[command(subcommand)]
    Ssv(cli::ssv::SsvCommand),
    /// Print a multibody model's coordinates, joints and bodies.
    Model(cli::dynamics::ModelArgs),
    /// Forward/inverse dynamics and mass matrices on JSON Lines from stdin.
    Dynamics(cli::dynamics::DynamicsArgs),
    /// Calibrate absolute-encoder offsets from jig measurements (thesis 3.5).
    Calibrate(cli::calibrate::CalibrateArgs),
    /// Simulate a scenario (stand, drop, sway) and write signals, plots and a summary.
    Simulate(Box<cli::simulate::SimulateArgs>),
    /// Walk Lola with the whole-body IK and compare the arm methods (thesis ch. 7).
    Walk(cli::walk::WalkArgs),
    /// Benchmarks of whole capabilities.
    #[command(subcommand)]
    Bench(cli::BenchCommand),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Ssv(cmd) => cli::ssv::run(cmd),
        Command::Model(args) => cli::dynamics::run_model(args),
        Command::Dynamics(args) => cli::dynamics::run_dynamics(args),
        Command::Calibrate(args) => cli::calibrate::run(args),
        Command::Simulate(args) => cli::simulate::run(*args),
        Command::Walk(args) => cli::walk::run(args),
        Command::Bench(cmd) => cli::run_bench(cmd),
    };
    match result {
        Ok(code) => code,
        Err(err) => {
            eprintln!("error: {err}");
            ExitCode::FAILURE
        }
    }
}
