//! `biped walk`: Lola's whole-body IK over a walking pattern with the arm methods of thesis
//! ch. 7; writes per-method CSV, SVG plots in the style of Fig. 7.1/7.4 and `summary.json`.
//! With `--dynamic` the walk of one method (`--method`, default minimisation) is then tracked
//! in the contact simulation: `dynamic.csv`, plots and a `"dynamic"` summary entry.

use super::outdir::{self, OutputDir, Status};
use super::{interrupt, range, CliResult};
use crate::cli::out::outln;
use biped_control::pattern::WalkingPattern;
use biped_control::walk::run::RECORDED_JOINTS;
use biped_control::walk::{
    run_dynamic_walk, run_walk, walk_pattern_params, DynamicWalkParams, DynamicWalkRun,
    DynamicWalkSummary, Method, WalkParams, WalkRun,
};
use biped_robots::lola::{self, LolaModel, LolaType};
use biped_sim::Recorder;
use clap::Args;
use serde_json::{Map, Value};
use std::path::{Path, PathBuf};

mod report;

/// Arguments of `biped walk`; the numbers are checked against [`range::walk`] while parsing.
#[derive(Args)]
pub struct WalkArgs {
    /// Number of steps (1 to 100).
    #[arg(long, value_name = "N", default_value_t = 10, allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::STEPS.parse_whole(s).map(|n| n as usize))]
    steps: usize,
    /// Step length in m (footprint ahead of the previous one; -0.6 to 0.6, negative: backwards).
    #[arg(long, value_name = "M", default_value_t = 0.4, allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::STEP_LENGTH.parse(s))]
    step_length: f64,
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
    /// Coulomb coefficient of the ground that the friction verdict checks the planned ground
    /// wrench against (0.05 to 3).
    #[arg(long, value_name = "MU", default_value_t = 0.8, allow_hyphen_values = true,
          value_parser = |s: &str| range::walk::FRICTION.parse(s))]
    friction: f64,
    /// Report a walk that leaves the joint ranges, lets segments interpenetrate or needs more
    /// friction than the ground has as a warning and exit 0 (for exploration); by default
    /// such a walk exits non-zero.
    #[arg(long)]
    allow_violations: bool,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/walk")]
    out: PathBuf,
}

/// Run `biped walk`.
pub fn run(args: WalkArgs) -> CliResult {
    let methods: Vec<Method> = match args.method.as_str() {
        "all" => Method::ALL.to_vec(),
        m => vec![m.parse().map_err(|e| format!("--method: {e}"))?],
    };
    let lola = lola::build(LolaType::Type2)?;
    let params = walk_pattern_params(&lola, args.steps, args.step_length, args.step_time)?;
    let pattern = WalkingPattern::generate(&params)?;
    let out = OutputDir::create(&args.out, "--out")?;
    let mut summary = Map::new();
    let (runs, dynamic) = match walk_all(&args, &lola, &pattern, &methods, out.path(), &mut summary)
    {
        Ok(done) => done,
        Err(e) => {
            let status = match interrupt::requested() {
                true => Status::Interrupted,
                false => Status::Failed,
            };
            let reason = e.to_string();
            let note = out.abandon(status, &reason, Some(Value::Object(summary)));
            return Err(format!("{reason}{note}").into());
        }
    };
    let dynamic_summary = dynamic.as_ref().map(|(_, r)| &r.summary);
    let mut lines = report::violation_lines(&runs);
    lines.extend(dynamic_summary.and_then(dynamic_violation));
    summary.insert("violations".into(), serde_json::to_value(&lines)?);
    outdir::stamp(&mut summary, Status::Completed);
    outdir::write_json(&out.path().join("summary.json"), &Value::Object(summary))?;
    out.commit()?;
    report::print(&args, &lola, &runs, dynamic.as_ref())?;
    outln!("wrote {}", args.out.display())?;
    if let Some(s) = dynamic_summary.filter(|s| !s.walked) {
        return Err(verdict_error(s).into());
    }
    report::violations(&lines, args.allow_violations)
}

/// Error of a walk stopped by SIGINT / SIGTERM between two of its parts.
fn check_interrupt() -> Result<(), Box<dyn std::error::Error>> {
    match interrupt::requested() {
        true => Err(outdir::interrupted_reason().into()),
        false => Ok(()),
    }
}

