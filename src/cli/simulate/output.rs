//! Outputs of `biped simulate`: `signals.csv` (every recorded signal), SVG plots of the
//! quantities one checks first, `summary.json` (the library's `Summary` plus the run's
//! description) and the text report on stdout.

use super::setup::{Info, StepRule};
use biped_sim::plant::Plant;
use biped_sim::record::Recorder;
use biped_sim::simulation::{Frame, Summary};
use biped_sim::SimError;
use serde_json::{json, Value};
use std::path::Path;

/// Result of this module.
type OutResult<T> = Result<T, Box<dyn std::error::Error>>;

/// At most this many signals per plot (the largest by excursion).
const MAX_LINES: usize = 8;

/// Column of the total vertical contact force, recorded besides the library's signals.
pub const TOTAL_FZ: &str = "contact.fz";

/// Records the total vertical contact force of `f` in the current row of `rec`.
pub fn record_total(f: &Frame, rec: &mut Recorder) -> Result<(), SimError> {
    let fz: f64 = f
        .plant
        .last_outputs()
        .contact
        .feet
        .iter()
        .map(|w| w.force.z)
        .sum();
    rec.set(TOTAL_FZ, fz)
        .map_err(|e| SimError::Output(e.to_string()))
}

/// After a failed run: writes what was recorded; returns a note for the error line.
pub fn write_partial(rec: &Recorder, dir: &Path) -> String {
    let path = dir.join("signals.csv");
    match rec.is_empty() || rec.write_csv(&path).is_err() {
        true => String::new(),
        false => format!(" (signals until then in {})", path.display()),
    }
}

/// One line of a plot: legend label and recorder column.
struct Line {
    label: String,
    column: String,
}

impl Line {
    fn new(label: impl Into<String>, column: impl Into<String>) -> Self {
        Self {
            label: label.into(),
            column: column.into(),
        }
    }
}

/// Writes the CSV, the plots and `summary.json` into `dir`; returns the file names.
pub fn write_all(
    rec: &Recorder,
    plant: &Plant,
    summary: &Summary,
    info: &Info,
    dir: &Path,
) -> OutResult<Vec<String>> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut files = vec!["signals.csv".to_string()];
    rec.write_csv(&dir.join(&files[0]))?;
    let title = |what: &str| format!("{what} ({} {}, {})", info.model, info.scenario, info.method);
    let feet: Vec<String> = plant.contact().specs().map(|s| s.name.clone()).collect();
    let per_foot = |cs: &[&str]| -> Vec<Line> {
        feet.iter()
            .flat_map(|f| {
                cs.iter()
                    .map(move |c| Line::new(format!("{f}.{c}"), format!("{f}.{c}")))
            })
            .collect()
    };
    let mut plots: Vec<(&str, String, Vec<Line>, &str)> = Vec::new();
    if let Some((qi, _)) = plant.floating_base() {
        let lines = vec![
            Line::new("base z", format!("q[{}]", qi + 2)),
            Line::new("CoM z", "com.z"),
        ];
        plots.push((
            "base_height.svg",
            title("Base and CoM height"),
            lines,
            "height [m]",
        ));
    }
    let mut forces = per_foot(&["fz"]);
    forces.push(Line::new("total", TOTAL_FZ));
    plots.push((
        "contact_forces.svg",
        title("Vertical contact force per foot"),
        forces,
        "force [N]",
    ));
    plots.push((
        "foot_shear.svg",
        title("Tangential foot forces"),
        per_foot(&["fx", "fy"]),
        "force [N]",
    ));
    plots.push((
        "foot_torques.svg",
        title("Foot torques about the sole point"),
        per_foot(&["tx", "ty", "tz"]),
        "torque [N m]",
    ));
    let l_g = ["x", "y", "z"].map(|c| Line::new(format!("L_G.{c}"), format!("L_G.{c}")));
    plots.push((
        "angular_momentum.svg",
        title("Angular momentum about the CoM"),
        l_g.into(),
        "L_G [N m s]",
    ));
    let acts = plant.actuators();
    let angles = largest(
        rec,
        acts.iter()
            .map(|a| Line::new(&a.name, format!("q[{}]", a.joint_q))),
    );
    plots.push((
        "joint_angles.svg",
        title(&selected("Joint angles", acts.len())),
        angles,
        "angle [rad]",
    ));
    let currents = largest(
        rec,
        acts.iter()
            .map(|a| Line::new(&a.name, format!("i[{}]", a.name))),
    );
    if !currents.is_empty() {
        plots.push((
            "motor_currents.svg",
            title(&selected("Motor currents", acts.len())),
            currents,
            "current [A]",
        ));
    }
    for (file, title, lines, y) in plots {
        plot(rec, &dir.join(file), &title, &lines, y)?;
        files.push(file.to_string());
    }
    files.push("summary.json".to_string());
    let json = summary_json(summary, final_base_height(rec, plant), plant, info, &files)?;
    let text = serde_json::to_string_pretty(&json)?;
    let path = dir.join("summary.json");
    std::fs::write(&path, text + "\n").map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(files)
}

