//! `biped simulate`: runs a scenario of `biped_sim` (drop / stand / sway, issue item 7) on the
//! Lola-like biped or a floating-base URDF robot and writes the recorded signals (CSV), SVG
//! plots and `summary.json` (thesis 2.1, Fig. 2.1: the simulation outputs).
//!
//! Choices: choice-valued options are parsed here, not by clap, so that a bad value is one
//! error line like every other input error. Fixed-step methods step at the control period
//! (1 ms) except on Type 3, whose stiff elastic gears need 0.1 ms (see `PlantConfig`); `--step`
//! overrides. The default duration is the scenario's own (stand 3 s, drop 4 s, sway 5 s), not
//! a fixed 2 s: criteria such as "at rest at the end" only hold after it. One row is recorded
//! per control period (`--every N`: every N-th, and always the final state). The exit status
//! is 0 when the run completes, whatever the pass criteria say (`--check`: 1 if one fails).

mod execute;
mod model;
pub mod output;
mod parse;
mod progress;
mod recording;
mod report;
pub(crate) mod setup;

use super::outdir::{self, OutputDir};
use super::{interrupt, CliResult};
use biped_sim::controller::Hook;
use biped_sim::plant::Plant;
use biped_sim::SimError;
use clap::Args;
pub use execute::{parse_args, Abandoned, Outcome, Prepared, SetupError};
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `biped simulate`.
#[derive(Args, Debug)]
pub struct SimulateArgs {
    /// Lola-like biped: `type2` (rigid drives) or `type3` (elastic gears); the default model.
    #[arg(long, value_name = "TYPE")]
    lola: Option<String>,
    /// Simulate a URDF robot instead (needs --floating and --feet).
    #[arg(long, value_name = "FILE")]
    urdf: Option<PathBuf>,
    /// Give the URDF root a free-flyer joint (required: the scenarios stand on the ground).
    #[arg(long)]
    floating: bool,
    /// URDF links of the left and right sole.
    #[arg(long, value_name = "LEFT,RIGHT")]
    feet: Option<String>,
    /// Centre of each sole rectangle in its link frame in m (default 0,0,-0.05).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    sole_center: Option<String>,
    /// Sole rectangle length (link x) and width (link y) in m (default 0.2,0.1).
    #[arg(long, value_name = "LENGTH,WIDTH", allow_hyphen_values = true)]
    sole_size: Option<String>,
    /// Hip and ankle adduction joints for `sway` on a URDF robot.
    #[arg(long, value_name = "HIP_L,HIP_R,ANKLE_L,ANKLE_R")]
    sway_joints: Option<String>,
    /// Sway amplitude of the leg lean in rad and sway period in s (default 0.06,2).
    #[arg(long, value_name = "RAD,S", allow_hyphen_values = true)]
    sway: Option<String>,
    /// Reflected rotor inertia `N^2 J` [kg m^2] of URDF joints, added as geared rotor bodies,
    /// e.g. `*_knee_joint=0.025,*_ankle_*=0.0072` (`*` matches any run; first match wins).
    #[arg(long, value_name = "JOINT=KG_M2,...", allow_hyphen_values = true)]
    armature: Option<String>,
    /// The URDF robot's SRDF: its `<rotor_params>` add motor rotors of reflected inertia
    /// `N^2 J` (after the `--armature` entries, which win).
    #[arg(long, value_name = "FILE")]
    srdf: Option<PathBuf>,
    /// Start pose from the SRDF's `<group_state>` NAME (e.g. TALOS's `half_sitting`); `--pose`
    /// entries override its joints.
    #[arg(long, value_name = "NAME")]
    srdf_state: Option<String>,
    /// Ignore the URDF's joint ranges (no end stops at `<limit lower upper>`).
    #[arg(long)]
    no_end_stops: bool,
    /// Ignore the URDF's joint damping and friction (`<dynamics>`).
    #[arg(long)]
    no_joint_friction: bool,
    /// Contact stiffness [N/m] and damping [N s/m] of each sole point, normal and tangential
    /// (default: Lola 2e5,400 with a tangential damper of 200; URDF 5e4,100 for the light feet
    /// of URDF robots).
    #[arg(long, value_name = "K,D", allow_hyphen_values = true)]
    contact: Option<String>,
    /// Coulomb friction coefficient `mu` between soles and ground (default 0.8).
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    friction: Option<String>,
    /// Initial joint angles in rad, e.g. `knee=0.4,hip=-0.2` (Lola: added to its bent-knee pose).
    #[arg(long, value_name = "JOINT=ANGLE,...", allow_hyphen_values = true)]
    pose: Option<String>,
    /// Bandwidth `w` of the joint PD controllers in rad/s (`k_p = w^2 m`, `k_d = 2 w m` with the
    /// joint's inertia `m`, capped for the 1 kHz hold; default 40).
    #[arg(long, value_name = "RAD_S", allow_hyphen_values = true)]
    bandwidth: Option<String>,
    /// No IMU damping through the ankles (by default the ankles also get torques from the
    /// base's low-passed angular velocity, which damp the rocking on the soles).
    #[arg(long)]
    no_stance_damping: bool,
    /// Scenario: `stand`, `drop` or `sway`.
    #[arg(long, value_name = "NAME", default_value = "stand")]
    scenario: String,
    /// Simulated time in s (default: the scenario's own, long enough for its pass criteria:
    /// stand 3, drop 4, sway 5); one control period to 1e6 s, and the recorded samples must
    /// fit 1 GiB (rows x columns x 8 bytes; see --every).
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    duration: Option<String>,
    /// Integration method: `euler`, `symplectic`, `rk4` or `dopri5`.
    #[arg(long, value_name = "METHOD", default_value = "rk4")]
    integrator: String,
    /// Fixed step in s of euler / symplectic / rk4 (default: control period; Type 3: 1e-4);
    /// 1e-6 up to the control period, rounded down to a whole number of steps per period.
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    step: Option<String>,
    /// Relative and absolute tolerance of dopri5 (default 1e-6,1e-9).
    #[arg(long, value_name = "RTOL,ATOL", allow_hyphen_values = true)]
    tolerances: Option<String>,
    /// Record every N-th control period (and the final state).
    #[arg(
        long,
        value_name = "N",
        default_value = "1",
        allow_hyphen_values = true
    )]
    every: String,
    /// Also plot the chosen signals: `signals.csv` column names or `*` patterns, comma-separated
    /// (e.g. `q[l_shank],left.f*`); each `--plot` writes one `plot_<k>.svg`.
    #[arg(long, value_name = "SIGNALS", action = clap::ArgAction::Append)]
    plot: Vec<String>,
    /// Output folder (default `out/simulate/<scenario>`).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Exit with status 1 if a pass criterion of the scenario fails.
    #[arg(long)]
    check: bool,
}