/// What [`walk_all`] returns: the kinematic walks and the dynamic one, if asked for.
type Walks = (Vec<WalkRun>, Option<(Method, DynamicWalkRun)>);

/// Walks every method (then the dynamic walk if asked), writing into `dir` and adding each
/// part's summary to `summary` as it finishes.
fn walk_all(
    args: &WalkArgs,
    lola: &LolaModel,
    pattern: &WalkingPattern,
    methods: &[Method],
    dir: &Path,
    summary: &mut Map<String, Value>,
) -> Result<Walks, Box<dyn std::error::Error>> {
    let mut runs = Vec::new();
    for &m in methods {
        check_interrupt()?;
        report::progress(&format!(
            "walking: {m} ({} of {})",
            runs.len() + 1,
            methods.len()
        ));
        let params = WalkParams {
            friction: args.friction,
            ..WalkParams::default()
        };
        let run = run_walk(lola, pattern, m, params)?;
        write_csv(&run, &dir.join(format!("{m}.csv")))?;
        write_trajectory(&run, &dir.join(format!("{m}_trajectory.csv")))?;
        summary.insert(m.name().to_string(), serde_json::to_value(&run.summary)?);
        runs.push(run);
    }
    report::progress("");
    write_plots(&runs, dir)?;
    if !args.dynamic {
        return Ok((runs, None));
    }
    check_interrupt()?;
    let method = match methods {
        [m] => *m,
        _ => Method::Minimization,
    };
    let run = dynamic_walk(args, method, dir)?;
    summary.insert("dynamic".into(), serde_json::to_value(run.summary)?);
    Ok((runs, Some((method, run))))
}

/// The dynamic walk's friction violation, if a foot slipped.
fn dynamic_violation(s: &DynamicWalkSummary) -> Option<String> {
    s.slip_at.map(|t| {
        format!(
            "dynamic walk: friction: a foot slid {:.1} mm within one contact by t = {t:.3} s",
            1e3 * s.max_slip_distance
        )
    })
}

/// One-line error of a failed dynamic walk.
fn verdict_error(s: &DynamicWalkSummary) -> String {
    let what = match (s.fell_at, s.diverged) {
        (Some(t), true) => format!("the simulation diverged at t = {t:.3} s (a fall)"),
        (Some(t), false) => format!("the robot fell at t = {t:.3} s"),
        (None, _) => "the robot did not advance enough".to_string(),
    };
    format!(
        "--dynamic: {what}: {:.2} m of {:.2} m planned, max trunk tilt {:.3} rad",
        s.distance, s.planned_distance, s.max_tilt
    )
}

/// Runs the dynamic walk, writes `dynamic.csv` and its plots.
fn dynamic_walk(
    args: &WalkArgs,
    method: Method,
    dir: &Path,
) -> Result<DynamicWalkRun, Box<dyn std::error::Error>> {
    let p = DynamicWalkParams {
        steps: args.steps,
        step_length: args.step_length,
        step_time: args.step_time,
        method,
        end_stops: !args.no_end_stops,
        ..DynamicWalkParams::default()
    };
    let p = if args.open_loop {
        DynamicWalkParams {
            zmp_iterations: 0,
            stabiliser: None,
            ..p
        }
    } else {
        p
    };
    let run = run_dynamic_walk(&p)?;
    write_dynamic(&run, dir)?;
    Ok(run)
}

