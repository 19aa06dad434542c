//! `biped calibrate`: encoder-offset calibration from jig measurements (thesis 3.5).

use super::CliResult;
use crate::cli::out::{errln, outln};
use biped_robots::calibration::{calibrate, Calibration, LoadedFile, PoseReport, SolveOptions};
use clap::Args;
use serde_json::json;
use std::path::PathBuf;
use std::process::ExitCode;

/// Condition number of the scaled Jacobian above which the text output warns.
const ILL_CONDITIONED: f64 = 1e4;

/// Arguments of `biped calibrate`.
#[derive(Args)]
pub struct CalibrateArgs {
    /// Calibration file (JSON: model, joints, jig constraints, measured poses).
    file: PathBuf,
    /// Print one JSON object instead of the text report.
    #[arg(long)]
    json: bool,
}

/// Run `biped calibrate`.
pub fn run(args: CalibrateArgs) -> CliResult {
    let file = LoadedFile::read(&args.file)?;
    let urdf = file.load_model()?;
    for w in &urdf.warnings {
        errln!("warning: {w}");
    }
    let problem = file.problem(&urdf)?;
    let cal = calibrate(&problem, &SolveOptions::default())?;
    if args.json {
        outln!("{}", to_json(&file, &cal))?;
    } else {
        print_text(&file, &cal)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Ratio of the largest to the smallest singular value.
fn condition(cal: &Calibration) -> f64 {
    let sv = &cal.singular_values;
    match (sv.first(), sv.last()) {
        (Some(a), Some(b)) if *b > 0.0 => a / b,
        _ => f64::INFINITY,
    }
}

/// The whole result as one JSON object.
fn to_json(file: &LoadedFile, cal: &Calibration) -> serde_json::Value {
    let joints: Vec<_> = cal
        .joints
        .iter()
        .enumerate()
        .map(|(i, name)| {
            json!({
                "joint": name,
                "offset": cal.offsets[i],
                "std_error": cal.std_errors[i],
                "reference": file.spec.reference_offsets.get(name),
            })
        })
        .collect();
    let poses: Vec<_> = cal.poses.iter().map(pose_json).collect();
    json!({
        "file": file.file,
        "offsets": joints,
        "iterations": cal.iterations,
        "singular_values": cal.singular_values,
        "condition": condition(cal),
        "rms_after": cal.rms_after,
        "poses": poses,
    })
}

/// One pose report as JSON.
fn pose_json(r: &PoseReport) -> serde_json::Value {
    let cons: Vec<_> = r
        .constraints
        .iter()
        .map(|c| {
            json!({
                "constraint": c.name,
                "position_before": c.position_before,
                "position_after": c.position_after,
                "orientation_before": c.orientation_before,
                "orientation_after": c.orientation_after,
            })
        })
        .collect();
    json!({
        "pose": r.name,
        "rms_before": r.rms_before,
        "max_before": r.max_before,
        "rms_after": r.rms_after,
        "max_after": r.max_after,
        "constraints": cons,
    })
}

/// Human-readable report.
fn print_text(file: &LoadedFile, cal: &Calibration) -> std::io::Result<()> {
    outln!(
        "{}: {} joints, {} poses, {} iterations",
        file.file,
        cal.joints.len(),
        cal.poses.len(),
        cal.iterations
    )?;
    outln!(
        "{:<28} {:>13} {:>11} {:>13}",
        "joint",
        "offset [rad]",
        "std err",
        "reference"
    )?;
    for (i, name) in cal.joints.iter().enumerate() {
        let reference = file.spec.reference_offsets.get(name);
        let r = reference.map_or("-".to_string(), |x| format!("{x:.6}"));
        outln!(
            "{name:<28} {:>13.6} {:>11.2e} {r:>13}",
            cal.offsets[i],
            cal.std_errors[i]
        )?;
    }
    let cond = condition(cal);
    outln!("observability: full rank, condition number {cond:.3e}")?;
    if cond > ILL_CONDITIONED {
        errln!("warning: ill-conditioned calibration (condition {cond:.1e}): add or vary poses");
    }
    outln!("residual (weighted rows): rms / max before -> after")?;
    for r in &cal.poses {
        outln!(
            "  {}: rms {:.3e} -> {:.3e}, max {:.3e} -> {:.3e}",
            r.name,
            r.rms_before,
            r.rms_after,
            r.max_before,
            r.max_after
        )?;
        for c in &r.constraints {
            outln!(
                "    {}: position {:.4} -> {:.4} mm, orientation {:.4} -> {:.4} mrad",
                c.name,
                1e3 * c.position_before,
                1e3 * c.position_after,
                1e3 * c.orientation_before,
                1e3 * c.orientation_after
            )?;
        }
    }
    Ok(())
}