/// Run `biped simulate`.
pub fn run(args: SimulateArgs) -> CliResult {
    let mut bar = None;
    let mut stop = |t: f64, duration: f64| -> Result<(), SimError> {
        if interrupt::requested() {
            return Err(SimError::Stopped(outdir::interrupted_reason().into()));
        }
        let bar = bar.get_or_insert_with(|| progress::Progress::new(duration));
        bar.update(t);
        Ok(())
    };
    let result = execute(&args, None, &mut stop, true);
    if let Some(mut bar) = bar {
        bar.finish();
    }
    let Run {
        done,
        files,
        target,
    } = result.map_err(|e| e.to_string())?;
    let (summary, plant, rec) = (&done.summary, done.sim.plant(), &done.rec);
    let pd = done.sim.controller().inner();
    let target = target.unwrap_or_default();
    report::print_report(summary, plant, rec, &done.info, pd, &target, &files)?;
    let failed = args.check && !summary.passed();
    Ok(if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

/// A run that completed, with the files it wrote and where.
pub struct Run {
    /// The finished simulation.
    pub done: Outcome,
    /// The files written (none when nothing was written).
    pub files: Vec<String>,
    /// The output folder, if written.
    pub target: Option<PathBuf>,
}

/// Makes a controller hook for the plant of the run (e.g. knowing its actuators).
pub type MakeHook<'a> = Box<dyn FnOnce(&Plant) -> Hook + Send + 'a>;

/// Runs `biped simulate` with `args`: the controller hook that `hook` makes runs after the
/// scenario's joint PD each cycle, `stop` is asked once per control period with the time and
/// the run's duration. With `write` (or `--out` given) the output folder is replaced as a whole: the signals, plots and `summary.json` of a completed run, or of
/// a run that failed or was stopped, the signals until then and a summary saying so.
pub fn execute(
    args: &SimulateArgs,
    hook: Option<MakeHook<'_>>,
    stop: &mut dyn FnMut(f64, f64) -> Result<(), SimError>,
    write: bool,
) -> Result<Run, SetupError> {
    let mut prepared = Prepared::new(args)?;
    let hook = hook.map(|make| make(&prepared.job.plant));
    let target = (write || args.out.is_some()).then(|| {
        args.out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/simulate").join(prepared.job.scenario_name()))
    });
    let chosen = output::chosen_plots(&prepared.rec, &args.plot).map_err(|e| e.to_string())?;
    let out = match &target {
        Some(dir) => Some(OutputDir::create(dir, "--out").map_err(|e| e.to_string())?),
        None => None,
    };
    // The buffer mapped before the timed loop (no page faults in it).
    prepared.rec.prefault();
    let done = match (prepared.run(hook, stop), out) {
        (Ok(done), out) => (done, out),
        (Err(a), Some(out)) => {
            return Err(output::abandon(out, &a.rec, &a.model, &a.info, a.t, &a.error).into())
        }
        (Err(a), None) => return Err(output::abandoned_line(a.t, &a.error).into()),
    };
    let (done, files) = match done {
        (done, Some(out)) => {
            let files = output::write_all(&done, &chosen, out.path()).map_err(|e| e.to_string())?;
            out.commit().map_err(|e| e.to_string())?;
            (done, files)
        }
        (done, None) => (done, Vec::new()),
    };
    Ok(Run {
        done,
        files,
        target,
    })
}