/// `dynamic.csv` and the plots of base x/z, trunk tilt, vertical foot forces and `tau_z`.
fn write_dynamic(run: &DynamicWalkRun, out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let s = &run.series;
    let mut rec = Recorder::with_capacity(s.t.len());
    for k in 0..s.t.len() {
        rec.sample(s.t[k])?;
        let [x, y, z] = s.base[k];
        for (name, v) in [
            ("base_x", x),
            ("base_y", y),
            ("base_z", z),
            ("planned_base_x", s.planned_base_x[k]),
            ("trunk_tilt", s.tilt[k]),
            ("fz_left", s.foot_fz[k][0]),
            ("fz_right", s.foot_fz[k][1]),
            ("tau_z_left", s.tau_z[k][0]),
            ("tau_z_right", s.tau_z[k][1]),
            ("toe_fz_left", s.toe_fz[k][0]),
            ("toe_fz_right", s.toe_fz[k][1]),
            ("heel_lift_left", s.heel_lift[k][0]),
            ("heel_lift_right", s.heel_lift[k][1]),
            ("friction_usage_left", s.friction_usage[k][0]),
            ("friction_usage_right", s.friction_usage[k][1]),
            ("slip_speed_left", s.slip_speed[k][0]),
            ("slip_speed_right", s.slip_speed[k][1]),
            ("points_in_contact_left", s.points_in_contact[k][0] as f64),
            ("points_in_contact_right", s.points_in_contact[k][1] as f64),
            ("tracking_error", s.tracking_error[k]),
        ] {
            rec.set(name, v)?;
        }
    }
    rec.write_csv(&out.join("dynamic.csv"))?;
    let plots: [(&[&str], &str, &str, &str); 4] = [
        (
            &["base_x", "planned_base_x", "base_z"],
            "base position [m]",
            "dynamic_base.svg",
            "base x (simulated, planned) and height",
        ),
        (
            &["trunk_tilt"],
            "tilt [rad]",
            "dynamic_tilt.svg",
            "trunk tilt",
        ),
        (
            &["fz_left", "fz_right"],
            "F_z [N]",
            "dynamic_fz.svg",
            "vertical foot forces",
        ),
        (
            &["tau_z_left", "tau_z_right"],
            "tau_z [N m]",
            "dynamic_tau_z.svg",
            "vertical torque on the feet (F/T sensors)",
        ),
    ];
    for (names, unit, file, title) in plots {
        rec.plot_svg(
            &out.join(file),
            &format!("dynamic walk: {title}"),
            names,
            unit,
        )?;
    }
    Ok(())
}

/// Time series of one method as CSV.
fn write_csv(run: &WalkRun, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let s = &run.series;
    let mut rec = Recorder::with_capacity(s.t.len());
    for k in 0..s.t.len() {
        rec.sample(s.t[k])?;
        rec.set("L_z", s.lz[k])?;
        rec.set("dL_z", s.dlz[k])?;
        rec.set("tau_z", s.tau_z[k])?;
        rec.set("min_distance", s.min_distance[k])?;
        rec.set("friction_usage", s.friction_usage[k])?;
        rec.set("zmp_x", s.zmp[k][0])?;
        rec.set("zmp_y", s.zmp[k][1])?;
        for (name, v) in RECORDED_JOINTS.iter().zip(s.joints[k]) {
            rec.set(name, v)?;
        }
    }
    rec.write_csv(path)?;
    Ok(())
}

/// The full motion of one method (`METHOD_trajectory.csv`, see docs/walking.md).
fn write_trajectory(run: &WalkRun, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let tr = &run.trajectory;
    let columns = tr.columns();
    let mut rec = Recorder::with_capacity(tr.len());
    for k in 0..tr.len() {
        rec.sample(tr.t[k])?;
        for (name, v) in columns.iter().zip(tr.row(k)) {
            rec.set(name, v)?;
        }
    }
    rec.write_csv(path)?;
    Ok(())
}

/// `L_z` and `tau_z` of all methods over time, side by side (Fig. 7.1/7.4 style).
fn write_plots(runs: &[WalkRun], out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let Some(first) = runs.first() else {
        return Ok(());
    };
    let mut rec = Recorder::with_capacity(first.series.t.len());
    for k in 0..first.series.t.len() {
        rec.sample(first.series.t[k])?;
        for r in runs {
            rec.set(&format!("L_z {}", r.method), r.series.lz[k])?;
            rec.set(&format!("tau_z {}", r.method), r.series.tau_z[k])?;
        }
    }
    for (sig, unit, file) in [
        ("L_z", "L_z [N m s]", "lz.svg"),
        ("tau_z", "tau_z [N m]", "tau_z.svg"),
    ] {
        let names: Vec<String> = runs.iter().map(|r| format!("{sig} {}", r.method)).collect();
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let title = format!("{sig} during walking, arm methods compared");
        rec.plot_svg(&out.join(file), &title, &refs, unit)?;
    }
    Ok(())
}
