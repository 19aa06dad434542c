//! `biped walk` as a library call, shared by the command line and the Python package: the
//! options from command-line words, the walks of every method and the dynamic walk, the
//! summary, the verdicts and the tables of the CSV files.

use super::outdir::{self, OutputDir, Status};
use super::{interrupt, report, robot, tables, WalkArgs};
use biped_control::pattern::{PatternParams, WalkingPattern};
use biped_control::walk::{
    run_dynamic_walk_robot, run_walk_robot, DynamicRobot, DynamicWalkParams, DynamicWalkRun,
    DynamicWalkSummary, Method, WalkParams, WalkRobot, WalkRun,
};
use biped_sim::record::replay::write_csv_gz;
use biped_sim::Recorder;
use serde_json::{Map, Value};
use std::path::Path;

/// A finished `biped walk`: the model, every method's walk, the dynamic walk if asked for, the
/// summary of `summary.json`, the violation lines and the tables of the CSV files.
pub struct Walk {
    /// The walked robot.
    pub robot: WalkRobot,
    /// What the report calls it (`the Lola-like biped (Type 2, 31 DoF)`).
    pub label: String,
    /// The step length walked \[m].
    pub step_length: f64,
    /// The kinematic walk of each method.
    pub runs: Vec<WalkRun>,
    /// The dynamic walk and the method it tracked.
    pub dynamic: Option<(Method, DynamicWalkRun)>,
    /// `summary.json`'s content.
    pub summary: Value,
    /// One line per violated verdict.
    pub lines: Vec<String>,
    /// The tables by file stem (`none`, `none_trajectory`, `none_recording`, ..., `dynamic`,
    /// `dynamic_recording`).
    pub tables: Vec<(String, Recorder)>,
}

impl Walk {
    /// The one-line error of a dynamic walk that fell or did not advance.
    pub fn failure(&self) -> Option<String> {
        let (_, run) = self.dynamic.as_ref()?;
        (!run.summary.walked).then(|| verdict_error(&run.summary))
    }

    /// The first violation as the error `biped walk` exits with (none with `allow`).
    pub fn violation(&self, allow: bool) -> Option<String> {
        let first = self.lines.first().filter(|_| !allow)?;
        Some(format!(
            "{first} (--allow-violations to accept such a walk)"
        ))
    }
}

/// Parses the options of `biped walk` given as command-line words (without the program and
/// sub-command names).
pub fn parse_args<I, S>(words: I) -> Result<WalkArgs, String>
where
    I: IntoIterator<Item = S>,
    S: Into<String>,
{
    crate::cli::words::parse("walk", words)
}

/// Runs `biped walk` with `args`; with `write` (or `--out` given) its output folder is
/// replaced as a whole (on a failure: the parts done and a summary saying why).
pub fn execute(args: &WalkArgs, write: bool) -> Result<Walk, String> {
    let methods: Vec<Method> = match args.method.as_str() {
        "all" => Method::ALL.to_vec(),
        m => vec![m.parse().map_err(|e| format!("--method: {e}"))?],
    };
    let chosen = robot::choose(args.robot.as_deref(), args.dynamic)?;
    let robot = chosen.robot;
    let step_length = args.step_length.unwrap_or(robot.natural_step_length);
    let params = robot.pattern_params(args.steps, step_length, args.step_time);
    let pattern = WalkingPattern::generate(&params).map_err(|e| format!("walking pattern: {e}"))?;
    let out = match write || args.out.is_some() {
        true => Some(OutputDir::create(&args.target(), "--out").map_err(|e| e.to_string())?),
        false => None,
    };
    let dir = out.as_ref().map(|o| o.path());
    let mut summary = Map::new();
    summary.insert("robot".into(), robot_entry(&robot, &params));
    let mut tables = Vec::new();
    let walked = walk_all(
        args,
        (&robot, chosen.dynamic.as_ref()),
        &pattern,
        &methods,
        dir,
        &mut summary,
        &mut tables,
    );
    let ((runs, dynamic), out) = match (walked, out) {
        (Ok(done), out) => (done, out),
        (Err(e), out) => {
            let reason = e.to_string();
            let Some(out) = out else {
                return Err(reason);
            };
            let status = match interrupt::requested() {
                true => Status::Interrupted,
                false => Status::Failed,
            };
            let note = out.abandon(status, &reason, Some(Value::Object(summary)));
            return Err(format!("{reason}{note}"));
        }
    };
    let dynamic_summary = dynamic.as_ref().map(|(_, r)| &r.summary);
    let mut lines = report::violation_lines(&runs);
    lines.extend(dynamic_summary.map_or(Vec::new(), |s| {
        dynamic_violations(s, DynamicWalkParams::default().max_flight)
    }));
    summary.insert("violations".into(), lines.clone().into());
    outdir::stamp(&mut summary, Status::Completed);
    let summary = Value::Object(summary);
    if let Some(out) = out {
        outdir::write_json(&out.path().join("summary.json"), &summary)
            .map_err(|e| e.to_string())?;
        out.commit().map_err(|e| e.to_string())?;
    }
    Ok(Walk {
        robot,
        label: chosen.label,
        step_length,
        runs,
        dynamic,
        summary,
        lines,
        tables,
    })
}

