//! `biped`: command-line front end of the biped toolkit.
//!
//! Each capability owns one module under `cli/`; this file only wires the sub-commands and
//! turns every error into one line on stderr: a bad command line (exit status 2), a failed
//! sub-command (exit status 1). A reader that closes stdout early (`biped ... | head -1`)
//! ends the run quietly with status 0.

use biped::cli;
use clap::error::ErrorKind;
use clap::{Parser, Subcommand};
use cli::out::{clap_error_line as one_line, diagnostic, is_broken_pipe};
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
    /// Serve the browser viewer and SSV modelling tool (robot, collision model, recordings).
    #[cfg(feature = "view")]
    View(cli::view::ViewArgs),
    /// Benchmarks of whole capabilities.
    #[command(subcommand)]
    Bench(cli::BenchCommand),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return usage_error(&e),
    };
    let result = match cli.command {
        Command::Ssv(cmd) => cli::ssv::run(cmd),
        Command::Model(args) => cli::dynamics::run_model(args),
        Command::Dynamics(args) => cli::dynamics::run_dynamics(args),
        Command::Calibrate(args) => cli::calibrate::run(args),
        Command::Simulate(args) => cli::simulate::run(*args),
        Command::Walk(args) => cli::walk::run(args),
        #[cfg(feature = "view")]
        Command::View(args) => cli::view::run(args),
        Command::Bench(cmd) => cli::run_bench(cmd),
    };
    match result {
        Ok(code) => code,
        Err(err) if is_broken_pipe(&*err) => ExitCode::SUCCESS,
        Err(err) => {
            diagnostic(format_args!("error: {err}"));
            ExitCode::FAILURE
        }
    }
}

/// Prints `--help` / `--version` as clap does, or a command-line error as one line.
fn usage_error(e: &clap::Error) -> ExitCode {
    match e.kind() {
        ErrorKind::DisplayHelp
        | ErrorKind::DisplayVersion
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print(); // Help on a closed pipe: nothing to report.
            ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2))
        }
        _ => {
            diagnostic(format_args!("{}", one_line(e)));
            ExitCode::from(2)
        }
    }
}

/// The command tree with its argument parsing, as `main` uses it (for the tests).
#[cfg(test)]
fn parse(args: &[&str]) -> Result<Cli, clap::Error> {
    use clap::FromArgMatches;
    let mut cmd = <Cli as clap::CommandFactory>::command();
    let matches = cmd.try_get_matches_from_mut(args)?;
    Cli::from_arg_matches(&matches)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    /// Placeholders of option values that are not numbers (names, paths, choices).
    const NOT_NUMERIC: [&str; 11] = [
        "FILE",
        "DIR",
        "NAME",
        "TYPE",
        "METHOD",
        "SIGNALS",
        "LEFT,RIGHT",
        "HIP_L,HIP_R,ANKLE_L,ANKLE_R",
        "POSE",
        "ALGORITHM",
        "INTEGRATOR",
    ];

    /// Every option that takes a number (any value whose placeholder is not a name, a path or
    /// a choice) accepts one written with a minus sign, so that the range checks, not the
    /// flag parser, judge it: `--step-length -0.4`, `--sole-size -1,1`, `--step -1e-3`.
    #[test]
    fn numeric_options_take_negative_values() {
        let mut root = Cli::command();
        root.build();
        let (mut checked, mut failed) = (0, Vec::new());
        let mut stack: Vec<(Vec<String>, &clap::Command)> = vec![(vec![], &root)];
        while let Some((path, cmd)) = stack.pop() {
            for sub in cmd.get_subcommands() {
                let mut p = path.clone();
                p.push(sub.get_name().to_string());
                stack.push((p, sub));
            }
            for arg in cmd.get_arguments() {
                let (Some(long), Some(names)) = (arg.get_long(), arg.get_value_names()) else {
                    continue;
                };
                let name = names.first().map(|n| n.as_str()).unwrap_or_default();
                if NOT_NUMERIC.contains(&name) || !arg.get_action().takes_values() {
                    continue;
                }
                let mut argv = vec!["biped".to_string()];
                argv.extend(path.iter().cloned());
                argv.extend([format!("--{long}"), "-1e-3".into()]);
                let argv: Vec<&str> = argv.iter().map(String::as_str).collect();
                if let Err(e) = parse(&argv) {
                    let k = e.kind();
                    if k == ErrorKind::UnknownArgument || k == ErrorKind::NoEquals {
                        failed.push(format!("{argv:?}: {}", one_line(&e)));
                    }
                }
                checked += 1;
            }
        }
        assert!(failed.is_empty(), "{failed:#?}");
        assert!(checked >= 19, "only {checked} numeric options found");
    }

    #[test]
    fn clap_errors_are_one_line() {
        for argv in [
            &["biped", "walk", "--open-loop"][..],
            &["biped", "walk", "--no-such-option"],
            &["biped", "model"],
            &["biped", "model", "--dill", "x"],
            &["biped", "walk", "--steps", "-1"],
            &["biped", "model", "--dill", "-3"],
        ] {
            let e = parse(argv).err().expect("an error");
            let line = one_line(&e);
            assert!(
                !line.contains('\n') && line.starts_with("error: "),
                "{argv:?}: {line}"
            );
        }
        let e = parse(&["biped", "walk", "--open-loop"]).err().unwrap();
        assert!(one_line(&e).contains("--dynamic"), "{}", one_line(&e));
        let e = parse(&["biped", "model", "--dill", "-3"]).err().unwrap();
        assert!(one_line(&e).contains("'--dill <N>'"), "{}", one_line(&e));
        let e = parse(&["biped", "walk", "--steps", "-1"]).err().unwrap();
        assert!(
            one_line(&e).starts_with("error: --steps: -1 is out of range"),
            "{}",
            one_line(&e)
        );
    }
}
