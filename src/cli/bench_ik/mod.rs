//! `biped bench ik`: the time of one whole-body IK step on a described robot, with the task set
//! of the QP-based peers (PlaCo, mink, pink in `scripts/ik_peers.py`) and with the full set
//! (plus self-collision avoidance and momentum compensation), checked to have tracked.

mod bounds;
mod scenario;

use super::CliResult;
use crate::cli::out::outln;
use biped_robots::description::Robot;
use clap::Args;
use scenario::{settled, Errors, Posture, Scenario, TaskSet};
use serde::Serialize;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Steps run before the timed ones (caches, branch predictors, the solver's first sizing).
const WARMUP: usize = 100;
/// Largest foot or CoM position error allowed in settled cycles \[m].
const MAX_POSITION_ERROR: f64 = 2e-3;
/// Largest foot or pelvis orientation error allowed in settled cycles \[rad].
const MAX_ORIENTATION_ERROR: f64 = 1e-3;
/// Slack of the limit checks (rounding of the integration).
const LIMIT_SLACK: f64 = 1e-9;

/// Arguments of `biped bench ik`.
#[derive(Args)]
pub struct BenchIkArgs {
    /// Robot: a bundled description (`g1`, `talos`) or the path of a description FILE.toml.
    #[arg(long, value_name = "NAME")]
    robot: String,
    /// Number of timed steps (after a warm-up of 100; at most 10^7, the samples are kept).
    #[arg(
        long,
        default_value_t = 2000,
        allow_hyphen_values = true,
        value_parser = clap::value_parser!(u32).range(1..=10_000_000)
    )]
    steps: u32,
    /// Pull towards the start pose by a soft posture task (`task`, as the peers) or by the
    /// comfort term in the null space (`comfort`, which never competes with the tasks).
    #[arg(long, value_enum, value_name = "METHOD", default_value = "task")]
    posture: Posture,
    /// Print one JSON line `{"peer_tasks": {"median_us", "p99_us"}, "full": {..}}`.
    #[arg(long)]
    json: bool,
}

/// Median and 99th percentile of the step time \[µs].
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StepTimes {
    /// Median \[µs].
    pub median_us: f64,
    /// 99th percentile (linear interpolation between order statistics) \[µs].
    pub p99_us: f64,
}

/// Timing and tracking of one task set.
struct Measured {
    times: StepTimes,
    worst: Errors,
    /// Smallest distance of an active segment pair seen (full set only).
    min_distance: Option<f64>,
    min_margin: f64,
}

#[derive(Serialize)]
struct Report {
    peer_tasks: StepTimes,
    full: StepTimes,
}

/// The description file named by `--robot`.
pub(crate) fn robot_file(name: &str) -> Result<PathBuf, String> {
    if let Some(path) = Robot::bundled(name) {
        return Ok(path);
    }
    if name.ends_with(".toml") || name.contains(std::path::MAIN_SEPARATOR) {
        return Ok(PathBuf::from(name));
    }
    Err(format!(
        "--robot: unknown robot \"{name}\" (bundled: g1, talos; or a description FILE.toml)"
    ))
}

/// `q`-quantile of sorted `v` with linear interpolation (as numpy's default percentile).
fn quantile(v: &[f64], q: f64) -> f64 {
    let x = q * (v.len() - 1) as f64;
    let (i, f) = (x.floor() as usize, x.fract());
    let j = (i + 1).min(v.len() - 1);
    v[i] + f * (v[j] - v[i])
}

