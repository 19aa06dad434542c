//! What `biped walk` prints: what was walked, one block per arm method (what the method does,
//! then its numbers), the verdicts (tracking, contact, joint limits, self-collision, friction),
//! and the dynamic walk.

use super::Walk;
use super::WalkArgs;
use crate::cli::out::{self, errln, outln};
use crate::cli::CliResult;
use biped_control::walk::{
    DynamicWalkRun, DynamicWalkSummary, Method, Verdict, WalkRun, WalkVerdicts,
};
use std::io::{self, IsTerminal};
use std::process::ExitCode;

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
    walk: &Walk,
    dynamic: Option<&(Method, DynamicWalkRun)>,
) -> io::Result<()> {
    let runs = &walk.runs;
    outln!(
        "walked {} with the whole-body IK at 1 kHz: {} steps of {:.2} m, {:.2} s per step",
        walk.label,
        args.steps,
        walk.step_length,
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

/// One verdict line: its name, which verdict, the words for kept and not kept.
type Check = (
    &'static str,
    fn(&WalkVerdicts) -> &Verdict,
    &'static str,
    &'static str,
);

/// Whether the walks tracked their tasks, kept the supporting feet down, kept the joint
/// ranges, stayed clear of self-collision and inside the friction cone: one line per check
/// over all methods.
fn verdicts(runs: &[WalkRun]) -> io::Result<()> {
    let checks: [Check; 5] = [
        ("tracking", |v| &v.tracking, "kept", "MISSED"),
        ("contact", |v| &v.contact, "kept", "LIFTED"),
        ("joint limits", |v| &v.joint_limits, "kept", "LEFT"),
        (
            "self-collision",
            |v| &v.self_collision,
            "none",
            "INTERPENETRATE",
        ),
        ("friction", |v| &v.friction, "kept", "EXCEEDED"),
    ];
    for (name, pick, good, bad) in checks {
        let failed: Vec<&str> = runs
            .iter()
            .filter(|r| !pick(&r.summary.verdicts).kept)
            .map(|r| r.method.name())
            .collect();
        let worst = runs.iter().map(|r| (pick(&r.summary.verdicts), r.method));
        let worst = match name {
            "friction" | "tracking" | "contact" => {
                worst.max_by(|a, b| a.0.value.total_cmp(&b.0.value))
            }
            _ => worst.min_by(|a, b| a.0.value.total_cmp(&b.0.value)),
        };
        let Some((v, method)) = worst else {
            continue;
        };
        let what = match name {
            "joint limits" => format!("smallest margin {:.3} rad, {}", v.value, v.at),
            "self-collision" => format!("smallest segment distance {:.4} m, {}", v.value, v.at),
            "tracking" => format!("largest task error {:.4}", v.value),
            "contact" => format!(
                "supporting feet at most {:.2} mm above the ground, {}",
                1e3 * v.value,
                v.at
            ),
            _ => format!("largest use of the friction limit {:.0} %", 100.0 * v.value),
        };
        match failed.is_empty() {
            true => outln!("{name}: {good} ({what}, {method})")?,
            false => outln!("{name}: {bad} by {} ({what}, {method})", failed.join(", "))?,
        }
    }
    Ok(())
}

/// Every limit the walks did not keep, one line each (method, quantity, where, when, how
/// much); also the `"violations"` list of `summary.json`.
pub fn violation_lines(runs: &[WalkRun]) -> Vec<String> {
    runs.iter()
        .flat_map(|r| {
            r.summary
                .verdicts
                .violations()
                .into_iter()
                .map(move |v| format!("{} walk: {v}", r.method))
        })
        .collect()
}

/// Exit status for the violation `lines`: the first as the error, or with `allow` each as a
/// warning and success.
pub fn violations(lines: &[String], allow: bool) -> CliResult {
    if !allow {
        return match lines.first() {
            Some(first) => {
                Err(format!("{first} (--allow-violations to accept such a walk)").into())
            }
            None => Ok(ExitCode::SUCCESS),
        };
    }
    for v in lines {
        errln!("warning: {v}");
    }
    Ok(ExitCode::SUCCESS)
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
    )?;
    match s.slip_at {
        None => outln!(
            "dynamic slip: none (largest sliding {:.1} mm within one contact, at up to {:.2} m/s)",
            1e3 * s.max_slip_distance,
            s.max_slip_speed
        ),
        Some(t) => outln!(
            "dynamic slip: a foot SLIPPED at t = {t:.3} s (up to {:.1} mm within one contact)",
            1e3 * s.max_slip_distance
        ),
    }?;
    contact_line(s)?;
    margins_line(s)
}

/// The simulated motion's joint-limit margin and segment distance, in one line.
fn margins_line(s: &DynamicWalkSummary) -> io::Result<()> {
    outln!(
        "dynamic limits and self-collision: {} (smallest joint margin {:.3} rad, {}; smallest segment distance {:.4} m, {})",
        match (s.limits_kept, s.collision_free) {
            (true, true) => "kept",
            (false, true) => "a joint LEFT ITS RANGE",
            (true, false) => "segments INTERPENETRATED",
            (false, false) => "a joint LEFT ITS RANGE and segments INTERPENETRATED",
        },
        s.min_joint_margin,
        s.min_joint_margin_at,
        s.min_distance,
        s.min_distance_at
    )
}

/// The dynamic walk's flight phases and peak ground force, in one line.
fn contact_line(s: &DynamicWalkSummary) -> io::Result<()> {
    let peak = match s.mean_ground_force > 0.0 {
        true => format!(
            "{:.0} N, {:.1}x the mean",
            s.peak_ground_force,
            s.peak_ground_force / s.mean_ground_force
        ),
        false => format!("{:.0} N", s.peak_ground_force),
    };
    match s.longest_flight_at {
        None => outln!("dynamic contact: a foot on the ground throughout, peak ground force {peak}"),
        Some(t) => outln!(
            "dynamic contact: BOTH FEET OFF the ground for {:.3} s in all (longest {:.3} s from t = {t:.3} s), peak ground force {peak}",
            s.flight_time,
            s.longest_flight
        ),
    }
}