/// Plot title noting a selection of the largest signals.
fn selected(what: &str, n: usize) -> String {
    match n > MAX_LINES {
        true => format!("{what}, {MAX_LINES} largest of {n}"),
        false => what.to_string(),
    }
}

/// The [`MAX_LINES`] lines with the largest excursion from their first value (lines whose
/// column is missing or constant are dropped).
fn largest(rec: &Recorder, lines: impl Iterator<Item = Line>) -> Vec<Line> {
    let excursion = |col: &[f64]| {
        let first = col.first().copied().unwrap_or(0.0);
        col.iter().map(|x| (x - first).abs()).fold(0.0, f64::max)
    };
    let mut scored: Vec<(f64, Line)> = lines
        .filter_map(|l| rec.column(&l.column).ok().map(|c| (excursion(c), l)))
        .filter(|(e, _)| *e > 0.0)
        .collect();
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    scored.into_iter().take(MAX_LINES).map(|(_, l)| l).collect()
}

/// Plots `lines` of `rec` under their labels (copied into a small recorder of their own).
fn plot(rec: &Recorder, path: &Path, title: &str, lines: &[Line], y_label: &str) -> OutResult<()> {
    let cols = lines
        .iter()
        .map(|l| rec.column(&l.column))
        .collect::<Result<Vec<_>, _>>()?;
    let mut view = Recorder::with_capacity(rec.len());
    let ids = lines
        .iter()
        .map(|l| view.register(&l.label))
        .collect::<Result<Vec<_>, _>>()?;
    for (row, &t) in rec.time().iter().enumerate() {
        view.sample(t)?;
        for (id, col) in ids.iter().zip(&cols) {
            view.set_id(*id, &col[row..=row])?;
        }
    }
    let labels: Vec<&str> = lines.iter().map(|l| l.label.as_str()).collect();
    view.plot_svg(path, title, &labels, y_label)?;
    Ok(())
}

/// `summary.json`: the library summary plus the run's description and final heights.
fn summary_json(
    s: &Summary,
    base: Option<f64>,
    plant: &Plant,
    info: &Info,
    files: &[String],
) -> OutResult<Value> {
    let mut v = serde_json::to_value(s)?;
    let (step, tolerances) = match info.step {
        StepRule::Fixed(h) => (json!(h), Value::Null),
        StepRule::Adaptive(r, a) => (Value::Null, json!({"rtol": r, "atol": a})),
    };
    let extra = json!({
        "model": info.model,
        "scenario": info.scenario,
        "step": step,
        "tolerances": tolerances,
        "passed": s.passed(),
        "final_base_height": base,
        "final_com_height": s.final_com[2],
        "actuators": plant.actuators().len(),
        "files": files,
    });
    if let (Value::Object(map), Value::Object(more)) = (&mut v, extra) {
        map.extend(more);
    }
    Ok(v)
}

/// Height of the floating base in the last recorded row.
fn final_base_height(rec: &Recorder, plant: &Plant) -> Option<f64> {
    let (qi, _) = plant.floating_base()?;
    rec.column(&format!("q[{}]", qi + 2)).ok()?.last().copied()
}

/// Text report on stdout: what ran, how fast, the checks, where the files are.
pub fn print_report(
    s: &Summary,
    plant: &Plant,
    rec: &Recorder,
    info: &Info,
    dir: &Path,
    files: &[String],
) {
    let step = match info.step {
        StepRule::Fixed(h) => format!("h = {h} s"),
        StepRule::Adaptive(r, a) => format!("rtol {r:e}, atol {a:e}"),
    };
    println!(
        "{} on {}, {} ({step})",
        info.scenario, info.model, info.method
    );
    println!(
        "  {:.3} s simulated in {:.3} s: realtime factor {:.3}; {} steps, {} rhs evaluations",
        s.sim_time, s.wall_time, s.realtime_factor, s.steps, s.rhs_evaluations
    );
    if let Some(z) = final_base_height(rec, plant) {
        println!(
            "  final base height {z:.4} m, CoM height {:.4} m",
            s.final_com[2]
        );
    }
    println!(
        "  contact force: final {:.1} N, max {:.1} N (weight {:.1} N)",
        s.final_contact_force, s.max_contact_force, s.weight
    );
    for c in &s.checks {
        let verdict = if c.passed { "ok" } else { "FAILED" };
        println!(
            "  {verdict:>6}: {} {:.3e} (limit {:.3e})",
            c.name, c.value, c.limit
        );
    }
    let failed = s.checks.iter().filter(|c| !c.passed).count();
    match failed {
        0 => println!("  pass criteria: all {} hold", s.checks.len()),
        n => println!("  pass criteria: {n} of {} FAILED", s.checks.len()),
    }
    println!("wrote {}: {}", dir.display(), files.join(", "));
}