/// The `"robot"` entry of `summary.json`: the walked robot and the pattern geometry it walked
/// with.
fn robot_entry(robot: &WalkRobot, p: &PatternParams) -> Value {
    serde_json::json!({
        "name": robot.name,
        "dof": robot.model.nv(),
        "step_length": p.step_length,
        "step_width": p.step_width,
        "com_height": p.com_height,
        "reach": p.reach,
    })
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
    (robot, dynamic): (&WalkRobot, Option<&DynamicRobot>),
    pattern: &WalkingPattern,
    methods: &[Method],
    dir: Option<&Path>,
    summary: &mut Map<String, Value>,
    tables: &mut Vec<(String, Recorder)>,
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
        let run = run_walk_robot(robot, pattern, m, params)?;
        keep(tables, dir, format!("{m}"), tables::series_table(&run)?)?;
        keep(
            tables,
            dir,
            format!("{m}_trajectory"),
            tables::trajectory_table(&run)?,
        )?;
        let recording = tables::recording_table(&run, &robot.model)?;
        keep(tables, dir, format!("{m}_recording"), recording)?;
        summary.insert(m.name().to_string(), serde_json::to_value(&run.summary)?);
        runs.push(run);
    }
    report::progress("");
    if let Some(dir) = dir {
        tables::write_plots(&runs, dir)?;
    }
    let Some(dynamic) = dynamic else {
        return Ok((runs, None));
    };
    check_interrupt()?;
    let method = match methods {
        [m] => *m,
        _ => Method::Minimization,
    };
    let run = dynamic_walk(args, dynamic, method, pattern.params().step_length)?;
    let table = tables::dynamic_table(&run)?;
    if let Some(dir) = dir {
        tables::dynamic_plots(&table, dir)?;
    }
    keep(tables, dir, "dynamic".into(), table)?;
    let recording = tables::dynamic_recording(&run)?;
    keep(tables, dir, "dynamic_recording".into(), recording)?;
    summary.insert("dynamic".into(), serde_json::to_value(&run.summary)?);
    Ok((runs, Some((method, run))))
}

/// The dynamic walk's violations: a foot that slipped (friction), a hop (contact), a joint past
/// its range (limits), interpenetrating segments (self-collision).
fn dynamic_violations(s: &DynamicWalkSummary, max_flight: f64) -> Vec<String> {
    let slip = s.slip_at.map(|t| {
        format!(
            "dynamic walk: friction: a foot slid {:.1} mm within one contact by t = {t:.3} s",
            1e3 * s.max_slip_distance
        )
    });
    let hop = s.longest_flight_at.filter(|_| !s.contact_kept).map(|t| {
        format!(
            "dynamic walk: contact: both feet off the ground for {:.3} s from t = {t:.3} s \
             (a hop: longer than {max_flight:.3} s)",
            s.longest_flight
        )
    });
    let limits = (!s.limits_kept).then(|| {
        format!(
            "dynamic walk: joint limits: {} {:.4} rad beyond its range in the simulation",
            s.min_joint_margin_at, -s.min_joint_margin
        )
    });
    let collision = (!s.collision_free).then(|| {
        format!(
            "dynamic walk: self-collision: {} interpenetrate by {:.4} m in the simulation",
            s.min_distance_at, -s.min_distance
        )
    });
    slip.into_iter()
        .chain(hop)
        .chain(limits)
        .chain(collision)
        .collect()
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

/// Writes `table` as `dir/STEM.csv` (if writing) and keeps it under `stem`; a stem ending in
/// `_recording` is a recording for replay, written gzip-compressed as `dir/STEM.csv.gz`.
fn keep(
    tables: &mut Vec<(String, Recorder)>,
    dir: Option<&Path>,
    stem: String,
    table: Recorder,
) -> Result<(), Box<dyn std::error::Error>> {
    match dir {
        Some(dir) if stem.ends_with("_recording") => {
            write_csv_gz(&table, &dir.join(format!("{stem}.csv.gz")))?
        }
        Some(dir) => table.write_csv(&dir.join(format!("{stem}.csv")))?,
        None => {}
    }
    tables.push((stem, table));
    Ok(())
}

/// Runs the dynamic walk of `robot` with `method`.
fn dynamic_walk(
    args: &WalkArgs,
    robot: &DynamicRobot,
    method: Method,
    step_length: f64,
) -> Result<DynamicWalkRun, Box<dyn std::error::Error>> {
    let p = DynamicWalkParams {
        steps: args.steps,
        step_length,
        step_time: args.step_time,
        method,
        end_stops: !args.no_end_stops,
        friction: args.friction,
        ..DynamicWalkParams::for_robot(robot)?
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
    Ok(run_dynamic_walk_robot(robot, &p)?)
}
