//! `biped walk`: the whole-body IK of the Lola-like biped (or of a described robot,
//! `--robot`) over a walking pattern with the arm methods of thesis
//! ch. 7; writes per-method CSV, SVG plots in the style of Fig. 7.1/7.4 and `summary.json`.
//! With `--dynamic` the walk of one method (`--method`, default minimisation) is then tracked
//! in the contact simulation: `dynamic.csv`, plots and a `"dynamic"` summary entry.

use super::{interrupt, outdir, range, CliResult};
use crate::cli::out::outln;
use clap::Args;
use std::path::PathBuf;

mod execute;
mod report;
mod robot;
pub mod tables;

pub use execute::{execute, parse_args, Walk};

/// Arguments of `biped walk`; the numbers are checked against [`range::walk`] while parsing.
#[derive(Args)]
pub struct WalkArgs {
    /// Number of steps (1 to 100).
    #[arg(long, value_name = "N", default_value_t = 10, allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::STEPS.parse_whole(s).map(|n| n as usize))]
    steps: usize,
    /// Robot: `g1`, `talos` (bundled descriptions) or a robot description file
    /// (docs/robot_description.md); default: the Lola-like biped.
    #[arg(long, value_name = "NAME")]
    robot: Option<String>,
    /// Step length in m (footprint ahead of the previous one; -0.6 to 0.6, negative:
    /// backwards; default 0.4 for the Lola-like biped, a described robot's natural step
    /// length from its leg geometry).
    #[arg(long, value_name = "M", allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::STEP_LENGTH.parse(s))]
    step_length: Option<f64>,
    /// Step time in s (0.2 to 5).
    #[arg(long, value_name = "S", default_value_t = 0.8, allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::STEP_TIME.parse(s))]
    step_time: f64,
    /// Arm method: `none` (arms held still), `reference` (arms swing with the opposite legs,
    /// thesis 7.3.1), `compensation` (arms move to cancel the legs' vertical angular momentum,
    /// 7.3.2), `minimization` (the IK minimises the vertical angular momentum, 7.5) or `all`.
    #[arg(long, value_name = "METHOD", default_value = "all")]
    method: String,
    /// Then track the walk of one method (--method, default minimization) in the contact
    /// simulation; fails if the robot falls.
    #[arg(long)]
    dynamic: bool,
    /// With --dynamic: track the LIPM pattern as planned, without the multibody ZMP correction
    /// and the ankle stabiliser (for comparison; the default walk falls).
    #[arg(long, requires = "dynamic")]
    open_loop: bool,
    /// With --dynamic: no end stops at the joint ranges in the plant (by default the plant has
    /// them; the planned motion stays inside the ranges).
    #[arg(long, requires = "dynamic")]
    no_end_stops: bool,
    /// Coulomb coefficient of the ground (0.05 to 3): the friction verdict checks the planned
    /// ground wrench against it, and with --dynamic the simulated soles slide on it.
    #[arg(long, value_name = "MU", default_value_t = 0.8, allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::FRICTION.parse(s))]
    friction: f64,
    /// Report a walk that leaves the joint ranges, lets segments interpenetrate, needs more
    /// friction than the ground has or lifts a supporting foot as a warning and exit 0 (for
    /// exploration); by default such a walk exits non-zero.
    #[arg(long)]
    allow_violations: bool,
    /// Output directory (default `out/walk`).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

/// Run `biped walk`.
pub fn run(args: WalkArgs) -> CliResult {
    let walk = execute(&args, true)?;
    let target = args.target();
    report::print(&args, &walk, walk.dynamic.as_ref())?;
    outln!("wrote {}", target.display())?;
    if let Some(line) = walk.failure() {
        return Err(line.into());
    }
    report::violations(&walk.lines, args.allow_violations)
}

impl WalkArgs {
    /// Whether violations are accepted (`--allow-violations`).
    pub fn allow_violations(&self) -> bool {
        self.allow_violations
    }

    /// The output folder (`--out`, default `out/walk`).
    fn target(&self) -> PathBuf {
        self.out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/walk"))
    }
}