/// Runs `set` for `WARMUP + steps` cycles, timing the last `steps`, and checks every cycle.
fn measure(robot: &Robot, set: TaskSet, args: &BenchIkArgs) -> Result<Measured, String> {
    let mut s = Scenario::new(robot, set, args.posture)?;
    let steps = args.steps as usize;
    let mut times = Vec::with_capacity(steps);
    let (mut worst, mut min_distance) = (Errors::default(), None::<f64>);
    let mut min_margin = f64::INFINITY;
    for k in 0..WARMUP + steps {
        let start = Instant::now();
        let report = s.step(k)?;
        let elapsed = start.elapsed();
        if k >= WARMUP {
            times.push(elapsed.as_secs_f64() * 1e6);
        }
        let m = s
            .check_limits(LIMIT_SLACK)
            .map_err(|e| format!("step {k}: {e}"))?;
        min_margin = min_margin.min(m);
        let excess = s.velocity_excess();
        if excess > LIMIT_SLACK {
            return Err(format!(
                "step {k}: a joint velocity exceeds its limit by {excess:.2e}"
            ));
        }
        if let Some(d) = report.min_distance {
            min_distance = Some(min_distance.map_or(d, |m: f64| m.min(d)));
        }
        if settled(k) {
            let e = s.errors(k)?;
            worst.position = worst.position.max(e.position);
            worst.orientation = worst.orientation.max(e.orientation);
            worst.com = worst.com.max(e.com);
        }
    }
    check_tracking(set, &worst, min_distance)?;
    times.sort_by(f64::total_cmp);
    Ok(Measured {
        times: StepTimes {
            median_us: quantile(&times, 0.5),
            p99_us: quantile(&times, 0.99),
        },
        worst,
        min_distance,
        min_margin,
    })
}

/// Fails when the IK did not track: a fast IK that misses its targets is not a result.
fn check_tracking(set: TaskSet, e: &Errors, min_distance: Option<f64>) -> Result<(), String> {
    let what = match set {
        TaskSet::Peer => "peer task set",
        TaskSet::Full => "full task set",
    };
    if !(e.position <= MAX_POSITION_ERROR && e.com <= MAX_POSITION_ERROR) {
        return Err(format!(
            "{what}: the IK did not track: foot error {:.2e} m, CoM error {:.2e} m (allowed {MAX_POSITION_ERROR} m)",
            e.position, e.com
        ));
    }
    if e.orientation.is_nan() || e.orientation > MAX_ORIENTATION_ERROR {
        return Err(format!(
            "{what}: the IK did not track: orientation error {:.2e} rad (allowed {MAX_ORIENTATION_ERROR} rad)",
            e.orientation
        ));
    }
    if let Some(d) = min_distance.filter(|d| *d <= 0.0) {
        return Err(format!(
            "{what}: two segments collided (distance {d:.3e} m)"
        ));
    }
    Ok(())
}

/// Run `biped bench ik`.
pub fn run(args: BenchIkArgs) -> CliResult {
    let robot = Robot::load(robot_file(&args.robot)?)?;
    let peer = measure(&robot, TaskSet::Peer, &args)?;
    let full = measure(&robot, TaskSet::Full, &args)?;
    if args.json {
        let report = Report {
            peer_tasks: peer.times,
            full: full.times,
        };
        outln!("{}", serde_json::to_string(&report)?)?;
        return Ok(ExitCode::SUCCESS);
    }
    let name = &robot.description.name;
    let nv = robot.urdf.model.nv();
    let steps = args.steps;
    outln!(
        "IK step on {name} (nv {nv}), {steps} timed steps of 1 ms after {WARMUP} warm-up steps"
    )?;
    for (label, m) in [("peer tasks", &peer), ("full set", &full)] {
        outln!(
            "{label:>10}: median {:8.2} us, p99 {:8.2} us; worst foot {:.1e} m, CoM {:.1e} m, orientation {:.1e} rad; joint margin >= {:.4}{}",
            m.times.median_us,
            m.times.p99_us,
            m.worst.position,
            m.worst.com,
            m.worst.orientation,
            m.min_margin,
            m.min_distance
                .map_or(String::new(), |d| format!("; closest active pair {d:.4} m")),
        )?;
    }
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::quantile;

    #[test]
    fn quantiles_interpolate_like_numpy() {
        // numpy.percentile([1, 2, 3, 4], [50, 99]) = [2.5, 3.97]
        let v = [1.0, 2.0, 3.0, 4.0];
        assert!((quantile(&v, 0.5) - 2.5).abs() < 1e-12);
        assert!((quantile(&v, 0.99) - 3.97).abs() < 1e-12);
        assert_eq!(quantile(&[7.0], 0.99), 7.0);
    }
}
