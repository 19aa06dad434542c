//! What `biped walk` prints: what was walked, one block per arm method (what the method does,
//! then its numbers), the verdicts on joint limits and self-collision, and the dynamic walk.

use super::WalkArgs;
use crate::cli::out::{self, outln};
use biped_control::walk::{DynamicWalkRun, Method, WalkRun};
use biped_robots::lola::LolaModel;
use std::io::{self, IsTerminal};

/// A progress line on a terminal's stderr, overwritten by the next (`""` clears it); nothing
/// when stderr is a file or pipe.
pub fn progress(text: &str) {
    if io::stderr().is_terminal() {
        out::progress(&format!("\r\x1b[2K{text}"));
    }
}

/// Prints the report of a finished walk.
pub fn print(
    args: &WalkArgs,
    lola: &LolaModel,
    runs: &[WalkRun],
    dynamic: Option<&(Method, DynamicWalkRun)>,
) -> io::Result<()> {
    outln!(
        "walked the Lola-like biped (Type 2, {} DoF) with the whole-body IK at 1 kHz: {} steps of {:.2} m, {:.2} s per step",
        lola.model.nv(),
        args.steps,
        args.step_length,
        args.step_time
    )?;
    for r in runs {
        let s = &r.summary;
        outln!("{}: {}", r.method, r.method.description())?;
        outln!(
            "    peak |L_z| {:.3} N m s, peak |dL_z/dt| {:.2} N m, peak |tau_z| {:.2} N m, min distance {:.4} m, min joint margin {:.3} rad, IK median {:.1} µs",
            s.peak_abs_lz,
            s.peak_abs_dlz,
            s.peak_abs_tau_z,
            s.min_distance,
            s.min_joint_margin,
            s.ik_us_median
        )?;
    }
    verdicts(runs)?;
    if let Some((method, run)) = dynamic {
        dynamic_line(*method, run)?;
    }
    Ok(())
}

/// Whether the walks kept the joint ranges and stayed clear of self-collision.
fn verdicts(runs: &[WalkRun]) -> io::Result<()> {
    let worst = |f: fn(&WalkRun) -> f64| {
        runs.iter()
            .map(|r| (f(r), r.method))
            .min_by(|a, b| a.0.total_cmp(&b.0))
    };
    if let Some((margin, method)) = worst(|r| r.summary.min_joint_margin) {
        let bad: Vec<&str> = runs
            .iter()
            .filter(|r| r.summary.min_joint_margin < 0.0)
            .map(|r| r.method.name())
            .collect();
        match bad.is_empty() {
            true => outln!("joint limits: kept (smallest margin {margin:.3} rad, {method})")?,
            false => outln!(
                "joint limits: LEFT by up to {:.3} rad ({})",
                -margin,
                bad.join(", ")
            )?,
        }
    }
    if let Some((d, method)) = worst(|r| r.summary.min_distance) {
        match d > 0.0 {
            true => outln!("self-collision: none (smallest segment distance {d:.4} m, {method})")?,
            false => outln!(
                "self-collision: segments INTERPENETRATE by {:.4} m ({method})",
                -d
            )?,
        }
    }
    Ok(())
}

/// The dynamic walk's line.
fn dynamic_line(method: Method, run: &DynamicWalkRun) -> io::Result<()> {
    let s = &run.summary;
    outln!(
        "dynamic ({}): {} - {:.2} m of {:.2} m planned ({:.0} %), max trunk tilt {:.3} rad, min base height {:.3} m, max tracking error {:.4} rad, peak |tau_z| {:.2} N m, realtime factor {:.2}",
        method,
        if s.walked { "walked" } else { "FAILED" },
        s.distance,
        s.planned_distance,
        100.0 * s.progress,
        s.max_tilt,
        s.min_base_height,
        s.max_tracking_error,
        s.peak_abs_tau_z,
        s.realtime_factor
    )
}
